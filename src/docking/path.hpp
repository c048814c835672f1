#pragma once

#include <limits>
#include <vector>

#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// One sample of a planned path.
struct PathPoint {
  geometry::Pose2 pose;    ///< in the frame the path was planned in (map or odom)
  double s = 0.0;          ///< [m] arc length from the start
  double curvature = 0.0;  ///< [1/m] signed, counter-clockwise positive
};

/// Where a pose projects onto a path.
struct PathProjection {
  std::size_t index = 0;  ///< segment start index
  double s = 0.0;         ///< [m] arc length of the foot point (may exceed Length() past the end)
  double cross_track_m = 0.0;      ///< [m] signed lateral offset, left positive
  double heading_error_rad = 0.0;  ///< pose yaw minus path yaw
  double curvature = 0.0;          ///< [1/m] path curvature at the foot point
};

/// A sampled, forward-driven path. The last point is the goal.
struct Path {
  std::vector<PathPoint> points;

  bool empty() const { return points.empty(); }
  double Length() const { return points.empty() ? 0.0 : points.back().s; }
  const geometry::Pose2& Goal() const { return points.back().pose; }
  /// Largest |curvature| of the points beyond arc length `after_s` (all points by default).
  double MaxAbsCurvature(double after_s = -std::numeric_limits<double>::infinity()) const;

  /// Projects `pose` onto the path, searching segments from `hint` onward (progress is monotone
  /// while tracking). Past the end the goal's tangent line is used, so s keeps growing.
  PathProjection Project(const geometry::Pose2& pose, std::size_t hint = 0) const;
};

}  // namespace shelfdock::docking
