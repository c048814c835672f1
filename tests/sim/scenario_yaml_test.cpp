#include "io/scenario_yaml.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../common/temp_dir.hpp"
#include "geometry/angle.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"

namespace shelfdock::io {
namespace {

const std::string kRoot = SHELFDOCK_SOURCE_DIR;

std::vector<geometry::ShelfModel> Models() {
  return ReadShelfModels(kRoot + "/config/models.yaml");
}

/// Writes `text` to a fresh temporary YAML file and returns its path.
std::string WriteTemp(const std::string& name, const std::string& text) {
  const auto path =
      shelfdock::testing::ProcessTempDir().path() / ("shelfdock_sim_" + name + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

/// Expects ReadScenario to throw an InputError naming the file and exactly `field`.
void ExpectScenarioError(const std::string& name, const std::string& text,
                         const std::string& field) {
  const std::string path = WriteTemp(name, text);
  try {
    ReadScenario(path, Models());
    ADD_FAILURE() << name << ": expected InputError on " << field;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), field) << e.what();
  }
}

const std::string kStart = "robot_start: {x: 0, y: 0}\n";

TEST(ScenarioYamlTest, ShippedScenariosLoad) {
  const auto paper = ReadScenario(kRoot + "/config/scenarios/paper_docking.yaml", Models());
  EXPECT_EQ(paper.target_shelf_id, 2);
  ASSERT_NE(paper.FindShelf(2), nullptr);
  EXPECT_EQ(paper.FindShelf(2)->model_name, "t1-rect-1075x883");
  // The robot starts its approach on the shelf's axis, facing it, far enough before the
  // docking area's entry (4.5 m from the final pose) to cross it at cruise speed, as in the paper.
  const geometry::Pose2 T_map_shelf = paper.FindShelf(2)->T_map_shelf;
  EXPECT_GT(geometry::Distance(paper.T_map_robot_start, T_map_shelf), 4.5 + 1.0);
  EXPECT_NEAR(paper.T_map_robot_start.y, T_map_shelf.y, 1e-9);
  EXPECT_NEAR(geometry::AngleDiff(paper.T_map_robot_start.yaw, T_map_shelf.yaw), 0.0, 1e-9);
  EXPECT_EQ(paper.world.LegFootprints(2).size(), 4u);

  const auto aisle = ReadScenario(kRoot + "/config/scenarios/warehouse_aisle.yaml", Models());
  EXPECT_EQ(aisle.shelves.size(), 16u);
  EXPECT_EQ(aisle.world.shelves().size(), 16u);
  const auto dock = ReadScenario(kRoot + "/config/scenarios/cluttered_dock.yaml", Models());
  EXPECT_EQ(dock.world.people().size(), 2u);
  EXPECT_EQ(dock.world.robots().size(), 1u);

  // The paper's set-up with its shelf off its drawing: the same shelf, preset and start, each
  // leg where the file puts it off the model's place.
  const auto built =
      ReadScenario(kRoot + "/config/scenarios/paper_docking_as_built.yaml", Models());
  ASSERT_NE(built.FindShelf(2), nullptr);
  EXPECT_EQ(built.FindShelf(2)->T_map_shelf.x, T_map_shelf.x);
  EXPECT_EQ(built.T_map_robot_start.x, paper.T_map_robot_start.x);
  const auto designed = paper.world.LegFootprints(2);
  const auto legs = built.world.LegFootprints(2);
  ASSERT_EQ(legs.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const double off =
        (legs[i].T_world_leg.translation() - designed[i].T_world_leg.translation()).norm();
    EXPECT_GT(off, 0.005);
    EXPECT_LT(off, 0.011);
  }
}

TEST(ScenarioYamlTest, PresetOffsetDrawsWithinRangeAndRepeatsForASeed) {
  const std::string path = WriteTemp("offset", kStart + R"(shelves:
  - {id: 1, model: t1-rect-1075x883, pose: {x: 2, y: 1, yaw: 0.5},
     preset_offset: {xy_m: 0.3, yaw_rad: 0.17}}
  - {id: 2, model: t1-rect-1075x883, pose: {x: 5, y: 1}, preset: {x: 5.1, y: 0.9, yaw: 0.02}}
)");
  const auto s = ReadScenario(path, Models());
  double spread = 0.0;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const auto preset = *s.PresetPose(1, seed);
    EXPECT_LE(std::abs(preset.x - 2.0), 0.3);
    EXPECT_LE(std::abs(preset.y - 1.0), 0.3);
    EXPECT_LE(std::abs(geometry::AngleDiff(preset.yaw, 0.5)), 0.17 + 1e-12);
    EXPECT_EQ(s.PresetPose(1, seed)->x, preset.x);
    spread = std::max(spread, std::abs(preset.x - 2.0));
  }
  EXPECT_GT(spread, 0.2);                          // the draws do cover the range
  EXPECT_NEAR(s.PresetPose(2, 7)->x, 5.1, 1e-12);  // a stated preset is used as is
  EXPECT_FALSE(s.PresetPose(3, 7).has_value());
}

TEST(ScenarioYamlTest, ErrorsNameTheFileAndKey) {
  ExpectScenarioError("nostart", "name: x\n", "robot_start");
  ExpectScenarioError("model", kStart + "shelves:\n  - {id: 1, model: nope, pose: {x: 0, y: 0}}\n",
                      "shelves[0].model");
  ExpectScenarioError("pose", kStart + "shelves:\n  - {id: 1, model: t1-rect-1075x883}\n",
                      "shelves[0].pose");
  ExpectScenarioError("posey",
                      kStart + "shelves:\n  - {id: 1, model: t1-rect-1075x883, pose: {x: 0}}\n",
                      "shelves[0].pose.y");
  ExpectScenarioError("dupid",
                      kStart +
                          "shelves:\n  - {id: 1, model: t1-rect-1075x883, pose: {x: 0, y: 0}}\n"
                          "  - {id: 1, model: t1-rect-1075x883, pose: {x: 3, y: 0}}\n",
                      "shelves[1].id");
  ExpectScenarioError("point", kStart + "walls:\n  - {points: [[0, 0], [1]]}\n",
                      "walls[0].points[1]");
  ExpectScenarioError("unknown", kStart + "walls:\n  - {points: [[0, 0], [1, 1]], colour: red}\n",
                      "walls[0].colour");
  ExpectScenarioError("shape",
                      kStart + "posts:\n  - {shape: hexagonal, pose: {x: 0, y: 0}, size: 1}\n",
                      "posts[0].shape");
  ExpectScenarioError("speed", kStart + "people:\n  - {path: [[0, 0], [1, 0]], speed: -1}\n",
                      "people[0].speed");
  ExpectScenarioError("target", kStart + "target_shelf: 9\n", "target_shelf");
  ExpectScenarioError("number", kStart + "boxes:\n  - {pose: {x: 0, y: 0}, length: wide}\n",
                      "boxes[0].length");
  const std::string shelf =
      kStart + "shelves:\n  - {id: 1, model: t1-rect-1075x883, pose: {x: 0, y: 0}, ";
  ExpectScenarioError("built3",
                      shelf + "legs_as_built: [{x: 0, y: 0}, {x: 0, y: 0}, {x: 0, y: 0}]}\n",
                      "shelves[0].legs_as_built");
  ExpectScenarioError("builtfar",
                      shelf +
                          "legs_as_built: [{x: 0.1, y: 0}, {x: 0, y: 0}, {x: 0, y: 0}, "
                          "{x: 0, y: 0}]}\n",
                      "shelves[0].legs_as_built");
  ExpectScenarioError("builty", shelf + "legs_as_built: [{x: 0, y: 0}, {x: 0.01}]}\n",
                      "shelves[0].legs_as_built[1].y");
  EXPECT_THROW(ReadScenario("/nonexistent/scenario.yaml", Models()), InputError);
}

TEST(LidarConfigYamlTest, PresetsLoadAndBadKeysAreNamed) {
  const auto wlr = ReadLidarConfig(kRoot + "/config/lidar_wlr716.yaml");
  EXPECT_EQ(wlr.num_beams, 811);
  EXPECT_NEAR(wlr.AngleMax(), geometry::DegToRad(135.0), 1e-9);
  const auto ust = ReadLidarConfig(kRoot + "/config/lidar_ust10lx.yaml");
  EXPECT_EQ(ust.num_beams, 1081);
  EXPECT_NEAR(ust.AngleMax(), geometry::DegToRad(135.0), 1e-9);
  EXPECT_NEAR(ust.range_max_m, 10.0, 1e-12);
  EXPECT_EQ(ReadLidarConfig(kRoot + "/config/lidar_tim571.yaml").num_beams, 811);

  const std::string bad = WriteTemp("lidar_bad", "range_max_m: 0.01\n");
  try {
    ReadLidarConfig(bad);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "range_max_m");
  }
  const std::string unknown = WriteTemp("lidar_unknown", "beams: 10\n");
  EXPECT_THROW(ReadLidarConfig(unknown), InputError);
  // The receiver's echo choice: a name of the three, anything else named as the field.
  EXPECT_EQ(ReadLidarConfig(WriteTemp("lidar_last", "echo_choice: last\n")).echo_choice,
            sim::EchoChoice::kLast);
  EXPECT_EQ(ReadLidarConfig(WriteTemp("lidar_strong", "echo_choice: strongest\n")).echo_choice,
            sim::EchoChoice::kStrongest);
  EXPECT_EQ(wlr.echo_choice, sim::EchoChoice::kFirst);
  try {
    ReadLidarConfig(WriteTemp("lidar_echo", "echo_choice: loudest\n"));
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "echo_choice");
  }
}

