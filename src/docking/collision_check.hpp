#pragma once

#include <vector>

#include <Eigen/Core>

#include "docking/docking_config.hpp"
#include "docking/path.hpp"
#include "geometry/shelf_model.hpp"

namespace shelfdock::docking {

/// A leg as a disc that covers its cross-section (conservative for square legs).
struct LegDisc {
  Eigen::Vector2d centre;  ///< [m] in the path's frame
  double radius_m = 0.0;   ///< [m]
};

/// The closest approach of the robot's footprint along a path.
struct ClearanceResult {
  double min_clearance_m = 1e9;  ///< [m] smallest footprint-to-obstacle distance along the path
  std::size_t worst_index = 0;   ///< path sample where it occurs
  bool ok = true;                ///< min_clearance_m >= the required margin
};

/// Signed distance from a point (robot base frame) to the robot's rectangular footprint
/// (negative inside).
double FootprintDistance(const Eigen::Vector2d& p_base, const SafetyConfig& safety);

/// The shelf model's legs placed at `T_frame_shelf`.
std::vector<LegDisc> LegDiscs(const geometry::ShelfModel& model,
                              const geometry::Pose2& T_frame_shelf);

/// Sweeps the footprint along `path` (every `stride_m`, plus the goal) against the legs and
/// requires safety.leg_margin_m of clearance.
ClearanceResult CheckPathAgainstLegs(const Path& path, const std::vector<LegDisc>& legs,
                                     const SafetyConfig& safety, double stride_m = 0.02);

/// First scan point (path frame) inside the footprint grown by obstacle_margin_m along the path
/// from arc length `s_from` for obstacle_lookahead_m; points near an expected leg are ignored.
/// Returns the arc length of the blocked pose, or a negative number when the way is clear.
double FirstBlockedArcLength(const Path& path, double s_from,
                             const std::vector<Eigen::Vector2d>& points,
                             const std::vector<LegDisc>& legs, const SafetyConfig& safety);

}  // namespace shelfdock::docking
