#pragma once

#include <optional>
#include <vector>

#include "eval/peers/peer_estimate.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::eval::peers {

/// Peer "centroid only": shelfdock's preprocessing, pruned search and Eq. 2 screening, but the
/// plain cluster centroids as leg centres (no 3.3 leg fit) and the plain average of the legs as
/// the shelf pose (no 3.4 shelf fit), as simpler open projects do. Picks the set nearest the
/// preset (without one, the best err_sum). nullopt: no shelf.
std::optional<PeerEstimate> CentroidPeerDetect(const geometry::LaserScan& scan,
                                               const std::optional<geometry::Pose2>& T_lidar_preset,
                                               const std::vector<geometry::ShelfModel>& models,
                                               const perception::DetectorConfig& config);

}  // namespace shelfdock::eval::peers
