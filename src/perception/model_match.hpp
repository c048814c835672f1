#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::perception {

/// Mean side lengths of a leg set given in cyclic order (see LegSet).
struct EdgeSizes {
  double long_m = 0.0;           ///< l_k: mean of the long edges
  double short_m = 0.0;          ///< w_k: mean of the short edges
  bool first_edge_long = false;  ///< legs[0] -> legs[1] runs along the long side
};

/// A points-model pair (paper 3.2) with its Eq. 2 errors.
struct ModelPair {
  int model = -1;        ///< index into the model list
  double err_L = 0.0;    ///< |l_k - L_i| [m]
  double err_W = 0.0;    ///< |w_k - W_i| [m]
  double err_sum = 0.0;  ///< err_L + err_W [m]
};

/// Edge lengths of 3 or 4 legs in cyclic order: opposite edges are averaged.
EdgeSizes MeasureEdges(const std::array<Eigen::Vector2d, 4>& legs, int count);

/// Eq. 2 errors of one model.
ModelPair ScoreModel(const EdgeSizes& edges, const geometry::ShelfModel& model, int index);

/// Eq. 2 screening: every model within gamma_L, gamma_W and gamma_sum, then only the pairs
/// whose err_sum is within lambda of the best; sorted best first. Empty when none fits.
std::vector<ModelPair> MatchModels(const EdgeSizes& edges,
                                   const std::vector<geometry::ShelfModel>& models,
                                   const ModelMatchConfig& config);

/// True when a pair passes the Eq. 2 thresholds.
bool PassesThresholds(const ModelPair& pair, const ModelMatchConfig& config);

}  // namespace shelfdock::perception
