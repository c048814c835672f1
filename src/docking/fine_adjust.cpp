#include "docking/fine_adjust.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {
constexpr double kPositionDoneM = 0.0002;  // a fifth of a millimetre
constexpr double kYawDoneRad = 0.0003;
constexpr double kTailFraction = 0.6;  // share of the remaining error covered per step

/// Speed that stops exactly after |e| at deceleration a, min(v_max, sqrt(2 a |e|)), with a
/// dead-beat tail: never more than a fixed share of the error per control step (no overshoot).
double StoppingSpeed(double e, double v_max, double a, double dt_s) {
  return std::min({v_max, std::sqrt(2.0 * a * std::abs(e)), kTailFraction * std::abs(e) / dt_s});
}
}  // namespace

void FineAdjust::AddStraight(const geometry::Pose2& from, const geometry::Pose2& to) {
  const Eigen::Vector2d heading(std::cos(from.yaw), std::sin(from.yaw));
  const double along = heading.dot(to.translation() - from.translation());
  if (std::abs(along) < kPositionDoneM) return;
  moves_.push_back({Kind::kStraightTo, to, along > 0.0 ? 1.0 : -1.0});
}

void FineAdjust::Start(const geometry::Pose2& T_odom_base, const geometry::Pose2& T_odom_goal) {
  moves_.clear();
  const geometry::Pose2 T_base_goal = T_odom_base.inverse() * T_odom_goal;
  const double dx = T_base_goal.x;
  const double dy = T_base_goal.y;
  if (std::abs(dy) <= config_.lateral_tolerance_m) {
    AddStraight(T_odom_base, T_odom_base * geometry::Pose2(dx, 0.0, 0.0));
  } else {
    // Lever: the straight move onto the goal point must come from at least this far along the
    // heading, so that the turn toward the point stays below max_lever_angle_rad.
    const double reach = std::abs(dy) / std::tan(config_.max_lever_angle_rad);
    const double lever_back = std::max(0.0, reach - dx);  // then drive forward onto the point
    const double lever_fwd = std::max(0.0, reach + dx);   // then reverse onto the point
    const double path_back = 2.0 * lever_back + dx;
    const double path_fwd = 2.0 * lever_fwd - dx;
    const double lever = path_back <= path_fwd ? -lever_back : lever_fwd;
    const geometry::Pose2 from = T_odom_base * geometry::Pose2(lever, 0.0, 0.0);
    AddStraight(T_odom_base, from);
    const Eigen::Vector2d d = T_odom_goal.translation() - from.translation();
    double heading = std::atan2(d.y(), d.x());
    if (std::abs(geometry::AngleDiff(heading, from.yaw)) > 0.5 * 3.14159265358979) {
      heading = geometry::WrapAngle(heading + 3.14159265358979);  // drive backwards onto it
    }
    const geometry::Pose2 turned(from.x, from.y, heading);
    moves_.push_back({Kind::kRotateTo, turned, 0.0});
    AddStraight(turned, T_odom_goal);
  }
  moves_.push_back({Kind::kRotateTo, T_odom_goal, 0.0});
}

void FineAdjust::StartTurn(double yaw_rad) {
  moves_.clear();
  moves_.push_back({Kind::kRotateTo, geometry::Pose2(0.0, 0.0, yaw_rad), 0.0});
}

void FineAdjust::StartStraight(const geometry::Pose2& T_odom_base,
                               const geometry::Pose2& T_odom_to) {
  moves_.clear();
  AddStraight(T_odom_base, T_odom_to);
}

VelocityCommand FineAdjust::Update(const geometry::Pose2& T_odom_base, double dt_s, bool* done) {
  while (!moves_.empty()) {
    const Move& m = moves_.front();
    if (m.kind == Kind::kRotateTo) {
      const double e = geometry::AngleDiff(m.target.yaw, T_odom_base.yaw);
      if (std::abs(e) < kYawDoneRad) {
        moves_.pop_front();
        continue;
      }
      *done = false;
      return {0.0, std::copysign(StoppingSpeed(e, config_.adjust_yaw_rate_radps,
                                               config_.adjust_yaw_accel_radps2, dt_s),
                                 e)};
    }
    // Straight: signed distance to the target along the current heading; a sign flip against
    // the planned direction means the target was passed (by less than one step).
    const Eigen::Vector2d heading(std::cos(T_odom_base.yaw), std::sin(T_odom_base.yaw));
    const double e = heading.dot(m.target.translation() - T_odom_base.translation());
    if (std::abs(e) < kPositionDoneM || e * m.sign < 0.0) {
      moves_.pop_front();
      continue;
    }
    *done = false;
    return {std::copysign(
                StoppingSpeed(e, config_.adjust_speed_mps, config_.adjust_accel_mps2, dt_s), e),
            0.0};
  }
  *done = true;
  return {};
}

}  // namespace shelfdock::docking
