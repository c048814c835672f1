#include "docking/obstacle_returns.hpp"

#include <cmath>

#include <Eigen/Core>

namespace shelfdock::docking {

std::vector<char> ObstacleReturns(const geometry::LaserScan& scan, double max_gap_m) {
  const std::size_t n = scan.ranges.size();
  std::vector<char> out(n, 0);
  std::vector<Eigen::Vector2d> p(n, Eigen::Vector2d::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || r < scan.range_min || r > scan.range_max) continue;
    const double a = scan.BeamAngle(i);
    p[i] = {r * std::cos(a), r * std::sin(a)};
    out[i] = 1;
  }
  if (max_gap_m <= 0.0) return out;
  const double gap2 = max_gap_m * max_gap_m;
  std::vector<char> confirmed(n, 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (out[i] && out[i + 1] && (p[i] - p[i + 1]).squaredNorm() <= gap2) {
      confirmed[i] = confirmed[i + 1] = 1;
    }
  }
  return confirmed;
}

}  // namespace shelfdock::docking
