#include "eval/harsh_lidar.hpp"

namespace shelfdock::eval {

sim::LidarConfig HarshLidar(sim::LidarConfig nominal, const HarshLidarConfig& harsh) {
  nominal.enable_range_noise = true;
  nominal.range_noise_sigma_m = harsh.range_noise_sigma_m;
  nominal.enable_footprint = true;
  nominal.beam_divergence_rad = harsh.beam_divergence_rad;
  nominal.echo_separation_m = harsh.echo_separation_m;
  nominal.enable_dropouts = true;
  nominal.dropout_probability = harsh.dropout_probability;
  nominal.dark_dropout_gain = harsh.dark_dropout_gain;
  nominal.enable_tilt = true;
  nominal.tilt_pitch_rad = harsh.tilt_pitch_rad;
  return nominal;
}

}  // namespace shelfdock::eval
