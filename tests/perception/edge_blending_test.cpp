// EstimateEdgeBlending (src/perception/edge_blending.cpp): how many large depth steps a scan
// bridges with one mixed return. Synthetic returns for the counting rules; the simulator's
// LiDAR for the two kinds of receiver it tells apart (sim::LidarConfig::echo_separation_m: a
// pulsed receiver that separates echoes more than 0.5 m apart, and one that blends every echo of
// a beam, as config/lidar_variants/blend_any.yaml).
#include "perception/edge_blending.hpp"

#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "perception/detector.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kGap = 0.6;   // [m] a large step
constexpr double kFlat = 0.1;  // [m] a surface goes on within this

// Returns on beams first, first + 1, ... at `ranges`.
std::vector<ScanPoint> Returns(int first, const std::vector<double>& ranges) {
  std::vector<ScanPoint> out;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    out.push_back(testing::BeamPoint(first + static_cast<int>(i), ranges[i]));
  }
  return out;
}

TEST(EdgeBlendingTest, ACleanStepCountsAsAStep) {
  const auto e = EstimateEdgeBlending(Returns(0, {2.0, 2.0, 2.0, 5.0, 5.0, 5.0}), kGap, kFlat);
  EXPECT_EQ(e.steps, 1);
  EXPECT_EQ(e.bridged, 0);
  EXPECT_DOUBLE_EQ(e.Share(), 0.0);
  EXPECT_DOUBLE_EQ(e.widest_bridged_m, 0.0);
  EXPECT_DOUBLE_EQ(e.widest_bridged_twice_m, 0.0);
}

TEST(EdgeBlendingTest, OneReturnBetweenTheSurfacesBridgesTheStep) {
  // Either way round (near to far, far to near).
  for (const auto& ranges : {std::vector<double>{2.0, 2.0, 2.0, 3.4, 5.0, 5.0, 5.0},
                             std::vector<double>{5.0, 5.0, 5.0, 3.4, 2.0, 2.0, 2.0}}) {
    const auto e = EstimateEdgeBlending(Returns(10, ranges), kGap, kFlat);
    EXPECT_EQ(e.steps, 0);
    EXPECT_EQ(e.bridged, 1);
    EXPECT_DOUBLE_EQ(e.Share(), 1.0);
    EXPECT_DOUBLE_EQ(e.widest_bridged_m, 3.0);        // the surfaces' depth apart
    EXPECT_DOUBLE_EQ(e.widest_bridged_twice_m, 0.0);  // bridged once only
  }
}

TEST(EdgeBlendingTest, KeepsTheWidestBridgedStepAndTheWidestBridgedTwice) {
  // Two bridged steps, 1.2 m and 3 m deep, and a clean one of 4 m: the widest bridged is 3 m, the
  // widest bridged twice 1.2 m (both steps are at least that deep).
  std::vector<double> ranges{2.0, 2.0, 2.0, 2.6, 3.2, 3.2, 3.2, 4.5, 6.2, 6.2, 6.2, 2.2, 2.2, 2.2};
  auto e = EstimateEdgeBlending(Returns(0, ranges), kGap, kFlat);
  EXPECT_EQ(e.bridged, 2);
  EXPECT_EQ(e.steps, 1);
  EXPECT_NEAR(e.widest_bridged_m, 3.0, 1e-12);
  EXPECT_NEAR(e.widest_bridged_twice_m, 1.2, 1e-12);
  // A third, 2 m deep: now two steps of 2 m or more.
  for (const double r : {3.2, 4.2, 4.2, 4.2}) ranges.push_back(r);
  e = EstimateEdgeBlending(Returns(0, ranges), kGap, kFlat);
  EXPECT_EQ(e.bridged, 3);
  EXPECT_NEAR(e.widest_bridged_m, 3.0, 1e-12);
  EXPECT_NEAR(e.widest_bridged_twice_m, 2.0, 1e-9);
}

