#pragma once

#include <deque>
#include <vector>

#include <Eigen/Core>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::docking {

/// Recent odometry poses, to know where the robot was when each beam of a scan was fired.
class OdometryBuffer {
 public:
  explicit OdometryBuffer(double keep_s = 1.5) : keep_s_(keep_s) {}

  void Add(double t_s, const geometry::Pose2& T_odom_base);
  bool empty() const { return samples_.empty(); }
  double latest_time() const { return samples_.back().t_s; }

  /// Pose at time t: linear interpolation (yaw on the circle) between samples, clamped to the
  /// oldest and newest samples outside the kept window.
  geometry::Pose2 At(double t_s) const;

 private:
  struct Sample {
    double t_s;
    geometry::Pose2 T_odom_base;
  };
  double keep_s_;
  std::deque<Sample> samples_;
};

/// A scan's returns as points in the LiDAR frame at `t_ref_s`, each beam moved by the odometry
/// between its firing time and t_ref (per-beam motion compensation): p_ref = T_lidar_base *
/// T_odom_base(t_ref)^-1 * T_odom_base(t_i) * T_base_lidar * p_i. Beam order is kept; beams with
/// no return (NaN, out of range) are skipped.
std::vector<perception::ScanPoint> CompensatedPoints(const geometry::LaserScan& scan,
                                                     const OdometryBuffer& odometry,
                                                     const geometry::Pose2& T_base_lidar,
                                                     double t_ref_s);

}  // namespace shelfdock::docking
