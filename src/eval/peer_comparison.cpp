#include "eval/peer_comparison.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "eval/monte_carlo.hpp"
#include "eval/peers/centroid_peer.hpp"
#include "eval/peers/corner_peer.hpp"
#include "eval/peers/exhaustive_leg_search.hpp"
#include "geometry/angle.hpp"
#include "perception/detector.hpp"
#include "perception/leg_search.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::eval {
namespace {

Quantiles QuantilesOf(const std::vector<double>& v) {
  return {Quantile(v, 0.5), Quantile(v, 0.95)};
}

}  // namespace

std::string_view PeerMethodName(PeerMethod method) {
  switch (method) {
    case PeerMethod::kShelfdock:
      return "shelfdock";
    case PeerMethod::kCentroid:
      return "centroid-only";
    case PeerMethod::kCorner:
      return "corner-finding";
    case PeerMethod::kIcp:
      return "icp-pcl";
  }
  return "?";
}

std::vector<PeerRow> ComparePeers(const PeerSceneSet& set,
                                  const std::vector<geometry::ShelfModel>& models,
                                  const perception::DetectorConfig& detector_config,
                                  const ClockFn& now_s, const PeerDetectFn& icp,
                                  const PeerScoring& scoring) {
  const perception::Detector detector(models, detector_config);
  using Scan = geometry::LaserScan;
  using Preset = std::optional<geometry::Pose2>;
  std::vector<std::pair<PeerMethod, PeerDetectFn>> methods = {
      {PeerMethod::kShelfdock,
       [&](const Scan& scan, const Preset& preset) -> std::optional<peers::PeerEstimate> {
         const perception::DetectionResult r = detector.Detect(scan, preset);
         if (r.detections.empty()) return std::nullopt;
         return peers::PeerEstimate{r.detections[0].model, r.detections[0].T_lidar_shelf,
                                    r.detections[0].legs_used};
       }},
      {PeerMethod::kCentroid,
       [&](const Scan& scan, const Preset& preset) {
         return peers::CentroidPeerDetect(scan, preset, models, detector_config);
       }},
      {PeerMethod::kCorner,
       [&](const Scan& scan, const Preset& preset) {
         return peers::CornerPeerDetect(scan, preset, models, detector_config);
       }},
  };
  if (icp) methods.emplace_back(PeerMethod::kIcp, icp);

  std::vector<PeerRow> rows;
  for (const auto& [method, detect] : methods) {
    PeerRow row;
    row.set = set.name;
    row.method = method;
    std::vector<double> pos, yaw, time;
    for (const PeerScene& scene : set.scenes) {
      const double t0 = now_s();
      const std::optional<peers::PeerEstimate> answer = detect(scene.scan, scene.T_lidar_preset);
      time.push_back(now_s() - t0);
      ++row.scenes;
      if (!answer || answer->model != scene.model) continue;
      const double e = geometry::Distance(answer->T_lidar_shelf, scene.T_lidar_shelf);
      if (e > scoring.success_radius_m) continue;
      ++row.successes;
      pos.push_back(e);
      yaw.push_back(geometry::AngleDiffModulo(answer->T_lidar_shelf.yaw, scene.T_lidar_shelf.yaw,
                                              scene.heading_period_rad));
    }
    row.position_m = QuantilesOf(pos);
    row.heading_rad = QuantilesOf(yaw);
    row.time_s = QuantilesOf(time);
    rows.push_back(row);
  }
  return rows;
}

SearchRow CompareSearch(const PeerSceneSet& set, const std::vector<geometry::ShelfModel>& models,
                        const perception::DetectorConfig& detector, const ClockFn& now_s) {
  SearchRow row;
  row.set = set.name;
  std::vector<double> pruned_t, exhaustive_t;
  double candidates = 0.0, pruned = 0.0, exhaustive = 0.0;
  for (const PeerScene& scene : set.scenes) {
    const perception::PreprocessOutput pre =
        perception::Preprocess(perception::ScanToPoints(scene.scan), scene.scan.angle_increment,
                               std::nullopt, models, detector.preprocess);
    std::vector<Eigen::Vector2d> centres;
    for (const perception::Cluster& c : pre.candidates) centres.push_back(c.centroid);
    perception::LegSearchCounts p, e;
    // The detector caps the sets it keeps (max_leg_sets); both searches here run uncapped so
    // that they do the same job.
    perception::LegSearchConfig search = detector.leg_search;
    search.max_leg_sets = 1 << 30;
    const double t0 = now_s();
    const auto pruned_sets = perception::SearchLegSets(centres, models, search, &p);
    const double t1 = now_s();
    const auto exhaustive_sets = peers::ExhaustiveLegSets(centres, models, search, &e);
    const double t2 = now_s();
    pruned_t.push_back(t1 - t0);
    exhaustive_t.push_back(t2 - t1);
    candidates += static_cast<double>(centres.size());
    pruned += static_cast<double>(p.checks);
    exhaustive += static_cast<double>(e.checks);
    ++row.scenes;
  }
  if (row.scenes > 0) {
    row.mean_candidates = candidates / row.scenes;
    row.mean_pruned_checks = pruned / row.scenes;
    row.mean_exhaustive_checks = exhaustive / row.scenes;
  }
  row.pruned_time_s = QuantilesOf(pruned_t);
  row.exhaustive_time_s = QuantilesOf(exhaustive_t);
  return row;
}

}  // namespace shelfdock::eval
