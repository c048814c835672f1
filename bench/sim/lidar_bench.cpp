// One simulated LiDAR scan of the scenarios in config/scenarios (issue 3: "well under a
// millisecond" for an 811-beam scan of a warehouse aisle). Run with
//   build/bin/sim_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <string>

#include <benchmark/benchmark.h>

#include "io/models_yaml.hpp"
#include "io/scenario_yaml.hpp"
#include "sim/lidar.hpp"

namespace shelfdock::sim {
namespace {

Scenario Load(const std::string& name) {
  const std::string root = SHELFDOCK_SOURCE_DIR;
  return io::ReadScenario(root + "/config/scenarios/" + name + ".yaml",
                          io::ReadShelfModels(root + "/config/models.yaml"));
}

/// `state.range(0)`: 1 = every flaw on (WLR-716 defaults), 0 = ideal ray casting only,
/// 2 = every flaw but the beam footprint (which casts extra sub-rays at depth edges).
void ScanScenario(benchmark::State& state, const std::string& name, const geometry::Pose2& pose) {
  const Scenario scenario = Load(name);
  LidarConfig config = state.range(0) != 0 ? LidarConfig{} : IdealLidarConfig();
  if (state.range(0) == 2) config.enable_footprint = false;
  Lidar lidar(config, 1);
  double t = 0.0;
  for (auto _ : state) {
    auto scan = lidar.Scan(scenario.world, pose, t);
    benchmark::DoNotOptimize(scan.ranges.data());
    t += config.ScanPeriod();
  }
  state.counters["beams"] = config.num_beams;
  state.counters["primitives"] =
      static_cast<double>(scenario.world.static_grid().primitives().size());
}

void BM_ScanWarehouseAisle(benchmark::State& state) {
  ScanScenario(state, "warehouse_aisle", geometry::Pose2(-2.0, 0.0, 0.0));
}
void BM_ScanClutteredDock(benchmark::State& state) {
  ScanScenario(state, "cluttered_dock", geometry::Pose2(0.0, 0.0, 0.0));
}
void BM_ScanPaperDocking(benchmark::State& state) {
  ScanScenario(state, "paper_docking", geometry::Pose2(1.0, 2.0, 0.0));
}

BENCHMARK(BM_ScanWarehouseAisle)->Arg(1)->Arg(0)->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScanClutteredDock)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScanPaperDocking)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace shelfdock::sim
