// Frames: a detection in the lidar frame expressed in base and map frames.
#include "perception/frames.hpp"

#include <gtest/gtest.h>

namespace shelfdock::perception {
namespace {

TEST(FramesTest, ComposesExtrinsicAndRobotPose) {
  Detection d;
  d.T_lidar_shelf = geometry::Pose2(2.0, 0.5, 0.3);
  d.legs = {Eigen::Vector2d(1.5, 0.2)};
  d.covariance = Eigen::Vector3d(1e-4, 4e-4, 1e-5).asDiagonal();
  const geometry::Pose2 T_base_lidar(0.3, 0.0, M_PI);  // LiDAR facing backwards
  const geometry::Pose2 T_map_base(5.0, -1.0, 0.5 * M_PI);
  // Base: (0.3 - 2.0, -0.5), yaw 0.3 + pi -> wrapped.
  const geometry::Pose2 in_base = ShelfInBase(d, T_base_lidar);
  EXPECT_NEAR(in_base.x, -1.7, 1e-12);
  EXPECT_NEAR(in_base.y, -0.5, 1e-12);
  EXPECT_NEAR(in_base.yaw, 0.3 - M_PI, 1e-12);
  // Map: rotate the base point by +90 degrees and shift: (5 + 0.5, -1 - 1.7).
  const geometry::Pose2 in_map = ShelfInMap(d, T_base_lidar, T_map_base);
  EXPECT_NEAR(in_map.x, 5.5, 1e-12);
  EXPECT_NEAR(in_map.y, -2.7, 1e-12);
  EXPECT_NEAR(in_map.yaw, 0.3 - 0.5 * M_PI, 1e-12);
  // Legs and covariance follow the rotation: a quarter turn swaps the x and y variances.
  const Detection moved = ExpressIn(d, geometry::Pose2(0.0, 0.0, 0.5 * M_PI));
  EXPECT_NEAR(moved.legs[0].x(), -0.2, 1e-12);
  EXPECT_NEAR(moved.legs[0].y(), 1.5, 1e-12);
  EXPECT_NEAR(moved.covariance(0, 0), 4e-4, 1e-15);
  EXPECT_NEAR(moved.covariance(1, 1), 1e-4, 1e-15);
  EXPECT_NEAR(moved.covariance(2, 2), 1e-5, 1e-15);
}

}  // namespace
}  // namespace shelfdock::perception
