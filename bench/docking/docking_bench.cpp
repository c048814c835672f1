// Cost of the docking layer per control step: Docker::Step with a fresh scan (motion
// compensation, detection, fusion, re-plan check, obstacle check), Docker::Step without a scan
// (path tracking only), and the path planner. Scene: the paper's docking set-up, the robot at
// the docking area's entry 4.5 m in front of shelf 2, the WLR-716 LiDAR.
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "docking/docker.hpp"
#include "docking/path_planner.hpp"
#include "io/models_yaml.hpp"
#include "io/scenario_yaml.hpp"
#include "perception/detector.hpp"
#include "sim/lidar.hpp"

namespace {

using namespace shelfdock;
using geometry::Pose2;

struct Scene {
  std::vector<geometry::ShelfModel> models =
      io::ReadShelfModels(std::string(SHELFDOCK_SOURCE_DIR) + "/config/models.yaml");
  sim::Scenario scenario = io::ReadScenario(
      std::string(SHELFDOCK_SOURCE_DIR) + "/config/scenarios/paper_docking.yaml", models);
  docking::DockingConfig config;
  docking::DockingTask task;
  perception::Detector detector{models, perception::DetectorConfig{}};
  geometry::LaserScan scan;
  Pose2 T_map_entry;  ///< on the shelf axis, entry_distance_m before the preset goal

  Scene() {
    task.shelf_id = scenario.target_shelf_id;
    task.T_map_shelf_preset = scenario.PresetPose(task.shelf_id, 1).value_or(Pose2());
    const std::string model_name = scenario.FindShelf(task.shelf_id)->model_name;
    for (const auto& m : models) {
      if (m.name == model_name) task.model = m;
    }
    // The scenario starts the approach before the entry; the benchmark stands at the entry so
    // that the Docker is in its docking stage and every scan goes through detection.
    T_map_entry = task.T_map_shelf_preset * Pose2(-config.entry_distance_m, 0.0, 0.0);
    sim::Lidar lidar(sim::LidarConfig{}, 1);
    const Pose2 T_world_lidar = T_map_entry * config.T_base_lidar;
    scan = lidar.Scan(
        scenario.world, [&](double) { return T_world_lidar; }, 0.0);
  }

  std::unique_ptr<docking::Docker> StartDocker() const {
    auto docker = std::make_unique<docking::Docker>(
        config, task, docking::Method::kContinuous,
        [this](const std::vector<perception::ScanPoint>& points, double increment,
               const std::optional<Pose2>& preset) {
          return detector.DetectPoints(points, increment, preset);
        });
    docking::Observations obs;
    obs.T_odom_base = T_map_entry;
    obs.T_map_base_estimate = T_map_entry;
    docker->Step(obs);
    return docker;
  }
};

/// One control step with a scan, standing at the entry (the robot does not move, so every
/// scan is recognised; a fresh Docker every 300 steps keeps it far from its timeout).
void BM_DockerStepWithScan(benchmark::State& state) {
  const Scene scene;
  std::unique_ptr<docking::Docker> docker;
  docking::Observations obs;
  obs.T_odom_base = scene.T_map_entry;
  obs.T_map_base_estimate = obs.T_odom_base;
  int n = 0;
  for (auto _ : state) {
    if (n++ % 300 == 0) {
      state.PauseTiming();
      docker = scene.StartDocker();
      obs.t_s = 0.0;
      state.ResumeTiming();
    }
    obs.t_s += scene.scan.scan_time > 0.0 ? scene.scan.scan_time : 1.0 / 15.0;
    obs.scan = &scene.scan;
    benchmark::DoNotOptimize(docker->Step(obs));
  }
  state.counters["detections"] = docker->detections();
}
BENCHMARK(BM_DockerStepWithScan)->Unit(benchmark::kMicrosecond);

/// One control step without a scan while driving in (a unicycle integrates the commands):
/// path tracking and the checks only. The scan timeouts are lifted so the Docker keeps driving.
void BM_DockerStepWithoutScan(benchmark::State& state) {
  Scene scene;
  scene.config.scan_timeout_s = 1e9;
  scene.config.detection_lost_s = 1e9;
  std::unique_ptr<docking::Docker> docker;
  docking::Observations obs;
  int n = 0;
  for (auto _ : state) {
    if (n++ % 200 == 0) {
      state.PauseTiming();
      docker = scene.StartDocker();
      obs.t_s = 0.0;
      obs.T_odom_base = scene.T_map_entry;
      state.ResumeTiming();
    }
    obs.t_s += 0.02;
    obs.T_map_base_estimate = obs.T_odom_base;
    const docking::Command cmd = docker->Step(obs);
    obs.T_odom_base =
        obs.T_odom_base * Pose2(cmd.velocity.v_mps * 0.02, 0.0, cmd.velocity.w_radps * 0.02);
  }
  state.counters["phase_dock"] = docker->phase() == docking::Phase::kDock ? 1.0 : 0.0;
}
BENCHMARK(BM_DockerStepWithoutScan)->Unit(benchmark::kMicrosecond);

/// The planner from the entry (4.5 m, the shelf 4 cm / 0.03 rad off) and from a re-plan close
/// in (1 m to go, 3 cm lateral and 0.05 rad heading error).
void BM_PlanDockingPath(benchmark::State& state) {
  const docking::PlannerConfig config;
  const Pose2 goal(5.5, 2.0, 0.0);
  const Pose2 start = state.range(0) == 0 ? Pose2(1.0, 2.04, -0.03) : Pose2(4.5, 2.03, 0.05);
  for (auto _ : state) {
    benchmark::DoNotOptimize(docking::PlanDockingPath(start, goal, config));
  }
}
BENCHMARK(BM_PlanDockingPath)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
