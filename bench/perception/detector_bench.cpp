// Speed of Detector::Detect on 811-beam simulated WLR-716 scans (paper's sensor): one shelf in
// a room, three shelves side by side, a row of five, and 100 leg-like round posts around one
// shelf; and the 100 posts with the shelf gone and a preset where it stood (nothing is found
// near the preset, so the detector also tries to complete shelves from two legs). Targets
// (issue 7): medians <= 50 us for one shelf, <= 0.3 ms for a row of five, <= 0.5 ms with 100
// posts.
#include <optional>
#include <random>

#include <benchmark/benchmark.h>

#include "perception/detector.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

void RunDetect(benchmark::State& state, const sim::World& world,
               const std::optional<geometry::Pose2>& preset = std::nullopt) {
  const Detector detector(testing::PaperModels());
  const geometry::LaserScan scan = testing::SimScan(world, {}, 1);
  for (auto _ : state) {
    DetectionResult r = detector.Detect(scan, preset);
    benchmark::DoNotOptimize(r);
  }
}

void BM_DetectOneShelfInRoom(benchmark::State& state) {
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, testing::PaperModels()[1], {2.0, 0.2, 0.1});
  RunDetect(state, world);
}

void BM_DetectThreeShelves(benchmark::State& state) {
  sim::World world;
  testing::AddRoom(world);
  const auto model = testing::PaperModels()[3];
  for (int i = -1; i <= 1; ++i)
    world.AddShelf(i + 2, model, {2.2, i * (model.width_m + 0.34), 0.0});
  RunDetect(state, world);
}

// Five 1080x856 shelves side by side, 0.3 m apart, seen from 2 m in front of the middle one
// (no preset: every shelf and every phantom of neighbours' legs is considered).
void BM_DetectRowOfFive(benchmark::State& state) {
  sim::World world;
  testing::AddRoom(world);
  const auto model = testing::PaperModels()[3];
  for (int i = -2; i <= 2; ++i) {
    world.AddShelf(i + 3, model, {2.0 + 0.5 * model.length_m, i * (model.width_m + 0.34), 0.0});
  }
  RunDetect(state, world);
}

void AddHundredPosts(sim::World& world) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ux(0.5, 6.0), uy(-4.5, 4.5), ur(0.012, 0.025);
  for (int i = 0; i < 100; ++i) world.AddRoundPost({ux(rng), uy(rng)}, ur(rng));
}

void BM_DetectHundredPosts(benchmark::State& state) {
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, testing::PaperModels()[1], {2.0, 0.2, 0.1});
  AddHundredPosts(world);
  RunDetect(state, world);
}

void BM_DetectHundredPostsPresetNoShelf(benchmark::State& state) {
  sim::World world;
  testing::AddRoom(world);
  AddHundredPosts(world);
  RunDetect(state, world, geometry::Pose2(2.0, 0.2, 0.1));
}

BENCHMARK(BM_DetectOneShelfInRoom)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DetectThreeShelves)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DetectRowOfFive)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DetectHundredPosts)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DetectHundredPostsPresetNoShelf)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace shelfdock::perception
