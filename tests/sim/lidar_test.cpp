#include "sim/lidar.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::sim {
namespace {

using geometry::Pose2;

/// The index of the beam nearest to a bearing.
std::size_t BeamAt(const geometry::LaserScan& scan, double bearing_rad) {
  return static_cast<std::size_t>(
      std::lround((bearing_rad - scan.angle_min) / scan.angle_increment));
}

TEST(LidarTest, IdealScanMeasuresDistanceToRoundPost) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(3.0, 1.0), 0.1);
  Lidar lidar(IdealLidarConfig(), 1);
  const Pose2 T_world_lidar(1.0, 1.0, 0.0);  // post 2 m straight ahead
  const auto scan = lidar.Scan(world, T_world_lidar);
  ASSERT_EQ(scan.ranges.size(), 811u);
  EXPECT_NEAR(scan.ranges[BeamAt(scan, 0.0)], 2.0 - 0.1, 1e-9);
}

TEST(LidarTest, BeamsMissingEverythingAreNaN) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(3.0, 0.0), 0.1);
  Lidar lidar(IdealLidarConfig(), 1);
  const auto scan = lidar.Scan(world, Pose2());
  EXPECT_TRUE(std::isnan(scan.ranges[BeamAt(scan, std::numbers::pi / 2)]));
  EXPECT_TRUE(std::isnan(scan.ranges.front()));
}

TEST(LidarTest, RotatedLidarSeesBoxCorner) {
  // A square 1 m box centred at (3, 0) rotated 45 deg: its near corner is at x = 3 - sqrt(0.5).
  World world;
  Box box;
  box.T_world_box = Pose2(3.0, 0.0, std::numbers::pi / 4);
  world.AddBox(box);
  Lidar lidar(IdealLidarConfig(), 1);
  const auto scan = lidar.Scan(world, Pose2(0.0, 0.0, 0.0));
  EXPECT_NEAR(scan.ranges[BeamAt(scan, 0.0)], 3.0 - std::sqrt(0.5), 1e-9);
}

}  // namespace
}  // namespace shelfdock::sim
