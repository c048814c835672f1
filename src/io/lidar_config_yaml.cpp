#include "io/lidar_config_yaml.hpp"

#include <string>

#include "io/yaml_fields.hpp"

namespace shelfdock::io {

sim::LidarConfig ReadLidarConfig(const std::string& path) {
  const YAML::Node root = LoadYamlFile(path);
  YamlFields f(root, path, "");
  sim::LidarConfig c;
  f.Read("angle_min_rad", c.angle_min_rad);
  f.Read("angle_increment_rad", c.angle_increment_rad);
  f.Read("num_beams", c.num_beams);
  f.Read("frequency_hz", c.frequency_hz);
  f.Read("sweep_fraction", c.sweep_fraction);
  f.Read("range_min_m", c.range_min_m);
  f.Read("range_max_m", c.range_max_m);
  f.Read("enable_range_noise", c.enable_range_noise);
  f.Read("range_noise_sigma_m", c.range_noise_sigma_m);
  f.Read("range_noise_per_m", c.range_noise_per_m);
  f.Read("enable_quantisation", c.enable_quantisation);
  f.Read("quantisation_m", c.quantisation_m);
  f.Read("enable_footprint", c.enable_footprint);
  f.Read("beam_divergence_rad", c.beam_divergence_rad);
  f.Read("beam_aperture_m", c.beam_aperture_m);
  f.Read("footprint_rays", c.footprint_rays);
  f.Read("min_echo_fraction", c.min_echo_fraction);
  f.Read("echo_separation_m", c.echo_separation_m);
  std::string echo_choice = "first";
  f.Read("echo_choice", echo_choice);
  if (echo_choice == "first") {
    c.echo_choice = sim::EchoChoice::kFirst;
  } else if (echo_choice == "strongest") {
    c.echo_choice = sim::EchoChoice::kStrongest;
  } else if (echo_choice == "last") {
    c.echo_choice = sim::EchoChoice::kLast;
  } else {
    f.Require(false, "echo_choice", "first, strongest or last");
  }
  f.Read("enable_dropouts", c.enable_dropouts);
  f.Read("dropout_probability", c.dropout_probability);
  f.Read("dark_dropout_gain", c.dark_dropout_gain);
  f.Read("shiny_dropout_gain", c.shiny_dropout_gain);
  f.Read("stray_probability", c.stray_probability);
  f.Read("range_bias_m", c.range_bias_m);
  f.Read("enable_intensities", c.enable_intensities);
  f.Read("intensity_scale", c.intensity_scale);
  f.Read("intensity_noise_rel", c.intensity_noise_rel);
  f.Read("mount_height_m", c.mount_height_m);
  f.Read("enable_tilt", c.enable_tilt);
  f.Read("tilt_pitch_rad", c.tilt_pitch_rad);
  f.Read("tilt_roll_rad", c.tilt_roll_rad);
  f.Read("yaw_offset_rad", c.yaw_offset_rad);
  f.Read("floor_reflectivity", c.floor_reflectivity);
  std::string name;  // a label for the preset, for the reader of the file only
  f.Read("name", name);
  f.RejectUnknown();
  f.Reject(sim::FindConfigViolation(c));
  return c;
}

}  // namespace shelfdock::io
