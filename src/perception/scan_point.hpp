#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geometry/angle.hpp"

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

/// The first and last beam (inclusive) whose bearing lies within `half_rad` of `bearing_rad`,
/// the fan's start and increment read off `points` (beam order); nullopt when they cannot be
/// (fewer than two beams). Beams outside the scan are counted too.
inline std::optional<std::pair<int, int>> BeamWindow(const std::vector<ScanPoint>& points,
                                                     double bearing_rad, double half_rad) {
  if (points.empty() || points.back().beam == points.front().beam) return std::nullopt;
  const ScanPoint& a = points.front();
  const ScanPoint& b = points.back();
  const double inc = (b.angle - a.angle) / static_cast<double>(b.beam - a.beam);
  // The bearing's offset from the first beam, wrapped about the fan's middle: a fan wider than
  // pi (270 deg LiDARs) has bearings more than pi from its first beam, which a wrap about the
  // first beam would put on the wrong side of it.
  const double middle = a.angle + 0.5 * (b.angle - a.angle);
  const double offset = (middle - a.angle) + geometry::AngleDiff(bearing_rad, middle);
  const double centre = a.beam + offset / inc;
  const double half = half_rad / std::abs(inc);
  return std::pair{static_cast<int>(std::ceil(centre - half)),
                   static_cast<int>(std::floor(centre + half))};
}

}  // namespace shelfdock::perception
