#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace shelfdock::perception {

/// One valid return, in the scan's frame (`lidar`, sensor at the origin). Invariant: p = range *
/// (cos angle, sin angle) with range > 0 (the fits take the beam direction as p / range).
struct ScanPoint {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();  ///< [m] position, lidar frame
  double range = 0.0;                           ///< [m]
  double angle = 0.0;                           ///< [rad] beam bearing
  int beam = 0;                                 ///< index in the scan
};

/// The index of the first return of beam `beam` or a later one in `points` (beam order).
inline std::size_t IndexOfBeam(const std::vector<ScanPoint>& points, int beam) {
  const auto it = std::lower_bound(points.begin(), points.end(), beam,
                                   [](const ScanPoint& q, int b) { return q.beam < b; });
  return static_cast<std::size_t>(it - points.begin());
}

/// The return of beam `beam` in `points` (beam order); nullptr when that beam gave none.
inline const ScanPoint* FindBeam(const std::vector<ScanPoint>& points, int beam) {
  const std::size_t i = IndexOfBeam(points, beam);
  return i < points.size() && points[i].beam == beam ? &points[i] : nullptr;
}

}  // namespace shelfdock::perception
