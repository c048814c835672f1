#include "sim/lidar_config.hpp"

#include <cmath>

namespace shelfdock::sim {
namespace {

bool InUnitRange(double v) { return v >= 0.0 && v <= 1.0; }

}  // namespace

double LidarConfig::TimeIncrement() const {
  return num_beams > 1 ? sweep_fraction * ScanPeriod() / (num_beams - 1) : 0.0;
}

std::optional<geometry::ConfigViolation> FindConfigViolation(const LidarConfig& c) {
  geometry::ConfigChecker k;
  k.Check(c.angle_increment_rad > 0.0, "angle_increment_rad", "> 0");
  k.Check(c.num_beams >= 1 && c.num_beams <= 100000, "num_beams", "in [1, 100000]");
  k.Check(c.frequency_hz > 0.0, "frequency_hz", "> 0");
  k.Check(InUnitRange(c.sweep_fraction), "sweep_fraction", "in [0, 1]");
  k.Check(c.range_min_m >= 0.0, "range_min_m", ">= 0");
  k.Check(c.range_max_m > c.range_min_m, "range_max_m", "> range_min");
  k.Check(c.range_noise_sigma_m >= 0.0, "range_noise_sigma_m", ">= 0");
  k.Check(c.range_noise_per_m >= 0.0, "range_noise_per_m", ">= 0");
  k.Check(c.quantisation_m > 0.0, "quantisation_m", "> 0");
  k.Check(c.beam_divergence_rad >= 0.0 && c.beam_divergence_rad < 0.2, "beam_divergence_rad",
          "in [0, 0.2) rad");
  k.Check(c.beam_aperture_m >= 0.0, "beam_aperture_m", ">= 0");
  // Odd: one sub-ray runs along the beam's axis.
  k.Check(c.footprint_rays >= 3 && c.footprint_rays <= 31 && c.footprint_rays % 2 == 1,
          "footprint_rays", "an odd number in [3, 31]");
  k.Check(c.min_echo_fraction > 0.0 && c.min_echo_fraction <= 1.0, "min_echo_fraction",
          "in (0, 1]");
  k.Check(c.echo_separation_m > 0.0, "echo_separation_m", "> 0");
  k.Check(InUnitRange(c.dropout_probability), "dropout_probability", "in [0, 1]");
  k.Check(InUnitRange(c.dark_dropout_gain), "dark_dropout_gain", "in [0, 1]");
  k.Check(InUnitRange(c.shiny_dropout_gain), "shiny_dropout_gain", "in [0, 1]");
  k.Check(InUnitRange(c.stray_probability), "stray_probability", "in [0, 1]");
  k.Check(std::abs(c.range_bias_m) <= 0.5, "range_bias_m", "within +-0.5 (metres)");
  k.Check(c.intensity_scale >= 0.0, "intensity_scale", ">= 0");
  k.Check(c.intensity_noise_rel >= 0.0, "intensity_noise_rel", ">= 0");
  k.Check(c.mount_height_m > 0.0, "mount_height_m", "> 0");
  k.Check(std::abs(c.tilt_pitch_rad) < 0.5, "tilt_pitch_rad", "|tilt| < 0.5 rad");
  k.Check(std::abs(c.tilt_roll_rad) < 0.5, "tilt_roll_rad", "|tilt| < 0.5 rad");
  k.Check(std::abs(c.yaw_offset_rad) < 0.5, "yaw_offset_rad", "|offset| < 0.5 rad");
  k.Check(InUnitRange(c.floor_reflectivity), "floor_reflectivity", "in [0, 1]");
  return k.Result();
}

LidarConfig IdealLidarConfig(LidarConfig config) {
  config.enable_range_noise = false;
  config.enable_quantisation = false;
  config.enable_footprint = false;
  config.enable_dropouts = false;
  config.stray_probability = 0.0;
  config.range_bias_m = 0.0;
  config.enable_tilt = false;
  config.yaw_offset_rad = 0.0;
  return config;
}

}  // namespace shelfdock::sim
