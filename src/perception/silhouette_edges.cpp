#include "perception/silhouette_edges.hpp"

#include <algorithm>

#include "geometry/angle.hpp"

namespace shelfdock::perception {
namespace {

// The edge between `outer` and the next beam out (`step` beams away), when that beam passed
// beside the object. `cut` tells whether an open side may hide much more of the object: the
// next beam returned from nearer, or the scan has no beam there (before its first beam or after
// its last return).
std::optional<double> EdgeBeside(const std::vector<ScanPoint>& scan_points, const ScanPoint& outer,
                                 int step, double min_depth_m, bool& cut,
                                 std::optional<double>& depth_step_m) {
  const int beam = outer.beam + step;
  const ScanPoint* next = FindBeam(scan_points, beam);
  if (next != nullptr) depth_step_m = next->range - outer.range;
  if (next != nullptr && next->range >= outer.range + min_depth_m) {
    cut = false;
    return geometry::WrapAngle(outer.angle + 0.5 * geometry::AngleDiff(next->angle, outer.angle));
  }
  cut = next == nullptr ? beam < 0 || scan_points.empty() || beam > scan_points.back().beam
                        : next->range < outer.range;
  return std::nullopt;
}

}  // namespace

SilhouetteEdges FindSilhouetteEdges(const std::vector<ScanPoint>& scan_points,
                                    const ScanPoint& first, const ScanPoint& last,
                                    double min_depth_m) {
  SilhouetteEdges edges;
  const int outward = last.beam >= first.beam ? 1 : -1;
  edges.before_rad =
      EdgeBeside(scan_points, first, -outward, min_depth_m, edges.before_cut, edges.before_step_m);
  edges.after_rad =
      EdgeBeside(scan_points, last, outward, min_depth_m, edges.after_cut, edges.after_step_m);
  return edges;
}

}  // namespace shelfdock::perception
