#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace shelfdock::geometry {

/// One 2D LiDAR scan, field for field as ROS sensor_msgs/LaserScan. Beam i points at
/// angle_min + i * angle_increment in the scan's own frame (`lidar`). A beam with no return is
/// NaN in `ranges` (`null` in the JSON files); ranges outside [range_min, range_max], and 0, are
/// also no return (HasReturn).
struct LaserScan {
  double angle_min = 0.0;        ///< [rad]
  double angle_max = 0.0;        ///< [rad]
  double angle_increment = 0.0;  ///< [rad]
  double range_min = 0.0;        ///< [m]
  double range_max = 0.0;        ///< [m]
  std::vector<double> ranges;    ///< [m], NaN for no return
  std::vector<double> intensities;
  double time_increment = 0.0;  ///< [s] between beams
  double scan_time = 0.0;       ///< [s] between scans
  double stamp = 0.0;           ///< [s] time of the first beam
  std::string frame_id = "lidar";

  double BeamAngle(std::size_t i) const {
    return angle_min + static_cast<double>(i) * angle_increment;
  }
  /// True when beam i returned: a finite range above 0 within [range_min, range_max]. Every
  /// consumer of a scan's points (the detector, the docking's motion-corrected and obstacle
  /// returns) takes the same beams.
  bool HasReturn(std::size_t i) const {
    const double r = ranges[i];
    return std::isfinite(r) && r > 0.0 && r >= range_min && r <= range_max;
  }
  /// The beam nearest to `angle_rad` (inverse of BeamAngle); the caller keeps the angle within
  /// [angle_min, angle_max].
  std::size_t NearestBeam(double angle_rad) const {
    return static_cast<std::size_t>(std::lround((angle_rad - angle_min) / angle_increment));
  }
};

}  // namespace shelfdock::geometry
