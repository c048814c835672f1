#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::sim {

/// Motion along a polyline at constant speed, for people and other robots. At the end of an
/// open path the mover turns around (back and forth); a closed path loops.
struct PathMotion {
  std::vector<Eigen::Vector2d> waypoints;  ///< [m] world frame, at least one
  double speed_mps = 1.0;                  ///< [m/s]
  bool closed = false;                     ///< loop from the last waypoint to the first
  double start_offset_m = 0.0;             ///< [m] distance along the path at t = 0

  double Length() const;
  /// Pose at time t: position on the path, yaw along the direction of travel.
  geometry::Pose2 PoseAt(double t_s) const;
};

/// The first impossible value of a motion: a speed in [0, 10) m/s. Keys as in scenario files
/// (`speed`), where a mover's path keys sit beside its other keys; the loader requires the
/// waypoints, and any closed flag or start offset will do.
std::optional<geometry::ConfigViolation> FindConfigViolation(const PathMotion& motion);

}  // namespace shelfdock::sim
