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

EndPieces FrontEndPieces(const std::vector<ScanPoint>& points, const ClusterSpan& span,
                         double max_extent_m, double min_step_m) {
  EndPieces out;
  if (span.size() < 3) return out;
  // Front piece [begin, k): grows while it fits, the step at k must go away from the sensor.
  double best = min_step_m;
  for (std::size_t k = span.begin + 2; k < span.end; ++k) {
    if ((points[k - 1].p - points[span.begin].p).norm() > max_extent_m) break;
    const double step = points[k].range - points[k - 1].range;
    if (step >= best) {
      best = step;
      out.front_end = k;
    }
  }
  // Back piece [k, end), the mirror image.
  best = min_step_m;
  for (std::size_t k = span.end - 2; k > span.begin; --k) {
    if ((points[span.end - 1].p - points[k].p).norm() > max_extent_m) break;
    const double step = points[k - 1].range - points[k].range;
    if (step >= best) {
      best = step;
      out.back_begin = k;
    }
  }
  return out;
}

}  // namespace shelfdock::perception
