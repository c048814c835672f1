#include "perception/width_bloom.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace shelfdock::perception {
namespace {

// Whether the scan's return on the first beam out from `edge` that returned, `side` (-1 or +1)
// beams at a time and at most two beams out, stands at least `min_step_m` behind it. `raw` are
// the scan's valid returns in beam order, before the Eq. 1 filter (which removes the trailing
// points at a depth step and often the first background return with them); a dropout between
// only lowers the estimate.
bool ClearBehind(const std::vector<ScanPoint>& raw, const ScanPoint& edge, int side,
                 double min_step_m) {
  for (int k = 1; k <= 2; ++k) {
    const int beam = edge.beam + side * k;
    const auto it = std::lower_bound(raw.begin(), raw.end(), beam,
                                     [](const ScanPoint& q, int b) { return q.beam < b; });
    if (it == raw.end() || it->beam != beam) continue;  // no return on that beam
    return it->range >= edge.range + min_step_m;
  }
  return false;
}

}  // namespace

WidthBloomEstimate EstimateWidthBloom(const std::vector<ScanPoint>& raw_points,
                                      const std::vector<ScanPoint>& points,
                                      const std::vector<ClusterSpan>& spans,
                                      double angle_increment_rad, double narrowest_leg_m,
                                      const EvidenceConfig& config) {
  WidthBloomEstimate out;
  if (config.width_bloom_max_rad <= 0.0) return out;
  const double alpha = std::abs(angle_increment_rad);
  std::vector<double> excess;
  for (const ClusterSpan& span : spans) {
    // A lone return tells nothing: a stray echo in mid-air or a far thin object one beam hit.
    if (span.size() < 2 || span.extent_m > config.width_bloom_max_extent_m) continue;
    const ScanPoint& first = points[span.begin];
    const ScanPoint& last = points[span.end - 1];
    if (!ClearBehind(raw_points, first, -1, config.width_bloom_min_step_m) ||
        !ClearBehind(raw_points, last, +1, config.width_bloom_min_step_m)) {
      continue;
    }
    const double range = span.centroid.norm();
    if (range <= 0.0) continue;
    // Beams spanned, half a beam of them the quantisation: a thin object drawn true spans its own
    // angle plus up to one beam. A whole beam counted off underrated a blooming scanner's spot,
    // none cost right shelves on the default sensors (measured while the estimate still took
    // clusters up to 0.2 m and lone returns: config/lidar_variants/bloom.yaml 85.3 % right first
    // with a whole beam, 91.6 % with half, 94.4 % with none, but 1-4 right shelves fewer on each
    // usual sample of the default sensors).
    const double seen = static_cast<double>(std::abs(last.beam - first.beam) + 1) * alpha;
    excess.push_back(seen - 0.5 * alpha - std::atan2(narrowest_leg_m, range));
  }
  out.objects = static_cast<int>(excess.size());
  if (out.objects < std::max(config.width_bloom_min_objects, 1)) return out;
  const auto k = static_cast<std::size_t>(std::floor(
      std::clamp(config.width_bloom_quantile, 0.0, 1.0) * static_cast<double>(excess.size() - 1)));
  std::nth_element(excess.begin(), excess.begin() + static_cast<std::ptrdiff_t>(k), excess.end());
  out.bloom_rad = std::clamp(excess[k], 0.0, config.width_bloom_max_rad);
  return out;
}

}  // namespace shelfdock::perception
