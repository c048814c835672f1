// Every input the fuzzers (fuzz/) found to crash, hang or exhaust memory, kept in
// tests/data/fuzz/<reader>/, read again by the reader it broke: each must now be a clear
// InputError naming the file (no other exception, no sanitizer report, no hang).
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "io/camera_yaml.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/pgm.hpp"
#include "io/robot_yaml.hpp"
#include "io/rosbag_scans.hpp"
#include "io/scan_json.hpp"
#include "io/scenario_yaml.hpp"

namespace shelfdock::io {
namespace {

const std::filesystem::path kFindings =
    std::filesystem::path(SHELFDOCK_SOURCE_DIR) / "tests" / "data" / "fuzz";

/// The reader each folder's inputs broke (as the fuzz target of the same name calls it).
const std::map<std::string, std::function<void(const std::string&)>>& Readers() {
  static const std::map<std::string, std::function<void(const std::string&)>> readers = {
      {"scan_json", [](const std::string& p) { ReadScans(p); }},
      {"rosbag",
       [](const std::string& p) {
         ListBagScanTopics(p);
         ReadBagScans(p, "");
       }},
      {"models_yaml", [](const std::string& p) { ReadShelfModels(p); }},
      {"detector_yaml", [](const std::string& p) { ReadDetectorConfig(p); }},
      {"docking_yaml", [](const std::string& p) { ReadDockingConfig(p); }},
      {"scenario_yaml", [](const std::string& p) { ReadScenario(p, testing::PaperModels()); }},
      {"lidar_yaml", [](const std::string& p) { ReadLidarConfig(p); }},
      {"robot_yaml", [](const std::string& p) { ReadRobotConfig(p); }},
      {"camera_yaml", [](const std::string& p) { ReadCameraSetup(p); }},
      {"pgm", [](const std::string& p) { ReadPgm(p); }},
  };
  return readers;
}

TEST(FuzzRegressionTest, EveryFindingIsAnInputErrorNamingTheFile) {
  int inputs = 0;
  for (const auto& folder : std::filesystem::directory_iterator(kFindings)) {
    const std::string reader = folder.path().filename().string();
    ASSERT_TRUE(Readers().contains(reader)) << "no reader for tests/data/fuzz/" << reader;
    for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
      const std::string path = file.path().string();
      SCOPED_TRACE(path);
      ++inputs;
      try {
        Readers().at(reader)(path);
        ADD_FAILURE() << "read without an error";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(file.path().filename().string()), std::string::npos)
            << e.what();
      }
    }
  }
  EXPECT_GT(inputs, 0);
}

}  // namespace
}  // namespace shelfdock::io
