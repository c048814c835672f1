#include "eval/peers/centroid_peer.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "perception/leg_search.hpp"
#include "perception/model_match.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::eval::peers {

std::optional<PeerEstimate> CentroidPeerDetect(const geometry::LaserScan& scan,
                                               const std::optional<geometry::Pose2>& T_lidar_preset,
                                               const std::vector<geometry::ShelfModel>& models,
                                               const perception::DetectorConfig& config) {
  const std::vector<perception::ScanPoint> points = perception::ScanToPoints(scan);
  const perception::PreprocessOutput pre = perception::Preprocess(
      points, scan.angle_increment, T_lidar_preset, models, config.preprocess);
  std::vector<Eigen::Vector2d> centres;
  for (const perception::Cluster& c : pre.candidates) centres.push_back(c.centroid);
  const std::vector<perception::LegSet> sets =
      perception::SearchLegSets(centres, models, config.leg_search);

  std::optional<PeerEstimate> best;
  double best_score = std::numeric_limits<double>::infinity();
  for (const perception::LegSet& set : sets) {
    std::array<Eigen::Vector2d, 4> legs;
    for (int k = 0; k < set.count; ++k) legs[k] = centres[set.legs[k]];
    const perception::EdgeSizes edges = perception::MeasureEdges(legs, set.count);
    const std::vector<perception::ModelPair> pairs =
        perception::MatchModels(edges, models, config.model_match);
    if (pairs.empty()) continue;
    const geometry::ShelfModel& model = models[pairs.front().model];
    // The centre: the mean of four legs, or the middle of a 3-leg set's hypotenuse.
    const Eigen::Vector2d centre =
        set.count == 4 ? Eigen::Vector2d(0.25 * (legs[0] + legs[1] + legs[2] + legs[3]))
                       : Eigen::Vector2d(0.5 * (legs[0] + legs[2]));
    // The heading: the long edges' direction (legs are in cyclic order).
    Eigen::Vector2d along = edges.first_edge_long ? legs[1] - legs[0] : legs[2] - legs[1];
    if (set.count == 4) {
      const Eigen::Vector2d opposite =
          edges.first_edge_long ? legs[2] - legs[3] : legs[3] - legs[0];
      along += opposite.dot(along) >= 0.0 ? opposite : Eigen::Vector2d(-opposite);
    }
    geometry::Pose2 T_lidar_shelf(centre.x(), centre.y(), std::atan2(along.y(), along.x()));
    T_lidar_shelf.yaw =
        ResolvePeerHeading(T_lidar_shelf.yaw, T_lidar_shelf, T_lidar_preset, model.HeadingPeriod());
    const double score = T_lidar_preset ? geometry::Distance(T_lidar_shelf, *T_lidar_preset)
                                        : pairs.front().err_sum - set.count;
    if (score < best_score) {
      best_score = score;
      best = PeerEstimate{model.name, T_lidar_shelf, set.count};
    }
  }
  return best;
}

}  // namespace shelfdock::eval::peers
