#pragma once

#include <cstdint>
#include <optional>
#include <random>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::sim {

/// Wheel odometry errors. Scale errors are drawn once per run (a worn or mis-calibrated wheel
/// keeps its error), slip is a random walk in travelled distance, so the pose drifts the way
/// dead reckoning does: heading error grows with the wheel difference, lateral error with the
/// integral of the heading error. With the defaults, 4.5 m straight ahead (the paper's docking
/// run) ends with a heading error of std 0.014 rad and a lateral error of std 3.3 cm (formulas
/// in tests/sim/odometry_test.cpp): the shelf must be re-detected on the way, as in the paper.
struct OdometryNoiseConfig {
  double wheel_scale_std = 0.001;        ///< [-] per-wheel radius error, fixed per run
  double wheel_base_scale_std = 0.005;   ///< [-] effective track-width error, fixed per run
  double slip_std_m_per_sqrt_m = 0.001;  ///< [m/sqrt(m)] per-wheel slip random walk
};

/// The first impossible value of the odometry errors (keys as under `odometry` in
/// config/robot.yaml): scale errors are fractions below 10 %, no spread is negative.
std::optional<geometry::ConfigViolation> FindConfigViolation(const OdometryNoiseConfig& config);

/// Dead reckoning from simulated wheel encoders. Fed with the TRUE wheel travel of each step;
/// integrates what the encoders would report. Starts at the identity of the `odom` frame.
class WheelOdometry {
 public:
  WheelOdometry(const OdometryNoiseConfig& config, double wheel_base_m, uint64_t seed);

  /// One control step: the true distance (centre of the axle) and heading change.
  void Update(double true_distance_m, double true_dyaw_rad);

  geometry::Pose2 T_odom_base() const { return T_odom_base_; }
  double left_scale_error() const { return left_scale_error_; }
  double right_scale_error() const { return right_scale_error_; }

 private:
  OdometryNoiseConfig config_;
  double wheel_base_m_;
  std::mt19937_64 rng_;
  double left_scale_error_ = 0.0;
  double right_scale_error_ = 0.0;
  double wheel_base_estimate_m_;  ///< the track width the odometry believes
  geometry::Pose2 T_odom_base_;
};

}  // namespace shelfdock::sim
