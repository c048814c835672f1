#include "io/robot_yaml.hpp"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

std::string WriteYaml(const std::string& text) {
  const auto path = shelfdock::testing::ProcessTempDir().path() / "shelfdock_robot_test.yaml";
  std::ofstream(path) << text;
  return path.string();
}

TEST(RobotYaml, TheShippedFileWritesOutTheDefaults) {
  const sim::DiffDriveConfig c = ReadRobotConfig(SHELFDOCK_SOURCE_DIR "/config/robot.yaml");
  const sim::DiffDriveConfig d;
  EXPECT_EQ(c.max_v_mps, d.max_v_mps);
  EXPECT_EQ(c.max_alpha_radps2, d.max_alpha_radps2);
  EXPECT_EQ(c.footprint_width_m, d.footprint_width_m);
  EXPECT_EQ(c.lift_duration_s, d.lift_duration_s);
  EXPECT_EQ(c.odometry.wheel_scale_std, d.odometry.wheel_scale_std);
  EXPECT_EQ(c.odometry.slip_std_m_per_sqrt_m, d.odometry.slip_std_m_per_sqrt_m);
  EXPECT_EQ(c.localisation.bias_std_m, d.localisation.bias_std_m);
  EXPECT_EQ(c.localisation.update_rate_hz, d.localisation.update_rate_hz);
}

TEST(RobotYaml, ReadsNestedKeysAndNamesBadOnes) {
  const sim::DiffDriveConfig c =
      ReadRobotConfig(WriteYaml("max_v_mps: 0.4\nodometry: {slip_std_m_per_sqrt_m: 0}\n"));
  EXPECT_EQ(c.max_v_mps, 0.4);
  EXPECT_EQ(c.odometry.slip_std_m_per_sqrt_m, 0.0);
  EXPECT_EQ(c.odometry.wheel_scale_std, sim::OdometryNoiseConfig{}.wheel_scale_std);

  auto field_of = [](const std::string& text) -> std::string {
    try {
      ReadRobotConfig(WriteYaml(text));
    } catch (const InputError& e) {
      return e.field();
    }
    return "(accepted)";
  };
  EXPECT_EQ(field_of("max_v_mps: 0\n"), "max_v_mps");
  EXPECT_EQ(field_of("localisation: {bias_time_constant_s: 0}\n"),
            "localisation.bias_time_constant_s");
  EXPECT_EQ(field_of("odometry: {wheel_scale: 0.1}\n"), "odometry.wheel_scale");
  EXPECT_EQ(field_of("wheelbase: 0.5\n"), "wheelbase");
}

}  // namespace
}  // namespace shelfdock::io
