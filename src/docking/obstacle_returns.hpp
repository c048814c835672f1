#pragma once

#include <vector>

#include "geometry/laser_scan.hpp"

namespace shelfdock::docking {

/// Which returns of `scan` may be obstacles (one flag per beam): a valid return that beam i - 1 or
/// i + 1 corroborates with a point within `max_gap_m` of it. A real obstacle near the robot's way
/// is hit by several beams (a 2 cm rod 1.7 m ahead by two of the WLR-716's, a person's leg by
/// dozens); a return no neighbour confirms is a stray echo (dust, an insect, another robot's
/// LiDAR pulse) and stops nothing. A thin thing seen by one beam only far off is seen by more as
/// the robot nears it. `max_gap_m` <= 0: every valid return may be an obstacle.
std::vector<char> ObstacleReturns(const geometry::LaserScan& scan, double max_gap_m);

}  // namespace shelfdock::docking
