#pragma once

#include "sim/lidar_config.hpp"

namespace shelfdock::eval {

/// The harsh sensor, as changes to a nominal LiDAR: more range noise, more mixed
/// (trailing) points at depth edges, more dropouts and a mounting tilt.
struct HarshLidarConfig {
  double range_noise_sigma_m = 0.020;  ///< [m] (nominal WLR-716: 0.010)
  /// [rad] a wider beam straddles more depth edges: more trailing points (nominal 0.006)
  double beam_divergence_rad = 0.012;
  /// [m] returns this close blend into one mixed point (nominal 0.5): more trailing points
  double echo_separation_m = 1.0;
  double dropout_probability = 0.02;             ///< [-] any beam (nominal 0.002)
  double dark_dropout_gain = 0.15;               ///< [-] extra on dark legs (nominal 0.05)
  double tilt_pitch_rad = 0.017453292519943295;  ///< [rad] 1 deg nose down (nominal 0)
};

/// `nominal` with the harsh sensor's flaws switched on and set.
sim::LidarConfig HarshLidar(sim::LidarConfig nominal, const HarshLidarConfig& harsh = {});

}  // namespace shelfdock::eval
