#pragma once

#include "geometry/pose2.hpp"
#include "perception/detection.hpp"

namespace shelfdock::perception {

/// A detection expressed in another frame: `T_target_lidar` maps lidar coordinates into the
/// target frame. Pose, legs and covariance (position block rotated) are transformed.
Detection ExpressIn(const Detection& detection_lidar, const geometry::Pose2& T_target_lidar);

/// The shelf pose in the robot's base frame, given the LiDAR extrinsic.
geometry::Pose2 ShelfInBase(const Detection& detection_lidar, const geometry::Pose2& T_base_lidar);

/// The shelf pose in the map frame, given the extrinsic and the robot pose (paper 3.4, last
/// step: T_map_shelf = T_map_base * T_base_lidar * T_lidar_shelf).
geometry::Pose2 ShelfInMap(const Detection& detection_lidar, const geometry::Pose2& T_base_lidar,
                           const geometry::Pose2& T_map_base);

}  // namespace shelfdock::perception
