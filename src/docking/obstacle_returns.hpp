#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// A scan's returns in some frame, one per beam (beams without one at the origin).
struct ScanReturns {
  std::vector<Eigen::Vector2d> points;  ///< [m] in the frame, one per beam
  std::vector<char> valid;              ///< the beam returned within range
};

/// The valid returns of `scan` placed in a frame by T_frame_lidar (PlaceReturns(scan, T_odom_lidar)
/// puts them in the odometry frame), with a flag per beam telling which are valid.
ScanReturns PlaceReturns(const geometry::LaserScan& scan, const geometry::Pose2& T_frame_lidar);

/// Which returns of `scan` may be obstacles (one flag per beam): a valid return that something
/// corroborates within `max_gap_m`, either a neighbouring beam's return (i - 1 or i + 1) or one of
/// the previous scan's returns (`previous`, in the same frame as `now`). A real obstacle is hit
/// by several beams (a person's leg by dozens), or by one beam scan after scan (a 26 mm leg 3 m
/// off); a stray echo (dust, an insect, another robot's LiDAR pulse) is one return that the next
/// scan does not repeat, and stops nothing. `max_gap_m` <= 0, or no scan before (`previous`
/// empty): every valid return may be one.
std::vector<char> ObstacleReturns(const ScanReturns& now, const ScanReturns& previous,
                                  double max_gap_m);

}  // namespace shelfdock::docking
