// Which scan returns may stop the robot: those a neighbouring beam or the scan before corroborates.
#include "docking/obstacle_returns.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace shelfdock::docking {
namespace {

// 41 beams 1/3 degree apart across the robot's way, a wall 2 m ahead on every one.
geometry::LaserScan WallScan() {
  geometry::LaserScan scan;
  scan.angle_min = -20 * 0.005817764173314432;
  scan.angle_increment = 0.005817764173314432;
  scan.range_min = 0.05;
  scan.range_max = 25.0;
  scan.ranges.assign(41, 2.0);
  return scan;
}

// A stray echo 1 m ahead on beam 20 alone is no obstacle; the wall's returns beside it are (each
// has a neighbour 12 mm away). A post 1 m ahead on beams 10-11 (5.8 mm apart) is one on both; so
// is a return whose neighbour is missing on one side and corroborated on the other. A beam with
// no return, or out of range, is none. The stray seen again by the next scan within the gap (a
// thin leg far off is hit by one beam scan after scan) is one. With the gap 0, or on the first
// scan (nothing before it to tell a stray from a thin thing), every valid return is one.
TEST(ObstacleReturnsTest, AReturnNothingCorroboratesStopsNothing) {
  geometry::LaserScan scan = WallScan();
  scan.ranges[20] = 1.0;
  scan.ranges[10] = scan.ranges[11] = 1.0;
  scan.ranges[30] = std::numeric_limits<double>::quiet_NaN();
  scan.ranges[35] = 30.0;
  const geometry::Pose2 T_frame_lidar(0.5, -0.2, 0.1);
  const ScanReturns now = PlaceReturns(scan, T_frame_lidar);
  ASSERT_EQ(now.points.size(), scan.ranges.size());
  EXPECT_NEAR((now.points[20] - T_frame_lidar.translation()).norm(), 1.0, 1e-12);
  const ScanReturns before = PlaceReturns(WallScan(), T_frame_lidar);
  const std::vector<char> obstacle = ObstacleReturns(now, before, 0.15);
  ASSERT_EQ(obstacle.size(), scan.ranges.size());
  EXPECT_FALSE(obstacle[20]);
  EXPECT_TRUE(obstacle[19]);
  EXPECT_TRUE(obstacle[21]);
  EXPECT_TRUE(obstacle[10]);
  EXPECT_TRUE(obstacle[11]);
  EXPECT_TRUE(obstacle[29]);
  EXPECT_TRUE(obstacle[31]);
  EXPECT_FALSE(obstacle[30]);
  EXPECT_FALSE(obstacle[35]);
  // The next scan, the robot 5 cm farther along: the lone return is there again.
  geometry::LaserScan next = scan;
  next.ranges[20] = 0.95;
  const ScanReturns again = PlaceReturns(next, T_frame_lidar * geometry::Pose2(0.05, 0.0, 0.0));
  EXPECT_TRUE(ObstacleReturns(again, now, 0.15)[20]);
  // ... or it was a stray, and the next one stands elsewhere.
  next.ranges[20] = 1.6;
  const ScanReturns elsewhere = PlaceReturns(next, T_frame_lidar);
  EXPECT_FALSE(ObstacleReturns(elsewhere, now, 0.15)[20]);
  for (const std::vector<char>& all :
       {ObstacleReturns(now, before, 0.0), ObstacleReturns(now, ScanReturns{}, 0.15)}) {
    EXPECT_TRUE(all[20]);
    EXPECT_FALSE(all[30]);
    EXPECT_FALSE(all[35]);
  }
}

}  // namespace
}  // namespace shelfdock::docking