// The sensor variants (config/lidar_variants, README "On a sensor unlike our model") keep the
// WLR-716's geometry and change only how returns are made: each must load and differ from the
// WLR-716 in its beam, echo, noise, dropout, stray-echo or range-bias model, or the robustness
// figures measure nothing.
TEST(LidarConfigYamlTest, SensorVariantsKeepTheGeometryAndChangeTheReturns) {
  const auto wlr = ReadLidarConfig(kRoot + "/config/lidar_wlr716.yaml");
  int variants = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kRoot + "/config/lidar_variants")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const auto v = ReadLidarConfig(entry.path().string());
    EXPECT_EQ(v.num_beams, wlr.num_beams);
    EXPECT_DOUBLE_EQ(v.angle_min_rad, wlr.angle_min_rad);
    EXPECT_DOUBLE_EQ(v.angle_increment_rad, wlr.angle_increment_rad);
    const bool differs =
        v.enable_footprint != wlr.enable_footprint || v.echo_choice != wlr.echo_choice ||
        v.echo_separation_m != wlr.echo_separation_m ||
        v.beam_divergence_rad != wlr.beam_divergence_rad ||
        v.footprint_rays != wlr.footprint_rays ||
        v.range_noise_sigma_m != wlr.range_noise_sigma_m ||
        v.range_noise_per_m != wlr.range_noise_per_m ||
        v.dropout_probability != wlr.dropout_probability ||
        v.stray_probability != wlr.stray_probability || v.range_bias_m != wlr.range_bias_m;
    EXPECT_TRUE(differs);
    ++variants;
  }
  EXPECT_GE(variants, 12);
}

}  // namespace
}  // namespace shelfdock::io
