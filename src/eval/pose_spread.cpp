#include "eval/pose_spread.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::eval {
namespace {

Spread SpreadOfValues(const std::vector<double>& v) {
  Spread s;
  if (v.size() < 2) return s;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  s.range = *hi - *lo;
  double mean = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  s.stddev = std::sqrt(ss / static_cast<double>(v.size() - 1));
  return s;
}

}  // namespace

PoseSpread SpreadOf(const std::vector<geometry::Pose2>& poses, double yaw_symmetry_rad) {
  PoseSpread out;
  out.samples = static_cast<int>(poses.size());
  if (poses.size() < 2) return out;
  std::vector<double> x, y, yaw;
  for (const geometry::Pose2& p : poses) {
    x.push_back(p.x);
    y.push_back(p.y);
    // Offset from the first heading, folded into [-symmetry/2, symmetry/2).
    const double d = geometry::AngleDiff(p.yaw, poses.front().yaw);
    yaw.push_back(d - yaw_symmetry_rad * std::round(d / yaw_symmetry_rad));
  }
  out.x = SpreadOfValues(x);
  out.y = SpreadOfValues(y);
  out.yaw = SpreadOfValues(yaw);
  return out;
}

}  // namespace shelfdock::eval
