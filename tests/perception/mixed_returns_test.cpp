// Which of a leg's returns may be blends of the leg and the surface beyond its edge, and the
// weight the fits give their ranges.
#include "perception/mixed_returns.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::BeamPoint;

// Three returns on a leg 3 m away: the outer ones 5 cm behind the middle one.
std::vector<ScanPoint> BlendedLeg() {
  return {BeamPoint(10, 3.05), BeamPoint(11, 3.0), BeamPoint(12, 3.05)};
}

void ExpectNoBlend(const MixedEdges& mixed) {
  EXPECT_EQ(mixed.first_gap_m, 0.0);
  EXPECT_EQ(mixed.last_gap_m, 0.0);
}

TEST(MixedReturnsTest, OuterReturnsBehindTheLegWithASurfaceBeyondMayBeBlends) {
  SilhouetteEdges edges;
  edges.before_step_m = 0.1;
  edges.after_step_m = 0.3;
  const MixedEdges mixed = FindMixedEdges(BlendedLeg(), edges, 0.01);
  EXPECT_DOUBLE_EQ(mixed.Gap(0, 3), 0.1);
  EXPECT_DOUBLE_EQ(mixed.Gap(1, 3), 0.0);  // an inner return is the leg's
  EXPECT_DOUBLE_EQ(mixed.Gap(2, 3), 0.3);
}

TEST(MixedReturnsTest, NoBlendWithoutASurfaceBeyondOrAStepBehind) {
  // The beam beyond returned from something nearer (an occluder), or nothing.
  SilhouetteEdges occluded;
  occluded.before_step_m = -0.5;
  ExpectNoBlend(FindMixedEdges(BlendedLeg(), occluded, 0.01));
  // The outer returns no farther than their neighbour allows: the leg's own face.
  SilhouetteEdges edges;
  edges.before_step_m = 0.1;
  edges.after_step_m = 0.1;
  const std::vector<ScanPoint> flat = {BeamPoint(10, 3.005), BeamPoint(11, 3.0),
                                       BeamPoint(12, 3.008)};
  ExpectNoBlend(FindMixedEdges(flat, edges, 0.01));
  // One return: nothing tells a blend from the leg.
  ExpectNoBlend(FindMixedEdges({BeamPoint(10, 3.0)}, edges, 0.01));
  ExpectNoBlend(FindMixedEdges({}, edges, 0.01));
}

TEST(MixedReturnsTest, TheWeightFallsOnceTheNoiseNoLongerExplainsTheResidual) {
  const double sigma = 0.01, gap = 0.1, share = 0.5;
  // In front of the leg: a plain return; at the surface most likely one too.
  EXPECT_GT(MixedReturnSqrtWeight(-0.03, sigma, gap, share), 0.95);
  EXPECT_GT(MixedReturnSqrtWeight(0.0, sigma, gap, share), 0.9);
  // Three and five sigmas behind it: a blend.
  EXPECT_LT(MixedReturnSqrtWeight(0.03, sigma, gap, share), 0.5);
  EXPECT_LT(MixedReturnSqrtWeight(0.05, sigma, gap, share), 0.01);
  // Monotone behind the surface.
  double last = 1.0;
  for (double r = 0.0; r < 0.1; r += 0.005) {
    const double w = MixedReturnSqrtWeight(r, sigma, gap, share);
    EXPECT_LE(w, last + 1e-12) << r;
    last = w;
  }
  // Far out, where both densities underflow: still a weight, never NaN.
  EXPECT_EQ(MixedReturnSqrtWeight(-2.0, sigma, gap, share), 1.0);
  EXPECT_EQ(MixedReturnSqrtWeight(2.0, sigma, gap, share), 0.0);
  // Not a candidate, or blends off: full weight.
  EXPECT_EQ(MixedReturnSqrtWeight(0.05, sigma, 0.0, share), 1.0);
  EXPECT_EQ(MixedReturnSqrtWeight(0.05, sigma, gap, 0.0), 1.0);
}

}  // namespace
}  // namespace shelfdock::perception
