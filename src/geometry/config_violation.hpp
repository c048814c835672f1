#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shelfdock::geometry {

/// An impossible configuration value: its dotted key (e.g. `controller.max_speed_mps`, as in the
/// YAML file) and the rule it breaks ("> 0"). Every config struct has one function that checks
/// all of its fields and returns the first of these; the YAML loaders only add the file name
/// (and, for an entry of a list, its path: `people[1].`).
struct ConfigViolation {
  std::string key;
  std::string requirement;
};

/// Collects the first failed rule of a config check; later checks are skipped once one failed.
/// Keys are prefixed with the struct's place in its file ("planner." for DockingConfig::planner).
class ConfigChecker {
 public:
  explicit ConfigChecker(std::string prefix = "") : prefix_(std::move(prefix)) {}

  void Check(bool ok, std::string_view key, std::string_view requirement) {
    if (!ok && !violation_) {
      violation_ = ConfigViolation{prefix_ + std::string(key), std::string(requirement)};
    }
  }
  /// Takes the result of a nested struct's check, its keys under `prefix` + "." (e.g. "planner"),
  /// or as they are when `prefix` is empty: a struct whose keys sit in its parent's map (a
  /// Person's PathMotion and Material, written `speed` and `reflectivity` beside `stride`).
  void Nested(std::string_view prefix, const std::optional<ConfigViolation>& nested) {
    if (nested && !violation_) {
      const std::string under = prefix.empty() ? "" : std::string(prefix) + ".";
      violation_ = ConfigViolation{prefix_ + under + nested->key, nested->requirement};
    }
  }
  const std::optional<ConfigViolation>& Result() const { return violation_; }

 private:
  std::string prefix_;
  std::optional<ConfigViolation> violation_;
};

}  // namespace shelfdock::geometry
