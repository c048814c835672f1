#pragma once

#include <string>
#include <vector>

#include "docking/collision_check.hpp"
#include "docking/docking_config.hpp"
#include "docking/free_space.hpp"
#include "docking/path.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// How the robot gets from where it stands to the docking area's entry, cheapest first.
enum class ApproachKind {
  kDockNow,         ///< already inside the docking area with a smooth path to the goal
  kSmooth,          ///< one smooth forward curve to the entry, crossed at the docking speed
  kTurnThenSmooth,  ///< turn on the spot toward the entry, then a smooth curve to it
  kTurnDriveTurn,   ///< turn toward the entry, drive straight to it, stop, turn to the goal
  kMoveOut,         ///< drive straight along the heading (forward or reversing) to where a turn
                    ///< is free, then plan again (e.g. half under a shelf)
};
/// The kind's snake_case name (records, events).
std::string_view ToString(ApproachKind kind);

/// How the robot reaches the docking area's entry.
struct ApproachPlan {
  bool ok = false;
  ApproachKind kind = ApproachKind::kDockNow;
  double entry_distance_m = 0.0;    ///< [m] docking area used (entry this far behind the goal)
  geometry::Pose2 T_frame_entry;    ///< the entry pose (goal heading)
  double first_turn_yaw_rad = 0.0;  ///< turn kinds: heading to turn to first
  geometry::Pose2 T_frame_move_to;  ///< kMoveOut: where the straight move ends
  Path path;           ///< kSmooth / kTurnThenSmooth: curve to the entry; kTurnDriveTurn: line
  std::string reason;  ///< why no plan exists
};

/// Plans the approach from `T_frame_base` to the docking area in front of `T_frame_goal`, whose
/// straight is at most `max_entry_m` long, keeping clear of `free_space` (which holds the target
/// shelf's legs too) by safety.obstacle_margin_m. Shorter docking areas (down to
/// min_entry_distance_m) are tried when the longest cannot be reached. A move out is planned
/// (when `allow_move_out`) only toward a place from which an approach exists.
ApproachPlan PlanApproach(const geometry::Pose2& T_frame_base, const geometry::Pose2& T_frame_goal,
                          double max_entry_m, const FreeSpace& free_space,
                          const DockingConfig& config, bool allow_move_out = true);

}  // namespace shelfdock::docking
