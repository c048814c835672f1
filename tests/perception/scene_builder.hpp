#pragma once
// Placement helpers for end-to-end tests: a shelf at a given standoff from the LiDAR.

#include <algorithm>
#include <cmath>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"

namespace shelfdock::perception::testing {

/// The shelf pose (LiDAR at the origin) with heading `yaw` whose centre lies on the ray at
/// `bearing` and whose nearest leg centre is `standoff_m` from the LiDAR (bisection).
inline geometry::Pose2 PlaceShelf(const geometry::ShelfModel& model, double standoff_m,
                                  double bearing, double yaw) {
  auto nearest = [&](double dist) {
    const geometry::Pose2 T(dist * std::cos(bearing), dist * std::sin(bearing), yaw);
    double best = 1e9;
    for (const auto& c : model.LegCentres()) best = std::min(best, (T * c).norm());
    return best;
  };
  double lo = 0.0, hi = standoff_m + model.Diagonal();
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (nearest(mid) < standoff_m ? lo : hi) = mid;
  }
  return {hi * std::cos(bearing), hi * std::sin(bearing), yaw};
}

}  // namespace shelfdock::perception::testing
