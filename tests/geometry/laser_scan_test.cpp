// LaserScan: beam angles and which beams count as returns.
#include "geometry/laser_scan.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace shelfdock::geometry {
namespace {

TEST(LaserScanTest, AReturnIsAFinitePositiveRangeWithinTheScansLimits) {
  LaserScan scan;
  scan.range_min = 0.05;
  scan.range_max = 25.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  scan.ranges = {1.0, 0.05, 25.0, 0.04, 25.01, nan, inf, -inf, 0.0, -1.0};
  const bool expected[] = {true, true, true, false, false, false, false, false, false, false};
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    EXPECT_EQ(scan.HasReturn(i), expected[i]) << "range " << scan.ranges[i];
  }
  // A zero range is no return even when the scan allows ranges from 0 (drivers write 0 for none).
  scan.range_min = 0.0;
  EXPECT_FALSE(scan.HasReturn(8));
  EXPECT_TRUE(scan.HasReturn(0));
}

TEST(LaserScanTest, NearestBeamInvertsBeamAngle) {
  LaserScan scan;
  scan.angle_min = -2.356194490192345;
  scan.angle_increment = 0.005817764173314432;
  for (std::size_t i : {0u, 1u, 405u, 810u}) {
    EXPECT_NEAR(scan.BeamAngle(i), scan.angle_min + static_cast<double>(i) * scan.angle_increment,
                1e-15);
    EXPECT_EQ(scan.NearestBeam(scan.BeamAngle(i) + 0.4 * scan.angle_increment), i);
  }
}

}  // namespace
}  // namespace shelfdock::geometry
