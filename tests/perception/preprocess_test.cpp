// Paper 3.1 stage tests: points, Eq. 1 trailing filter, clustering, ROI and size screening.
#include "perception/preprocess.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = 0.005817764173314432;  // WLR-716: 1/3 degree

ScanPoint At(int beam, double range) {
  const double a = beam * kAlpha;
  return {Eigen::Vector2d(range * std::cos(a), range * std::sin(a)), range, a, beam};
}

TEST(PreprocessTest, ScanToPointsSkipsInvalidReturns) {
  geometry::LaserScan scan;
  scan.angle_min = -0.5;
  scan.angle_increment = 0.25;
  scan.range_min = 0.05;
  scan.range_max = 10.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  scan.ranges = {2.0, nan, inf, 0.0, 0.01, 11.0, 3.0};
  const auto points = ScanToPoints(scan);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].beam, 0);
  EXPECT_EQ(points[1].beam, 6);
  // Beam 6 at -0.5 + 6 * 0.25 = 1.0 rad, range 3.
  EXPECT_NEAR(points[1].p.x(), 3.0 * std::cos(1.0), 1e-12);
  EXPECT_NEAR(points[1].p.y(), 3.0 * std::sin(1.0), 1e-12);
  scan.ranges = {nan, nan, -1.0};
  EXPECT_TRUE(ScanToPoints(scan).empty());
  scan.ranges.clear();
  EXPECT_TRUE(ScanToPoints(scan).empty());
}

TEST(PreprocessTest, TrailingAngleMatchesEquationOne) {
  // Equal ranges: the triangle O-A-B is isosceles, beta = (pi - alpha) / 2.
  EXPECT_NEAR(TrailingAngle(2.0, 2.0, kAlpha), 0.5 * (M_PI - kAlpha), 1e-12);
  // Eq. 1 directly, OA = 3, OB = 2.
  const double expected = std::atan(2.0 * std::sin(kAlpha) / (3.0 - 2.0 * std::cos(kAlpha)));
  EXPECT_NEAR(TrailingAngle(3.0, 2.0, kAlpha), expected, 1e-12);
  // A far point right behind its neighbour leaves almost no angle.
  EXPECT_LT(TrailingAngle(5.0, 2.0, kAlpha), 0.01);
}

TEST(PreprocessTest, TrailingFilterDropsTheFartherPointOfADepthJump) {
  // A leg at 2 m (beams 10-14), a mixed point at 3 m (beam 15), the wall at 5 m (16-20).
  std::vector<ScanPoint> pts;
  for (int b = 10; b <= 14; ++b) pts.push_back(At(b, 2.0 + 0.002 * (b % 2)));
  pts.push_back(At(15, 3.0));
  for (int b = 16; b <= 20; ++b) pts.push_back(At(b, 5.0));
  const PreprocessConfig config;
  const int removed = RemoveTrailingPoints(pts, kAlpha, config);
  // The mixed point and the first wall point (both the far side of a jump) go; the leg stays.
  EXPECT_EQ(removed, 2);
  for (const auto& q : pts) EXPECT_NE(q.beam, 15);
  int leg = 0;
  for (const auto& q : pts) leg += q.range < 2.1;
  EXPECT_EQ(leg, 5);
  // Range noise on one surface is no depth edge.
  std::vector<ScanPoint> wall;
  for (int b = 0; b < 20; ++b) wall.push_back(At(b, 0.5 + 0.01 * (b % 3)));
  EXPECT_EQ(RemoveTrailingPoints(wall, kAlpha, config), 0);
  std::vector<ScanPoint> one{At(0, 1.0)};
  EXPECT_EQ(RemoveTrailingPoints(one, kAlpha, config), 0);
}

TEST(PreprocessTest, ClustersSplitAtGapsAndLongHoles) {
  const PreprocessConfig config;
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 5; ++b) pts.push_back(At(b, 2.0));
  for (int b = 5; b < 10; ++b) pts.push_back(At(b, 2.5));  // 0.5 m depth step
  // Two dropped beams inside one surface: still one cluster.
  for (int b = 12; b < 15; ++b) pts.push_back(At(b, 2.5));
  // Docking report (a): no wall behind the shelf, the next return is 60 beams on at the same
  // range (another leg, 0.7 m away). A gap widened by 60 beam spacings would join them.
  for (int b = 75; b < 80; ++b) pts.push_back(At(b, 2.5));
  const auto clusters = ClusterPoints(pts, kAlpha, config);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0].points.size(), 5u);
  EXPECT_EQ(clusters[1].points.size(), 8u);
  EXPECT_EQ(clusters[2].points.size(), 5u);
  // Centroid = mean (Eq. 3).
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int b = 0; b < 5; ++b) mean += At(b, 2.0).p / 5.0;
  EXPECT_NEAR((clusters[0].centroid - mean).norm(), 0.0, 1e-12);
  EXPECT_TRUE(ClusterPoints({}, kAlpha, config).empty());
}

TEST(PreprocessTest, RoiAndSizeScreeningKeepOnlyLegsNearThePreset) {
  const auto models = testing::PaperModels();
  const PreprocessConfig config;
  std::vector<ScanPoint> pts;
  // A 40 mm leg at 2 m (about 3 beams) and a 1 m wall piece at 2 m elsewhere.
  for (int b = 0; b < 4; ++b) pts.push_back(At(b, 2.0));
  for (int b = 100; b < 186; ++b) pts.push_back(At(b, 2.0));
  // A second leg 3 m away from the first (outside any ROI around the first).
  for (int b = 300; b < 303; ++b) pts.push_back(At(b, 2.0));
  const auto all = Preprocess(pts, kAlpha, std::nullopt, models, config);
  EXPECT_EQ(all.clusters, 3);
  ASSERT_EQ(all.candidates.size(), 2u);  // the wall is too long for a leg
  const geometry::Pose2 preset(2.0, 0.2, 0.0);
  const auto near = Preprocess(pts, kAlpha, preset, models, config);
  ASSERT_EQ(near.candidates.size(), 1u);
  EXPECT_EQ(near.candidates[0].points.front().beam, 0);
  // Empty and one-point inputs.
  EXPECT_TRUE(Preprocess({}, kAlpha, std::nullopt, models, config).candidates.empty());
  const auto one = Preprocess({At(0, 3.0)}, kAlpha, std::nullopt, models, config);
  EXPECT_EQ(one.clusters, 1);
}

}  // namespace
}  // namespace shelfdock::perception
