#include "sim/scenario.hpp"

#include <algorithm>
#include <random>
#include <string>

namespace shelfdock::sim {

const ScenarioShelf* Scenario::FindShelf(int id) const {
  for (const ScenarioShelf& s : shelves) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

std::optional<geometry::Pose2> Scenario::PresetPose(int shelf_id, std::uint64_t seed) const {
  const ScenarioShelf* shelf = FindShelf(shelf_id);
  if (shelf == nullptr) return std::nullopt;
  if (shelf->T_map_shelf_preset) return *shelf->T_map_shelf_preset;
  if (shelf->preset_offset_xy_m <= 0.0 && shelf->preset_offset_yaw_rad <= 0.0) {
    return shelf->T_map_shelf;
  }
  // One stream per (seed, shelf): adding a shelf does not change the others' presets.
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(shelf_id)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double dx = shelf->preset_offset_xy_m * unit(rng);
  const double dy = shelf->preset_offset_xy_m * unit(rng);
  const double dyaw = shelf->preset_offset_yaw_rad * unit(rng);
  const geometry::Pose2& T = shelf->T_map_shelf;
  return geometry::Pose2(T.x + dx, T.y + dy, T.yaw + dyaw);
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const ScenarioShelf& shelf) {
  geometry::ConfigChecker k;  // model_name: looked up by the loader; poses: any
  k.Check(shelf.id >= 0, "id", "given, an integer >= 0 (the code under the shelf)");
  // PresetPose uses a stated preset as it is: an offset range beside it would be ignored.
  const bool offset = shelf.preset_offset_xy_m != 0.0 || shelf.preset_offset_yaw_rad != 0.0;
  k.Check(!(shelf.T_map_shelf_preset && offset), "preset_offset", "absent when preset is given");
  k.Check(shelf.preset_offset_xy_m >= 0.0, "preset_offset.xy_m", ">= 0 (metres)");
  k.Check(shelf.preset_offset_yaw_rad >= 0.0, "preset_offset.yaw_rad", ">= 0 (radians)");
  return k.Result();
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const Scenario& s) {
  geometry::ConfigChecker k;  // name and robot_start: any
  for (auto it = s.shelves.begin(); it != s.shelves.end(); ++it) {
    const std::string where = "shelves[" + std::to_string(it - s.shelves.begin()) + "]";
    const bool unique = std::none_of(
        s.shelves.begin(), it, [&](const ScenarioShelf& earlier) { return earlier.id == it->id; });
    k.Check(unique, where + ".id", "unique among the shelves");
    k.Nested(where, FindConfigViolation(*it));
  }
  k.Check(s.target_shelf_id == -1 || s.FindShelf(s.target_shelf_id) != nullptr, "target_shelf",
          "the id of a shelf in this scenario");
  return k.Result();
}

}  // namespace shelfdock::sim
