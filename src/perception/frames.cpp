#include "perception/frames.hpp"

namespace shelfdock::perception {

Detection ExpressIn(const Detection& detection_lidar, const geometry::Pose2& T_target_lidar) {
  Detection out = detection_lidar;
  out.T_lidar_shelf = T_target_lidar * detection_lidar.T_lidar_shelf;
  for (auto& leg : out.legs) leg = T_target_lidar * leg;
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  A.topLeftCorner<2, 2>() = T_target_lidar.rotation();
  out.covariance = A * detection_lidar.covariance * A.transpose();
  return out;
}

geometry::Pose2 ShelfInBase(const Detection& detection_lidar, const geometry::Pose2& T_base_lidar) {
  return T_base_lidar * detection_lidar.T_lidar_shelf;
}

geometry::Pose2 ShelfInMap(const Detection& detection_lidar, const geometry::Pose2& T_base_lidar,
                           const geometry::Pose2& T_map_base) {
  return T_map_base * (T_base_lidar * detection_lidar.T_lidar_shelf);
}

}  // namespace shelfdock::perception
