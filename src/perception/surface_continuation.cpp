#include "perception/surface_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shelfdock::perception {

bool ContinuesSurface(const std::vector<ScanPoint>& points, std::size_t begin, std::size_t end,
                      double max_step_m, double min_chord_m, double tolerance_m) {
  if (begin == 0 || end >= points.size() || begin >= end) return false;
  const ScanPoint& before = points[begin - 1];
  const ScanPoint& after = points[end];
  constexpr int kMaxMissingBeams = 1;
  if (std::abs(points[begin].beam - before.beam) - 1 > kMaxMissingBeams ||
      std::abs(after.beam - points[end - 1].beam) - 1 > kMaxMissingBeams ||
      (points[begin].p - before.p).norm() > max_step_m ||
      (after.p - points[end - 1].p).norm() > max_step_m) {
    return false;
  }
  const Eigen::Vector2d chord = after.p - before.p;
  const double length = chord.norm();
  if (length < std::max(min_chord_m, 1e-9)) return false;
  const Eigen::Vector2d along = chord / length;
  for (std::size_t i = begin; i < end; ++i) {
    const Eigen::Vector2d d = points[i].p - before.p;
    const double t = d.dot(along);
    const double off = std::abs(d.x() * along.y() - d.y() * along.x());
    if (t < 0.0 || t > length || off > tolerance_m) return false;
  }
  return true;
}

}  // namespace shelfdock::perception
