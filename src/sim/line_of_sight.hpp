#pragma once

#include <array>

#include "geometry/pose2.hpp"
#include "sim/lidar_config.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim {

/// How many beams of a LiDAR's beam grid hit each leg of one shelf first, in an ideal cast: no
/// noise, no dropouts, no beam footprint, no tilt. It says what the geometry lets the sensor
/// see, whatever the scan's flaws then make of it.
struct LegSight {
  std::array<int, 4> beams{};  ///< per leg, indexed as geometry::ShelfModel::LegCentres()

  /// Legs hit first by at least `min_beams` beams.
  int LegsInSight(int min_beams = 2) const;
};

/// Casts the beam grid of `lidar` (angles, count, range limits; flaws switched off) from
/// T_world_lidar and counts the first hits on shelf `shelf_id`'s legs. People stand where they
/// are at t = 0 (they are re-placed along the sweep as in a real scan).
LegSight ComputeLegSight(const World& world, const geometry::Pose2& T_world_lidar,
                         const LidarConfig& lidar, int shelf_id);

}  // namespace shelfdock::sim
