#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::perception {

/// What the scan says about one leg of a shelf hypothesis.
enum class LegView {
  kSeen,         ///< a leg cluster of the hypothesis
  kPresent,      ///< no leg cluster, but returns at the leg's range in its direction
  kOccluded,     ///< something nearer blocks the beams toward it: excused
  kSeenThrough,  ///< beams pass where the leg should stand: the leg is not there
  kUnobserved,   ///< no beam says anything (outside the field of view, dropouts)
};

/// The evidence the scan holds for or against one hypothesis (a shelf pose and model).
struct ShelfEvidence {
  std::array<LegView, 4> legs{LegView::kUnobserved, LegView::kUnobserved, LegView::kUnobserved,
                              LegView::kUnobserved};  ///< per model corner (LegCentres order)
  int legs_measured = 0;  ///< own candidates placed by their own returns (no blend's assumed range)
  int legs_seen = 0;      ///< kSeen + kPresent
  int legs_occluded = 0;  ///< kOccluded
  int legs_seen_through = 0;  ///< kSeenThrough
  /// Of legs_occluded, those hidden (also) by something that is not one of its own legs.
  int legs_hidden_by_other = 0;
  /// Of the unobserved legs, those whose bearing lies inside the scan's field of view (between
  /// its first and last return): beams looked there and none came back near the leg.
  int legs_unobserved_in_view = 0;
  /// Of the kPresent legs, those whose returns belong to a cluster wider than
  /// EvidenceConfig::max_present_object_m: a box, a wall or a rack stands where the leg should.
  int legs_in_large_object = 0;
  /// Of its own leg clusters, those that may be a thinner leg blended with its background
  /// (MayBeBlend): their range overstates the leg's.
  int legs_maybe_blended = 0;
  int interior_points = 0;      ///< points inside the footprint shrunk by interior_margin_m,
                                ///< not counting the occluders that hide one of its legs
  int interior_leg_points = 0;  ///< of interior_points, those of foreign legs
  /// The other interior points (objects), each weighted by its beam spacing over
  /// EvidenceConfig::object_point_spacing_m, at most 1.
  double interior_object_points = 0.0;
  int foreign_legs_inside = 0;   ///< legs of other leg sets (not its own) standing inside, and
                                 ///< lone legs on its edge lines (OnEdgeLine in the .cpp)
  double leg_width_error_m = 0;  ///< worst |seen width - model leg's silhouette| over its legs
  double leg_width_bias_m = 0;   ///< mean (seen width - model leg's silhouette) over its legs
                                 ///< with both outline edges seen (or seen too wide)
  double leg_width_bias_excess_m = 0;  ///< |leg_width_bias_m| beyond its allowance
  double width_bloom_rad = 0.0;  ///< [rad] the bloom taken off its legs' widths (the scan's or
                                 ///< its own legs' common bloom; 0 where no map vouches for it)
  double confidence = 0.0;       ///< [0, 1], see ShelfConfidence
  /// The map vouches for the shelf (GatherEvidence's `vouched`): objects inside weigh less.
  bool vouched = false;
};

/// What a cluster of the scan (a PreprocessOutput span) is to the free-space check.
enum class SpanRole : char {
  kOther,            ///< a leg of no leg set of the search
  kLeg,              ///< a leg of some leg set (a shelf-shaped group), its outline whole
  kPartlyHiddenLeg,  ///< the same, but something nearer hides one side of it (SilhouetteEdges'
                     ///< cut): it may be the visible sliver of a larger object
  kLoneLeg,          ///< a leg candidate in no leg set, its outline whole: inside a footprint
                     ///< an object like any other, on its edge line a leg (OnEdgeLine)
};

/// The scan as GatherEvidence reads it, the same for every hypothesis of one detection.
struct EvidenceScan {
  const PreprocessOutput& pre;  ///< Preprocess on the scan (its points in beam order)
  /// Per cluster (pre.spans): which belong to some leg set of the search (legs of some
  /// shelf-shaped group): inside a footprint they are the phantom's signature; spans past its end
  /// count as kOther.
  const std::vector<SpanRole>& span_roles;
  double angle_increment_rad = 0.0;  ///< [rad] the scan's beam spacing
  /// [m] the narrowest side of any model's leg (NarrowestLegSection), which says where one return
  /// can be a leg (EvidenceConfig::edge_lone_max_beams; 0: anywhere).
  double narrowest_leg_m = 0.0;
};

/// Gathers the evidence for a shelf at `T_lidar_shelf` of `model` whose model corner k is the
/// leg candidate `corner_candidate[k]` (index into scan.pre.candidates, -1 when no cluster).
/// `vouched`: the map vouches for a shelf there (a preset within its own error).
/// `corner_error_m` [m]: how far off the pose may put a corner no candidate stands for (the
/// detector passes half the legs' RMS off their fitted corners): beams through a missing leg's
/// core prove it absent only where the corner is known that well.
ShelfEvidence GatherEvidence(const geometry::Pose2& T_lidar_shelf,
                             const geometry::ShelfModel& model,
                             const std::array<int, 4>& corner_candidate, const EvidenceScan& scan,
                             bool vouched, const EvidenceConfig& config,
                             double corner_error_m = 0.0);

/// True when the leg candidate `c` may be a thinner leg seen only blended with what stands close
/// behind it (one echo between the two, Eq. 1's mixed point with no clean return of the leg): at
/// most blend_max_returns returns, and the beams either side returned from behind it, at most
/// blend_max_step_m. Its range then overstates the leg's. Never for blend_max_returns 0, or for
/// a cluster already placed by its bearing (Cluster::assumed_range_m).
bool MayBeBlend(const Cluster& c, const EvidenceConfig& config);

/// Confidence in [0, 1]: the product of
/// - leg support: (seen + occluded_credit * occluded + unobserved_credit * unobserved) / 4,
///   a leg seen through counts 0;
/// - fit: 1 / (1 + chi2 / (dof * c)), where chi2 is the legs' chi-square against the model
///   (RefineShelfPose: each leg's error along and across its beam over what its own returns
///   allow), dof = 2 legs - 3 its degrees of freedom and c fit_chi2_three_legs or
///   fit_chi2_four_legs;
/// - free space: 1 / (1 + blocked / interior_scale_points), where blocked counts each interior
///   point of a foreign leg once, each other interior point (interior_object_points: near the
///   sensor less than one each) object_point_weight times (once when a leg is missing, nothing
///   hides it and no map vouches for the shelf), and each foreign leg inside foreign_leg_points
///   more (what hides a missing leg counts nothing, and a foreign leg within hider_partner_m of
///   it, the one thing inside besides it, counts as an object: the hider's other part);
/// - leg size: 1 / (1 + (leg_width_error_m / leg_width_scale_m)^2)
///             / (1 + (leg_width_bias_excess_m / leg_width_scale_m)^2).
/// It reads as "how sure the scan makes us that this is a shelf of this model here": 1 is four
/// legs seen at model size with nothing between them.
double ShelfConfidence(const ShelfEvidence& evidence, double leg_chi2, int legs,
                       const EvidenceConfig& config);

/// [rad] Angle a leg section (rectangle length x width with its x axis at `leg_yaw`, or a
/// circle) centred at `centre` subtends at the sensor (the origin): between its outline's
/// tangents, exact at any range (near the sensor a square leg's extreme corners lie at
/// different depths, and a width across the beam at the centre's range is no longer what the
/// beams see).
double LegSilhouetteAngle(const geometry::LegModel& leg, double leg_yaw,
                          const Eigen::Vector2d& centre);

}  // namespace shelfdock::perception
