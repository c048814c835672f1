#include "docking/shelf_tracker.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "geometry/angle.hpp"

namespace shelfdock::docking {

void ShelfTracker::SetPrior(const geometry::Pose2& T_odom_shelf) {
  const double sx = config_.preset_sigma_xy_m * config_.preset_sigma_xy_m;
  const double sy = config_.preset_sigma_yaw_rad * config_.preset_sigma_yaw_rad;
  Restart(T_odom_shelf, Eigen::Vector3d(sx, sx, sy).asDiagonal());
  detections_ = 0;
}

void ShelfTracker::Restart(const geometry::Pose2& T_odom_shelf, const Eigen::Matrix3d& covariance) {
  mean_ = T_odom_shelf;
  drift_rate_ = 0.0;
  cov_.setZero();
  cov_.topLeftCorner<3, 3>() = covariance;
  cov_(3, 3) = config_.drift_rate_sigma_yaw_per_m * config_.drift_rate_sigma_yaw_per_m;
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
    Restart(z, R);
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
      Restart(z, R);
      detections_ = 1;
      return TrackUpdate::kReinitialised;
    }
    return TrackUpdate::kRejected;
  }
  consecutive_rejects_ = 0;
  // Kalman update of (x, y, yaw, drift_rate) by a pose measurement (H = [I 0]): the drift rate
  // is corrected through its correlation with the pose, which the motions build up.
  const Eigen::Matrix3d S = cov_.topLeftCorner<3, 3>() + R;
  const Eigen::Matrix<double, 4, 3> K = cov_.leftCols<3>() * S.inverse();
  const Eigen::Vector4d dx = K * innovation;
  mean_ = geometry::Pose2(mean_.x + dx(0), mean_.y + dx(1), mean_.yaw + dx(2));
  drift_rate_ += dx(3);
  cov_ -= K * cov_.topRows<3>();
  cov_ = 0.5 * (cov_ + cov_.transpose());
  ++detections_;
  return TrackUpdate::kFused;
}

void ShelfTracker::AddOdometryMotion(const geometry::Pose2& T_odom_base_before,
                                     const geometry::Pose2& T_odom_base_after) {
  // Signed distance driven along the robot's heading (reversing turns the drift back), and
  // the spot the heading error is picked up at: the middle of the step.
  const double ds = (T_odom_base_before.inverse() * T_odom_base_after).x;
  const double d = geometry::Distance(T_odom_base_before, T_odom_base_after);
  const Eigen::Vector2d pivot =
      0.5 * (T_odom_base_before.translation() + T_odom_base_after.translation());
  // Turn the estimate about the pivot by drift_rate * ds (a rotation of a few microradians per
  // step: the first-order form is exact to far below a micrometre).
  const double turn = drift_rate_ * ds;
  const Eigen::Vector2d lever = mean_.translation() - pivot;
  const Eigen::Vector2d perp(-lever.y(), lever.x());
  // Jacobian of the motion with respect to (x, y, yaw, drift_rate).
  Eigen::Matrix4d F = Eigen::Matrix4d::Identity();
  F(0, 1) = -turn;
  F(1, 0) = turn;
  F.block<2, 1>(0, 3) = ds * perp;
  F(2, 3) = ds;
  mean_ = geometry::Pose2(mean_.x + turn * perp.x(), mean_.y + turn * perp.y(),
                          geometry::WrapAngle(mean_.yaw + turn));
  cov_ = F * cov_ * F.transpose();
  cov_(0, 0) += config_.drift_sigma_xy_per_m * config_.drift_sigma_xy_per_m * d;
  cov_(1, 1) += config_.drift_sigma_xy_per_m * config_.drift_sigma_xy_per_m * d;
  cov_(2, 2) += config_.drift_sigma_yaw_per_m * config_.drift_sigma_yaw_per_m * d;
}

}  // namespace shelfdock::docking
