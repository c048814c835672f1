#include "io/models_yaml.hpp"

#include <algorithm>
#include <string>

#include "io/input_error.hpp"
#include "io/input_limits.hpp"
#include "io/yaml_fields.hpp"

namespace shelfdock::io {

std::vector<geometry::ShelfModel> ReadShelfModels(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  YamlFields top(root, path, "");
  const YAML::Node list = top.Child("models");
  top.RejectUnknown();
  if (!list.IsDefined() || !list.IsSequence() || list.size() == 0) {
    throw InputError(path, "models", "expected a non-empty list of shelf models");
  }
  if (list.size() > kMaxShelfModels) {
    throw InputError(path, "models",
                     std::to_string(list.size()) + " models exceed the limit of " +
                         std::to_string(kMaxShelfModels));
  }

  std::vector<geometry::ShelfModel> models;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = "models[" + std::to_string(i) + "]";
    YamlFields f(list[i], path, where);
    geometry::ShelfModel m;  // sizes are required: 0 makes an absent one break its "> 0" rule
    m.length_m = 0.0;
    m.width_m = 0.0;
    f.Read("name", m.name);
    f.Read("length", m.length_m);
    f.Read("width", m.width_m);
    YamlFields leg(f.Child("leg"), path, where + ".leg");
    f.RejectUnknown();
    std::string shape = "rectangle";
    m.leg.length_m = 0.0;
    m.leg.width_m = 0.0;
    leg.Read("shape", shape);
    leg.Read("length", m.leg.length_m);
    leg.Read("width", m.leg.width_m);
    leg.RejectUnknown();
    if (shape == "rectangle") {
      m.leg.shape = geometry::LegShape::kRectangle;
    } else if (shape == "circle") {
      m.leg.shape = geometry::LegShape::kCircle;
      if (m.leg.width_m == 0.0) m.leg.width_m = m.leg.length_m;
    } else {
      throw InputError(path, where + ".leg.shape", "expected rectangle or circle, got " + shape);
    }
    models.push_back(m);
  }
  top.Reject(geometry::FindConfigViolation(models));  // keys `models[i].name`, ...
  return models;
}

std::vector<geometry::ShelfModel> SelectModels(const std::vector<geometry::ShelfModel>& models,
                                               const std::vector<std::string>& names,
                                               const std::string& path, const std::string& field) {
  if (names.empty()) return models;
  auto named = [](const std::string& name) {
    return [&name](const geometry::ShelfModel& m) { return m.name == name; };
  };
  std::vector<geometry::ShelfModel> kept;
  for (const std::string& name : names) {
    const auto it = std::find_if(models.begin(), models.end(), named(name));
    if (it == models.end()) {
      std::string message = "no model '";
      message.append(name).append("' in the file; it holds");
      for (const auto& m : models) message.append(" ").append(m.name);
      throw InputError(path, field, message);
    }
    if (std::none_of(kept.begin(), kept.end(), named(name))) kept.push_back(*it);
  }
  return kept;
}

}  // namespace shelfdock::io
