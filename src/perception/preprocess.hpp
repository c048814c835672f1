#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/edge_blending.hpp"
#include "perception/scan_point.hpp"
#include "perception/silhouette_edges.hpp"

namespace shelfdock::perception {

/// Consecutive points of one object.
struct Cluster {
  std::vector<ScanPoint> points;                       ///< beam order
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  ///< [m] mean of the points (Eq. 3)
  double extent_m = 0.0;  ///< [m] largest distance of a point from the first one
  int span = -1;          ///< index in PreprocessOutput::spans (-1 when built on its own)
  SilhouetteEdges edges;  ///< where the scan shows the object's outline to end (leg fit)
  /// [m] Set for a thin leg seen only blended with its background (CompleteLegSets): its
  /// returns tell its bearing, not its range, so the leg stands at this range on their bearing.
  std::optional<double> assumed_range_m;
  /// Cut from a surface it stands in front of (SurfaceProtrusions), inside a cluster no other
  /// rule would have split: CompleteLegSets looks at its returns as at any wall's.
  bool from_surface = false;
  /// Completed as a leg flush with something small beside it (CompleteLegSets,
  /// completion.flush_object_max_m): its returns trimmed to the leg from its free edge.
  bool flush = false;
  /// ... and cut from a wider candidate's returns (completion.merged_candidates): the search
  /// took them for part of something else, so a set leaning on it is held as a blended one is.
  bool cut_from_candidate = false;
};

/// Where a blended leg (Cluster::assumed_range_m set) stands: at its assumed range on the
/// bearing of its returns' mean.
inline Eigen::Vector2d AssumedCentre(const Cluster& c) {
  return c.assumed_range_m.value_or(c.centroid.norm()) * c.centroid.normalized();
}

/// A cluster as a span [begin, end) of a point vector in beam order, with its shape.
struct ClusterSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  ///< [m] mean of the points (Eq. 3)
  double extent_m = 0.0;  ///< [m] largest distance of a point from the first one
  std::size_t size() const { return end - begin; }
};

/// What preprocessing (paper 3.1) hands the leg search.
struct PreprocessOutput {
  std::vector<ScanPoint> points;    ///< valid points after the trailing-point filter
  std::vector<ClusterSpan> spans;   ///< every cluster of `points` (inside the ROI or not)
  std::vector<Cluster> candidates;  ///< clusters that fit a leg of some model
  int roi_points = 0;               ///< points in clusters inside the ROI
  int clusters = 0;                 ///< clusters inside the ROI, before screening
  int trailing_removed = 0;         ///< points removed by the Eq. 1 filter
  double range_noise_m = 0.0;       ///< [m] the scan's range noise (EstimateRangeNoise; 0: unknown)
  EdgeBlendingEstimate edge_blending;  ///< its large depth steps and the bridged ones
  /// Whether they show a sensor that blends every echo of a beam however far apart
  /// (PreprocessConfig::blend_any_share, blend_any_min_bridged): its thin legs' edge beams
  /// return blends with what stands behind them.
  bool blends_every_echo = false;
  /// [rad] How much wider than they stand the scan's sensor draws thin objects
  /// (EstimateWidthBloom; set by the detector, 0 until then).
  double width_bloom_rad = 0.0;
  int split_candidates = 0;   ///< candidates cut from wider clusters at a depth step
  int stray_returns = 0;      ///< lone returns too narrow for a leg at their range (stray echoes)
  int joined_candidates = 0;  ///< candidates joined from fragments of one leg (noise breaks)
};

/// Ranges to points, skipping NaN, infinite, zero and out-of-[range_min, range_max] returns.
std::vector<ScanPoint> ScanToPoints(const geometry::LaserScan& scan);

