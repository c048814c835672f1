#pragma once

#include <optional>
#include <string>

#include "geometry/config_violation.hpp"

namespace shelfdock::perception {

/// Paper 3.1: ranges to points, region of interest, clustering, trailing points, size screening.
struct PreprocessConfig {
  double roi_gamma = 0.75;  ///< [-] ROI radius around the preset = roi_gamma * R (R: longest
                            ///< model diagonal); the paper's gamma. Must exceed 0.5 to hold legs.
  double cluster_gap_m = 0.05;        ///< [m] break distance between consecutive points at range 0
  double cluster_gap_beams = 2.0;     ///< [-] plus this many beam spacings at the point's range
  int cluster_max_missing_beams = 3;  ///< [-] beams without return tolerated inside a cluster
                                      ///< (dark legs drop some); a longer hole splits it
  double trailing_min_angle_rad = 0.17;  ///< [rad] Eq. 1: beta below this marks a trailing point
  double trailing_min_jump_m = 0.04;     ///< [m] depth jumps below this are noise, not trailing
  double leg_extent_margin_m = 0.04;     ///< [m] a leg cluster may exceed the leg diagonal by this
  double leg_extent_noise_sigmas = 3.0;  ///< [-] or by this many times the scan's range noise
                                         ///< (times sqrt 2, a difference of two ranges), if more
  int min_points = 1;                    ///< [-] fewest points of a leg cluster at any range
  double min_point_fraction = 0.3;       ///< [-] of the beams expected across the smallest leg
  double lone_return_max_beams = 2.5;    ///< [-] one return the beams on both sides passed by
                                         ///< (its outline closed) is no leg where the smallest
                                         ///< leg spans more beams than this; 0: off
  double lone_return_min_step_m = 0.3;   ///< [m] ... and it stands this far in front of the
                                         ///< surface both sides return from
  double split_max_extra_m = 0.25;    ///< [m] a cluster up to this much wider than a leg is split
                                      ///< at its strongest depth step (a leg with something
                                      ///< touching it); 0: never (end pieces: below)
  double split_min_step_m = 0.03;     ///< [m] smallest depth step split at
  bool split_end_pieces = true;       ///< wider clusters: a leg-sized piece at either end standing
                                      ///< a split step in front of the rest is a candidate too
  bool split_inner_pieces = true;     ///< wider clusters: a leg-sized piece inside that stands
                                      ///< out in front of the surface on both sides of it (a leg
                                      ///< just in front of a wall) is a candidate too
  double inner_step_sigmas = 2.0;     ///< [-] such a piece has a depth step of at least this many
                                      ///< times the range noise (x sqrt 2) or split_min_step_m at
                                      ///< one end
  double inner_offset_sigmas = 4.0;   ///< [-] and stands in front of the line through the points
                                      ///< beside it by a mean of this many times that mean's
                                      ///< noise ...
  double inner_min_offset_m = 0.04;   ///< [m] ... and at least this
  int inner_surface_points = 4;       ///< [-] points on each side that line is fitted to
  double split_noise_steps = 3.0;     ///< [-] and at least this many times the scan's range noise
                                      ///< (times sqrt 2: a step is a difference of two ranges)
  double surface_tolerance_m = 0.02;  ///< [m] a piece within this of the line through its beam
                                      ///< neighbours continues their surface: not a leg
  double surface_noise_sigmas = 3.0;  ///< [-] or within this many times the range noise, if more
  double surface_max_step_m = 0.25;   ///< [m] farthest beam neighbour taken for the same surface
                                      ///< (0: the rule is off)
  bool join_noise_breaks = true;   ///< neighbouring clusters whose breaks the range noise explains
                                   ///< (no deeper than the split step) are offered whole as a
                                   ///< leg candidate too, when the whole fits a leg
  double blend_probe_gap_m = 0.6;  ///< [m] a large depth step, for the scan's count of them
                                   ///< (EstimateEdgeBlending)
  double blend_any_share = 0.5;    ///< [-] a scan that bridges this share of them with one mixed
                                   ///< return comes from a sensor that blends every echo of a
                                   ///< beam (PreprocessOutput::blends_every_echo); 0: never
  int blend_any_min_bridged = 4;   ///< [-] ... and at least this many of them
};

/// Paper 3.2: pruned rectangle / right-triangle search over cluster centres.
struct LegSearchConfig {
  double pair_tolerance_m = 0.06;        ///< [m] a pair must fit a model side or diagonal
  double pythagoras_tolerance_m = 0.06;  ///< [m] |hypotenuse - sqrt(a^2 + b^2)| of a triangle
  double fourth_leg_radius_m = 0.08;     ///< [m] search radius around the predicted 4th leg
  bool allow_three_legs = true;          ///< accept right triangles (one leg hidden)
  int max_leg_sets = 500;                ///< [-] cap on sets kept (pathological clutter)
};

/// Paper 3.2, Eq. 2: screening of points-model pairs.
struct ModelMatchConfig {
  double gamma_L_m = 0.05;            ///< [m] err_L threshold (long side)
  double gamma_W_m = 0.05;            ///< [m] err_W threshold (short side)
  double gamma_sum_m = 0.07;          ///< [m] err_sum threshold
  double lambda_m = 0.03;             ///< [m] keep pairs whose err_sum is within this of the best
  double three_leg_err_sum_m = 0.04;  ///< [m] stricter err_sum (fitted legs) for 3-leg sets:
                                      ///< two edges constrain less than four
  double three_leg_err_sum_preset_m = 0.06;  ///< [m] the same bound with a preset: the preset
                                             ///< gate already confines where a shelf may stand,
                                             ///< so far fewer chance triangles can pass and the
                                             ///< bound can allow 20 mm range noise (the
                                             ///< confidence's chi-square reads the fit then)
};

/// Paper 3.3: leg centres by PCA and nonlinear least squares.
struct LegFitConfig {
  double loss_scale_m = 0.015;          ///< [m] Huber scale of the point residuals
  double prior_weight = 0.1;            ///< [-] weak pull to the bias-corrected centroid (keeps a
                                        ///< single visible face well posed along the face)
  double range_sigma_m = 0.01;          ///< [m] LiDAR range noise (1 sigma): weighs the ranges
                                        ///< against the silhouette's bearing
  double silhouette_sigma_beams = 0.3;  ///< [beams] std of the bearing of the silhouette's
                                        ///< centre (both edges known to a beam: 0.2, plus margin)
  int pca_min_points = 6;               ///< [-] fewer points: leg axes from the shelf edge
  int one_edge_max_points = 5;          ///< [-] a leg whose outline shows one edge is placed by
                                        ///< that edge when it has at most this many returns, or
                                        ///< its other side is cut (an occluder, the field of
                                        ///< view's end); else between its outer beams
  double pca_min_anisotropy = 20;       ///< [-] eigenvalue ratio for a PCA direction to be trusted
  int max_iterations = 20;              ///< [-] solver iterations
  double mixed_edge_share = 0.5;        ///< [-] prior share of blends (mixed pixels) among a leg's
                                        ///< outer returns that lie behind their inner neighbour
                                        ///< with a farther surface beyond (FindMixedEdges); 0: off
  double mixed_min_noise_m = 0.005;     ///< [m] floor on the range noise that weighing assumes:
                                        ///< an ideal or very quiet scanner's scan estimates a
                                        ///< fraction of a millimetre, and a return a millimetre
                                        ///< off a fitted face would then pass for a blend
};

/// Paper 3.4: shelf centre and heading by nonlinear least squares (Eq. 8-11).
struct ShelfFitConfig {
  double loss_scale_m = 0.02;             ///< [m] Cauchy scale of the leg residuals
  int max_iterations = 25;                ///< [-] solver iterations
  double leg_radial_sigma_m = 0.004;      ///< [m] std of a fitted leg centre along its beam at
                                          ///< 1 m; grows as sqrt(range) (fewer beams on the leg)
  double leg_bearing_sigma_rad = 0.0015;  ///< [rad] its std across the beam, as a bearing
  double min_leg_sigma_m = 0.003;         ///< [m] floor of the per-leg std used for the covariance
  double max_rms_m = 0.03;                ///< [m] legs farther (RMS) from the model: rejected
  double background_mix_share = 0.25;     ///< [-] the returned pose counts a leg's range as this
                                          ///< share of the gap to a surface close behind it less
                                          ///< certain (mixed returns pull it there) ...
  double background_mix_max_m = 0.3;      ///< [m] ... a surface at most this far behind; 0: off
  double background_mix_any_cap_m = 0.1;  ///< [m] ... any surface behind a leg of one or two
                                          ///< returns, its gap counting as at most this, where
                                          ///< the scan's sensor blends every echo of a beam
                                          ///< (PreprocessOutput::blends_every_echo); 0: never
  double returns_chi2_margin = 8.0;       ///< [-] models of one leg set whose legs' chi-squares
                                          ///< differ by less are chosen on the shelf fitted to
                                          ///< the legs' returns (FitShelfToReturns); 0: never
  double one_edge_bloom_share = 0.5;      ///< [-] share of the bloom granted to a leg set's
                                          ///< legs (ShelfEvidence::width_bloom_rad) by which a
                                          ///< leg placed by one outline edge is less certain
                                          ///< across its beam: in the legs' chi-square that
                                          ///< chooses between models (times its range) and as
                                          ///< that edge's bearing in the fit on the legs'
                                          ///< returns; 0: off
  double spot_bloom_share = 0.5;          ///< [-] share of the bloom granted to a leg set's
                                          ///< legs taken as each beam's spot on either side
                                          ///< of it in the fit on the legs' returns: a beam
                                          ///< that passes a leg within it returned from the
                                          ///< nearest part it reached (ReturnRayResidual);
                                          ///< 0: off
};

/// What the scan says about each hypothesis (legs seen, hidden or seen through; free space
/// inside the footprint; leg sizes) and how that makes its confidence (see ShelfConfidence).
struct EvidenceConfig {
  double present_margin_m = 0.08;     ///< [m] a return this close to a leg's range: it is there
  double max_present_object_m = 0.4;  ///< [m] such returns in a wider cluster: an object stands
                                      ///< there, not a leg (with at most a person's leg beside
                                      ///< it); a 3-leg shelf nothing vouches for is then not
                                      ///< returned; 0: off
  bool present_in_core = true;        ///< such returns count only when the beams through the
                                      ///< leg's core (leg_position_tolerance_m, or the corner's
                                      ///< error if more, inside its edge) that passed beyond it
                                      ///< (min_through_beams or more) do not outnumber those of
                                      ///< them in the core: else they lie beside the leg, which
                                      ///< is not there
  double through_margin_m = 0.15;     ///< [m] returns this far beyond a leg: the beam went through
  int min_through_beams = 2;          ///< [-] beams through a leg that prove it absent
  double leg_position_tolerance_m = 0.005;  ///< [m] error of a predicted leg position: only
                                            ///< beams this far inside its edge prove absence
  double interior_margin_m = 0.06;        ///< [m] shrink of the footprint for the free-space check
  double occluded_credit = 0.75;          ///< [-] a hidden leg counts this much of a seen one
  double unobserved_credit = 0.5;         ///< [-] a leg no beam reaches counts this much
  double fit_chi2_three_legs = 6.0;       ///< [-] chi-square per degree of freedom of three
                                          ///< legs against the model (each leg's error over
                                          ///< what its returns allow) that halves the confidence
  double fit_chi2_four_legs = 12.0;       ///< [-] the same for four legs
  double build_sigma_m = 0.0;             ///< [m] std of a real shelf's leg centres off its
                                          ///< model's (welding, bent legs), added to each
                                          ///< leg's own for the confidence's chi-square of a
                                          ///< shelf the preset vouches for; 0: off
  double range_bias_sigma_m = 0.01;       ///< [m] std of the scanner's systematic range error,
                                          ///< fitted per shelf for the confidence; 0: off
  double width_bloom_edge_share = 0.5;    ///< [-] share of the bloom its legs were granted
                                          ///< (width_bloom_rad) times range added to the
                                          ///< across-beam std of a leg placed by one outline
                                          ///< edge, for the confidence's chi-square of a shelf
                                          ///< whose four corners the scan accounts for; 0: off
  double interior_scale_points = 4.0;     ///< [-] points inside the footprint that halve it
  double foreign_leg_points = 6.0;        ///< [-] a leg-sized cluster inside counts as this many
  double edge_band_m = 0.05;              ///< [m] a foreign leg this near an edge line of the
                                          ///< footprint (inside or outside it) stands on the
                                          ///< edge and counts as inside; 0: off
  double edge_corner_clearance_m = 0.2;   ///< [m] ... when at least this far from every corner
  double edge_partner_m = 0.4;            ///< [m] ... and no other object stands this near it
  double edge_lone_step_sigmas = 5.0;     ///< [-] one return counts there as a leg only when
                                          ///< the beams either side return from at least this
                                          ///< many times the range noise (x sqrt 2) behind it
                                          ///< (a noise spike on a wall is no leg); 0: any step
  double edge_lone_max_beams = 2.0;       ///< [beams] ... and only where the thinnest model leg
                                          ///< would span fewer beams than this at its range
                                          ///< (nearer, a leg returns from two or more: one
                                          ///< return is an outlier), unless the sensor blends
                                          ///< every echo; 0: at any range
  double hider_partner_m = 0.4;           ///< [m] a leg-sized cluster inside this near what
                                          ///< hides one of the shelf's legs is the hider's other
                                          ///< part (a person's other leg): an object; 0: off
  int foreign_legs_excused = 1;           ///< [-] legs of other sets inside that do not count
                                          ///< when four legs measured by their own returns and
                                          ///< the map vouch for the shelf (a person under its
                                          ///< edge); 0: every one counts
  double object_point_weight = 0.25;      ///< [-] weight of an interior point of a larger object
  double object_point_spacing_m = 0.01;   ///< [m] an object's interior return counts as one point
                                          ///< per this much beam spacing at most: a near object's
                                          ///< dense returns count the surface they cover; 0: off
  double leg_size_margin_m = 0.04;        ///< [m] clusters up to the leg's extent plus this are
                                          ///< leg-sized
  double leg_width_slack_m = 0.015;       ///< [m] seen leg widths may differ by one beam plus this
                                          ///< (the beam footprint blurs a leg's edges)
  double leg_width_bias_beams = 0.25;     ///< [beams] legs' mean width may differ by this many
                                          ///< beam spacings plus leg_width_bias_slack_m
  double leg_width_bias_slack_m = 0.006;  ///< [m] legs' mean width: see leg_width_bias_beams
  double leg_width_blur_beams = 2.0;      ///< [beams] a leg with a background close behind it
                                          ///< (blend_max_step_m) on a side, of a shelf the map
                                          ///< vouches for, may look up to this many beam
                                          ///< spacings too wide without counting in the legs'
                                          ///< mean width (a wide beam's blended edge); 0: off
  double leg_width_blend_beams = 0.5;     ///< [beams] the legs' mean seen width may be this many
                                          ///< beam spacings narrower still where the scan's
                                          ///< sensor blends every echo (its legs' edge beams
                                          ///< return blends: PreprocessOutput::
                                          ///< blends_every_echo); 0: off
  bool leg_width_skip_blended = true;     ///< the one leg of a shelf seen only blended with its
                                          ///< background (completed: its bearing, not its
                                          ///< width) does not count in the legs' mean width
                                          ///< where it looks too narrow; false: it counts
  double leg_width_scale_m = 0.01;        ///< [m] leg width error beyond the slack that halves it
  /// A scanner that blooms (EstimateWidthBloom: every thin object drawn wider by its spot) may
  /// show legs, and foreign legs, too wide by the scan's estimated bloom times their range.
  double width_bloom_max_rad = 0.02;     ///< [rad] at most this bloom is granted; 0: off
  double width_bloom_quantile = 0.1;     ///< [-] quantile of the thin objects' excess width
  double width_bloom_order_share = 0.5;  ///< [-] share of that quantile's expected shortfall from
                                         ///< beam quantisation added back (EstimateWidthBloom)
  // One: a shelf against a wall, behind a box or beside a person often shows only one or two thin
  // objects clear of their background (its front legs), and then its blooming legs failed the
  // width checks. Three -> two in the twenty-first session (independent scene generator, seeds 1 /
  // 1001: 90.4 / 90.2 -> 94.9 / 95.0 % right first), two -> one in the twenty-third (seeds 1 /
  // 1001 / 2001 / 3001 / 4001: 96.69 / 96.10 / 96.93 / 95.56 / 96.03 -> 96.88 / 96.43 / 97.00 /
  // 96.40 / 96.42 %, no phantom added); the default sensors' eval-layouts samples within a scene,
  // phantom counts and clutter detections unchanged both times. The estimate from one is that
  // object's excess, an overestimate when it is a 40 mm leg seen corner-on (its diagonal against
  // the thinnest leg); granted only where the preset vouches for a shelf.
  int width_bloom_min_objects = 1;        ///< [-] fewer thin objects clear of their background:
                                          ///< no bloom granted
  double width_bloom_max_extent_m = 0.1;  ///< [m] a cluster this long at most is a thin object
  double width_bloom_min_step_m = 0.1;    ///< [m] ... clear of its background by this much
  /// Where the preset vouches for a shelf, also its own legs' common bloom (OwnLegsBloom in
  /// shelf_evidence.cpp: their mean excess width with four seen, the least less
  /// width_bloom_three_legs_beams with three).
  bool width_bloom_own_legs = true;
  double width_bloom_three_legs_beams = 0.5;  ///< [beams] with three legs, their own bloom is the
                                              ///< least of their excess widths less this many
                                              ///< beam spacings
  bool width_bloom_far_legs = true;  ///< ... read from the legs whose background stands more
                                     ///< than blend_max_step_m behind both sides of their
                                     ///< outline, when two or more do (a near background blends
                                     ///< with a leg's edge beams and hides its bloom)
  /// A leg of at most blend_max_returns returns whose beams either side returned from at most
  /// blend_max_step_m behind it may be a thinner leg blended with its background (MayBeBlend);
  /// a hypothesis on two or more such legs whose legs look narrower than its model's by more
  /// than blend_narrow_bias_m on average is not returned (blended_legs). 0 returns: off.
  int blend_max_returns = 2;      ///< [-] a leg of at most this many returns may be a blend (see
                                  ///< above); 0: off
  double blend_max_step_m = 0.3;  ///< [m] see blend_max_returns
  double blend_narrow_bias_m = 0.006;     ///< [m] see blend_max_returns
  double min_confidence = 0.3;            ///< [-] below this a hypothesis is not returned
  double min_confidence_unvouched = 0.4;  ///< [-] the same for three legs (the fourth not seen)
                                          ///< with no preset or beyond the map's error of it
  bool hidden_leg_competes = true;        ///< no preset: three legs, the fourth hidden or unseen
                                          ///< in view, are never returned (hidden_leg_no_preset)
                                          ///< but compete for their legs, so a phantom on two
                                          ///< neighbours' legs cannot take them; false: dropped
  double overlap_margin_m = 0.05;         ///< [m] two hypotheses whose leg rectangles, each
                                          ///< shrunk by this on every side, overlap compete as
                                          ///< if they shared a leg (shelves do not interpenetrate)
};

/// How far a returned shelf may stand from the preset (the pose the map expects it at). The
/// preset is the paper's prior; a shelf well away from it, or turned against it, is a neighbour
/// or clutter that happens to fit a model, not the one the robot was sent to. Hypotheses outside
/// still compete for legs (a phantom near the preset loses to the neighbours it borrows from),
/// they are just not returned. With no preset nothing is gated. The defaults leave room for a map
/// 0.3 m / 0.17 rad off (shelves pushed about, as in the aisle scenario) plus the localisation
/// and odometry error of a robot still metres away: 0.4 m / 0.25 rad took the clutter detections
/// with a preset from 8 to 2 in 2000 scenes (eval-layouts --class clutter --scenes-per-class 2000
/// --seed0 1000), but in warehouse_aisle.yaml docking (eval-docking --method continuous --runs
/// 200) 4 and 6 runs of 200 never saw their shelf (success 97.5 % / 96.5 % instead of 99.5 %).
struct PresetGateConfig {
  double max_offset_m = 0.5;         ///< [m] centre distance from the preset; 0 turns the gate off
  double max_yaw_offset_rad = 0.35;  ///< [rad] heading difference modulo the shelf's symmetry
                                     ///< (pi, or pi/2 for a square one); 0 turns it off
  /// [m] The map's own error: the preset vouches for a shelf only this close to it (a 3-leg set
  /// whose fourth leg is hidden, the looser 3-leg err_sum bound, completing a shelf from two
  /// legs). Farther out, up to max_offset_m (a shelf pushed about), the scan alone must vouch
  /// for it, as without a preset. The layouts' presets are off by up to 0.2 m and 0.1 rad.
  double map_error_m = 0.25;        ///< [m] the map's own error of a shelf's pose (see above)
  double map_error_yaw_rad = 0.15;  ///< [rad] the same for the heading (modulo symmetry)
};

/// Completing a shelf from two leg candidates when the search of paper 3.2 found nothing near
/// the preset (CompleteLegSets): a leg in sight whose returns never became a candidate (one
/// return beside an occluder or taken for a mixed point, a leg merged with a person's) is cut
/// from the scan at the corner the two legs and the preset predict.
/// A completed shelf leans on the map more than one the search found whole, so it must stand
/// where the map says within the map's own error (PresetGateConfig::map_error_m and
/// map_error_yaw_rad), not merely inside the preset gate, which also allows for shelves pushed
/// about.
struct LegCompletionConfig {
  bool enabled = true;               ///< with a preset and nothing found near it, complete pairs
  double corner_margin_m = 0.03;     ///< [m] returns within half the leg's extent plus this of a
                                     ///< predicted corner are its leg
  double max_blend_m = 0.3;          ///< [m] with none there, returns on the corner's bearing up to
                                     ///< this far behind it and in front of their background are
                                     ///< the leg blended with it (its bearing only); 0: off
  double blend_partner_max_m = 0.8;  ///< [m] ... those farther than candidate_blend_far_max_m
                                     ///< behind it only when something stands within this behind
                                     ///< the corner to blend with (wider where the scan bridges
                                     ///< wider steps twice, any where its sensor blends every
                                     ///< echo); 0: off
  double blended_max_err_sum_m = 0.03;  ///< [m] a set with a blended leg: Eq. 2 err_sum bound
  double blended_min_confidence = 0.5;  ///< [-] and the confidence it must reach
  int min_measured_legs = 2;  ///< a set needs this many legs whose ranges the scan measured (not
                              ///< blended): fewer fix no size, the blends standing where the
                              ///< pose puts them (0 or 1: off)
  double surface_min_offset_m = 0.025;  ///< [m] returns at a corner that lie on a surface (a wall
                                        ///< a few cm behind the leg) are its leg when they stand
                                        ///< this far in front of the surface beside them ...
  double surface_offset_sigmas = 3.5;   ///< [-] ... and this many times the noise of that
                                        ///< offset; 0: off (such returns are no leg)
  bool surface_open_end = true;         ///< a leg at the end of what it touches (a person's leg
                                        ///< beside it), the background past it, is measured
                                        ///< against that surface alone
  double candidate_blend_max_m = 0.06;  ///< [m] a blend the search took as a leg completes a
                                        ///< corner alone when its returns lie at most this far
                                        ///< behind the corner (two returns or more; only
                                        ///< blends within max_blend_m count); 0: off
  double candidate_blend_far_max_m = 0.15;  ///< [m] ... or at most this far behind, when they
                                            ///< are at most blended_candidate_max_returns with the
                                            ///< background as blended_candidate_max_step_m says
  int blended_candidate_max_returns = 3;    ///< a leg the search took at a corner (within
                                            ///< corner_margin_m), of at most this many returns
                                            ///< lying behind the corner's centre on average,
                                            ///< completes it by its bearing ... ; 0: off
  double blended_candidate_max_step_m = 0.3;  ///< [m] ... when the beams either side return from
                                              ///< a depth step behind it, at most this far
  double lone_return_tolerance_m = 0.025;     ///< [m] a lone return beside a nearer step (what a
                                           ///< mixed point looks like) completes a corner when it
                                           ///< lies this near the ranges the leg returns
                                           ///< from (its nearest point to its centre) ...
  double lone_return_sigmas = 2.0;    ///< [-] ... or this many times the range noise, if more;
                                      ///< both 0: such a return never completes a corner
  double flush_object_max_m = 0.2;    ///< [m] returns at a corner whose object goes on past one
                                      ///< side only and ends within this are the leg flush with
                                      ///< something beside it (a person's leg), when the other
                                      ///< side's outline ends at the leg's silhouette; 0: off
  bool flush_edge_background = true;  ///< ... and past that outline the scan sees the
                                      ///< background: the first return out (two dropped beams
                                      ///< skipped) lies farther, or none does; not a nearer
                                      ///< occluder nor the same surface past a dropout
  bool merged_candidates = true;      ///< returns at a corner that are part of a wider candidate
                                      ///< (a leg merged with a person's leg beside it) are cut as
                                      ///< a leg the search never saw, under the flush rules above
};

/// All detector parameters, one struct per stage (config/detector.yaml).
struct DetectorConfig {
  PreprocessConfig preprocess;
  LegSearchConfig leg_search;
  ModelMatchConfig model_match;
  LegFitConfig leg_fit;
  ShelfFitConfig shelf_fit;
  EvidenceConfig evidence;
  PresetGateConfig preset_gate;
  LegCompletionConfig completion;
};

/// An impossible parameter: its dotted key (e.g. `preprocess.cluster_gap_m`) and the rule.
using ConfigViolation = geometry::ConfigViolation;

/// The first impossible value in `config`, if any. The single place the rules live: the
/// Detector constructor throws on it and the YAML loader reports it with the file name.
std::optional<ConfigViolation> FindConfigViolation(const DetectorConfig& config);

}  // namespace shelfdock::perception
