#pragma once

#include <Eigen/Core>

namespace shelfdock::perception {

/// One valid return, in the scan's frame (`lidar`, sensor at the origin). Invariant: p = range *
/// (cos angle, sin angle) with range > 0 (the fits take the beam direction as p / range).
struct ScanPoint {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();  ///< [m] position, lidar frame
  double range = 0.0;                           ///< [m]
  double angle = 0.0;                           ///< [rad] beam bearing
  int beam = 0;                                 ///< index in the scan
};

}  // namespace shelfdock::perception
