#pragma once

#include <cstdint>
#include <optional>

#include "geometry/gray_image.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "sim/diff_drive_robot.hpp"
#include "sim/lidar.hpp"
#include "sim/marker_camera.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim {

/// When the robot's sensors deliver, and the failures a test may inject.
struct SensorRigConfig {
  double camera_rate_hz = 15.0;  ///< [Hz] upward camera frames while it is on
  /// LiDAR blackout (a failure injection): no scans from this long after `blackout_from_s` is
  /// armed (the docking area's entry), for blackout_duration_s. Negative: no blackout.
  double blackout_start_s = -1.0;
  double blackout_duration_s = 1e9;  ///< [s]
  /// Camera failure (a failure injection): frames keep arriving but show no code, as with a
  /// shelf whose code is missing or a covered lens.
  bool camera_blind = false;
};

/// What the sensors delivered in one control step.
struct SensorReadings {
  const geometry::LaserScan* scan = nullptr;  ///< a scan completed since the last step, if any
  bool camera_frame = false;                  ///< the camera delivered a frame
  std::optional<geometry::GrayImage> image;   ///< its image when a shelf's code was above
};

/// The sensors on the robot beside it: a LiDAR whose scan started at t0 is complete (and
/// delivered) one period later, skewed by the robot's motion during it; an upward camera that,
/// when on, renders the code of the shelf the robot stands under at its frame rate.
class SensorRig {
 public:
  SensorRig(const LidarConfig& lidar, const CameraConfig& camera, const SensorRigConfig& config,
            const geometry::Pose2& T_base_lidar, std::uint64_t seed, double t0_s);

  /// Readings at time t_s of the robot's step. `since_entry_s` (NaN before the docking area's
  /// entry) times the injected blackout; `camera_on` is what the robot commanded last.
  SensorReadings Sense(const World& world, const DiffDriveRobot& robot, double t_s,
                       double since_entry_s, bool camera_on);

 private:
  LidarConfig lidar_config_;
  CameraConfig camera_;
  SensorRigConfig config_;
  geometry::Pose2 T_base_lidar_;
  std::uint64_t seed_;
  Lidar lidar_;
  double next_scan_t0_s_;
  double next_camera_t_s_;
  int camera_frames_ = 0;
  geometry::LaserScan scan_;
};

/// The shelf whose leg rectangle contains the robot's centre (the one the camera looks at).
std::optional<ShelfInstance> ShelfAbove(const World& world, const geometry::Pose2& T_world_base);

}  // namespace shelfdock::sim
