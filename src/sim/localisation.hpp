#pragma once

#include <cstdint>
#include <optional>
#include <random>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::sim {

/// A map-frame localisation estimate as laser SLAM would give: white noise on each update plus
/// a bias that wanders slowly (an Ornstein-Uhlenbeck process with stationary standard deviation
/// bias_std and correlation time bias_time_constant_s), so that consecutive estimates agree
/// with each other better than with the truth.
struct LocalisationNoiseConfig {
  double noise_std_m = 0.010;          ///< [m] white noise per update, x and y
  double noise_std_rad = 0.005;        ///< [rad] white noise per update, yaw
  double bias_std_m = 0.03;            ///< [m] stationary std of the wandering bias, x and y
  double bias_std_rad = 0.01;          ///< [rad] stationary std of the wandering yaw bias
  double bias_time_constant_s = 20.0;  ///< [s] correlation time of the bias
  double update_rate_hz = 10.0;        ///< [Hz] how often noise and bias are refreshed
};

/// The first impossible value of the localisation errors (keys as under `localisation` in
/// config/robot.yaml): no spread is negative, the bias's time constant and the rate are positive.
std::optional<geometry::ConfigViolation> FindConfigViolation(const LocalisationNoiseConfig& config);

/// The error of the localisation estimate, advanced in time; applied to the true pose.
class LocalisationError {
 public:
  LocalisationError(const LocalisationNoiseConfig& config, uint64_t seed);

  void Advance(double dt_s);

  /// The estimate for a true pose: the map-frame error added to x, y and yaw.
  geometry::Pose2 Apply(const geometry::Pose2& T_map_base_true) const;

  /// Current bias (without the white noise): x, y [m] in the map frame and yaw [rad].
  geometry::Pose2 bias() const { return bias_; }

 private:
  void Refresh();

  LocalisationNoiseConfig config_;
  std::mt19937_64 rng_;
  geometry::Pose2 bias_;
  geometry::Pose2 noise_;
  double since_refresh_s_ = 0.0;
};

}  // namespace shelfdock::sim
