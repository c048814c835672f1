#pragma once

#include <optional>
#include <vector>

#include "eval/peers/peer_estimate.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::eval::peers {

/// Settings of the corner-finding peer.
struct CornerPeerConfig {
  double length_tolerance_m = 0.05;  ///< [m] a pair fits a model side or diagonal
  double max_corner_cos = 0.1;       ///< [-] |cos| of a right-angle corner (about 84-96 deg)
  double group_radius_m = 0.1;       ///< [m] corners whose implied centres lie this close agree
};

/// Peer "corner finding", as open ROS shelf detectors do it: leg candidates (shelfdock's
/// clusters and leg-size screening, centroids as leg centres), pairs of them at a model's side
/// or diagonal length, right-angle corners (a model's two sides meeting at a right angle, their
/// free ends at its diagonal; each implies a centre at the middle of the diagonal), then corners
/// that agree on the centre grouped and averaged (centre and heading). The group with most corners
/// wins (ties: nearest the preset). nullopt: no corner.
std::optional<PeerEstimate> CornerPeerDetect(const geometry::LaserScan& scan,
                                             const std::optional<geometry::Pose2>& T_lidar_preset,
                                             const std::vector<geometry::ShelfModel>& models,
                                             const perception::DetectorConfig& detector,
                                             const CornerPeerConfig& config = {});

}  // namespace shelfdock::eval::peers
