#include "docking/collision_check.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::docking {

double FootprintDistance(const Eigen::Vector2d& p_base, const SafetyConfig& safety) {
  // Box signed distance: outside, the norm of the positive excess; inside, the largest excess.
  const Eigen::Vector2d half(0.5 * safety.robot_length_m, 0.5 * safety.robot_width_m);
  const Eigen::Vector2d q(std::abs(p_base.x() - safety.robot_offset_x_m), std::abs(p_base.y()));
  const Eigen::Vector2d d = q - half;
  const double outside = d.cwiseMax(0.0).norm();
  const double inside = std::min(std::max(d.x(), d.y()), 0.0);
  return outside + inside;
}

std::vector<LegDisc> LegDiscs(const geometry::ShelfModel& model,
                              const geometry::Pose2& T_frame_shelf) {
  std::vector<LegDisc> legs;
  const double r = 0.5 * model.leg.Extent();
  for (const Eigen::Vector2d& c : model.LegCentres()) legs.push_back({T_frame_shelf * c, r});
  return legs;
}

ClearanceResult CheckPathAgainstLegs(const Path& path, const std::vector<LegDisc>& legs,
                                     const SafetyConfig& safety, double stride_m) {
  ClearanceResult result;
  if (path.empty() || legs.empty()) return result;
  double next_s = 0.0;
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    const bool last = i + 1 == path.points.size();
    if (path.points[i].s < next_s && !last) continue;
    next_s = path.points[i].s + stride_m;
    const geometry::Pose2 T_base_frame = path.points[i].pose.inverse();
    for (const LegDisc& leg : legs) {
      const double d = FootprintDistance(T_base_frame * leg.centre, safety) - leg.radius_m;
      if (d < result.min_clearance_m) {
        result.min_clearance_m = d;
        result.worst_index = i;
      }
    }
  }
  result.ok = result.min_clearance_m >= safety.leg_margin_m;
  return result;
}

double FirstBlockedArcLength(const Path& path, double s_from,
                             const std::vector<Eigen::Vector2d>& points,
                             const std::vector<LegDisc>& legs, const SafetyConfig& safety) {
  if (path.empty() || points.empty()) return -1.0;
  std::vector<Eigen::Vector2d> unknown;
  unknown.reserve(points.size());
  for (const Eigen::Vector2d& p : points) {
    const bool is_leg = std::any_of(legs.begin(), legs.end(), [&](const LegDisc& leg) {
      return (p - leg.centre).norm() < leg.radius_m + safety.leg_exclusion_m;
    });
    if (!is_leg) unknown.push_back(p);
  }
  const double reach = 0.5 * std::hypot(safety.robot_length_m, safety.robot_width_m) +
                       std::abs(safety.robot_offset_x_m) + safety.obstacle_margin_m;
  constexpr double kStride = 0.05;
  double next_s = s_from;
  for (const PathPoint& pp : path.points) {
    if (pp.s < next_s) continue;
    if (pp.s > s_from + safety.obstacle_lookahead_m) break;
    next_s = pp.s + kStride;
    const geometry::Pose2 T_base_frame = pp.pose.inverse();
    for (const Eigen::Vector2d& p : unknown) {
      if ((p - pp.pose.translation()).norm() > reach) continue;
      if (FootprintDistance(T_base_frame * p, safety) < safety.obstacle_margin_m) return pp.s;
    }
  }
  return -1.0;
}

}  // namespace shelfdock::docking
