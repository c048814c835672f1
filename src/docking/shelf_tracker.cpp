#include "docking/shelf_tracker.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

void ShelfTracker::SetPrior(const geometry::Pose2& T_odom_shelf) {
  mean_ = T_odom_shelf;
  const double sx = config_.preset_sigma_xy_m * config_.preset_sigma_xy_m;
  const double sy = config_.preset_sigma_yaw_rad * config_.preset_sigma_yaw_rad;
  cov_ = Eigen::Vector3d(sx, sx, sy).asDiagonal();
  detections_ = 0;
  consecutive_rejects_ = 0;
}

Eigen::Matrix3d ShelfTracker::Floor(const Eigen::Matrix3d& covariance) const {
  Eigen::Matrix3d c = covariance;
  if (!c.allFinite()) c.setZero();
  c = 0.5 * (c + c.transpose());
  c(0, 0) += config_.min_sigma_xy_m * config_.min_sigma_xy_m;
  c(1, 1) += config_.min_sigma_xy_m * config_.min_sigma_xy_m;
  c(2, 2) += config_.min_sigma_yaw_rad * config_.min_sigma_yaw_rad;
  return c;
}

TrackUpdate ShelfTracker::Add(const geometry::Pose2& T_odom_shelf,
                              const Eigen::Matrix3d& covariance) {
  geometry::Pose2 z = T_odom_shelf;
  const Eigen::Matrix3d R = Floor(covariance);
  if (detections_ == 0) {
    mean_ = z;
    cov_ = R;
    detections_ = 1;
    return TrackUpdate::kInitialised;
  }
  // A rectangle's heading is ambiguous by pi: take the branch nearest the estimate.
  if (std::abs(geometry::AngleDiff(z.yaw, mean_.yaw)) > 0.5 * std::numbers::pi) {
    z.yaw = geometry::WrapAngle(z.yaw + std::numbers::pi);
  }
  const Eigen::Vector3d innovation(z.x - mean_.x, z.y - mean_.y,
                                   geometry::AngleDiff(z.yaw, mean_.yaw));
  const bool jump = innovation.head<2>().norm() > config_.gate_xy_m ||
                    std::abs(innovation.z()) > config_.gate_yaw_rad;
  if (jump) {
    const bool consistent_with_last =
        consecutive_rejects_ > 0 && geometry::Distance(z, last_rejected_) < config_.gate_xy_m &&
        std::abs(geometry::AngleDiff(z.yaw, last_rejected_.yaw)) < config_.gate_yaw_rad;
    consecutive_rejects_ = consistent_with_last ? consecutive_rejects_ + 1 : 1;
    last_rejected_ = z;
    if (consecutive_rejects_ >= config_.reinit_after_rejects) {
      mean_ = z;
      cov_ = R;
      detections_ = 1;
      consecutive_rejects_ = 0;
      return TrackUpdate::kReinitialised;
    }
    return TrackUpdate::kRejected;
  }
  consecutive_rejects_ = 0;
  const Eigen::Matrix3d K = cov_ * (cov_ + R).inverse();
  const Eigen::Vector3d dx = K * innovation;
  mean_ = geometry::Pose2(mean_.x + dx.x(), mean_.y + dx.y(), mean_.yaw + dx.z());
  cov_ = (Eigen::Matrix3d::Identity() - K) * cov_;
  cov_ = 0.5 * (cov_ + cov_.transpose());
  ++detections_;
  return TrackUpdate::kFused;
}

void ShelfTracker::AddOdometryDrift(double distance_m) {
  const double d = std::abs(distance_m);
  cov_(0, 0) += config_.drift_sigma_xy_per_m * config_.drift_sigma_xy_per_m * d;
  cov_(1, 1) += config_.drift_sigma_xy_per_m * config_.drift_sigma_xy_per_m * d;
  cov_(2, 2) += config_.drift_sigma_yaw_per_m * config_.drift_sigma_yaw_per_m * d;
}

}  // namespace shelfdock::docking
