#pragma once

#include <optional>
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>

#include "geometry/config_violation.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {

/// Loads a YAML file; throws InputError naming the file when missing or malformed.
YAML::Node LoadYamlFile(const std::string& path);

/// Reads optional keys of one YAML map into a config struct whose fields already hold their
/// defaults: a key that is absent leaves the default, a key that is not known is an error, and
/// every error names the file and the dotted key path. Used by every config loader so that the
/// struct stays the only place a default is written.
class YamlFields {
 public:
  YamlFields(const YAML::Node& node, std::string file, std::string path);

  /// Reads `key` into `value` when present. Throws on a type mismatch.
  void Read(const std::string& key, double& value);
  void Read(const std::string& key, int& value);
  void Read(const std::string& key, bool& value);
  void Read(const std::string& key, std::string& value);

  /// A nested map under `key` (an undefined node when absent), marked as known.
  YAML::Node Child(const std::string& key);

  /// Throws InputError when the map still has `old_key`, naming the key that replaced it
  /// (`new_key_path`, dotted from the document's root).
  void Renamed(const std::string& old_key, const std::string& new_key_path);

  /// Throws InputError when `ok` is false, naming `key` and the requirement. For parse rules
  /// only (a required key, a name to look up); value rules live with their structs.
  void Require(bool ok, const std::string& key, const std::string& requirement) const;

  /// Throws InputError for a config struct's violation (its FindConfigViolation): the file, the
  /// violation's key under this map's path, and "must be " + its requirement.
  void Reject(const std::optional<geometry::ConfigViolation>& violation) const;

  /// Throws InputError for the first key of the map that no Read/Child asked for.
  void RejectUnknown() const;

  std::string KeyPath(const std::string& key) const;
  const std::string& file() const { return file_; }

 private:
  YAML::Node Lookup(const std::string& key);

  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::set<std::string> known_;
};

}  // namespace shelfdock::io
