#include "perception/model_match.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::perception {

EdgeSizes MeasureEdges(const std::array<Eigen::Vector2d, 4>& legs, int count) {
  const double e0 = (legs[1] - legs[0]).norm();
  const double e1 = (legs[2] - legs[1]).norm();
  double side_a = e0;
  double side_b = e1;
  if (count == 4) {
    side_a = 0.5 * (e0 + (legs[3] - legs[2]).norm());
    side_b = 0.5 * (e1 + (legs[0] - legs[3]).norm());
  }
  EdgeSizes out;
  out.first_edge_long = side_a >= side_b;
  out.long_m = std::max(side_a, side_b);
  out.short_m = std::min(side_a, side_b);
  return out;
}

ModelPair ScoreModel(const EdgeSizes& edges, const geometry::ShelfModel& model, int index) {
  ModelPair pair;
  pair.model = index;
  pair.err_L = std::abs(edges.long_m - model.length_m);
  pair.err_W = std::abs(edges.short_m - model.width_m);
  pair.err_sum = pair.err_L + pair.err_W;
  return pair;
}

bool PassesThresholds(const ModelPair& pair, const ModelMatchConfig& config) {
  return pair.err_L < config.gamma_L_m && pair.err_W < config.gamma_W_m &&
         pair.err_sum < config.gamma_sum_m;
}

std::vector<ModelPair> MatchModels(const EdgeSizes& edges,
                                   const std::vector<geometry::ShelfModel>& models,
                                   const ModelMatchConfig& config) {
  std::vector<ModelPair> pairs;
  for (int i = 0; i < static_cast<int>(models.size()); ++i) {
    const ModelPair pair = ScoreModel(edges, models[i], i);
    if (PassesThresholds(pair, config)) pairs.push_back(pair);
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const ModelPair& a, const ModelPair& b) { return a.err_sum < b.err_sum; });
  // Keep the best model and those within lambda of it: close models (1075x883 vs 1080x856)
  // both survive the centroid-based screening and are told apart after the leg fit.
  if (!pairs.empty()) {
    const double best = pairs.front().err_sum;
    std::erase_if(pairs, [&](const ModelPair& p) { return p.err_sum - best > config.lambda_m; });
  }
  return pairs;
}

}  // namespace shelfdock::perception
