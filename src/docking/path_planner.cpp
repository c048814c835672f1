#include "docking/path_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using Eigen::Vector2d;
using geometry::Pose2;

/// Samples the cubic Bezier B(t) = sum C(3,i) (1-t)^(3-i) t^i P_i. Curvature from
/// k = (x' y'' - y' x'') / |B'|^3.
std::vector<PathPoint> SampleBezier(const std::array<Vector2d, 4>& P, double step_m) {
  const double chord = (P[3] - P[0]).norm() + (P[1] - P[0]).norm() + (P[2] - P[3]).norm();
  const int n = std::max(16, static_cast<int>(std::ceil(chord / step_m)));
  std::vector<PathPoint> out;
  out.reserve(n + 1);
  double s = 0.0;
  Vector2d prev = P[0];
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    const double u = 1.0 - t;
    const Vector2d b =
        u * u * u * P[0] + 3 * u * u * t * P[1] + 3 * u * t * t * P[2] + t * t * t * P[3];
    const Vector2d d1 =
        3 * u * u * (P[1] - P[0]) + 6 * u * t * (P[2] - P[1]) + 3 * t * t * (P[3] - P[2]);
    const Vector2d d2 = 6 * u * (P[2] - 2 * P[1] + P[0]) + 6 * t * (P[3] - 2 * P[2] + P[1]);
    const double speed = d1.norm();
    s += (b - prev).norm();
    prev = b;
    PathPoint pp;
    pp.pose = Pose2(b.x(), b.y(), std::atan2(d1.y(), d1.x()));
    pp.s = s;
    pp.curvature =
        speed > 1e-9 ? (d1.x() * d2.y() - d1.y() * d2.x()) / (speed * speed * speed) : 0.0;
    out.push_back(pp);
  }
  return out;
}

/// Path in the goal frame from `start` (goal frame) through (-straight, 0, 0) to the origin.
Path BuildPath(const Pose2& start, double straight_m, double handle_factor, double step_m) {
  Path path;
  const Vector2d p0 = start.translation();
  const Vector2d p3(-straight_m, 0.0);
  const double chord = (p3 - p0).norm();
  if (chord > 1e-3) {
    const double h = handle_factor * chord;
    const std::array<Vector2d, 4> P{p0, p0 + h * Vector2d(std::cos(start.yaw), std::sin(start.yaw)),
                                    p3 - h * Vector2d(1.0, 0.0), p3};
    path.points = SampleBezier(P, step_m);
  } else {
    path.points.push_back({Pose2(p3.x(), 0.0, 0.0), 0.0, 0.0});
  }
  const double s0 = path.points.back().s;
  const int n = static_cast<int>(std::ceil(straight_m / step_m));
  for (int i = 1; i <= n; ++i) {
    const double x = -straight_m + straight_m * i / n;
    path.points.push_back({Pose2(x, 0.0, 0.0), s0 + straight_m * i / n, 0.0});
  }
  return path;
}

}  // namespace

PlanResult PlanDockingPath(const Pose2& T_start, const Pose2& T_goal, const PlannerConfig& config) {
  PlanResult result;
  const Pose2 start_goal = T_goal.inverse() * T_start;  // start in the goal's frame
  const double available_m = -start_goal.x;
  if (available_m < config.min_final_straight_m) {
    result.reason = "the start is not far enough behind the goal to drive forward onto it";
    return result;
  }
  if (std::abs(geometry::WrapAngle(start_goal.yaw)) > 0.5 * 3.14159265358979) {
    result.reason = "the start faces away from the goal";
    return result;
  }
  constexpr int kStraightCandidates = 10;
  constexpr std::array<double, 5> kHandles{0.25, 0.33, 0.42, 0.5, 0.6};
  const double longest = std::min(config.final_straight_m, available_m);
  for (int k = 0; k < kStraightCandidates; ++k) {
    const double straight =
        longest - (longest - config.min_final_straight_m) * k / (kStraightCandidates - 1);
    Path best;
    double best_k = 1e300;
    for (double handle : kHandles) {
      Path candidate = BuildPath(start_goal, straight, handle, config.sample_step_m);
      const double peak = candidate.MaxAbsCurvature();
      if (peak < best_k) {
        best_k = peak;
        best = std::move(candidate);
      }
    }
    if (best_k <= config.max_curvature_1pm) {
      for (PathPoint& p : best.points) p.pose = T_goal * p.pose;
      result.ok = true;
      result.path = std::move(best);
      result.straight_m = straight;
      return result;
    }
  }
  result.reason =
      "no path within the curvature bound of " + std::to_string(config.max_curvature_1pm) + " 1/m";
  return result;
}

}  // namespace shelfdock::docking
