#include "sim/odometry.hpp"

#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::sim {

WheelOdometry::WheelOdometry(const OdometryNoiseConfig& config, double wheel_base_m, uint64_t seed)
    : config_(config), wheel_base_m_(wheel_base_m), rng_(seed) {
  std::normal_distribution<double> unit(0.0, 1.0);
  left_scale_error_ = config_.wheel_scale_std * unit(rng_);
  right_scale_error_ = config_.wheel_scale_std * unit(rng_);
  wheel_base_estimate_m_ = wheel_base_m_ * (1.0 + config_.wheel_base_scale_std * unit(rng_));
}

void WheelOdometry::Update(double true_distance_m, double true_dyaw_rad) {
  // True travel of each wheel for the step's arc.
  const double half_base = 0.5 * wheel_base_m_;
  const double true_left_m = true_distance_m - true_dyaw_rad * half_base;
  const double true_right_m = true_distance_m + true_dyaw_rad * half_base;

  // Encoders: a fixed scale error per wheel, plus slip whose variance grows with the wheel's
  // travel (a random walk in distance: std = slip_std * sqrt(travel)).
  std::normal_distribution<double> unit(0.0, 1.0);
  const double slip = config_.slip_std_m_per_sqrt_m;
  const double left_m = true_left_m * (1.0 + left_scale_error_) +
                        slip * std::sqrt(std::abs(true_left_m)) * unit(rng_);
  const double right_m = true_right_m * (1.0 + right_scale_error_) +
                         slip * std::sqrt(std::abs(true_right_m)) * unit(rng_);

  // Dead reckoning with the track width the robot believes, along the measured arc
  // (midpoint heading: exact for an arc's chord direction).
  const double ds = 0.5 * (left_m + right_m);
  const double dyaw = (right_m - left_m) / wheel_base_estimate_m_;
  const double chord = std::abs(dyaw) > 1e-9 ? 2.0 * ds * std::sin(0.5 * dyaw) / dyaw : ds;
  const double heading = T_odom_base_.yaw + 0.5 * dyaw;
  T_odom_base_ = geometry::Pose2(T_odom_base_.x + chord * std::cos(heading),
                                 T_odom_base_.y + chord * std::sin(heading),
                                 geometry::WrapAngle(T_odom_base_.yaw + dyaw));
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const OdometryNoiseConfig& c) {
  geometry::ConfigChecker k;
  k.Check(c.wheel_scale_std >= 0.0 && c.wheel_scale_std < 0.1, "wheel_scale_std",
          "in [0, 0.1) (a fraction, 0.001 = 0.1 %)");
  k.Check(c.wheel_base_scale_std >= 0.0 && c.wheel_base_scale_std < 0.1, "wheel_base_scale_std",
          "in [0, 0.1) (a fraction)");
  k.Check(c.slip_std_m_per_sqrt_m >= 0.0, "slip_std_m_per_sqrt_m", ">= 0 (m per sqrt(m))");
  return k.Result();
}

}  // namespace shelfdock::sim
