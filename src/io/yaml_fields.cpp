#include "io/yaml_fields.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/input_limits.hpp"

namespace shelfdock::io {

YAML::Node LoadYamlFile(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw InputError(path, "", "cannot open file");
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec) &&
      std::filesystem::file_size(path, ec) > kMaxYamlFileBytes) {
    throw InputError(path, "",
                     "larger than " + std::to_string(kMaxYamlFileBytes) + " bytes, the limit");
  }
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw InputError(path, "line " + std::to_string(e.mark.line + 1), "malformed YAML: " + e.msg);
  }
}

YamlFields::YamlFields(const YAML::Node& node, std::string file, std::string path)
    : node_(node), file_(std::move(file)), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_, path_.empty() ? "(document)" : path_, "expected a map of keys");
  }
}

std::string YamlFields::KeyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

YAML::Node YamlFields::Lookup(const std::string& key) {
  known_.insert(key);
  if (!node_.IsDefined() || node_.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
  return node_[key];
}

void YamlFields::Read(const std::string& key, double& value) {
  const YAML::Node v = Lookup(key);
  if (!v.IsDefined() || v.IsNull()) return;
  try {
    value = v.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(file_, KeyPath(key), "expected a number");
  }
  if (!std::isfinite(value)) throw InputError(file_, KeyPath(key), "expected a finite number");
}

void YamlFields::Read(const std::string& key, int& value) {
  const YAML::Node v = Lookup(key);
  if (!v.IsDefined() || v.IsNull()) return;
  try {
    value = v.as<int>();
  } catch (const YAML::Exception&) {
    throw InputError(file_, KeyPath(key), "expected an integer");
  }
}

void YamlFields::Read(const std::string& key, bool& value) {
  const YAML::Node v = Lookup(key);
  if (!v.IsDefined() || v.IsNull()) return;
  try {
    value = v.as<bool>();
  } catch (const YAML::Exception&) {
    throw InputError(file_, KeyPath(key), "expected true or false");
  }
}

void YamlFields::Read(const std::string& key, std::string& value) {
  const YAML::Node v = Lookup(key);
  if (!v.IsDefined() || v.IsNull()) return;
  if (!v.IsScalar()) throw InputError(file_, KeyPath(key), "expected a string");
  value = v.as<std::string>();
}

YAML::Node YamlFields::Child(const std::string& key) { return Lookup(key); }

void YamlFields::Renamed(const std::string& old_key, const std::string& new_key_path) {
  const YAML::Node v = Lookup(old_key);
  if (v.IsDefined()) {
    throw InputError(file_, KeyPath(old_key), "renamed: write " + new_key_path + " instead");
  }
}

void YamlFields::Require(bool ok, const std::string& key, const std::string& requirement) const {
  if (!ok) throw InputError(file_, KeyPath(key), "must be " + requirement);
}

void YamlFields::Reject(const std::optional<geometry::ConfigViolation>& violation) const {
  if (violation) Require(false, violation->key, violation->requirement);
}

void YamlFields::RejectUnknown() const {
  if (!node_.IsDefined() || node_.IsNull()) return;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) {
      throw InputError(file_, path_.empty() ? "(document)" : path_, "expected text keys");
    }
    const std::string key = kv.first.as<std::string>();
    if (!known_.contains(key)) throw InputError(file_, KeyPath(key), "unknown key");
  }
}

}  // namespace shelfdock::io
