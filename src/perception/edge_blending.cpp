#include "perception/edge_blending.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::perception {

EdgeBlendingEstimate EstimateEdgeBlending(const std::vector<ScanPoint>& points, double min_gap_m,
                                          double flat_m) {
  EdgeBlendingEstimate out;
  // points[i] .. points[i + k - 1] on consecutive beams.
  auto consecutive = [&](std::size_t i, std::size_t k) {
    return i + k <= points.size() &&
           points[i + k - 1].beam - points[i].beam == static_cast<int>(k) - 1;
  };
  auto flat = [&](std::size_t a, std::size_t b) {
    return std::abs(points[a].range - points[b].range) < flat_m;
  };
  for (std::size_t i = 0; i + 4 <= points.size(); ++i) {
    if (!consecutive(i, 4) || !flat(i, i + 1)) continue;
    // A clean step between returns i + 1 and i + 2.
    if (flat(i + 2, i + 3) && std::abs(points[i + 1].range - points[i + 2].range) >= min_gap_m) {
      ++out.steps;
    }
    // A step between returns i + 1 and i + 3 with return i + 2 between, off both surfaces.
    if (!consecutive(i, 5) || !flat(i + 3, i + 4)) continue;
    const double a = points[i + 1].range, b = points[i + 3].range, m = points[i + 2].range;
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (hi - lo >= min_gap_m && m > lo + flat_m && m < hi - flat_m) {
      ++out.bridged;
      const double depth = hi - lo;
      out.widest_bridged_twice_m =
          std::max(out.widest_bridged_twice_m, std::min(depth, out.widest_bridged_m));
      out.widest_bridged_m = std::max(out.widest_bridged_m, depth);
    }
  }
  return out;
}

}  // namespace shelfdock::perception
