#include "docking/free_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shelfdock::docking {

double TurnRadius(const SafetyConfig& safety) {
  return std::hypot(0.5 * safety.robot_length_m + std::abs(safety.robot_offset_x_m),
                    0.5 * safety.robot_width_m);
}

double FreeSpace::Clearance(const geometry::Pose2& T_frame_base, const SafetyConfig& safety) const {
  double best = std::numeric_limits<double>::infinity();
  const geometry::Pose2 T_base_frame = T_frame_base.inverse();
  const double reach = TurnRadius(safety);
  for (const LegDisc& o : obstacles) {
    const Eigen::Vector2d p = T_base_frame * o.centre;
    // Far obstacles cannot be the nearest once one closer than this bound is known.
    if (p.norm() - reach - o.radius_m > best) continue;
    best = std::min(best, FootprintDistance(p, safety) - o.radius_m);
  }
  return best;
}

double FreeSpace::PathClearance(const Path& path, const SafetyConfig& safety, double stride_m,
                                double s_from_m) const {
  double best = std::numeric_limits<double>::infinity();
  double next_s = s_from_m;
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    const bool last = i + 1 == path.points.size();
    if (path.points[i].s < next_s && !last) continue;
    next_s = path.points[i].s + stride_m;
    best = std::min(best, Clearance(path.points[i].pose, safety));
  }
  return best;
}

double FreeSpace::TurnClearance(const geometry::Pose2& T_frame_base,
                                const SafetyConfig& safety) const {
  double best = std::numeric_limits<double>::infinity();
  const double r = TurnRadius(safety);
  for (const LegDisc& o : obstacles) {
    best = std::min(best, (o.centre - T_frame_base.translation()).norm() - r - o.radius_m);
  }
  return best;
}

Path StraightPath(const geometry::Pose2& from, const geometry::Pose2& to, double step_m) {
  Path path;
  const Eigen::Vector2d d = to.translation() - from.translation();
  const double length = d.norm();
  const double yaw = length > 1e-9 ? std::atan2(d.y(), d.x()) : from.yaw;
  const int n = std::max(1, static_cast<int>(std::ceil(length / step_m)));
  for (int i = 0; i <= n; ++i) {
    const double f = static_cast<double>(i) / n;
    const Eigen::Vector2d p = from.translation() + f * d;
    path.points.push_back({geometry::Pose2(p.x(), p.y(), yaw), f * length, 0.0});
  }
  return path;
}

}  // namespace shelfdock::docking
