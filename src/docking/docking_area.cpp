#include "docking/docking_area.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

using geometry::Pose2;

Pose2 NearerEndGoal(const Pose2& T_frame_shelf, double dock_yaw_offset_rad,
                    const Pose2& T_frame_base) {
  const Pose2 T_shelf_goal(0.0, 0.0, dock_yaw_offset_rad);
  const Pose2 flipped(0.0, 0.0, dock_yaw_offset_rad + std::numbers::pi);
  const double along = ((T_frame_shelf * T_shelf_goal).inverse() * T_frame_base).x;
  const double along_flipped = ((T_frame_shelf * flipped).inverse() * T_frame_base).x;
  return along_flipped < along ? flipped : T_shelf_goal;
}

Pose2 GoalBranchNearHeading(const Pose2& T_shelf_goal, double yaw_rad) {
  if (std::abs(geometry::AngleDiff(yaw_rad, T_shelf_goal.yaw)) > 0.5 * std::numbers::pi) {
    return T_shelf_goal * Pose2(0.0, 0.0, std::numbers::pi);
  }
  return T_shelf_goal;
}

double ClearStraightBehind(const Pose2& T_frame_goal, const FreeSpace& free_space,
                           const SafetyConfig& safety, double max_m, double margin_m) {
  constexpr double kStep_m = 0.05;
  double clear_m = 0.0;
  for (double s = 0.0; s <= max_m + 1e-9; s += kStep_m) {
    if (free_space.Clearance(T_frame_goal * Pose2(-s, 0.0, 0.0), safety) < margin_m) break;
    clear_m = s;
  }
  return clear_m;
}

DockingAreaResult ChooseDockingArea(const Pose2& T_frame_shelf, const Pose2& T_frame_base,
                                    const FreeSpace& free_space, const DockingConfig& config) {
  DockingAreaResult result;
  const Pose2 nearer = NearerEndGoal(T_frame_shelf, config.dock_yaw_offset_rad, T_frame_base);
  double longest_m = 0.0;
  for (const Pose2& T_shelf_goal : {nearer, nearer * Pose2(0.0, 0.0, std::numbers::pi)}) {
    const double straight_m =
        ClearStraightBehind(T_frame_shelf * T_shelf_goal, free_space, config.safety,
                            config.entry_distance_m, config.safety.obstacle_margin_m);
    longest_m = std::max(longest_m, straight_m);
    if (straight_m >= config.min_entry_distance_m) {
      result.area = DockingArea{T_shelf_goal, straight_m};
      return result;
    }
  }
  result.reason = "no room for a docking area at either end of the shelf (longest clear straight " +
                  std::to_string(longest_m).substr(0, 4) + " m, need " +
                  std::to_string(config.min_entry_distance_m).substr(0, 4) + " m)";
  return result;
}

}  // namespace shelfdock::docking
