#include "sim/lidar.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::sim {
namespace {

using geometry::Pose2;

/// A closed square room of half-size `half_m` around the origin.
void AddRoom(World* world, double half_m) {
  world->AddWall({{-half_m, -half_m}, {half_m, -half_m}, {half_m, half_m}, {-half_m, half_m}},
                 true);
}

TEST(LidarTest, ScanHeaderFollowsTheConfig) {
  World world;
  const LidarConfig config;
  Lidar lidar(config, 1);
  const auto scan = lidar.Scan(world, Pose2(), 2.5);
  ASSERT_EQ(scan.ranges.size(), 811u);
  EXPECT_NEAR(scan.angle_min, geometry::DegToRad(-135.0), 1e-12);
  EXPECT_NEAR(scan.angle_max, geometry::DegToRad(135.0), 1e-9);
  EXPECT_NEAR(scan.scan_time, 1.0 / 15.0, 1e-12);
  EXPECT_NEAR(scan.stamp, 2.5, 1e-12);
  EXPECT_EQ(scan.intensities.size(), 811u);
}

TEST(LidarTest, IdealScanMeasuresDistanceToRoundPost) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(3.0, 1.0), 0.1);
  Lidar lidar(IdealLidarConfig(), 1);
  const auto scan = lidar.Scan(world, Pose2(1.0, 1.0, 0.0));  // post 2 m straight ahead
  EXPECT_NEAR(scan.ranges[scan.NearestBeam(0.0)], 2.0 - 0.1, 1e-9);
}

TEST(LidarTest, BeamsMissingEverythingAreNaN) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(3.0, 0.0), 0.1);
  Lidar lidar(IdealLidarConfig(), 1);
  const auto scan = lidar.Scan(world, Pose2());
  EXPECT_TRUE(std::isnan(scan.ranges[scan.NearestBeam(std::numbers::pi / 2)]));
  EXPECT_TRUE(std::isnan(scan.ranges.front()));
}

TEST(LidarTest, RotatedBoxCornerAndObliqueWall) {
  // A 1 m box at (3, 0) turned 45 deg: its near corner is at x = 3 - sqrt(0.5).
  World world;
  Box box;
  box.T_world_box = Pose2(3.0, 0.0, std::numbers::pi / 4);
  world.AddBox(box);
  world.AddWall({{-10.0, 4.0}, {10.0, 4.0}});
  Lidar lidar(IdealLidarConfig(), 1);
  // The LiDAR faces +x from (0, 0) rotated by 30 deg: the beam at bearing -30 deg points at +x.
  const double yaw = std::numbers::pi / 6;
  const auto scan = lidar.Scan(world, Pose2(0.0, 0.0, yaw));
  EXPECT_NEAR(scan.ranges[scan.NearestBeam(-yaw)], 3.0 - std::sqrt(0.5), 1e-9);
  // A beam at world angle phi hits the wall y = 4 at 4 / sin(phi).
  const std::size_t i = scan.NearestBeam(std::numbers::pi / 3);
  const double phi = yaw + scan.BeamAngle(i);
  EXPECT_NEAR(scan.ranges[i], 4.0 / std::sin(phi), 1e-9);
}

TEST(LidarTest, RangeNoiseHasConfiguredMeanAndSigma) {
  World world;
  AddRoom(&world, 4.0);
  LidarConfig config = IdealLidarConfig();
  config.enable_range_noise = true;
  config.enable_quantisation = true;
  config.range_noise_sigma_m = 0.01;
  Lidar lidar(config, 42);
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (int k = 0; k < 20; ++k) {
    const auto labelled = lidar.ScanLabelled(
        world, [](double) { return Pose2(); }, 0.0);
    for (std::size_t i = 0; i < labelled.scan.ranges.size(); ++i) {
      const double err = labelled.scan.ranges[i] - labelled.truth[i].true_range_m;
      ASSERT_TRUE(std::isfinite(err));
      sum += err;
      sum_sq += err * err;
      ++n;
    }
  }
  const double mean = sum / n;
  const double sigma = std::sqrt(sum_sq / n - mean * mean);
  // 16220 samples: the mean's standard error is 0.08 mm; sigma's about 0.6 %. Quantising to
  // 1 mm adds 1/12 mm^2 of variance, i.e. sigma grows by 0.04 %.
  EXPECT_NEAR(mean, 0.0, 4.0 * 0.01 / std::sqrt(n));
  EXPECT_NEAR(sigma, 0.01, 0.01 * 0.03);
}

TEST(LidarTest, RangeNoiseGrowsWithRange) {
  World world;
  world.AddWall({{10.0, -50.0}, {10.0, 50.0}});
  LidarConfig config = IdealLidarConfig();
  config.enable_range_noise = true;
  config.range_noise_sigma_m = 0.0;
  config.range_noise_per_m = 0.002;  // 2 mm per metre: 2 cm at 10 m
  Lidar lidar(config, 3);
  double sum_sq = 0.0;
  int n = 0;
  for (int k = 0; k < 30; ++k) {
    const auto labelled = lidar.ScanLabelled(
        world, [](double) { return Pose2(); }, 0.0);
    const std::size_t i = labelled.scan.NearestBeam(0.0);
    for (std::size_t j = i - 10; j <= i + 10; ++j) {  // beams near 10 m
      const double err = labelled.scan.ranges[j] - labelled.truth[j].true_range_m;
      sum_sq += err * err;
      ++n;
    }
  }
  EXPECT_NEAR(std::sqrt(sum_sq / n), 0.002 * 10.0, 0.002 * 10.0 * 0.1);
}

TEST(LidarTest, SameSeedSameScansOtherSeedOtherScans) {
  World world;
  AddRoom(&world, 5.0);
  world.AddRoundPost(Eigen::Vector2d(1.0, 1.0), 0.05);
  const LidarConfig config;  // everything on
  Lidar a(config, 11), b(config, 11), c(config, 12);
  for (int k = 0; k < 3; ++k) {
    const auto sa = a.Scan(world, Pose2(0.1, 0.2, 0.3), k / 15.0);
    const auto sb = b.Scan(world, Pose2(0.1, 0.2, 0.3), k / 15.0);
    const auto sc = c.Scan(world, Pose2(0.1, 0.2, 0.3), k / 15.0);
    for (std::size_t i = 0; i < sa.ranges.size(); ++i) {
      if (std::isnan(sa.ranges[i])) {
        EXPECT_TRUE(std::isnan(sb.ranges[i]));
      } else {
        EXPECT_EQ(sa.ranges[i], sb.ranges[i]);
      }
    }
    int differ = 0;
    for (std::size_t i = 0; i < sa.ranges.size(); ++i) differ += sa.ranges[i] != sc.ranges[i];
    EXPECT_GT(differ, 400);
  }
}

}  // namespace
}  // namespace shelfdock::sim
