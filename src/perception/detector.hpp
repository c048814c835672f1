#pragma once

#include <optional>
#include <vector>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detection.hpp"
#include "perception/detector_config.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// The shelf detector (paper 3.1-3.4): one scan (and optionally a preset shelf pose, in the
/// scan's frame) in, every shelf found out, ranked.
///
/// Every Eq. 2 points-model pair is a hypothesis; the scan's evidence about it (legs seen,
/// hidden or seen through, free space, leg sizes) gives its confidence, and hypotheses compete
/// for legs (a leg cluster belongs to at most one returned shelf; see SelectDisjoint).
/// Ranking: with a preset, nearest to the preset centre first; without, more visible legs first,
/// then higher confidence.
/// Heading: x along the long side. The pi ambiguity (pi/2 for square models) is resolved toward
/// the preset heading when given; otherwise so that the shelf's x axis points away from the
/// sensor, i.e. cos(yaw - bearing of the centre) >= 0 (for a square, the candidate closest to
/// the bearing). A robot that drives straight at the shelf thus sees yaw ~ its bearing.
/// Thread-safe: Detect is const and keeps no state between calls.
class Detector {
 public:
  /// Throws std::invalid_argument when there are no models or a parameter is impossible (the
  /// message names the key, e.g. `preprocess.cluster_gap_m`).
  explicit Detector(std::vector<geometry::ShelfModel> models, DetectorConfig config = {});

  /// `explain`: also return every hypothesis with its evidence and verdict.
  DetectionResult Detect(const geometry::LaserScan& scan,
                         const std::optional<geometry::Pose2>& T_lidar_preset = std::nullopt,
                         bool explain = false) const;

  /// As Detect, for points already in the lidar frame (e.g. motion-compensated by the docking
  /// layer), in beam order; `angle_increment_rad` sets the range-adaptive thresholds.
  DetectionResult DetectPoints(const std::vector<ScanPoint>& points_in_beam_order,
                               double angle_increment_rad,
                               const std::optional<geometry::Pose2>& T_lidar_preset,
                               bool explain = false) const;

  const std::vector<geometry::ShelfModel>& models() const { return models_; }
  const DetectorConfig& config() const { return config_; }

 private:
  std::vector<geometry::ShelfModel> models_;
  DetectorConfig config_;
  double narrowest_leg_m_ = 0.0;  ///< [m] NarrowestLegSection(models_): the bloom estimate, and
                                  ///< where one return can be a leg (GatherEvidence)
};

/// Picks among the symmetric equivalents of `yaw_rad` (yaw + k period_rad; the model's
/// ShelfModel::HeadingPeriod: pi, or pi/2 for a square model) the one closest to `reference_rad`.
double ResolveHeading(double yaw_rad, double reference_rad, double period_rad);

}  // namespace shelfdock::perception
