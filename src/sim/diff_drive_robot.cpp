#include "sim/diff_drive_robot.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::sim {
namespace {

/// SplitMix64: independent sub-seeds so that odometry and localisation draw from their own
/// streams (changing one noise model does not reshuffle the other).
uint64_t SubSeed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double ClampAbs(double value, double limit) { return std::clamp(value, -limit, limit); }

}  // namespace

geometry::Pose2 IntegrateArc(const geometry::Pose2& start, double v_mps, double w_radps,
                             double dt_s) {
  const double dyaw = w_radps * dt_s;
  const double ds = v_mps * dt_s;
  // Chord of the arc: length 2 (v / w) sin(dyaw / 2), direction yaw + dyaw / 2.
  const double chord = std::abs(dyaw) > 1e-12 ? 2.0 * ds * std::sin(0.5 * dyaw) / dyaw : ds;
  const double heading = start.yaw + 0.5 * dyaw;
  return geometry::Pose2(start.x + chord * std::cos(heading), start.y + chord * std::sin(heading),
                         geometry::WrapAngle(start.yaw + dyaw));
}

DiffDriveRobot::DiffDriveRobot(const DiffDriveConfig& config,
                               const geometry::Pose2& T_world_base_start, uint64_t seed)
    : config_(config),
      T_world_base_(T_world_base_start),
      odometry_(config.odometry, config.wheel_base_m, SubSeed(seed, 0)),
      localisation_(config.localisation, SubSeed(seed, 1)),
      lift_(config.lift_duration_s) {
  assert(config_.max_v_mps > 0.0 && config_.max_w_radps > 0.0);
  assert(config_.max_accel_mps2 > 0.0 && config_.max_alpha_radps2 > 0.0);
  assert(config_.wheel_base_m > 0.0);
}

void DiffDriveRobot::Step(double v_cmd_mps, double w_cmd_radps, double dt_s) {
  if (!(dt_s > 0.0)) return;
  // Velocity limits first, then the acceleration limits on the change from the current speed.
  const double v_target = ClampAbs(v_cmd_mps, config_.max_v_mps);
  const double w_target = ClampAbs(w_cmd_radps, config_.max_w_radps);
  v_mps_ += ClampAbs(v_target - v_mps_, config_.max_accel_mps2 * dt_s);
  w_radps_ += ClampAbs(w_target - w_radps_, config_.max_alpha_radps2 * dt_s);

  history_.push_back({time_s_, T_world_base_, v_mps_, w_radps_});
  while (history_.size() > 2 && history_[1].t_s < time_s_ + dt_s - config_.history_s) {
    history_.pop_front();
  }

  T_world_base_ = IntegrateArc(T_world_base_, v_mps_, w_radps_, dt_s);
  odometry_.Update(v_mps_ * dt_s, w_radps_ * dt_s);
  localisation_.Advance(dt_s);
  time_s_ += dt_s;
  distance_m_ += std::abs(v_mps_) * dt_s;
}

geometry::Pose2 DiffDriveRobot::T_world_base_at(double t_s) const {
  if (t_s >= time_s_ || history_.empty()) {
    return IntegrateArc(T_world_base_, v_mps_, w_radps_, std::max(0.0, t_s - time_s_));
  }
  if (t_s <= history_.front().t_s) return history_.front().T_world_base;
  // The last sample that started at or before t: its velocity was held until the next one.
  const auto after = std::upper_bound(history_.begin(), history_.end(), t_s,
                                      [](double t, const Sample& s) { return t < s.t_s; });
  const Sample& s = *std::prev(after);
  return IntegrateArc(s.T_world_base, s.v_mps, s.w_radps, t_s - s.t_s);
}

std::array<Eigen::Vector2d, 4> DiffDriveRobot::FootprintCorners() const {
  const double hl = 0.5 * config_.footprint_length_m;
  const double hw = 0.5 * config_.footprint_width_m;
  return {T_world_base_ * Eigen::Vector2d(hl, hw), T_world_base_ * Eigen::Vector2d(-hl, hw),
          T_world_base_ * Eigen::Vector2d(-hl, -hw), T_world_base_ * Eigen::Vector2d(hl, -hw)};
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const DiffDriveConfig& c) {
  geometry::ConfigChecker k;
  k.Nested("odometry", FindConfigViolation(c.odometry));
  k.Nested("localisation", FindConfigViolation(c.localisation));
  k.Check(c.max_v_mps > 0.0, "max_v_mps", "> 0 m/s");
  k.Check(c.max_w_radps > 0.0, "max_w_radps", "> 0 rad/s");
  k.Check(c.max_accel_mps2 > 0.0, "max_accel_mps2", "> 0 m/s^2");
  k.Check(c.max_alpha_radps2 > 0.0, "max_alpha_radps2", "> 0 rad/s^2");
  k.Check(c.wheel_base_m > 0.0, "wheel_base_m", "> 0 metres");
  k.Check(c.footprint_length_m > 0.0, "footprint_length_m", "> 0 metres");
  k.Check(c.footprint_width_m > 0.0, "footprint_width_m", "> 0 metres");
  k.Check(c.control_rate_hz > 0.0, "control_rate_hz", "> 0 Hz");
  k.Check(c.lift_duration_s >= 0.0, "lift_duration_s", ">= 0 seconds");  // 0: instant
  k.Check(c.history_s > 0.0, "history_s", "> 0 seconds");
  return k.Result();
}

}  // namespace shelfdock::sim
