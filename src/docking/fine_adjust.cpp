#include "docking/fine_adjust.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {
constexpr double kPositionDoneM = 0.0002;  // a fifth of a millimetre
constexpr double kYawDoneRad = 0.0004;
constexpr double kGainPerS = 2.0;  // proportional gain of both moves [1/s]
}  // namespace

void FineAdjust::Start(const geometry::Pose2& T_odom_base, const geometry::Pose2& T_odom_goal) {
  moves_.clear();
  const geometry::Pose2 T_base_goal = T_odom_base.inverse() * T_odom_goal;
  geometry::Pose2 from = T_odom_base;
  // A lateral offset needs room to approach at an angle: back off first.
  if (std::abs(T_base_goal.y) > kPositionDoneM * 5) {
    from = T_odom_base * geometry::Pose2(-config_.backoff_m, 0.0, 0.0);
    moves_.push_back({Kind::kStraightTo, from, true});
  }
  const Eigen::Vector2d d = T_odom_goal.translation() - from.translation();
  if (d.norm() > kPositionDoneM) {
    double heading = std::atan2(d.y(), d.x());
    bool reverse = false;
    // Drive backwards when the goal lies behind: keep turns small.
    if (std::abs(geometry::AngleDiff(heading, from.yaw)) > 0.5 * 3.14159265358979) {
      heading = geometry::WrapAngle(heading + 3.14159265358979);
      reverse = true;
    }
    moves_.push_back({Kind::kRotateTo, geometry::Pose2(from.x, from.y, heading), false});
    moves_.push_back({Kind::kStraightTo, T_odom_goal, reverse});
  }
  moves_.push_back({Kind::kRotateTo, T_odom_goal, false});
}

VelocityCommand FineAdjust::Update(const geometry::Pose2& T_odom_base, bool* done) {
  while (!moves_.empty()) {
    const Move& m = moves_.front();
    if (m.kind == Kind::kRotateTo) {
      const double e = geometry::AngleDiff(m.target.yaw, T_odom_base.yaw);
      if (std::abs(e) < kYawDoneRad) {
        moves_.pop_front();
        continue;
      }
      const double w =
          std::clamp(kGainPerS * e, -config_.adjust_yaw_rate_radps, config_.adjust_yaw_rate_radps);
      *done = false;
      return {0.0, std::copysign(std::max(std::abs(w), 0.01), w)};
    }
    // Straight: signed distance to the target along the current heading.
    const Eigen::Vector2d heading(std::cos(T_odom_base.yaw), std::sin(T_odom_base.yaw));
    const double e = heading.dot(m.target.translation() - T_odom_base.translation());
    if (std::abs(e) < kPositionDoneM || (m.reverse ? e > 0.0 : e < 0.0)) {
      moves_.pop_front();
      continue;
    }
    const double v = std::clamp(kGainPerS * e, -config_.adjust_speed_mps, config_.adjust_speed_mps);
    *done = false;
    return {std::copysign(std::max(std::abs(v), 0.003), v), 0.0};
  }
  *done = true;
  return {};
}

}  // namespace shelfdock::docking
