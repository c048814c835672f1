#include "perception/detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geometry/angle.hpp"
#include "perception/leg_fit.hpp"
#include "perception/leg_search.hpp"
#include "perception/model_match.hpp"
#include "perception/shelf_fit.hpp"

namespace shelfdock::perception {
namespace {

struct Candidate {
  Detection detection;
  std::array<int, 4> clusters{-1, -1, -1, -1};
};

// Leg fits depend only on the cluster and the leg section, so they are shared between the
// points-model pairs of a set and between sets that share a cluster.
struct LegFitCache {
  struct Entry {
    int cluster;
    const geometry::LegModel* leg;
    LegFitResult fit;
  };
  std::vector<Entry> entries;

  const LegFitResult& Get(int cluster, const geometry::ShelfModel& model, double hint,
                          const std::vector<Cluster>& clusters, const LegFitConfig& config) {
    for (const auto& e : entries) {
      if (e.cluster == cluster && e.leg->shape == model.leg.shape &&
          e.leg->length_m == model.leg.length_m && e.leg->width_m == model.leg.width_m) {
        return e.fit;
      }
    }
    entries.push_back(
        {cluster, &model.leg, FitLeg(clusters[cluster].points, model.leg, hint, config)});
    return entries.back().fit;
  }
};

// Free-space check: at the scan height a shelf's footprint is empty between its legs.
int CountInteriorPoints(const std::vector<ScanPoint>& points, const geometry::Pose2& T_lidar_shelf,
                        const geometry::ShelfModel& model, double margin_m) {
  const geometry::Pose2 T_shelf_lidar = T_lidar_shelf.inverse();
  const double hx = 0.5 * model.length_m - margin_m;
  const double hy = 0.5 * model.width_m - margin_m;
  int inside = 0;
  for (const auto& q : points) {
    const Eigen::Vector2d p = T_shelf_lidar * q.p;
    if (std::abs(p.x()) < hx && std::abs(p.y()) < hy) ++inside;
  }
  return inside;
}

// A 3-leg set claims its fourth leg is hidden or missed. Real clutter (furniture, the robot's
// own frame) forms right triangles of model size; what gives it away is that the beams toward
// the predicted fourth leg pass through it to something clearly farther, with no dip in range
// (a leg too thin for a clean return still pulls its mixed points nearer than their
// neighbours). Beams with no return are no evidence either way (dark legs drop out).
bool MissingLegContradicted(const std::vector<ScanPoint>& points, const Eigen::Vector2d& leg,
                            double leg_extent_m, double angle_increment_rad) {
  constexpr double kMargin_m = 0.15;  // farther than this behind the leg: seen through it
  constexpr double kDip_m = 0.05;     // nearer than the neighbours by this: something there
  const double range = leg.norm();
  if (range < 1e-6) return false;
  const double bearing = std::atan2(leg.y(), leg.x());
  const double half = std::atan2(0.5 * leg_extent_m, range) + 0.5 * std::abs(angle_increment_rad);
  int through = 0;
  double window_min = std::numeric_limits<double>::infinity();
  double outside_min = std::numeric_limits<double>::infinity();
  for (const auto& q : points) {
    const double d = std::abs(geometry::AngleDiff(q.angle, bearing));
    if (d <= half) {
      if (q.range <= range + kMargin_m) return false;  // a return at or before the leg
      ++through;
      window_min = std::min(window_min, q.range);
    } else if (d <= half + 2.0 * std::abs(angle_increment_rad)) {
      outside_min = std::min(outside_min, q.range);
    }
  }
  if (through < 2) return false;
  return window_min > outside_min - kDip_m;
}

// A 3-leg set around the sensor: the LiDAR would be under the shelf. Unless the preset says the
// robot is under it, one hidden leg there is likelier furniture (seen on the real bags) than a
// shelf, and docking stops using the LiDAR before it gets under the shelf anyway.
bool SensorInsideFootprint(const geometry::Pose2& T_lidar_shelf,
                           const geometry::ShelfModel& model) {
  const Eigen::Vector2d p = T_lidar_shelf.inverse() * Eigen::Vector2d::Zero();
  return std::abs(p.x()) < 0.5 * model.length_m && std::abs(p.y()) < 0.5 * model.width_m;
}

int SharedClusters(const Candidate& a, const Candidate& b) {
  int shared = 0;
  for (int i : a.clusters) {
    if (i >= 0 && std::find(b.clusters.begin(), b.clusters.end(), i) != b.clusters.end()) ++shared;
  }
  return shared;
}

}  // namespace

double ResolveHeading(double yaw_rad, double reference_rad, bool square) {
  const double step = square ? 0.5 * std::numbers::pi : std::numbers::pi;
  const double k = std::round(geometry::AngleDiff(reference_rad, yaw_rad) / step);
  return geometry::WrapAngle(yaw_rad + k * step);
}

Detector::Detector(std::vector<geometry::ShelfModel> models, DetectorConfig config)
    : models_(std::move(models)), config_(config) {
  if (models_.empty()) throw std::invalid_argument("models: at least one shelf model is needed");
  if (const auto v = FindConfigViolation(config_)) {
    throw std::invalid_argument(v->key + ": must be " + v->requirement);
  }
}

DetectionResult Detector::Detect(const geometry::LaserScan& scan,
                                 const std::optional<geometry::Pose2>& T_lidar_preset) const {
  return DetectPoints(ScanToPoints(scan), scan.angle_increment, T_lidar_preset);
}

DetectionResult Detector::DetectPoints(const std::vector<ScanPoint>& points,
                                       double angle_increment_rad,
                                       const std::optional<geometry::Pose2>& T_lidar_preset) const {
  DetectionResult result;
  DetectionStats& stats = result.stats;
  stats.valid_points = static_cast<int>(points.size());

  // 3.1 preprocessing.
  const PreprocessOutput pre =
      Preprocess(points, angle_increment_rad, T_lidar_preset, models_, config_.preprocess);
  stats.roi_points = pre.roi_points;
  stats.clusters = pre.clusters;
  stats.trailing_removed = pre.trailing_removed;
  stats.leg_candidates = static_cast<int>(pre.candidates.size());
  std::vector<Eigen::Vector2d> centres;
  centres.reserve(pre.candidates.size());
  for (const auto& c : pre.candidates) centres.push_back(c.centroid);

  // 3.2 geometric search.
  const std::vector<LegSet> sets = SearchLegSets(centres, models_, config_.leg_search);
  stats.leg_sets = static_cast<int>(sets.size());

  LegFitCache cache;
  std::vector<Candidate> candidates;
  for (const LegSet& set : sets) {
    std::array<Eigen::Vector2d, 4> rough{};
    for (int i = 0; i < set.count; ++i) rough[i] = centres[set.legs[i]];
    const EdgeSizes edges = MeasureEdges(rough, set.count);
    // Eq. 2 screening on the cluster centres.
    const std::vector<ModelPair> pairs = MatchModels(edges, models_, config_.model_match);
    stats.model_pairs += static_cast<int>(pairs.size());
    const Eigen::Vector2d long_edge = edges.first_edge_long ? Eigen::Vector2d(rough[1] - rough[0])
                                                            : Eigen::Vector2d(rough[2] - rough[1]);
    const double hint = std::atan2(long_edge.y(), long_edge.x());

    std::optional<Candidate> best;
    for (const ModelPair& pair : pairs) {
      const geometry::ShelfModel& model = models_[pair.model];
      // 3.3 leg centres, then 3.4 shelf pose.
      std::array<Eigen::Vector2d, 4> legs{};
      for (int i = 0; i < set.count; ++i) {
        legs[i] = cache.Get(set.legs[i], model, hint, pre.candidates, config_.leg_fit).centre;
      }
      const auto fit = FitShelf(legs, set.count, model, config_.shelf_fit);
      if (!fit || !fit->converged || fit->rms_m > config_.shelf_fit.max_rms_m) continue;
      // Eq. 2 again on the fitted (unbiased) leg centres: this is what tells close models apart.
      const ModelPair refined = ScoreModel(MeasureEdges(legs, set.count), model, pair.model);
      if (!PassesThresholds(refined, config_.model_match)) continue;
      if (set.count == 3 && refined.err_sum > config_.model_match.three_leg_err_sum_m) continue;
      if (set.count == 3 && SensorInsideFootprint(fit->T_lidar_shelf, model) &&
          !(T_lidar_preset && SensorInsideFootprint(*T_lidar_preset, model))) {
        continue;
      }
      if (set.count == 3 && MissingLegContradicted(points, legs[0] + legs[2] - legs[1],
                                                   std::min(model.leg.length_m, model.leg.width_m),
                                                   angle_increment_rad)) {
        continue;
      }
      if (best && refined.err_sum >= best->detection.err_sum) continue;
      if (config_.shelf_fit.max_interior_points >= 0 &&
          CountInteriorPoints(points, fit->T_lidar_shelf, model,
                              config_.shelf_fit.interior_margin_m) >
              config_.shelf_fit.max_interior_points) {
        continue;
      }
      Candidate c;
      c.clusters = set.legs;
      Detection& d = c.detection;
      d.model = model.name;
      d.T_lidar_shelf = fit->T_lidar_shelf;
      d.length_m = fit->length_m;
      d.width_m = fit->width_m;
      d.legs.assign(legs.begin(), legs.begin() + set.count);
      d.legs_used = set.count;
      d.err_sum = refined.err_sum;
      d.cost = fit->cost;
      d.covariance = fit->covariance;
      const double reference =
          T_lidar_preset ? T_lidar_preset->yaw : std::atan2(d.T_lidar_shelf.y, d.T_lidar_shelf.x);
      d.T_lidar_shelf.yaw = ResolveHeading(d.T_lidar_shelf.yaw, reference, model.IsSquare());
      best = std::move(c);
    }
    if (best) candidates.push_back(std::move(*best));
  }

  // One detection per shelf: a set sharing two or more legs with a better one is the same
  // shelf (or a mix of neighbours); more legs first, then the smaller err_sum.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.detection.legs_used != b.detection.legs_used) {
      return a.detection.legs_used > b.detection.legs_used;
    }
    return a.detection.err_sum < b.detection.err_sum;
  });
  std::vector<Candidate> kept;
  for (auto& c : candidates) {
    const bool duplicate = std::any_of(
        kept.begin(), kept.end(), [&](const Candidate& k) { return SharedClusters(c, k) >= 2; });
    if (!duplicate) kept.push_back(std::move(c));
  }
  if (T_lidar_preset) {
    std::stable_sort(kept.begin(), kept.end(), [&](const Candidate& a, const Candidate& b) {
      return geometry::Distance(a.detection.T_lidar_shelf, *T_lidar_preset) <
             geometry::Distance(b.detection.T_lidar_shelf, *T_lidar_preset);
    });
  }
  for (auto& c : kept) result.detections.push_back(std::move(c.detection));
  return result;
}

}  // namespace shelfdock::perception
