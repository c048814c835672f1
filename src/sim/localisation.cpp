#include "sim/localisation.hpp"

#include <cmath>

#include "geometry/angle.hpp"

namespace shelfdock::sim {

LocalisationError::LocalisationError(const LocalisationNoiseConfig& config, uint64_t seed)
    : config_(config), rng_(seed) {
  // Start from the stationary distribution so the first estimate is as wrong as any later one.
  std::normal_distribution<double> unit(0.0, 1.0);
  bias_ = geometry::Pose2(config_.bias_std_m * unit(rng_), config_.bias_std_m * unit(rng_),
                          config_.bias_std_rad * unit(rng_));
  Refresh();
}

void LocalisationError::Advance(double dt_s) {
  since_refresh_s_ += dt_s;
  const double period_s = 1.0 / config_.update_rate_hz;
  while (since_refresh_s_ >= period_s) {
    since_refresh_s_ -= period_s;
    // Exact discretisation of the Ornstein-Uhlenbeck process over one update period:
    // b' = a b + s sqrt(1 - a^2) n, a = exp(-dt / tau), keeps the stationary std s.
    const double a = std::exp(-period_s / config_.bias_time_constant_s);
    const double k = std::sqrt(1.0 - a * a);
    std::normal_distribution<double> unit(0.0, 1.0);
    bias_.x = a * bias_.x + k * config_.bias_std_m * unit(rng_);
    bias_.y = a * bias_.y + k * config_.bias_std_m * unit(rng_);
    bias_.yaw = a * bias_.yaw + k * config_.bias_std_rad * unit(rng_);
    Refresh();
  }
}

void LocalisationError::Refresh() {
  std::normal_distribution<double> unit(0.0, 1.0);
  noise_ = geometry::Pose2(config_.noise_std_m * unit(rng_), config_.noise_std_m * unit(rng_),
                           config_.noise_std_rad * unit(rng_));
}

geometry::Pose2 LocalisationError::Apply(const geometry::Pose2& T_map_base_true) const {
  return geometry::Pose2(T_map_base_true.x + bias_.x + noise_.x,
                         T_map_base_true.y + bias_.y + noise_.y,
                         geometry::WrapAngle(T_map_base_true.yaw + bias_.yaw + noise_.yaw));
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const LocalisationNoiseConfig& c) {
  geometry::ConfigChecker k;
  k.Check(c.noise_std_m >= 0.0, "noise_std_m", ">= 0 metres");
  k.Check(c.noise_std_rad >= 0.0, "noise_std_rad", ">= 0 radians");
  k.Check(c.bias_std_m >= 0.0, "bias_std_m", ">= 0 metres");
  k.Check(c.bias_std_rad >= 0.0, "bias_std_rad", ">= 0 radians");
  // Both divide: the bias's decay per step and the refresh period.
  k.Check(c.bias_time_constant_s > 0.0, "bias_time_constant_s", "> 0 seconds");
  k.Check(c.update_rate_hz > 0.0, "update_rate_hz", "> 0 Hz");
  return k.Result();
}

}  // namespace shelfdock::sim
