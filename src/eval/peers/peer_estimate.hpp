#pragma once

#include <optional>
#include <string>

#include "geometry/pose2.hpp"

namespace shelfdock::eval::peers {

/// What a peer method answers for one scan: the shelf it picked, in the scan's frame.
struct PeerEstimate {
  std::string model;
  geometry::Pose2 T_lidar_shelf;
  int legs = 0;  ///< legs it used (3 or 4)
};

/// The heading convention every method is scored with (the detector's): toward the preset
/// heading when there is one, else the shelf's x axis pointing away from the sensor. `period_rad`:
/// the model's ShelfModel::HeadingPeriod (pi/2 for a square, else pi).
double ResolvePeerHeading(double yaw_rad, const geometry::Pose2& T_lidar_shelf,
                          const std::optional<geometry::Pose2>& T_lidar_preset, double period_rad);

}  // namespace shelfdock::eval::peers
