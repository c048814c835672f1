// One test per rule of the LiDAR config (src/sim/lidar_config.cpp): the defaults and the ideal
// config pass, and breaking exactly one rule is reported with exactly its key.
#include "sim/lidar_config.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "../common/config_rules.hpp"

namespace shelfdock::sim {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using LidarRule = shelfdock::testing::RuleCase<LidarConfig>;

const LidarRule kRules[] = {
    {"angle_increment", "angle_increment_rad", [](auto& c) { c.angle_increment_rad = 0.0; }},
    {"no_beams", "num_beams", [](auto& c) { c.num_beams = 0; }},
    {"too_many_beams", "num_beams", [](auto& c) { c.num_beams = 100001; }},
    {"frequency", "frequency_hz", [](auto& c) { c.frequency_hz = 0.0; }},
    {"sweep_negative", "sweep_fraction", [](auto& c) { c.sweep_fraction = -0.1; }},
    {"sweep_above_one", "sweep_fraction", [](auto& c) { c.sweep_fraction = 1.1; }},
    {"range_min", "range_min_m", [](auto& c) { c.range_min_m = -0.01; }},
    {"range_max", "range_max_m", [](auto& c) { c.range_max_m = c.range_min_m; }},
    {"range_noise", "range_noise_sigma_m", [](auto& c) { c.range_noise_sigma_m = -0.001; }},
    {"range_noise_growth", "range_noise_per_m", [](auto& c) { c.range_noise_per_m = -0.001; }},
    {"quantisation", "quantisation_m", [](auto& c) { c.quantisation_m = 0.0; }},
    {"divergence_negative", "beam_divergence_rad", [](auto& c) { c.beam_divergence_rad = -0.001; }},
    {"divergence_wide", "beam_divergence_rad", [](auto& c) { c.beam_divergence_rad = 0.2; }},
    {"aperture", "beam_aperture_m", [](auto& c) { c.beam_aperture_m = -0.001; }},
    {"footprint_rays_few", "footprint_rays", [](auto& c) { c.footprint_rays = 1; }},
    {"footprint_rays_many", "footprint_rays", [](auto& c) { c.footprint_rays = 33; }},
    {"footprint_rays_even", "footprint_rays", [](auto& c) { c.footprint_rays = 4; }},
    {"echo_fraction_zero", "min_echo_fraction", [](auto& c) { c.min_echo_fraction = 0.0; }},
    {"echo_fraction_above_one", "min_echo_fraction", [](auto& c) { c.min_echo_fraction = 1.1; }},
    {"echo_separation", "echo_separation_m", [](auto& c) { c.echo_separation_m = 0.0; }},
    {"dropout_negative", "dropout_probability", [](auto& c) { c.dropout_probability = -0.1; }},
    {"dropout_above_one", "dropout_probability", [](auto& c) { c.dropout_probability = 1.1; }},
    {"dark_dropout_negative", "dark_dropout_gain", [](auto& c) { c.dark_dropout_gain = -0.1; }},
    {"dark_dropout_above_one", "dark_dropout_gain", [](auto& c) { c.dark_dropout_gain = 1.1; }},
    {"shiny_dropout_negative", "shiny_dropout_gain", [](auto& c) { c.shiny_dropout_gain = -0.1; }},
    {"shiny_dropout_above_one", "shiny_dropout_gain", [](auto& c) { c.shiny_dropout_gain = 1.1; }},
    {"stray_negative", "stray_probability", [](auto& c) { c.stray_probability = -0.01; }},
    {"stray_above_one", "stray_probability", [](auto& c) { c.stray_probability = 1.5; }},
    {"range_bias_beyond_half_a_metre", "range_bias_m", [](auto& c) { c.range_bias_m = -0.6; }},
    {"range_bias_nan", "range_bias_m",
     [](auto& c) { c.range_bias_m = std::numeric_limits<double>::quiet_NaN(); }},
    {"intensity_scale", "intensity_scale", [](auto& c) { c.intensity_scale = -1.0; }},
    {"intensity_noise", "intensity_noise_rel", [](auto& c) { c.intensity_noise_rel = -0.01; }},
    {"mount_height", "mount_height_m", [](auto& c) { c.mount_height_m = 0.0; }},
    {"pitch", "tilt_pitch_rad", [](auto& c) { c.tilt_pitch_rad = 0.5; }},
    {"roll", "tilt_roll_rad", [](auto& c) { c.tilt_roll_rad = -0.5; }},
    {"yaw_offset", "yaw_offset_rad", [](auto& c) { c.yaw_offset_rad = 0.5; }},
    {"floor_negative", "floor_reflectivity", [](auto& c) { c.floor_reflectivity = -0.1; }},
    {"floor_above_one", "floor_reflectivity", [](auto& c) { c.floor_reflectivity = 1.1; }},
};

TEST(LidarConfigTest, DefaultsPass) {
  EXPECT_FALSE(FindConfigViolation(LidarConfig{}));
  EXPECT_FALSE(FindConfigViolation(IdealLidarConfig()));
}

class LidarConfigRuleTest : public ::testing::TestWithParam<LidarRule> {};
TEST_P(LidarConfigRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(LidarConfig{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, LidarConfigRuleTest, ::testing::ValuesIn(kRules), kRuleName);

}  // namespace
}  // namespace shelfdock::sim
