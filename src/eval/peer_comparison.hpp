#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "eval/peer_scenes.hpp"
#include "eval/peers/peer_estimate.hpp"
#include "geometry/laser_scan.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"

namespace shelfdock::eval {

/// The methods `eval peers` runs side by side on the same scans.
enum class PeerMethod {
  kShelfdock,  ///< perception::Detector
  kCentroid,   ///< peers::CentroidPeerDetect: no leg fit (3.3), no shelf fit (3.4)
  kCorner,     ///< peers::CornerPeerDetect: corner finding as open ROS shelf detectors
  kIcp,        ///< peers::IcpPeer: PCL ICP on the legs' outline; its own library, built only
               ///< with SHELFDOCK_WITH_PCL, so ComparePeers takes it as a function
};
/// The method's name in tables and JSON.
std::string_view PeerMethodName(PeerMethod method);

/// What counts as a success.
struct PeerScoring {
  double success_radius_m = 0.05;  ///< [m] the answer's centre within this of the truth, and
                                   ///< its model the target's
};

/// Median and 95th percentile of a sample (NaN when empty).
struct Quantiles {
  double p50 = std::numeric_limits<double>::quiet_NaN();
  double p95 = std::numeric_limits<double>::quiet_NaN();
};

/// One method on one scene set.
struct PeerRow {
  std::string set;
  PeerMethod method = PeerMethod::kShelfdock;
  int scenes = 0;
  int successes = 0;
  Quantiles position_m;   ///< [m] over successes
  Quantiles heading_rad;  ///< [rad] over successes, modulo the model's symmetry
  Quantiles time_s;       ///< [s] per scan, every scene

  double SuccessRate() const { return scenes > 0 ? static_cast<double>(successes) / scenes : 0.0; }
};

/// The search work on one scene set, all leg candidates of the scan (no region of interest).
struct SearchRow {
  std::string set;
  int scenes = 0;
  double mean_candidates = 0.0;         ///< leg candidates per scan
  double mean_pruned_checks = 0.0;      ///< perception::SearchLegSets
  double mean_exhaustive_checks = 0.0;  ///< peers::ExhaustiveLegSets
  Quantiles pruned_time_s;              ///< [s] per scan
  Quantiles exhaustive_time_s;          ///< [s] per scan
};

/// A clock in seconds, injected by the caller (the core does not read the clock itself).
using ClockFn = std::function<double()>;

/// One scan in, the method's shelf out (nullopt: none found).
using PeerDetectFn = std::function<std::optional<peers::PeerEstimate>(
    const geometry::LaserScan& scan, const std::optional<geometry::Pose2>& T_lidar_preset)>;

/// Runs shelfdock, centroid-only, corner-finding and, when the caller has one, `icp` (kIcp's row)
/// on every scene of `set` and scores each against the truth; each call timed with `now_s`.
std::vector<PeerRow> ComparePeers(const PeerSceneSet& set,
                                  const std::vector<geometry::ShelfModel>& models,
                                  const perception::DetectorConfig& detector, const ClockFn& now_s,
                                  const PeerDetectFn& icp = nullptr,
                                  const PeerScoring& scoring = {});

/// Counts and times the pruned and the exhaustive leg search on every scene of `set`, over all
/// the scan's leg candidates (no preset, so no region of interest).
SearchRow CompareSearch(const PeerSceneSet& set, const std::vector<geometry::ShelfModel>& models,
                        const perception::DetectorConfig& detector, const ClockFn& now_s);

}  // namespace shelfdock::eval
