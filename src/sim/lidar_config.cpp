#include "sim/lidar_config.hpp"

#include <cmath>

namespace shelfdock::sim {

double LidarConfig::TimeIncrement() const {
  return num_beams > 1 ? sweep_fraction * ScanPeriod() / (num_beams - 1) : 0.0;
}

std::optional<ConfigError> Validate(const LidarConfig& c) {
  auto fail = [](const char* field, const char* req) {
    return std::optional<ConfigError>(ConfigError{field, req});
  };
  if (!(c.angle_increment_rad > 0.0)) return fail("angle_increment_rad", "> 0");
  if (c.num_beams < 1 || c.num_beams > 100000) return fail("num_beams", "in [1, 100000]");
  if (!(c.frequency_hz > 0.0)) return fail("frequency_hz", "> 0");
  if (!(c.sweep_fraction >= 0.0 && c.sweep_fraction <= 1.0)) {
    return fail("sweep_fraction", "in [0, 1]");
  }
  if (!(c.range_min_m >= 0.0)) return fail("range_min_m", ">= 0");
  if (!(c.range_max_m > c.range_min_m)) return fail("range_max_m", "> range_min");
  if (!(c.range_noise_sigma_m >= 0.0)) return fail("range_noise_sigma_m", ">= 0");
  if (!(c.range_noise_per_m >= 0.0)) return fail("range_noise_per_m", ">= 0");
  if (!(c.quantisation_m > 0.0)) return fail("quantisation_m", "> 0");
  if (!(c.beam_divergence_rad >= 0.0 && c.beam_divergence_rad < 0.2)) {
    return fail("beam_divergence_rad", "in [0, 0.2) rad");
  }
  if (!(c.beam_aperture_m >= 0.0)) return fail("beam_aperture_m", ">= 0");
  if (c.footprint_rays < 3 || c.footprint_rays > 31 || c.footprint_rays % 2 == 0) {
    return fail("footprint_rays", "an odd number in [3, 31]");
  }
  if (!(c.min_echo_fraction > 0.0 && c.min_echo_fraction <= 1.0)) {
    return fail("min_echo_fraction", "in (0, 1]");
  }
  if (!(c.echo_separation_m > 0.0)) return fail("echo_separation_m", "> 0");
  if (!(c.dropout_probability >= 0.0 && c.dropout_probability <= 1.0)) {
    return fail("dropout_probability", "in [0, 1]");
  }
  if (!(c.dark_dropout_gain >= 0.0 && c.dark_dropout_gain <= 1.0)) {
    return fail("dark_dropout_gain", "in [0, 1]");
  }
  if (!(c.shiny_dropout_gain >= 0.0 && c.shiny_dropout_gain <= 1.0)) {
    return fail("shiny_dropout_gain", "in [0, 1]");
  }
  if (!(c.intensity_scale >= 0.0)) return fail("intensity_scale", ">= 0");
  if (!(c.intensity_noise_rel >= 0.0)) return fail("intensity_noise_rel", ">= 0");
  if (!(c.mount_height_m > 0.0)) return fail("mount_height_m", "> 0");
  if (!(std::abs(c.tilt_pitch_rad) < 0.5)) return fail("tilt_pitch_rad", "|tilt| < 0.5 rad");
  if (!(std::abs(c.tilt_roll_rad) < 0.5)) return fail("tilt_roll_rad", "|tilt| < 0.5 rad");
  if (!(std::abs(c.yaw_offset_rad) < 0.5)) return fail("yaw_offset_rad", "|offset| < 0.5 rad");
  if (!(c.floor_reflectivity >= 0.0 && c.floor_reflectivity <= 1.0)) {
    return fail("floor_reflectivity", "in [0, 1]");
  }
  return std::nullopt;
}

LidarConfig IdealLidarConfig(LidarConfig config) {
  config.enable_range_noise = false;
  config.enable_quantisation = false;
  config.enable_footprint = false;
  config.enable_dropouts = false;
  config.enable_tilt = false;
  config.yaw_offset_rad = 0.0;
  return config;
}

}  // namespace shelfdock::sim
