#pragma once

#include <Eigen/Core>

namespace shelfdock::geometry {

/// A rigid transform in SE(2). Named T_<to>_<from> at use sites: p_to = T_to_from * p_from.
/// Yaw is counter-clockwise in radians, kept in [-pi, pi).
struct Pose2 {
  double x = 0.0;    ///< [m]
  double y = 0.0;    ///< [m]
  double yaw = 0.0;  ///< [rad]

  Pose2() = default;
  Pose2(double x_m, double y_m, double yaw_rad);

  Eigen::Vector2d translation() const { return {x, y}; }
  Eigen::Matrix2d rotation() const;

  Pose2 operator*(const Pose2& rhs) const;                    ///< composition
  Eigen::Vector2d operator*(const Eigen::Vector2d& p) const;  ///< transform a point
  Pose2 inverse() const;
};

/// Euclidean distance between the translations of two poses.
double Distance(const Pose2& a, const Pose2& b);

}  // namespace shelfdock::geometry
