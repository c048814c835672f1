#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"

namespace shelfdock::perception {

/// The next-best model on a detection's legs (Detection::runner_up).
struct RunnerUp {
  std::string model;         ///< its name
  double chi2_margin = 0.0;  ///< [-] the chi-square of its shelf fitted to the legs' returns
                             ///< (FitShelfToReturns) minus the returned model's (>= 0)
};

/// One shelf found in a scan, in the scan's frame (`lidar`).
struct Detection {
  std::string model;                  ///< name of the matched shelf model
  geometry::Pose2 T_lidar_shelf;      ///< shelf centre and heading (long side)
  double length_m = 0.0;              ///< fitted long side (mean of the long edges)
  double width_m = 0.0;               ///< fitted short side (mean of the short edges)
  std::vector<Eigen::Vector2d> legs;  ///< fitted leg centres [m], lidar frame
  int legs_used = 0;                  ///< 3 or 4
  double err_sum = 0.0;               ///< Eq. 2 err_L + err_W of the matched model [m]
  double cost = 0.0;                  ///< final cost of the shelf-pose fit [m^2]
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of (x, y, yaw) [m^2, rad^2], of
                                                         ///< T_lidar_shelf_fit
  /// The robust shelf fit's pose (3.4), the one `covariance` describes; T_lidar_shelf refines it
  /// on the legs' returns (FitShelfToReturns). nullopt: T_lidar_shelf is the fit's pose (a
  /// detection built elsewhere, e.g. in tests).
  std::optional<geometry::Pose2> T_lidar_shelf_fit;
  /// [0, 1] how strongly the scan supports this shelf (legs seen, hidden or unobserved, fit
  /// error, free space inside the footprint, leg sizes); see perception::ShelfConfidence.
  double confidence = 0.0;
  int legs_visible = 0;            ///< model legs seen in the scan (3 or 4)
  int legs_occluded = 0;           ///< model legs hidden behind something nearer
  int interior_points = 0;         ///< scan points inside the footprint (occluders excused)
  double leg_width_error_m = 0.0;  ///< [m] worst seen leg width against the model's, beyond a beam
  double leg_width_bias_m = 0.0;   ///< [m] mean seen leg width minus the model's silhouette
  /// The next-best model on the same legs, when its hypothesis passed every check too (close
  /// models, e.g. 1075x883 and 1080x856 with 27 mm between their widths), and how much worse
  /// the legs fit it. A margin of a few units means the returns barely tell the two models
  /// apart; empty: no other model fitted.
  std::optional<RunnerUp> runner_up;

