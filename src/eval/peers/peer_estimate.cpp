#include "eval/peers/peer_estimate.hpp"

#include <cmath>

#include "perception/detector.hpp"

namespace shelfdock::eval::peers {

double ResolvePeerHeading(double yaw_rad, const geometry::Pose2& T_lidar_shelf,
                          const std::optional<geometry::Pose2>& T_lidar_preset, double period_rad) {
  const double reference =
      T_lidar_preset ? T_lidar_preset->yaw : std::atan2(T_lidar_shelf.y, T_lidar_shelf.x);
  return perception::ResolveHeading(yaw_rad, reference, period_rad);
}

}  // namespace shelfdock::eval::peers
