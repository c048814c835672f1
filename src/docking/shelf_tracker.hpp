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
/// the estimate (the first lock was the outlier). Odometry drift is modelled as process noise
/// growing with the distance driven.
class ShelfTracker {
 public:
  explicit ShelfTracker(const ShelfTrackerConfig& config = {}) : config_(config) {}

  /// A prior (the preset pose) that is replaced, not fused, by the first detection.
  void SetPrior(const geometry::Pose2& T_odom_shelf);

  /// Adds one detection of the shelf, already in the odometry frame.
  TrackUpdate Add(const geometry::Pose2& T_odom_shelf, const Eigen::Matrix3d& covariance);

  /// Inflates the covariance for `distance_m` driven on odometry since the last call.
  void AddOdometryDrift(double distance_m);

  bool has_detection() const { return detections_ > 0; }
  int detections() const { return detections_; }
  const geometry::Pose2& estimate() const { return mean_; }
  const Eigen::Matrix3d& covariance() const { return cov_; }

 private:
  Eigen::Matrix3d Floor(const Eigen::Matrix3d& covariance) const;

  ShelfTrackerConfig config_;
  geometry::Pose2 mean_;
  Eigen::Matrix3d cov_ = Eigen::Matrix3d::Identity();
  int detections_ = 0;
  int consecutive_rejects_ = 0;
  geometry::Pose2 last_rejected_;
};

}  // namespace shelfdock::docking
