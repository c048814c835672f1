// One render of the code under the shelf and one AprilTag detection of it, with the default
// camera (640 x 480, code 8 cm at 0.30 m). Report medians: run with
// --benchmark_repetitions=10 --benchmark_report_aggregates_only=true.
#include <benchmark/benchmark.h>

#include "perception/marker_detector.hpp"
#include "sim/marker_camera.hpp"

namespace {

using shelfdock::geometry::Pose2;

void BM_RenderMarker(benchmark::State& state) {
  const shelfdock::sim::CameraConfig camera;
  uint64_t seed = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        shelfdock::sim::RenderMarker(camera, 7, Pose2(0.02, -0.01, 0.1), ++seed));
  }
}
BENCHMARK(BM_RenderMarker)->Unit(benchmark::kMillisecond);

void BM_DetectMarker(benchmark::State& state) {
  shelfdock::sim::CameraConfig camera;
  shelfdock::perception::MarkerDetectorConfig config;
  config.quad_decimate = static_cast<double>(state.range(0));
  shelfdock::perception::MarkerDetector detector(config);
  const auto image = shelfdock::sim::RenderMarker(camera, 7, Pose2(0.02, -0.01, 0.1), 1);
  for (auto _ : state) {
    auto obs = detector.Detect(image, camera.camera);
    if (!obs) state.SkipWithError("code not found");
    benchmark::DoNotOptimize(obs);
  }
}
BENCHMARK(BM_DetectMarker)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_DetectEmptyImage(benchmark::State& state) {
  shelfdock::sim::CameraConfig camera;
  shelfdock::perception::MarkerDetector detector;
  const auto image = shelfdock::sim::RenderMarker(camera, 7, Pose2(2.0, 0.0, 0.0), 1);
  for (auto _ : state) benchmark::DoNotOptimize(detector.Detect(image, camera.camera));
}
BENCHMARK(BM_DetectEmptyImage)->Unit(benchmark::kMillisecond);

}  // namespace
