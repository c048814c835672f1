// The docking run record (`shelfdock dock --record`): written from a run made up here, read back
// line by line, every field against what went in.
#include "io/run_record.hpp"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../common/paper_models.hpp"
#include "../common/temp_dir.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

sim::Scenario OneShelfScenario() {
  sim::Scenario scenario;
  scenario.name = "one shelf";
  scenario.target_shelf_id = 7;
  scenario.world.AddShelf(7, testing::PaperShelf2(), geometry::Pose2(3.0, 1.0, 0.5));
  return scenario;
}

eval::DockingRun MadeUpRun() {
  eval::DockingRun run;
  run.outcome = {docking::OutcomeCode::kWouldCollide, "a leg is in the way"};
  run.method = docking::Method::kContinuous;
  run.seed = 42;
  run.time_s = 12.5;
  run.error_before_check = {0.001, -0.002, 0.003, true};
  run.min_leg_clearance_m = 0.08;
  run.phases.dock_s = 10.0;
  eval::RecordFrame moving;
  moving.t_s = 0.02;
  moving.phase = "dock";
  moving.T_world_base_true = geometry::Pose2(1.0, 2.0, 0.1);
  moving.v_cmd = 0.3;
  moving.w_cmd = -0.1;
  moving.scan_world = {Eigen::Vector2d(1.23456, -0.00049), Eigen::Vector2d(2.0, 3.0)};
  moving.detection_world = geometry::Pose2(3.0, 1.0, 0.5);
  moving.path_world = {geometry::Pose2(1.0, 2.0, 0.1), geometry::Pose2(3.0, 1.0, 0.5)};
  moving.events = {"re-planned"};
  eval::RecordFrame quiet;
  quiet.t_s = 0.04;
  quiet.phase = "abort";
  run.record = {moving, quiet};
  return run;
}

std::vector<nlohmann::json> ReadLines(const std::string& path) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(RunRecordTest, WritesHeaderStepsAndSummary) {
  const testing::TempDir dir;
  const sim::Scenario scenario = OneShelfScenario();
  const eval::DockingRun run = MadeUpRun();
  const geometry::Pose2 preset(2.9, 1.1, 0.45);
  WriteRunRecord(dir.File("run.jsonl"), scenario, preset, run, 0.7, 0.5);

  const auto lines = ReadLines(dir.File("run.jsonl"));
  ASSERT_EQ(lines.size(), 4u);  // header, two steps, summary
  const auto& header = lines[0];
  EXPECT_EQ(header["type"], "header");
  EXPECT_EQ(header["scenario"], "one shelf");
  EXPECT_EQ(header["target_shelf"], 7);
  EXPECT_EQ(header["seed"], 42);
  EXPECT_DOUBLE_EQ(header["preset"]["yaw"].get<double>(), 0.45);
  EXPECT_DOUBLE_EQ(header["robot"]["length"].get<double>(), 0.7);
  ASSERT_EQ(header["shelves"].size(), 1u);
  const auto& shelf = header["shelves"][0];
  EXPECT_EQ(shelf["id"], 7);
  EXPECT_EQ(shelf["model"], testing::PaperShelf2().name);
  // Legs in the world: the model's leg centres moved by the true shelf pose.
  const geometry::Pose2 T_world_shelf(3.0, 1.0, 0.5);
  const auto centres = testing::PaperShelf2().LegCentres();
  ASSERT_EQ(shelf["legs"].size(), centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Eigen::Vector2d p = T_world_shelf * centres[i];
    EXPECT_NEAR(shelf["legs"][i][0].get<double>(), p.x(), 1e-12);
    EXPECT_NEAR(shelf["legs"][i][1].get<double>(), p.y(), 1e-12);
  }

  const auto& moving = lines[1];
  EXPECT_EQ(moving["type"], "step");
  EXPECT_EQ(moving["phase"], "dock");
  EXPECT_DOUBLE_EQ(moving["true"]["x"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(moving["cmd"]["w"].get<double>(), -0.1);
  // Scan points are rounded to the millimetre.
  EXPECT_DOUBLE_EQ(moving["scan"][0][0].get<double>(), 1.235);
  EXPECT_DOUBLE_EQ(moving["scan"][0][1].get<double>(), -0.0);
  EXPECT_DOUBLE_EQ(moving["detection"]["yaw"].get<double>(), 0.5);
  EXPECT_EQ(moving["path"].size(), 2u);
  EXPECT_EQ(moving["events"][0], "re-planned");
  // Optional fields are left out, not written empty.
  const auto& quiet = lines[2];
  for (const char* key : {"scan", "detection", "shelf", "path", "events"}) {
    EXPECT_FALSE(quiet.contains(key)) << key;
  }

  const auto& summary = lines[3];
  EXPECT_EQ(summary["type"], "summary");
  EXPECT_EQ(summary["result"], "would_collide");
  EXPECT_EQ(summary["reason"], "a leg is in the way");
  EXPECT_DOUBLE_EQ(summary["min_leg_clearance_m"].get<double>(), 0.08);
  EXPECT_DOUBLE_EQ(summary["error_before_check"]["yaw"].get<double>(), 0.003);
  EXPECT_TRUE(summary["error_after_check"]["x"].is_null());  // never reached
  EXPECT_DOUBLE_EQ(summary["phases"]["dock_s"].get<double>(), 10.0);
}

TEST(RunRecordTest, UnwritablePathIsAnInputErrorNamingIt) {
  const testing::TempDir dir;
  const std::string path = dir.File("no_such_dir/run.jsonl");
  try {
    WriteRunRecord(path, OneShelfScenario(), geometry::Pose2(), MadeUpRun(), 0.7, 0.5);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shelfdock::io