TEST(EdgeBlendingTest, AReturnOnEitherSurfaceIsNoBridge) {
  // Within kFlat of the near surface: that surface goes on, then a clean step.
  const auto e =
      EstimateEdgeBlending(Returns(0, {2.0, 2.0, 2.0, 2.05, 5.0, 5.0, 5.0}), kGap, kFlat);
  EXPECT_EQ(e.steps, 1);
  EXPECT_EQ(e.bridged, 0);
}

TEST(EdgeBlendingTest, SmallStepsDropoutsAndObliqueSurfacesAreNotCounted) {
  // A step smaller than kGap.
  auto e = EstimateEdgeBlending(Returns(0, {2.0, 2.0, 2.0, 2.4, 2.4, 2.4}), kGap, kFlat);
  EXPECT_EQ(e.steps + e.bridged, 0);
  // A beam without a return at the step: its neighbours are no neighbours.
  std::vector<ScanPoint> gap = Returns(0, {2.0, 2.0, 2.0});
  for (const ScanPoint& q : Returns(4, {5.0, 5.0, 5.0})) gap.push_back(q);
  e = EstimateEdgeBlending(gap, kGap, kFlat);
  EXPECT_EQ(e.steps + e.bridged, 0);
  // A surface seen obliquely: ranges grow by more than kFlat per beam, so no surface "goes on".
  e = EstimateEdgeBlending(Returns(0, {2.0, 2.2, 2.4, 3.1, 3.3, 3.5}), kGap, kFlat);
  EXPECT_EQ(e.steps + e.bridged, 0);
  // Too few returns for a step.
  e = EstimateEdgeBlending(Returns(0, {2.0, 5.0, 5.0}), kGap, kFlat);
  EXPECT_EQ(e.steps + e.bridged, 0);
  EXPECT_DOUBLE_EQ(e.Share(), 0.0);
}

// Twelve 40 mm posts 1.5-3.5 m from the sensor before the walls of a room (3-5 m behind them):
// 24 large steps in view. The simulator's default receiver separates the post's and the wall's
// echoes, so a step's edge beam returns one of them: few steps are bridged (a beam whose
// footprint sees a post and the wall and neither echo alone is strong enough drops out, or the
// post's weaker echo wins). A receiver that blends every echo returns their energy-weighted mean
// at nearly every edge. The detector reports both counts in its stats.
TEST(EdgeBlendingTest, TellsABlendingReceiverFromASeparatingOne) {
  sim::World world;
  testing::AddRoom(world);
  for (int i = 0; i < 12; ++i) {
    const double a = -1.2 + 0.2 * i;
    const double r = 1.5 + 0.17 * i;
    world.AddRoundPost({r * std::cos(a), r * std::sin(a)}, 0.02);
  }
  const auto models = testing::PaperModels();
  const Detector detector(models);
  sim::LidarConfig separating;  // the WLR-716 defaults: echoes > 0.5 m apart separate
  sim::LidarConfig blending;
  blending.echo_separation_m = 100.0;
  for (std::uint64_t seed : {31u, 32u, 33u}) {
    const auto sep_scan = testing::SimScan(world, {}, seed, separating);
    const auto blend_scan = testing::SimScan(world, {}, seed, blending);
    const auto sep = EstimateEdgeBlending(ScanToPoints(sep_scan), kGap, kFlat);
    const auto blend = EstimateEdgeBlending(ScanToPoints(blend_scan), kGap, kFlat);
    std::printf("[ edge blending ] seed %d: separating %d steps %d bridged, blending %d / %d\n",
                static_cast<int>(seed), sep.steps, sep.bridged, blend.steps, blend.bridged);
    EXPECT_GE(sep.steps + sep.bridged, 16);
    EXPECT_LT(sep.Share(), 0.2);
    EXPECT_GE(blend.bridged, 12);
    EXPECT_GT(blend.Share(), 0.6);
    // The detector's stats count the same (its config's large step is kGap).
    const DetectionResult r = detector.Detect(blend_scan);
    EXPECT_EQ(r.stats.depth_steps, blend.steps);
    EXPECT_EQ(r.stats.bridged_steps, blend.bridged);
  }
}

}  // namespace
}  // namespace shelfdock::perception
