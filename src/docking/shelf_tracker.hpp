#pragma once

#include <Eigen/Core>

#include "docking/docking_config.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking {

/// What a detection did to the shelf estimate.
enum class TrackUpdate { kInitialised, kFused, kRejected, kReinitialised };

/// Fuses shelf detections over time in the odometry frame. The shelf stands still, so the state
/// is its pose with a covariance: each detection is an information-weighted (Kalman) update with
/// the fit's covariance (floored, since a least-squares covariance is optimistic); detections
/// farther than the gate from the estimate are rejected as jumps, and a run of rejections restarts
/// the estimate (the first lock was the outlier).
///
/// Odometry drift moves the shelf as the odometry frame sees it: a heading error picked up where
/// the robot stands turns everything it sees afterwards about that spot. Its random part (wheel
/// slip) is process noise growing with the distance driven. Its systematic part (the two wheels'
/// radius errors differ) turns the odometry a fixed amount per metre driven; a filter that
/// treats the shelf as still lags that ramp by about its averaging length, which on the paper's
/// set-up was most of the heading error before the code check. So the state also holds that
/// rate, `drift_rate` [rad/m], learnt from how the detections turn as the robot drives, and each
/// motion turns the estimate about the robot by it: the estimate follows the ramp, also on the
/// last stretch the LiDAR no longer sees.
class ShelfTracker {
 public:
  explicit ShelfTracker(const ShelfTrackerConfig& config = {}) : config_(config) {}

  /// A prior (the preset pose) that is replaced, not fused, by the first detection.
  void SetPrior(const geometry::Pose2& T_odom_shelf);

  /// Adds one detection of the shelf, already in the odometry frame.
  TrackUpdate Add(const geometry::Pose2& T_odom_shelf, const Eigen::Matrix3d& covariance);

  /// The robot moved (odometry poses before and after one step): the estimate turns about the
  /// robot by the learnt drift rate times the signed distance driven, and its covariance grows
  /// by the random drift of that distance.
  void AddOdometryMotion(const geometry::Pose2& T_odom_base_before,
                         const geometry::Pose2& T_odom_base_after);

  bool has_detection() const { return detections_ > 0; }
  int detections() const { return detections_; }
  const geometry::Pose2& estimate() const { return mean_; }
  /// Covariance of estimate() (x [m], y [m], yaw [rad]).
  Eigen::Matrix3d covariance() const { return cov_.topLeftCorner<3, 3>(); }
  /// The odometry's learnt systematic heading drift [rad per metre driven forward].
  double drift_rate() const { return drift_rate_; }

 private:
  Eigen::Matrix3d Floor(const Eigen::Matrix3d& covariance) const;
  // Restarts the state at a pose and covariance (a prior or a detection; the caller sets the
  // detection count), the drift rate unknown again.
  void Restart(const geometry::Pose2& T_odom_shelf, const Eigen::Matrix3d& covariance);

  ShelfTrackerConfig config_;
  geometry::Pose2 mean_;
  double drift_rate_ = 0.0;  // [rad/m]
  // Of (x, y, yaw, drift_rate).
  Eigen::Matrix4d cov_ = Eigen::Matrix4d::Identity();
  int detections_ = 0;
  int consecutive_rejects_ = 0;
  geometry::Pose2 last_rejected_;
};

}  // namespace shelfdock::docking
