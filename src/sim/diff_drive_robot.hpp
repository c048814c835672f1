#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>

#include <Eigen/Core>

#include "geometry/config_violation.hpp"
#include "geometry/pose2.hpp"
#include "sim/lift.hpp"
#include "sim/localisation.hpp"
#include "sim/odometry.hpp"

namespace shelfdock::sim {

/// A differential-drive robot like the paper's AMR (section 4): velocity and acceleration
/// limits, a rectangular footprint that must pass between the shelf legs (shelf 2 of Table 1
/// leaves 1.075 - 0.04 = 1.035 m by 0.883 - 0.04 = 0.843 m between its legs), wheel odometry,
/// a localisation estimate and a lift.
struct DiffDriveConfig {
  double max_v_mps = 1.0;            ///< [m/s] |v| limit (forward and reverse)
  double max_w_radps = 1.5;          ///< [rad/s] |w| limit
  double max_accel_mps2 = 0.5;       ///< [m/s^2] |dv/dt| limit
  double max_alpha_radps2 = 2.0;     ///< [rad/s^2] |dw/dt| limit
  double wheel_base_m = 0.5;         ///< [m] distance between the drive wheels
  double footprint_length_m = 0.70;  ///< [m] along the robot's x, centred on the base origin
  double footprint_width_m = 0.50;   ///< [m] along the robot's y, centred on the base origin
  double control_rate_hz = 50.0;     ///< [Hz] rate at which (v, w) commands are applied
  double lift_duration_s = 2.0;      ///< [s] time for the lift to raise the shelf
  double history_s = 1.0;            ///< [s] how far back T_world_base_at() can look
  OdometryNoiseConfig odometry;
  LocalisationNoiseConfig localisation;
};

/// The first impossible value of the robot's config, keys as in config/robot.yaml: the
/// `odometry` and `localisation` maps' first, then positive limits, sizes and rates.
std::optional<geometry::ConfigViolation> FindConfigViolation(const DiffDriveConfig& config);

/// The simulated robot. The true pose is for sensors and scoring only; a controller sees
/// T_odom_base(), T_map_base_estimate(), v() and w(), as on a real robot. The world frame is
/// the map frame (a perfect map); only the robot's estimate of its place in it is wrong.
class DiffDriveRobot {
 public:
  DiffDriveRobot(const DiffDriveConfig& config, const geometry::Pose2& T_world_base_start,
                 uint64_t seed);

  /// Applies (v, w) for dt_s: commands are clamped to the velocity limits, then the change of
  /// velocity to the acceleration limits; the velocity is then held over the step and the pose
  /// integrated exactly along the resulting arc.
  void Step(double v_cmd_mps, double w_cmd_radps, double dt_s);

  geometry::Pose2 T_world_base() const { return T_world_base_; }  ///< TRUE pose
  geometry::Pose2 T_odom_base() const { return odometry_.T_odom_base(); }
  geometry::Pose2 T_map_base_estimate() const { return localisation_.Apply(T_world_base_); }
  double v() const { return v_mps_; }    ///< [m/s] current (limited) forward velocity
  double w() const { return w_radps_; }  ///< [rad/s] current (limited) yaw rate
  double time_s() const { return time_s_; }
  double distance_travelled_m() const { return distance_m_; }

  /// TRUE pose at time t (for beams fired during a scan): exact within the kept history,
  /// clamped to the oldest kept pose before it, extrapolated at the current velocity after now.
  geometry::Pose2 T_world_base_at(double t_s) const;

  void StartLift() { lift_.Start(time_s_); }
  bool LiftDone() const { return lift_.Done(time_s_); }
  double LiftProgress() const { return lift_.Progress(time_s_); }

  /// Footprint corners in the world frame at the true pose (front-left first, CCW).
  std::array<Eigen::Vector2d, 4> FootprintCorners() const;

  const DiffDriveConfig& config() const { return config_; }
  const LocalisationError& localisation_error() const { return localisation_; }

 private:
  struct Sample {
    double t_s;
    geometry::Pose2 T_world_base;
    double v_mps;
    double w_radps;
  };

  DiffDriveConfig config_;
  geometry::Pose2 T_world_base_;
  double v_mps_ = 0.0;
  double w_radps_ = 0.0;
  double time_s_ = 0.0;
  double distance_m_ = 0.0;
  WheelOdometry odometry_;
  LocalisationError localisation_;
  Lift lift_;
  std::deque<Sample> history_;  ///< pose at the start of each step and the velocity held over it
};

/// Pose reached from `start` by holding (v, w) for dt (the exact arc, a line when w = 0).
geometry::Pose2 IntegrateArc(const geometry::Pose2& start, double v_mps, double w_radps,
                             double dt_s);

}  // namespace shelfdock::sim
