// The outline edges of a cluster read from its neighbouring beams: seen where the next beam out
// passed beside the object, unknown where it returned nothing or something nearer.
#include "perception/silhouette_edges.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::BeamPoint;
using testing::kWlrAlpha;

constexpr double kMinDepth = 0.1;

// Beams 0-9: a wall at 3 m on beams 0-2, a leg at 1 m on beams 3-6, then `after` on beam 7
// (nothing when it is empty) and the wall again on beams 8-9.
std::vector<ScanPoint> Scan(std::optional<double> after) {
  std::vector<ScanPoint> points;
  for (int b = 0; b <= 2; ++b) points.push_back(BeamPoint(b, 3.0));
  for (int b = 3; b <= 6; ++b) points.push_back(BeamPoint(b, 1.0));
  if (after) points.push_back(BeamPoint(7, *after));
  for (int b = 8; b <= 9; ++b) points.push_back(BeamPoint(b, 3.0));
  return points;
}

TEST(SilhouetteEdgesTest, BackgroundOnBothSidesGivesBothEdgesHalfwayToTheNextBeam) {
  const auto points = Scan(3.0);
  const SilhouetteEdges edges = FindSilhouetteEdges(points, points[3], points[6], kMinDepth);
  ASSERT_TRUE(edges.before_rad.has_value());
  ASSERT_TRUE(edges.after_rad.has_value());
  EXPECT_NEAR(*edges.before_rad, 2.5 * kWlrAlpha, 1e-12);
  EXPECT_NEAR(*edges.after_rad, 6.5 * kWlrAlpha, 1e-12);
}

TEST(SilhouetteEdgesTest, ADropoutBesideTheObjectLeavesThatSideOpen) {
  const auto points = Scan(std::nullopt);
  const SilhouetteEdges edges = FindSilhouetteEdges(points, points[3], points[6], kMinDepth);
  ASSERT_TRUE(edges.before_rad.has_value());
  EXPECT_NEAR(*edges.before_rad, 2.5 * kWlrAlpha, 1e-12);
  EXPECT_FALSE(edges.after_rad.has_value());
}

TEST(SilhouetteEdgesTest, SomethingNearerOrJustBehindLeavesThatSideOpen) {
  // An occluder at 0.6 m on beam 7: the leg may go on behind it.
  const auto nearer = Scan(0.6);
  EXPECT_FALSE(FindSilhouetteEdges(nearer, nearer[3], nearer[6], kMinDepth).after_rad);
  // A return only 5 cm behind the leg's edge point is not clearly beside it.
  const auto close = Scan(1.05);
  EXPECT_FALSE(FindSilhouetteEdges(close, close[3], close[6], kMinDepth).after_rad);
}

// How far behind the object the next beam out returned, kept whatever it was: 2 m to the wall
// before the leg; after it 0.2 m (a background close behind, where a thin leg's echo may have
// blended with it), -0.4 m (an occluder) or nothing (a dropout).
TEST(SilhouetteEdgesTest, TheDepthStepToTheNextBeamOutIsKept) {
  for (const double after : {1.2, 0.6}) {
    const auto points = Scan(after);
    const SilhouetteEdges edges = FindSilhouetteEdges(points, points[3], points[6], kMinDepth);
    ASSERT_TRUE(edges.before_step_m.has_value());
    EXPECT_NEAR(*edges.before_step_m, 2.0, 1e-12);
    ASSERT_TRUE(edges.after_step_m.has_value());
    EXPECT_NEAR(*edges.after_step_m, after - 1.0, 1e-12);
  }
  const auto dropout = Scan(std::nullopt);
  EXPECT_FALSE(FindSilhouetteEdges(dropout, dropout[3], dropout[6], kMinDepth).after_step_m);
}

TEST(SilhouetteEdgesTest, AnOccluderOrTheScansEndCutsASideADropoutDoesNot) {
  const auto nearer = Scan(0.6);
  const SilhouetteEdges occluded = FindSilhouetteEdges(nearer, nearer[3], nearer[6], kMinDepth);
  EXPECT_TRUE(occluded.after_cut);
  EXPECT_FALSE(occluded.before_cut);  // the wall beyond: an edge seen
  const auto dropout = Scan(std::nullopt);
  const SilhouetteEdges dropped = FindSilhouetteEdges(dropout, dropout[3], dropout[6], kMinDepth);
  EXPECT_FALSE(dropped.after_rad);
  EXPECT_FALSE(dropped.after_cut);
  // The leg on the scan's first beams: nothing before beam 0.
  std::vector<ScanPoint> points;
  for (int b = 0; b <= 3; ++b) points.push_back(BeamPoint(b, 1.0));
  points.push_back(BeamPoint(4, 3.0));
  const SilhouetteEdges at_start = FindSilhouetteEdges(points, points[0], points[3], kMinDepth);
  EXPECT_TRUE(at_start.before_cut);
  EXPECT_FALSE(at_start.after_cut);
  // ... and on its last return: nothing after it either.
  const SilhouetteEdges at_end = FindSilhouetteEdges(points, points[4], points[4], kMinDepth);
  EXPECT_TRUE(at_end.after_cut);
}

TEST(SilhouetteEdgesTest, TheScanEndsLeaveTheSidesOpenAndReversedOrderSwapsThem) {
  std::vector<ScanPoint> points;
  for (int b = 0; b <= 3; ++b) points.push_back(BeamPoint(b, 1.0));
  points.push_back(BeamPoint(4, 3.0));
  const SilhouetteEdges edges = FindSilhouetteEdges(points, points[0], points[3], kMinDepth);
  EXPECT_FALSE(edges.before_rad.has_value());
  ASSERT_TRUE(edges.after_rad.has_value());
  EXPECT_NEAR(*edges.after_rad, 3.5 * kWlrAlpha, 1e-12);
  // Given last-to-first, "before" is the side of the first point passed in.
  const SilhouetteEdges reversed = FindSilhouetteEdges(points, points[3], points[0], kMinDepth);
  ASSERT_TRUE(reversed.before_rad.has_value());
  EXPECT_NEAR(*reversed.before_rad, 3.5 * kWlrAlpha, 1e-12);
  EXPECT_FALSE(reversed.after_rad.has_value());
}

}  // namespace
}  // namespace shelfdock::perception
