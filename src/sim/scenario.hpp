#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim {

/// How a shelf's preset (the pose stored in the robot's map) relates to its true pose: the
/// paper's shelves drift from their map coordinates by manual placement and collisions.
struct ScenarioShelf {
  int id = 0;
  std::string model_name;
  geometry::Pose2 T_map_shelf;  ///< true pose (the simulator's world frame is the map frame)
  std::optional<geometry::Pose2> T_map_shelf_preset;  ///< stated preset, when given
  double preset_offset_xy_m = 0.0;     ///< [m] else: preset = truth + uniform(+-xy) per axis
  double preset_offset_yaw_rad = 0.0;  ///< [rad] and uniform(+-yaw) on the heading
};

/// A simulated docking job: the true world, what the robot is told, and where it starts.
struct Scenario {
  std::string name;
  World world;  ///< ground truth
  std::vector<ScenarioShelf> shelves;
  geometry::Pose2 T_map_robot_start;  ///< robot base at the entry of the docking area
  int target_shelf_id = -1;           ///< the shelf to dock under (-1: none named)

  const ScenarioShelf* FindShelf(int id) const;
  /// The preset the robot is told for a shelf: the stated one, else the true pose plus a draw
  /// from the offset range (deterministic for a seed and shelf id), else the true pose.
  /// nullopt for unknown ids.
  std::optional<geometry::Pose2> PresetPose(int shelf_id, std::uint64_t seed) const;
};

/// The first impossible value of a shelf's entry (keys as in a scenario file's `shelves[i]`):
/// an id >= 0, offsets >= 0, and no offset range next to a stated preset (it would be ignored).
std::optional<geometry::ConfigViolation> FindConfigViolation(const ScenarioShelf& shelf);
/// The shelves' rules under `shelves[i].`, ids unique among them, and a target that is one of
/// them. The world's objects are checked one by one as they are built (their own functions):
/// the world does not keep which entry of the file each came from.
std::optional<geometry::ConfigViolation> FindConfigViolation(const Scenario& scenario);

}  // namespace shelfdock::sim
