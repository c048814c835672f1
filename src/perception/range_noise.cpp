#include "perception/range_noise.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::perception {

RangeNoiseEstimate EstimateRangeNoise(const std::vector<ScanPoint>& points,
                                      const std::vector<ClusterSpan>& spans, int min_samples) {
  std::vector<double> d2;
  d2.reserve(points.size());
  for (const ClusterSpan& span : spans) {
    for (std::size_t i = span.begin + 1; i + 1 < span.end; ++i) {
      const ScanPoint& a = points[i - 1];
      const ScanPoint& b = points[i];
      const ScanPoint& c = points[i + 1];
      if (b.beam - a.beam != 1 || c.beam - b.beam != 1) continue;  // a dropped beam between
      d2.push_back(std::abs(a.range - 2.0 * b.range + c.range));
    }
  }
  RangeNoiseEstimate out;
  out.samples = static_cast<int>(d2.size());
  if (out.samples < std::max(min_samples, 1)) return out;
  const auto mid = d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2);
  std::nth_element(d2.begin(), mid, d2.end());
  out.sigma_m = 1.4826 * *mid / std::sqrt(6.0);
  return out;
}

}  // namespace shelfdock::perception
