#include "perception/mixed_returns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shelfdock::perception {

MixedEdges FindMixedEdges(const std::vector<ScanPoint>& points, const SilhouetteEdges& edges,
                          double min_step_m) {
  MixedEdges out;
  const std::size_t n = points.size();
  if (n < 2) return out;
  if (edges.before_step_m && *edges.before_step_m > 0.0 &&
      points[0].range > points[1].range + min_step_m) {
    out.first_gap_m = *edges.before_step_m;
  }
  if (edges.after_step_m && *edges.after_step_m > 0.0 &&
      points[n - 1].range > points[n - 2].range + min_step_m) {
    out.last_gap_m = *edges.after_step_m;
  }
  return out;
}

double MixedReturnSqrtWeight(double range_residual_m, double sigma_m, double gap_m, double share) {
  if (gap_m <= 0.0 || share <= 0.0 || sigma_m <= 0.0) return 1.0;
  if (share >= 1.0) return 0.0;
  // A plain return: Gaussian about the leg's surface. A blend: uniform between the leg's surface
  // and the surface behind it, G away (the outer return's gap plus its own residual), blurred by
  // the same noise, so the weight falls smoothly from in front of the leg to behind it.
  const double r = range_residual_m;
  const double g = std::max(gap_m + r, sigma_m);
  const double z = r / sigma_m;
  const auto cdf = [](double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); };
  const double plain =
      (1.0 - share) * std::exp(-0.5 * z * z) / (sigma_m * std::sqrt(2.0 * std::numbers::pi));
  const double blend = share * (cdf(z) - cdf((r - g) / sigma_m)) / g;
  // Far out both densities underflow: in front of the leg a blend cannot be, behind it a plain
  // return cannot.
  if (!(plain + blend > 0.0)) return r < 0.0 ? 1.0 : 0.0;
  return std::sqrt(plain / (plain + blend));
}

}  // namespace shelfdock::perception
