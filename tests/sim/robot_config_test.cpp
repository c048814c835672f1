// One test per rule of the robot's config (config/robot.yaml): DiffDriveConfig
// (src/sim/diff_drive_robot.cpp) with its odometry (src/sim/odometry.cpp) and localisation
// (src/sim/localisation.cpp) errors. The defaults pass, and breaking exactly one rule is
// reported with exactly its key.
#include <gtest/gtest.h>

#include "../common/config_rules.hpp"
#include "sim/diff_drive_robot.hpp"

namespace shelfdock::sim {
namespace {

using shelfdock::testing::ExpectRuleNamesItsKey;
using shelfdock::testing::kRuleName;
using RobotRule = shelfdock::testing::RuleCase<DiffDriveConfig>;

const RobotRule kRules[] = {
    {"max_v", "max_v_mps", [](auto& c) { c.max_v_mps = 0.0; }},
    {"max_w", "max_w_radps", [](auto& c) { c.max_w_radps = 0.0; }},
    {"max_accel", "max_accel_mps2", [](auto& c) { c.max_accel_mps2 = -0.5; }},
    {"max_alpha", "max_alpha_radps2", [](auto& c) { c.max_alpha_radps2 = 0.0; }},
    {"wheel_base", "wheel_base_m", [](auto& c) { c.wheel_base_m = 0.0; }},
    {"footprint_length", "footprint_length_m", [](auto& c) { c.footprint_length_m = 0.0; }},
    {"footprint_width", "footprint_width_m", [](auto& c) { c.footprint_width_m = 0.0; }},
    {"control_rate", "control_rate_hz", [](auto& c) { c.control_rate_hz = 0.0; }},
    {"lift_duration", "lift_duration_s", [](auto& c) { c.lift_duration_s = -0.1; }},
    {"history", "history_s", [](auto& c) { c.history_s = 0.0; }},
    {"wheel_scale_negative", "odometry.wheel_scale_std",
     [](auto& c) { c.odometry.wheel_scale_std = -0.001; }},
    {"wheel_scale_large", "odometry.wheel_scale_std",
     [](auto& c) { c.odometry.wheel_scale_std = 0.1; }},
    {"wheel_base_scale_negative", "odometry.wheel_base_scale_std",
     [](auto& c) { c.odometry.wheel_base_scale_std = -0.001; }},
    {"wheel_base_scale_large", "odometry.wheel_base_scale_std",
     [](auto& c) { c.odometry.wheel_base_scale_std = 0.1; }},
    {"slip", "odometry.slip_std_m_per_sqrt_m",
     [](auto& c) { c.odometry.slip_std_m_per_sqrt_m = -0.001; }},
    {"noise_m", "localisation.noise_std_m", [](auto& c) { c.localisation.noise_std_m = -0.01; }},
    {"noise_rad", "localisation.noise_std_rad",
     [](auto& c) { c.localisation.noise_std_rad = -0.01; }},
    {"bias_m", "localisation.bias_std_m", [](auto& c) { c.localisation.bias_std_m = -0.01; }},
    {"bias_rad", "localisation.bias_std_rad", [](auto& c) { c.localisation.bias_std_rad = -0.01; }},
    {"bias_time_constant", "localisation.bias_time_constant_s",
     [](auto& c) { c.localisation.bias_time_constant_s = 0.0; }},
    {"update_rate", "localisation.update_rate_hz",
     [](auto& c) { c.localisation.update_rate_hz = 0.0; }},
};

TEST(RobotConfigTest, DefaultsPass) {
  EXPECT_FALSE(FindConfigViolation(DiffDriveConfig{}));
  EXPECT_FALSE(FindConfigViolation(OdometryNoiseConfig{}));
  EXPECT_FALSE(FindConfigViolation(LocalisationNoiseConfig{}));
}

// Zero noise and an instant lift are allowed: tests switch the errors off this way.
TEST(RobotConfigTest, NoErrorsAndAnInstantLiftPass) {
  DiffDriveConfig c;
  c.lift_duration_s = 0.0;
  c.odometry = {0.0, 0.0, 0.0};
  c.localisation.noise_std_m = c.localisation.noise_std_rad = 0.0;
  c.localisation.bias_std_m = c.localisation.bias_std_rad = 0.0;
  EXPECT_FALSE(FindConfigViolation(c));
}

class RobotConfigRuleTest : public ::testing::TestWithParam<RobotRule> {};
TEST_P(RobotConfigRuleTest, BreakingTheRuleNamesItsKey) {
  ExpectRuleNamesItsKey(DiffDriveConfig{}, GetParam());
}
INSTANTIATE_TEST_SUITE_P(EveryRule, RobotConfigRuleTest, ::testing::ValuesIn(kRules), kRuleName);

// The nested structs' own functions report their keys without the map's name.
TEST(RobotConfigTest, NestedStructsReportTheirOwnKeys) {
  OdometryNoiseConfig odometry;
  odometry.slip_std_m_per_sqrt_m = -1.0;
  ASSERT_TRUE(FindConfigViolation(odometry));
  EXPECT_EQ(FindConfigViolation(odometry)->key, "slip_std_m_per_sqrt_m");
  LocalisationNoiseConfig localisation;
  localisation.update_rate_hz = 0.0;
  ASSERT_TRUE(FindConfigViolation(localisation));
  EXPECT_EQ(FindConfigViolation(localisation)->key, "update_rate_hz");
}

}  // namespace
}  // namespace shelfdock::sim
