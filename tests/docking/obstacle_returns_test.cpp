// Which scan returns may stop the robot: those a neighbouring beam corroborates.
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
// no return, or out of range, is none. With the gap 0 every valid return is one.
TEST(ObstacleReturnsTest, AReturnNoNeighbourCorroboratesStopsNothing) {
  geometry::LaserScan scan = WallScan();
  scan.ranges[20] = 1.0;
  scan.ranges[10] = scan.ranges[11] = 1.0;
  scan.ranges[30] = std::numeric_limits<double>::quiet_NaN();
  scan.ranges[35] = 30.0;
  const std::vector<char> obstacle = ObstacleReturns(scan, 0.15);
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
  const std::vector<char> all = ObstacleReturns(scan, 0.0);
  EXPECT_TRUE(all[20]);
  EXPECT_FALSE(all[30]);
  EXPECT_FALSE(all[35]);
  // A lone return with no neighbours at all (a one-beam scan) is none either.
  scan.ranges.assign(1, 1.0);
  EXPECT_FALSE(ObstacleReturns(scan, 0.15)[0]);
}

}  // namespace
}  // namespace shelfdock::docking
