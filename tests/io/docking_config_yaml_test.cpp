// The docking YAML loader: shipped file, key errors naming file and key, the renamed camera
// keys, and the struct's rules reported with the file name (the rules themselves are tested in
// tests/docking/docking_config_test.cpp).
#include "io/docking_config_yaml.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

/// A directory of this test's own, removed at the end (suites running at once do not collide).
class DockingConfigYamlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "shelfdock_dockyaml_XXXXXX");
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string Write(const std::string& text) {
    const std::string path = (dir_ / "docking.yaml").string();
    std::ofstream(path) << text;
    return path;
  }
  void ExpectKeyError(const std::string& yaml, const std::string& key, const std::string& words) {
    const std::string path = Write(yaml);
    try {
      ReadDockingConfig(path);
      FAIL() << "expected InputError for " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.field(), key);
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }

  std::filesystem::path dir_;
};

TEST_F(DockingConfigYamlTest, ShippedFileLoads) {
  const auto c = ReadDockingConfig(std::string(SHELFDOCK_SOURCE_DIR) + "/config/docking.yaml");
  EXPECT_EQ(c.entry_distance_m, 4.5);
}

TEST_F(DockingConfigYamlTest, ReadsTheCameraCorrectionKeys) {
  const auto c = ReadDockingConfig(
      Write("camera_guide: {correct_xy_m: 0.001, correct_yaw_rad: 0.002}\nreplan_xy_m: 0.01\n"));
  EXPECT_DOUBLE_EQ(c.camera_guide.correct_xy_m, 0.001);
  EXPECT_DOUBLE_EQ(c.camera_guide.correct_yaw_rad, 0.002);
  EXPECT_DOUBLE_EQ(c.replan_xy_m, 0.01);  // the LiDAR's re-plan threshold, a different field
}

TEST_F(DockingConfigYamlTest, ReadsTheTwoLegTrackingSwitch) {
  EXPECT_TRUE(ReadDockingConfig(Write("entry_distance_m: 4.0\n")).two_leg_tracking);
  EXPECT_FALSE(ReadDockingConfig(Write("two_leg_tracking: false\n")).two_leg_tracking);
  ExpectKeyError("two_leg_tracking: 0.5\n", "two_leg_tracking", "");
}

TEST_F(DockingConfigYamlTest, OldCameraKeysNameTheirNewNames) {
  ExpectKeyError("camera_guide: {replan_xy_m: 0.001}\n", "camera_guide.replan_xy_m",
                 "camera_guide.correct_xy_m");
  ExpectKeyError("camera_guide: {replan_yaw_rad: 0.001}\n", "camera_guide.replan_yaw_rad",
                 "camera_guide.correct_yaw_rad");
}

TEST_F(DockingConfigYamlTest, RulesOfTheStructsNameFileAndKey) {
  // Fields that were never checked before (issue 10): each is now refused with its key.
  ExpectKeyError("replan_xy_m: 0\n", "replan_xy_m", "> 0");
  ExpectKeyError("replan_yaw_rad: -0.1\n", "replan_yaw_rad", "> 0");
  ExpectKeyError("lidar_cutoff_m: -1\n", "lidar_cutoff_m", ">= 0");
  ExpectKeyError("scan_timeout_s: 0\n", "scan_timeout_s", "(0, detection_lost_s]");
  ExpectKeyError("must_detect_by_m: 2.0\n", "must_detect_by_m", "min_entry_distance_m");
  ExpectKeyError("lift_timeout_s: 0\n", "lift_timeout_s", "> 0");
  ExpectKeyError("safety: {obstacle_wait_s: -1}\n", "safety.obstacle_wait_s", ">= 0");
  ExpectKeyError("verify: {max_missing_frames: 0}\n", "verify.max_missing_frames", ">= 1");
  ExpectKeyError("lidar_mount: {yaw: 7}\n", "lidar_mount.yaw", "[-pi, pi]");
}

TEST_F(DockingConfigYamlTest, UnknownAndMistypedKeys) {
  ExpectKeyError("controller: {max_sped_mps: 0.3}\n", "controller.max_sped_mps", "unknown key");
  ExpectKeyError("timeout_s: soon\n", "timeout_s", "expected a number");
}

}  // namespace
}  // namespace shelfdock::io
