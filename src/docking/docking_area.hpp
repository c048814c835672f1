#pragma once

#include <optional>
#include <string>

#include "docking/docking_config.hpp"
#include "docking/free_space.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"

namespace shelfdock::docking {

/// The robot's pose under the shelf (shelf frame) when it enters from the end nearer to
/// `T_frame_base`: the goal heading is `dock_yaw_offset_rad` or that plus pi, whichever has the
/// robot behind the goal. The one place that decides "which end" from a position.
geometry::Pose2 NearerEndGoal(const geometry::Pose2& T_frame_shelf, double dock_yaw_offset_rad,
                              const geometry::Pose2& T_frame_base);

/// The branch of `T_shelf_goal` (it or it turned by pi) whose heading is nearer `yaw_rad` (a
/// heading in the shelf frame): a code or a shelf seen from under it is ambiguous by pi.
geometry::Pose2 GoalBranchNearHeading(const geometry::Pose2& T_shelf_goal, double yaw_rad);

/// Where the autonomous stage starts: which end of the shelf, and how long the straight in front
/// of it is (the paper's 4.5 m when there is room, down to what an aisle allows).
struct DockingArea {
  geometry::Pose2 T_shelf_goal;   ///< the robot's final pose in the shelf frame
  double entry_distance_m = 0.0;  ///< [m] the entry lies this far behind the goal
};

/// The chosen docking area, or why none fits.
struct DockingAreaResult {
  std::optional<DockingArea> area;
  std::string reason;  ///< why there is none
};

/// Longest straight behind `T_frame_goal` (up to `max_m`) along which the footprint keeps
/// `margin_m` from every obstacle in `free_space`; 0 when the goal itself is not clear.
double ClearStraightBehind(const geometry::Pose2& T_frame_goal, const FreeSpace& free_space,
                           const SafetyConfig& safety, double max_m, double margin_m);

/// Chooses the docking area from the free space around the shelf at `T_frame_shelf`: the end
/// nearer the robot when its straight is at least area.min_entry_distance_m long, else the other
/// end. Without obstacles this is the nearer end and entry_distance_m.
DockingAreaResult ChooseDockingArea(const geometry::Pose2& T_frame_shelf,
                                    const geometry::Pose2& T_frame_base,
                                    const FreeSpace& free_space, const DockingConfig& config);

}  // namespace shelfdock::docking
