#include "perception/depth_step.hpp"

#include <cmath>

namespace shelfdock::perception {

std::optional<std::size_t> StrongestDepthStep(const std::vector<ScanPoint>& points,
                                              const ClusterSpan& span, double min_step_m) {
  std::optional<std::size_t> best;
  double best_step = min_step_m;
  for (std::size_t k = span.begin + 1; k < span.end; ++k) {
    const double step = std::abs(points[k].range - points[k - 1].range);
    if (step >= best_step) {
      best_step = step;
      best = k;
    }
  }
  return best;
}

}  // namespace shelfdock::perception
