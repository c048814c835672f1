#include "docking/obstacle_returns.hpp"

#include <cmath>

namespace shelfdock::docking {

ScanReturns PlaceReturns(const geometry::LaserScan& scan, const geometry::Pose2& T_frame_lidar) {
  const std::size_t n = scan.ranges.size();
  ScanReturns out;
  out.points.assign(n, Eigen::Vector2d::Zero());
  out.valid.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!scan.HasReturn(i)) continue;
    const double r = scan.ranges[i];
    const double a = scan.BeamAngle(i);
    out.points[i] = T_frame_lidar * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    out.valid[i] = 1;
  }
  return out;
}

std::vector<char> ObstacleReturns(const ScanReturns& now, const ScanReturns& previous,
                                  double max_gap_m) {
  // Without a scan before (the first one) nothing tells a stray from a thin thing: all count.
  if (max_gap_m <= 0.0 || previous.points.empty()) return now.valid;
  const std::size_t n = now.points.size();
  const double gap2 = max_gap_m * max_gap_m;
  auto near = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - b).squaredNorm() <= gap2;
  };
  std::vector<char> out(n, 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (now.valid[i] && now.valid[i + 1] && near(now.points[i], now.points[i + 1])) {
      out[i] = out[i + 1] = 1;
    }
  }
  // A lone return: does the previous scan show something there? Lone returns are few (strays,
  // thin legs far off), so a plain search over the previous scan is cheap.
  for (std::size_t i = 0; i < n; ++i) {
    if (!now.valid[i] || out[i]) continue;
    for (std::size_t j = 0; j < previous.points.size(); ++j) {
      if (previous.valid[j] && near(now.points[i], previous.points[j])) {
        out[i] = 1;
        break;
      }
    }
  }
  return out;
}

}  // namespace shelfdock::docking