/// The clustering rule: splits points (beam order) where the gap exceeds the range-adaptive
/// break distance cluster_gap_m + cluster_gap_beams * r * |angle_increment| per beam step, or
/// where more than cluster_max_missing_beams beams in between returned nothing. Spans index into
/// `points`; nothing is copied.
std::vector<ClusterSpan> ClusterSpans(const std::vector<ScanPoint>& points,
                                      double angle_increment_rad, const PreprocessConfig& config);

/// ClusterSpans with each span's points copied out.
std::vector<Cluster> ClusterPoints(const std::vector<ScanPoint>& points, double angle_increment_rad,
                                   const PreprocessConfig& config);

/// Eq. 1: the angle beta at the farther point F between the ray back to the sensor and the
/// segment to its neighbour N, beta = atan(|ON| sin(alpha) / (|OF| - |ON| cos(alpha))).
double TrailingAngle(double range_far_m, double range_near_m, double alpha_rad);

/// Removes trailing (mixed) points from points in beam order: of two neighbouring beams whose
/// depth jump exceeds the noise and whose Eq. 1 angle beta is too small, the farther point is
/// dropped. Returns how many were removed.
int RemoveTrailingPoints(std::vector<ScanPoint>& points, double angle_increment_rad,
                         const PreprocessConfig& config);

/// The narrowest section of any leg of `models` [m] (the smaller of a leg's two sides, the
/// diameter of a round one); +infinity for no models.
double NarrowestLegSection(const std::vector<geometry::ShelfModel>& models);

/// The widest a leg cluster may be [m]: the largest leg diagonal of `models` plus
/// leg_extent_margin_m, or plus leg_extent_noise_sigmas * sqrt 2 * range_noise_m when that is
/// more (range noise stretches a leg's returns along the beams).
double MaxLegExtent(const std::vector<geometry::ShelfModel>& models, const PreprocessConfig& config,
                    double range_noise_m);

/// The depth step that sets an object off from what stands beside or behind it (cutting merged
/// clusters, an outline's edge): split_min_step_m, or split_noise_steps times the noise of a
/// difference of two ranges (sqrt 2 * range_noise_m) when that is more.
double SplitStep(const PreprocessConfig& config, double range_noise_m);

/// How close to the line through its beam neighbours a piece lies when it continues their
/// surface (ContinuesSurface): surface_tolerance_m, or surface_noise_sigmas * range_noise_m
/// when that is more.
double SurfaceTolerance(const PreprocessConfig& config, double range_noise_m);

/// The surface test's limits, declared in perception/surface_protrusion.hpp.
struct ProtrusionLimits;

/// The surface test's limits (SurfaceProtrusions, ProtrusionSigmas) that the scan and these
/// settings fix, whoever runs the test: the scan's range noise (with a floor: a scan whose noise
/// could not be estimated reports 0), inner_surface_points, SurfaceTolerance as the surface's RMS,
/// cluster_max_missing_beams, `max_leg_extent_m` (MaxLegExtent) as the widest piece and the
/// depth step a piece's end needs (split_min_step_m, or inner_step_sigmas times the noise of a
/// difference of two ranges when more). The rest keeps its defaults, for the caller to set.
ProtrusionLimits SurfaceTestLimits(const PreprocessConfig& config, double range_noise_m,
                                   double max_leg_extent_m);

/// True when a cluster's extent is at most max_extent_m (MaxLegExtent of the scan) and its point
/// count fits a leg of some model at its range.
bool FitsLegSize(const Eigen::Vector2d& centroid, double extent_m, std::size_t num_points,
                 double angle_increment_rad, const std::vector<geometry::ShelfModel>& models,
                 const PreprocessConfig& config, double max_extent_m);

/// The whole of paper 3.1. With a preset shelf pose, only clusters whose centroid lies within
/// roi_gamma * R of the preset centre are kept.
PreprocessOutput Preprocess(const std::vector<ScanPoint>& points, double angle_increment_rad,
                            const std::optional<geometry::Pose2>& T_lidar_preset,
                            const std::vector<geometry::ShelfModel>& models,
                            const PreprocessConfig& config);

}  // namespace shelfdock::perception
