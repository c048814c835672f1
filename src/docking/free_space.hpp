#pragma once

#include <vector>

#include "docking/collision_check.hpp"
#include "docking/docking_config.hpp"
#include "docking/path.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// What the robot knows is occupied around the shelf, in one frame (the map's for planning the
/// approach): walls, racks, posts and the other shelves' legs from the map, as discs. The target
/// shelf is not in it (its legs are checked on their own, against the fused estimate).
struct FreeSpace {
  std::vector<LegDisc> obstacles;

  bool empty() const { return obstacles.empty(); }
  /// Smallest distance from the footprint at `T_frame_base` to an obstacle (negative: overlap).
  double Clearance(const geometry::Pose2& T_frame_base, const SafetyConfig& safety) const;
  /// Smallest clearance of the footprint swept along `path` from arc length `s_from_m` (every
  /// `stride_m` and the goal).
  double PathClearance(const Path& path, const SafetyConfig& safety, double stride_m = 0.05,
                       double s_from_m = 0.0) const;
  /// Smallest clearance of the circle the footprint sweeps when turning on the spot.
  double TurnClearance(const geometry::Pose2& T_frame_base, const SafetyConfig& safety) const;
};

/// Radius of the circle the footprint sweeps when the robot turns on the spot.
double TurnRadius(const SafetyConfig& safety);

/// A straight, forward-driven path from `from` to the point of `to` (heading from `from` toward
/// it); `to`'s heading is ignored.
Path StraightPath(const geometry::Pose2& from, const geometry::Pose2& to, double step_m);

}  // namespace shelfdock::docking
