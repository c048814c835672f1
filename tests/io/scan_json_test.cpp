#include "io/scan_json.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"

namespace shelfdock::io {
namespace {

const std::string kData = std::string(SHELFDOCK_SOURCE_DIR) + "/tests/data/";

TEST(ScanJsonTest, RoundTripKeepsNullsAsNaN) {
  geometry::LaserScan s;
  s.angle_min = -1.0;
  s.angle_max = -0.98;
  s.angle_increment = 0.01;
  s.range_min = 0.05;
  s.range_max = 25.0;
  s.ranges = {1.5, std::nan(""), 2.25};
  const auto path = shelfdock::testing::ProcessTempDir().path() / "shelfdock_io_scans.jsonl";
  {
    std::ofstream out(path);
    out << ScanToJson(s).dump() << "\n" << ScanToJson(s).dump() << "\n";  // JSON Lines
  }
  const auto scans = ReadScans(path.string());
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_DOUBLE_EQ(scans[1].ranges[0], 1.5);
  EXPECT_TRUE(std::isnan(scans[1].ranges[1]));
  EXPECT_DOUBLE_EQ(scans[1].angle_increment, 0.01);
}

TEST(ScanJsonTest, ExampleScanIsAnWlr716Scan) {
  const auto scans = ReadScans(kData + "example_scan.json");
  ASSERT_EQ(scans.size(), 1u);
  EXPECT_EQ(scans[0].ranges.size(), 811u);
}

TEST(ScanJsonTest, MalformedFilesNameTheFile) {
  for (const char* name : {"malformed_scan.json", "nan_text_scan.json", "missing.json"}) {
    try {
      ReadScans(kData + name);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(ModelsYamlTest, ShippedModelsAreThePapersTable1) {
  const auto models = ReadShelfModels(std::string(SHELFDOCK_SOURCE_DIR) + "/config/models.yaml");
  ASSERT_EQ(models.size(), 4u);
  EXPECT_EQ(models[1].name, "t1-rect-1075x883");
  EXPECT_DOUBLE_EQ(models[1].length_m, 1.075);
  EXPECT_DOUBLE_EQ(models[1].width_m, 0.883);
  EXPECT_EQ(models[0].leg.shape, geometry::LegShape::kCircle);
}

}  // namespace
}  // namespace shelfdock::io
