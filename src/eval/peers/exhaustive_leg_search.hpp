#pragma once

#include <vector>

#include <Eigen/Core>

#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/leg_search.hpp"

namespace shelfdock::eval::peers {

/// Peer "exhaustive search": the same acceptance rules as perception::SearchLegSets (two sides
/// of one model meeting at a right angle; a fourth leg making every corner right) without its
/// pruning: every 3-subset of the centres is checked with each of its points as the corner, and
/// every 4-subset in each of its three cyclic orders. One check per (subset, order).
std::vector<perception::LegSet> ExhaustiveLegSets(const std::vector<Eigen::Vector2d>& centres,
                                                  const std::vector<geometry::ShelfModel>& models,
                                                  const perception::LegSearchConfig& config,
                                                  perception::LegSearchCounts* counts = nullptr);

}  // namespace shelfdock::eval::peers
