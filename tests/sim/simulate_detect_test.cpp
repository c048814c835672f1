// End to end: scans of the paper's docking scenario from the simulated WLR-716 (every flaw on)
// fed to the detector, scored against the scenario's ground truth.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"
#include "io/models_yaml.hpp"
#include "io/scenario_yaml.hpp"
#include "perception/detector.hpp"
#include "sim/lidar.hpp"

namespace shelfdock {
namespace {

const std::string kRoot = SHELFDOCK_SOURCE_DIR;

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

TEST(SimulateDetectTest, PaperScenarioShelfFoundWithinDetectorFigures) {
  const auto models = io::ReadShelfModels(kRoot + "/config/models.yaml");
  const sim::Scenario scenario =
      io::ReadScenario(kRoot + "/config/scenarios/paper_docking.yaml", models);
  const perception::Detector detector(models);
  const sim::ScenarioShelf& shelf = *scenario.FindShelf(scenario.target_shelf_id);
  const geometry::Pose2 T_map_preset = *scenario.PresetPose(shelf.id, 1);

  // The LiDAR along the approach, 1 to 3.5 m from the shelf centre, a little off the axis and
  // turned, as a robot driving in from the docking area's entry would see it.
  std::vector<double> centre_err, yaw_err;
  int scans = 0, found = 0;
  std::uint64_t seed = 1;
  for (double distance : {1.0, 1.5, 2.0, 2.5, 3.0, 3.5}) {
    for (double lateral : {-0.1, 0.0, 0.1}) {
      const geometry::Pose2 T_map_lidar =
          shelf.T_map_shelf * geometry::Pose2(-distance, lateral, 0.03 * lateral / 0.1);
      sim::Lidar lidar(sim::LidarConfig{}, seed++);
      for (int k = 0; k < 4; ++k) {
        const auto scan = lidar.Scan(scenario.world, T_map_lidar, k / 15.0);
        const geometry::Pose2 T_lidar_map = T_map_lidar.inverse();
        const auto result = detector.Detect(scan, T_lidar_map * T_map_preset);
        ++scans;
        if (result.detections.empty() || result.detections[0].model != shelf.model_name) {
          // Dark legs drop beams (dropouts) and give one or two returns each beyond 2.5 m: a
          // single scan may miss the shelf there; the docking loop re-detects every scan.
          EXPECT_GT(distance, 2.5)
              << "no " << shelf.model_name << " at distance " << distance << " lateral " << lateral;
          continue;
        }
        ++found;
        const geometry::Pose2 truth = T_lidar_map * shelf.T_map_shelf;
        const geometry::Pose2& d = result.detections[0].T_lidar_shelf;
        centre_err.push_back(geometry::Distance(d, truth));
        yaw_err.push_back(std::abs(geometry::AngleDiff(d.yaw, truth.yaw)));
        // The detector's single-scan figures (tests/perception): 20 mm, 30 mrad up to 4 m.
        EXPECT_LT(centre_err.back(), 0.02) << "distance " << distance << " lateral " << lateral;
        EXPECT_LT(yaw_err.back(), 0.03) << "distance " << distance << " lateral " << lateral;
      }
    }
  }
  ASSERT_FALSE(centre_err.empty());
  // The detector's figures (issue 2): the right shelf in >= 98 % of scans, centre error p95
  // <= 10 mm and heading error p95 <= 10 mrad within 3.5 m. Measured (3a6d954): 72/72, max 7.6
  // mm, 8.3 mrad.
  EXPECT_GE(found, 0.98 * scans);
  auto p95 = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(0.95 * static_cast<double>(v.size() - 1) + 0.5)];
  };
  EXPECT_LE(p95(centre_err), 0.010);
  EXPECT_LE(p95(yaw_err), 0.010);
  std::printf(
      "[ sim->detect ] %d/%d found; centre error median %.4f max %.4f m; yaw error "
      "median %.4f max %.4f rad\n",
      found, scans, Median(centre_err), *std::max_element(centre_err.begin(), centre_err.end()),
      Median(yaw_err), *std::max_element(yaw_err.begin(), yaw_err.end()));
}

}  // namespace
}  // namespace shelfdock
