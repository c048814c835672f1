#pragma once

#include <string>

#include "docking/docking_config.hpp"
#include "docking/path.hpp"

namespace shelfdock::docking {

/// A planned path, or why there is none.
struct PlanResult {
  bool ok = false;
  Path path;                ///< valid when ok
  double straight_m = 0.0;  ///< [m] length of the straight, goal-aligned final segment
  std::string reason;       ///< why planning failed
};

/// Plans a forward path for a differential drive from `T_start` to `T_goal` (same frame): a cubic
/// Bezier whose end tangents match both headings (so curvature is continuous into the straight),
/// then a straight segment along the goal heading so the robot enters between the legs aligned.
/// The longest straight (up to final_straight_m, down to min_final_straight_m) whose curve keeps
/// |curvature| <= max_curvature_1pm wins; among curves, the one with the lowest peak curvature.
PlanResult PlanDockingPath(const geometry::Pose2& T_start, const geometry::Pose2& T_goal,
                           const PlannerConfig& config);

}  // namespace shelfdock::docking
