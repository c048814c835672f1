#include "perception/silhouette_edges.hpp"

#include <algorithm>

#include "geometry/angle.hpp"

namespace shelfdock::perception {
namespace {

// The return of beam `beam`, if it is valid (scan_points is in beam order).
const ScanPoint* FindBeam(const std::vector<ScanPoint>& scan_points, int beam) {
  const auto it = std::lower_bound(scan_points.begin(), scan_points.end(), beam,
                                   [](const ScanPoint& q, int b) { return q.beam < b; });
  return it != scan_points.end() && it->beam == beam ? &*it : nullptr;
}

// The edge between `outer` and the next beam out (`step` beams away), when that beam passed
// beside the object.
std::optional<double> EdgeBeside(const std::vector<ScanPoint>& scan_points, const ScanPoint& outer,
                                 int step, double min_depth_m) {
  const ScanPoint* next = FindBeam(scan_points, outer.beam + step);
  if (next == nullptr || next->range < outer.range + min_depth_m) return std::nullopt;
  return geometry::WrapAngle(outer.angle + 0.5 * geometry::AngleDiff(next->angle, outer.angle));
}

}  // namespace

SilhouetteEdges FindSilhouetteEdges(const std::vector<ScanPoint>& scan_points,
                                    const ScanPoint& first, const ScanPoint& last,
                                    double min_depth_m) {
  SilhouetteEdges edges;
  const int outward = last.beam >= first.beam ? 1 : -1;
  edges.before_rad = EdgeBeside(scan_points, first, -outward, min_depth_m);
  edges.after_rad = EdgeBeside(scan_points, last, outward, min_depth_m);
  return edges;
}

}  // namespace shelfdock::perception
