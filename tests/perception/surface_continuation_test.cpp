// ContinuesSurface (src/perception/surface_continuation.cpp): a leg-sized piece that only
// continues the surface of its beam neighbours (a wall at a grazing angle) is no leg. Exact
// synthetic points on the kWlrAlpha beam fan.
#include "perception/surface_continuation.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = testing::kWlrAlpha;
constexpr double kMaxStep = 0.25;    // [m]
constexpr double kMinChord = 0.1;    // [m]
constexpr double kTolerance = 0.02;  // [m]

// The return of beam `beam` on the line n . p = d with normal n at `normal_yaw`, exact.
ScanPoint OnWall(int beam, double normal_yaw, double d) {
  const double a = beam * kAlpha;
  return testing::BeamPoint(beam, d / std::cos(a - normal_yaw));
}

// A wall 0.15 rad off the beams at about 2.5 m (its returns about 10 cm apart): every single
// point between two others continues the wall.
TEST(SurfaceContinuationTest, GrazingWallPointsContinueTheWall) {
  constexpr double kNormalYaw = 105 * kAlpha + 0.5 * M_PI - 0.15;
  const double d = 2.5 * std::cos(0.5 * M_PI - 0.15);
  std::vector<ScanPoint> pts;
  for (int b = 100; b < 110; ++b) pts.push_back(OnWall(b, kNormalYaw, d));
  ASSERT_GT((pts[5].p - pts[4].p).norm(), 0.05);  // farther apart than the break distance
  ASSERT_LT((pts[5].p - pts[4].p).norm(), kMaxStep);
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    EXPECT_TRUE(ContinuesSurface(pts, i, i + 1, kMaxStep, kMinChord, kTolerance)) << i;
  }
  // The first and the last point lack a neighbour: nothing to continue.
  EXPECT_FALSE(ContinuesSurface(pts, 0, 1, kMaxStep, kMinChord, kTolerance));
  EXPECT_FALSE(ContinuesSurface(pts, 9, 10, kMaxStep, kMinChord, kTolerance));
}

// A leg 5 cm in front of a wall facing the sensor, fragments of one leg, a leg between two
// far neighbours, neighbours beyond a gap of two beams: none of them continues a surface.
TEST(SurfaceContinuationTest, LegsAreNotSurfaces) {
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 9; ++b) pts.push_back(testing::BeamPoint(b, b >= 3 && b < 6 ? 2.45 : 2.5));
  EXPECT_FALSE(ContinuesSurface(pts, 3, 6, kMaxStep, kMinChord, kTolerance));
  // The same 5 cm with a tolerance of 6 cm (high range noise) and a chord as short as these
  // neighbours' 6 cm: taken for the wall.
  EXPECT_TRUE(ContinuesSurface(pts, 3, 6, kMaxStep, 0.05, 0.06));
  // Three fragments of one 4 cm leg at 2 m (noise broke it): the neighbours are 2.3 cm apart,
  // less than a leg, so the middle fragment is not taken for a surface.
  pts.clear();
  for (int b = 0; b < 3; ++b) pts.push_back(testing::BeamPoint(b, 2.0));
  EXPECT_FALSE(ContinuesSurface(pts, 1, 2, kMaxStep, kMinChord, kTolerance));
  // A leg at 2 m between neighbours 0.5 m away on either side (a far wall behind it) that happen
  // to lie on a line with it: too far to be one surface.
  pts = {testing::BeamPoint(0, 1.5), testing::BeamPoint(1, 2.0), testing::BeamPoint(2, 2.5)};
  EXPECT_FALSE(ContinuesSurface(pts, 1, 2, kMaxStep, kMinChord, kTolerance));
  EXPECT_TRUE(ContinuesSurface(pts, 1, 2, 0.6, kMinChord, 0.05));  // allowed that far: a surface
  // Neighbours two beams away (two returns missing in between) are not taken as the surface.
  constexpr double kNormalYaw = 105 * kAlpha + 0.5 * M_PI - 0.15;
  const double d = 2.5 * std::cos(0.5 * M_PI - 0.15);
  pts.clear();
  for (const int b : {100, 103, 104, 107}) pts.push_back(OnWall(b, kNormalYaw, d));
  EXPECT_FALSE(ContinuesSurface(pts, 1, 3, 1.0, kMinChord, kTolerance));
  // One return missing on either side is still the same surface.
  pts.clear();
  for (const int b : {100, 102, 103, 105}) pts.push_back(OnWall(b, kNormalYaw, d));
  EXPECT_TRUE(ContinuesSurface(pts, 1, 3, 1.0, kMinChord, kTolerance));
}

}  // namespace
}  // namespace shelfdock::perception