  /// The pose to fuse with `covariance` in a filter: the fit's. In docking the refined pose's
  /// heading tail was worse (warehouse_aisle, p99 before the code check 4.7 -> 5.5 mrad).
  geometry::Pose2 FusionPose() const { return T_lidar_shelf_fit.value_or(T_lidar_shelf); }
};

/// Why hypotheses (leg sets paired with a model) were not returned, one count per hypothesis
/// and reason (the first reason that applied).
struct RejectionCounts {
  int fit = 0;                   ///< shelf fit failed, did not converge or left legs off the model
  int model = 0;                 ///< Eq. 2 on the fitted legs: no longer this model's size
  int three_leg_error = 0;       ///< 3-leg set beyond the stricter three_leg_err_sum_m
  int hidden_leg_no_preset = 0;  ///< without a preset, 3 legs whose 4th is hidden by something
                                 ///< other than its own legs: nothing vouches for it
  int leg_seen_through = 0;      ///< beams pass where a leg of the hypothesis should stand
  int blended_legs = 0;          ///< two or more legs may be blends of thinner legs and their
                                 ///< background, and the legs look narrower than the model's
  int low_confidence = 0;        ///< the evidence is too weak (confidence < min_confidence)
  int lost_legs = 0;             ///< its legs went to a better-supported shelf (or a better model)
  int off_preset = 0;            ///< won its legs, but stands too far from (or turned against) the
                                 ///< preset: a neighbour or clutter, not the expected shelf
};

/// Counters that tell where candidates were dropped; useful when tuning on real scans.
struct DetectionStats {
  int valid_points = 0;        ///< finite returns within [range_min, range_max]
  int roi_points = 0;          ///< points kept by the region of interest
  int clusters = 0;            ///< clusters before size screening
  int trailing_removed = 0;    ///< points dropped by the Eq. 1 trailing-point filter
  int leg_candidates = 0;      ///< clusters that fit the size of some model's leg
  int leg_sets = 0;            ///< 3- and 4-leg sets that passed the geometric search
  int model_pairs = 0;         ///< points-model pairs that passed Eq. 2 screening
  int hypotheses = 0;          ///< points-model pairs fitted and scored (one per pair)
  int completed_sets = 0;      ///< leg sets completed from two candidates (CompleteLegSets)
  double range_noise_m = 0.0;  ///< [m] range noise the scan shows (EstimateRangeNoise; 0: unknown)
  double width_bloom_rad = 0.0;  ///< [rad] how much wider the scan draws thin objects
                                 ///< (EstimateWidthBloom; 0: true to their width)
  int depth_steps = 0;       ///< large depth steps with no return between (EstimateEdgeBlending)
  int bridged_steps = 0;     ///< large depth steps bridged by one mixed return
  int stray_returns = 0;     ///< lone returns no leg could make at their range (stray echoes:
                             ///< PreprocessConfig::lone_return_max_beams), not candidates
  RejectionCounts rejected;  ///< why hypotheses were not returned
};

/// What became of one hypothesis (a leg set paired with a model).
enum class Verdict {
  kReturned,           ///< returned as a detection
  kFit,                ///< RejectionCounts::fit
  kModel,              ///< RejectionCounts::model
  kThreeLegError,      ///< RejectionCounts::three_leg_error
  kHiddenLegNoPreset,  ///< RejectionCounts::hidden_leg_no_preset
  kLegSeenThrough,     ///< RejectionCounts::leg_seen_through
  kBlendedLegs,        ///< RejectionCounts::blended_legs
  kLowConfidence,      ///< RejectionCounts::low_confidence
  kLostLegs,           ///< RejectionCounts::lost_legs
  kOffPreset,          ///< RejectionCounts::off_preset
};
/// The verdict's snake_case name, as in `detect --explain` and `stats.rejected`.
const char* VerdictName(Verdict verdict);

/// One hypothesis as the detector saw it, for explaining a scan ("why was my shelf not found").
struct HypothesisRecord {
  std::string model;
  geometry::Pose2 T_lidar_shelf;      ///< the 3.4 fit (heading not yet resolved)
  std::vector<Eigen::Vector2d> legs;  ///< fitted leg centres [m]
  /// Per leg of `legs`: true where the scan showed the leg only blended with what stands close
  /// behind it, so it stands on its returns' bearing at the range the completed shelf puts it
  /// (CompleteLegSets; its range was not measured), false where its own returns placed it.
  std::vector<bool> legs_blended;
  /// Per leg of `legs`: true where the completion took the leg's returns off something small
  /// standing flush beside it (completion.flush_object_max_m), trimmed to the leg.
  std::vector<bool> legs_flush;
  /// Per leg of `legs`: how many of its outer returns (0-2) its fit weighed as possible blends of
  /// the leg and the surface past its edge (FindMixedEdges; 0 for a blended leg, and for all
  /// with leg_fit.mixed_edge_share 0).
  std::vector<int> legs_edge_blends;
  double err_sum = 0.0;     ///< [m] Eq. 2 on the fitted legs (0 when the fit failed)
  double confidence = 0.0;  ///< 0 when rejected before the evidence was weighed
  int legs_visible = 0;
  int legs_occluded = 0;
  int legs_seen_through = 0;
  int interior_points = 0;
  int foreign_legs_inside = 0;
  double leg_width_error_m = 0.0;
  double leg_width_bias_m = 0.0;
  double width_bloom_rad = 0.0;  ///< [rad] the bloom its leg widths were granted (ShelfEvidence)
  Verdict verdict = Verdict::kFit;
};

/// A leg candidate as the geometric search (3.2) saw it (`detect --explain`): where no leg set
/// forms, these tell whether a leg in sight became no candidate or stood off its place.
struct CandidateRecord {
  /// [m] the centre the search used: the returns' mean pushed back from the sensor by half the
  /// thinnest model leg's depth, or a blended leg's assumed centre
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  int returns = 0;         ///< returns it is made of
  int first_beam = 0;      ///< beam index of its first return (beam order)
  int last_beam = 0;       ///< ... and of its last
  double extent_m = 0.0;   ///< [m] largest distance of a return from the first one
  bool completed = false;  ///< cut at a predicted corner by the completion (CompleteLegSets)
  bool blended = false;    ///< ... seen only blended with its background (assumed range)
  bool flush = false;      ///< ... taken off something small flush beside it
};

/// Everything Detector::Detect returns for one scan.
struct DetectionResult {
  std::vector<Detection> detections;  ///< best first; with a preset, nearest to it first
  DetectionStats stats;
  /// Every hypothesis with its evidence and verdict; filled only when asked for
  /// (Detector::Detect with explain = true).
  std::vector<HypothesisRecord> hypotheses;
  /// Every leg candidate (the scan's, then the completion's); filled only with explain.
  std::vector<CandidateRecord> candidates;
};

}  // namespace shelfdock::perception
