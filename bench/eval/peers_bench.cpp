// Speed of shelfdock's detector and the peers of `eval peers` on the same seeded 811-beam
// WLR-716 scans: the paper's set-up (shelf 2, 0.5 m before its front legs, preset given) and one
// shelf among 30 leg-like posts (no preset). The leg search alone, pruned against exhaustive,
// on clutter of 10, 30, 50 and 100 posts (all leg candidates, no region of interest).
#include <benchmark/benchmark.h>

#include "eval/peer_scenes.hpp"
#include "eval/peers/centroid_peer.hpp"
#include "eval/peers/corner_peer.hpp"
#include "eval/peers/exhaustive_leg_search.hpp"
#include "paper_models.hpp"
#include "perception/detector.hpp"
#include "perception/leg_search.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::eval {
namespace {

std::vector<geometry::ShelfModel> Models() { return testing::PaperModels(); }

PeerScenesConfig OneScene() {
  PeerScenesConfig c;
  c.paper_per_model = 1;
  c.clutter_scenes = 1;
  return c;
}

/// Shelf 2 of the paper's set-up (the second model's first scan), with its preset.
PeerScene PaperScene() { return PaperSetupScenes(Models(), {}, OneScene()).scenes[1]; }

/// One shelf and `posts` posts, without the preset (every candidate is searched).
PeerScene ClutterScene(int posts) {
  PeerScene s = ClutterScenes(Models(), {}, posts, OneScene()).scenes[0];
  s.T_lidar_preset.reset();
  return s;
}

enum Method { kShelfdock, kCentroid, kCorner };

void RunMethod(benchmark::State& state, const PeerScene& scene, Method method) {
  const auto models = Models();
  const perception::DetectorConfig config;
  const perception::Detector detector(models, config);
  for (auto _ : state) {
    switch (method) {
      case kShelfdock:
        benchmark::DoNotOptimize(detector.Detect(scene.scan, scene.T_lidar_preset));
        break;
      case kCentroid:
        benchmark::DoNotOptimize(
            peers::CentroidPeerDetect(scene.scan, scene.T_lidar_preset, models, config));
        break;
      case kCorner:
        benchmark::DoNotOptimize(
            peers::CornerPeerDetect(scene.scan, scene.T_lidar_preset, models, config));
        break;
    }
  }
}

void BM_PaperSetup_Shelfdock(benchmark::State& s) { RunMethod(s, PaperScene(), kShelfdock); }
void BM_PaperSetup_CentroidOnly(benchmark::State& s) { RunMethod(s, PaperScene(), kCentroid); }
void BM_PaperSetup_CornerFinding(benchmark::State& s) { RunMethod(s, PaperScene(), kCorner); }
void BM_Clutter30_Shelfdock(benchmark::State& s) { RunMethod(s, ClutterScene(30), kShelfdock); }
void BM_Clutter30_CentroidOnly(benchmark::State& s) { RunMethod(s, ClutterScene(30), kCentroid); }
void BM_Clutter30_CornerFinding(benchmark::State& s) { RunMethod(s, ClutterScene(30), kCorner); }

std::vector<Eigen::Vector2d> Candidates(const PeerScene& scene) {
  const perception::PreprocessOutput pre =
      perception::Preprocess(perception::ScanToPoints(scene.scan), scene.scan.angle_increment,
                             std::nullopt, Models(), perception::PreprocessConfig{});
  std::vector<Eigen::Vector2d> centres;
  for (const auto& c : pre.candidates) centres.push_back(c.centroid);
  return centres;
}

void RunSearch(benchmark::State& state, bool exhaustive) {
  const auto models = Models();
  const auto centres = Candidates(ClutterScene(static_cast<int>(state.range(0))));
  perception::LegSearchConfig config;
  config.max_leg_sets = 1 << 30;
  perception::LegSearchCounts counts;
  for (auto _ : state) {
    counts = {};
    benchmark::DoNotOptimize(exhaustive
                                 ? peers::ExhaustiveLegSets(centres, models, config, &counts)
                                 : perception::SearchLegSets(centres, models, config, &counts));
  }
  state.counters["candidates"] = static_cast<double>(centres.size());
  state.counters["checks"] = static_cast<double>(counts.checks);
}

void BM_LegSearch_Pruned(benchmark::State& s) { RunSearch(s, false); }
void BM_LegSearch_Exhaustive(benchmark::State& s) { RunSearch(s, true); }

BENCHMARK(BM_PaperSetup_Shelfdock)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperSetup_CentroidOnly)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PaperSetup_CornerFinding)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Clutter30_Shelfdock)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Clutter30_CentroidOnly)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Clutter30_CornerFinding)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LegSearch_Pruned)->Arg(10)->Arg(30)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LegSearch_Exhaustive)
    ->Arg(10)
    ->Arg(30)
    ->Arg(50)
    ->Arg(100)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace shelfdock::eval
