#include "perception/detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

#include "geometry/angle.hpp"
#include "perception/footprint_overlap.hpp"
#include "perception/leg_competition.hpp"
#include "perception/leg_completion.hpp"
#include "perception/leg_fit.hpp"
#include "perception/leg_search.hpp"
#include "perception/model_match.hpp"
#include "perception/preset_gate.hpp"
#include "perception/shelf_evidence.hpp"
#include "perception/shelf_fit.hpp"
#include "perception/shelf_return_fit.hpp"
#include "perception/width_bloom.hpp"

namespace shelfdock::perception {
namespace {

// One points-model pair, fitted and scored: a shelf hypothesis.
struct Hypothesis {
  Detection detection;                          // filled when it passed every check
  HypothesisRecord record;                      // what was found out about it
  LegSet set;                                   // leg candidates it is made of
  const geometry::ShelfModel* model = nullptr;  // the model it was scored against
  // Filled as Score fits its legs and the model to them (FitShelf), for the confidence's
  // chi-square (ConfidenceChiSquare) and the fits on the legs' returns (FitShelfToReturns), made
  // only when a choice between models or the returned pose needs them.
  std::array<Eigen::Vector2d, 4> legs{};             // fitted leg centres
  std::array<LegFitResult, 4> leg_fits{};            // their fits (none for a blended leg)
  std::array<int, 4> corner_of_leg{-1, -1, -1, -1};  // the model's corner each leg stands at
  geometry::Pose2 T_legs;                            // RefineShelfPose's on the fitted legs
  double legs_chi2 = 0.0;  // its chi-square for the model choice (ModelChoiceChiSquare)
  std::optional<ShelfReturnFitResult> on_returns;
  int corners_present = 0;  // corners without a leg cluster where returns stand at the leg's range
  // Passed every check but kHiddenLegNoPreset: it competes for its legs and is never returned.
  bool unreturnable = false;
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
                          const std::vector<Cluster>& clusters, const LegFitConfig& config,
                          double range_noise_m) {
    for (const auto& e : entries) {
      if (e.cluster == cluster && e.leg->shape == model.leg.shape &&
          e.leg->length_m == model.leg.length_m && e.leg->width_m == model.leg.width_m) {
        return e.fit;
      }
    }
    entries.push_back({cluster, &model.leg,
                       FitLeg(clusters[cluster].points, model.leg, hint, config,
                              clusters[cluster].edges, range_noise_m)});
    return entries.back().fit;
  }
};

// What scoring a hypothesis reads besides its leg set and model: the same for every hypothesis
// of a scan.
struct ScoreInputs {
  const PreprocessOutput& pre;
  const std::vector<SpanRole>& span_roles;
  double angle_increment_rad;
  const std::optional<geometry::Pose2>& T_lidar_preset;
  const DetectorConfig& config;
  double range_noise_m;    // the scan's own (EstimateRangeNoise), or the configured one
  double narrowest_leg_m;  // NarrowestLegSection of the models (GatherEvidence)
  bool completed = false;  // the sets were completed from two legs and the preset
};

void Count(Verdict verdict, RejectionCounts& rejected) {
  switch (verdict) {
    case Verdict::kFit:
      ++rejected.fit;
      break;
    case Verdict::kModel:
      ++rejected.model;
      break;
    case Verdict::kThreeLegError:
      ++rejected.three_leg_error;
      break;
    case Verdict::kBlendedLegs:
      ++rejected.blended_legs;
      break;
    case Verdict::kHiddenLegNoPreset:
      ++rejected.hidden_leg_no_preset;
      break;
    case Verdict::kLegSeenThrough:
      ++rejected.leg_seen_through;
      break;
    case Verdict::kLowConfidence:
      ++rejected.low_confidence;
      break;
    case Verdict::kLostLegs:
      ++rejected.lost_legs;
      break;
    case Verdict::kOffPreset:
      ++rejected.off_preset;
      break;
    case Verdict::kReturned:
      break;
  }
}

// [m^2] A surface close behind a leg (a wall a few centimetres behind a shelf pushed against
// it) mixes into the returns whose footprint straddles the leg's outline and pulls their ranges
// toward it by up to the gap: for the returned pose the leg's range counts as that much less
// certain (the variance of that pull; 0 with no such surface). A sensor that blends however far
// apart the echoes are (`any_gap`, PreprocessOutput::blends_every_echo) pulls them toward any
// surface behind: a 40 mm leg 3 m before a wall, seen by beams mostly on the leg, returned 5-10
// cm behind it, and such legs placed their shelf 5-10 cm off (blend_any, eval-layouts seeds 1: 65
// scenes with a shelf returned so). There every surface behind a leg of one or two returns counts,
// its gap taken as at most background_mix_any_cap_m: the blends' ranges then weigh less, and not
// nothing (with the gap uncapped: 52 such scenes, the centre's p95 at 10 mm 18.7 -> 19.4 mm; capped
// at 0.1 m: 51 and 16.2 mm, the right shelf first in 4 more; at 0.04 m: 62 and 14.2 mm, for legs of
// any number of returns). Legs of three returns or more too: the same 51 scenes and 14.8 mm, but
// where the scan's bridged steps are veil points beside clean legs (the rule forced on in our
// scenes, every scan with one bridged step) the p95 went 7.0 -> 8.1 mm against 7.0 -> 7.2.
double BackgroundMixVariance(const Cluster& c, const ShelfFitConfig& config, bool any_gap) {
  // Only a leg seen by one or two returns, each of them an edge beam of its outline: a leg seen
  // by more has returns whose footprint lies on it alone, and its range is measured.
  if (c.points.size() > 2 || config.background_mix_any_cap_m <= 0.0) any_gap = false;
  std::optional<double> gap;
  for (const auto& behind : {c.edges.before_step_m, c.edges.after_step_m}) {
    if (behind && *behind > 0.0 && (any_gap || *behind <= config.background_mix_max_m) &&
        (!gap || *behind < *gap)) {
      gap = behind;
    }
  }
  if (gap && any_gap) gap = std::min(*gap, config.background_mix_any_cap_m);
  return gap ? std::pow(config.background_mix_share * *gap, 2) : 0.0;
}

// What each fitted leg's own returns can tell (RefineShelfPose): along its beam the range noise
// over the number of returns on it, across the beam the quantisation of one beam step
// (step^2 / 12) over the same count; a millimetre floor either way. A far leg seen by one noisy
// return says little, about the pose or about which of two close models (1075x883, 1080x856)
// the set is.
std::array<LegSigma, 4> LegSigmas(const std::array<Eigen::Vector2d, 4>& legs, const LegSet& set,
                                  const ScoreInputs& in, bool with_background = false) {
  constexpr double kFloor2 = 1e-6;  // (1 mm)^2
  std::array<LegSigma, 4> sigma{};
  for (int i = 0; i < set.count; ++i) {
    const double range = std::max(legs[i].norm(), 0.1);
    const Cluster& c = in.pre.candidates[set.legs[i]];
    const double n = static_cast<double>(c.points.size());
    const double step = range * std::abs(in.angle_increment_rad);
    // A blended leg's range is the completed shelf's, not a measurement: only its bearing counts.
    const double mix2 =
        with_background ? BackgroundMixVariance(c, in.config.shelf_fit, in.pre.blends_every_echo)
                        : 0.0;
    sigma[i].along_m = c.assumed_range_m
                           ? in.config.completion.max_blend_m
                           : std::sqrt(in.range_noise_m * in.range_noise_m / n + kFloor2 + mix2);
    sigma[i].across_m = std::sqrt(step * step / 12.0 / n + kFloor2);
  }
  return sigma;
}

// [rad] Legs whose beams span less than this see a range bias as a shift along their beams,
// which the pose takes up; only legs around the sensor show it as a larger shelf.
constexpr double kMinBiasSpread_rad = std::numbers::pi / 3.0;

// True when the beams to two of the legs lie at least `angle_rad` apart (their cosine at most
// cos(angle_rad)).
bool BeamsSpanAtLeast(const std::array<Eigen::Vector2d, 4>& legs, int count, double angle_rad) {
  const double cos_limit = std::cos(angle_rad);
  for (int i = 0; i < count; ++i) {
    for (int j = i + 1; j < count; ++j) {
      if (legs[i].dot(legs[j]) <= cos_limit * legs[i].norm() * legs[j].norm()) return true;
    }
  }
  return false;
}

// [m] How far across its beam bloom_rad may put leg i of `h`: bloom_rad times its range for a leg
// placed by one outline edge (its fit's silhouette term holds that edge), 0 for the others.
double OneEdgeBloom(const Hypothesis& h, int i, double bloom_rad) {
  return h.leg_fits[i].silhouette.edge_side != 0 ? bloom_rad * h.legs[i].norm() : 0.0;
}

// [rad] The bearing by which a leg of `h` placed by one outline edge is less certain in the model
// choice and the fit on its returns: shelf_fit.one_edge_bloom_share of the bloom its legs were
// granted (ModelChoiceChiSquare).
double OneEdgeBloomForChoice(const Hypothesis& h, const ScoreInputs& in) {
  return in.config.shelf_fit.one_edge_bloom_share * h.record.width_bloom_rad;
}

// The legs' chi-square against the model for the confidence: each leg's own std widened by what a
// real shelf's legs stand off its drawing (evidence.build_sigma_m). A near leg seen by many beams
// is known to about a millimetre, so a frame welded 5 mm off its model halved the confidence of
// a real shelf and lost it (eval-layouts --as-built 0.01 0.05: 74 of 102 misses low_confidence).
// The pose, the model choice and the competition do not read that tolerance: only how sure the
// detector is of a shelf does, and only of one the map vouches for: with it for
// every hypothesis (3 mm) posts in clutter matched a model within it and made shelves
// (eval-layouts --scenes-per-class 1000, seed0 60001 .. 240001: phantom scenes 25 -> 44; only
// where vouched 25 -> 29, right first 73318 -> 73353 either way). Default 0: off.
//
// A scanner's systematic range error (evidence.range_bias_sigma_m) is fitted with the pose
// (FitWithRangeBias) where the legs' beams span kMinBiasSpread_rad or more: a large shelf around
// the sensor otherwise looks twice the bias larger than its model and loses its confidence
// (eval-layouts --lidar config/lidar_variants/range_bias.yaml, 2 cm: large_close 50.5 -> 92.7 %).
// Legs at one bearing show a bias only as a shift, which the pose takes up; fitting it there too
// (no spread limit) made one more phantom scene in the 100000 (25 -> 26), at 45 degrees a clutter
// detection more among 12000 WLR-716 clutter scenes, at 60 degrees neither.
//
// A blooming scanner draws every thin object wider by up to the bloom granted to the shelf's legs
// (ev.width_bloom_rad), half of it at each outline edge. A leg placed by one edge (the other cut by
// an occluder, a dropout or the field of view: its fit's silhouette term holds that edge) sits off
// across the beam by up to that half at its range, where the beam step alone allowed millimetres:
// its across-beam std is widened by evidence.width_bloom_edge_share of bloom times range. Legs
// peeking past a box, their free edge bloomed 1.2-2.9 cm, sank the confidence of the shelf behind
// it below its minimum (independent generator at 1.5 times its spot, seed 1: 6 of 28 misses).
// Legs with both edges seen keep their std (an allowance for unequal bloom there too lifted
// round-legged shelves' legs into rectangular phantoms on the blooming receivers), and so do the
// legs of three whose fourth corner nothing accounts for (neither seen nor hidden): their fit to
// the drawing is then all that tells them from legs of different shelves (an against_wall scene
// under blend_1p5m.yaml: two shelves' legs and a lone return made a 1075 x 883 at 0.30 with it).
double ConfidenceChiSquare(const Hypothesis& h, const ShelfRefineResult& refined,
                           const ShelfEvidence& ev, std::array<LegSigma, 4> sigma,
                           const ScoreInputs& in) {
  const std::array<Eigen::Vector2d, 4>& legs = h.legs;
  const int count = h.set.count;
  const double build = in.config.evidence.build_sigma_m;
  const double bias = in.config.evidence.range_bias_sigma_m;
  const bool corners_accounted = ev.legs_seen + ev.legs_occluded == 4;
  const double edge_bloom =
      corners_accounted ? in.config.evidence.width_bloom_edge_share * ev.width_bloom_rad : 0.0;
  if (build <= 0.0 && bias <= 0.0 && edge_bloom <= 0.0) return refined.chi2;
  for (int i = 0; i < count; ++i) {
    sigma[i].along_m = std::hypot(sigma[i].along_m, build);
    sigma[i].across_m = std::hypot(sigma[i].across_m, build, OneEdgeBloom(h, i, edge_bloom));
  }
  if (bias > 0.0 && BeamsSpanAtLeast(legs, count, kMinBiasSpread_rad)) {
    return FitWithRangeBias(legs, count, *h.model, h.corner_of_leg, refined.T_lidar_shelf, sigma,
                            bias)
        .chi2;
  }
  return LegsChiSquare(legs, count, *h.model, h.corner_of_leg, refined.T_lidar_shelf, sigma);
}

// The legs' chi-square at the refined pose on which the models of one leg set are chosen (or,
// within shelf_fit.returns_chi2_margin, sent on to the fit on their returns): a leg placed by one
// outline edge may sit off across its beam by half the bloom (ConfidenceChiSquare), and its std
// there is widened by shelf_fit.one_edge_bloom_share of the bloom granted to the set's legs
// (OneEdgeBloomForChoice) times its range, whatever vouches for the shelf (the choice is between
// models on the same legs, not whether they are a shelf). The fit on the legs' returns holds that
// edge's bearing as much less certain (SetReturns). Taken as fitted, such a leg 1.5-2 cm off across
// its beam (its other side behind a nearer leg, its free edge bloomed by a beam's spot) chose the
// model its misplacement made: the close models 1075 x 883 / 1080 x 856 confused where the rest of
// the legs told them apart (independent generator, seed 1001: row 0021, open 0049, aisle 0172).
double ModelChoiceChiSquare(const Hypothesis& h, const ShelfRefineResult& refined,
                            std::array<LegSigma, 4> sigma, const ScoreInputs& in) {
  const double bloom = OneEdgeBloomForChoice(h, in);
  bool widened = false;
  for (int i = 0; i < h.set.count; ++i) {
    const double bloom_m = OneEdgeBloom(h, i, bloom);
    if (bloom_m <= 0.0) continue;
    sigma[i].across_m = std::hypot(sigma[i].across_m, bloom_m);
    widened = true;
  }
  if (!widened) return refined.chi2;
  return LegsChiSquare(h.legs, h.set.count, *h.model, h.corner_of_leg, refined.T_lidar_shelf,
                       sigma);
}

// The legs of a hypothesis as FitShelfToReturns reads them: each leg's returns, its outline's
// silhouette term and possible blends as its fit weighed them (`h.leg_fits`) and the scan's range
// noise; a blended leg by its assumed centre (LegSigmas).
std::vector<LegReturns> SetReturns(const Hypothesis& h, const ScoreInputs& in) {
  const LegSet& set = h.set;
  const std::array<LegSigma, 4> sigma = LegSigmas(h.legs, set, in);
  std::vector<LegReturns> out;
  for (int i = 0; i < set.count; ++i) {
    const Cluster& c = in.pre.candidates[set.legs[i]];
    LegReturns r;
    r.corner = h.corner_of_leg[i];
    if (c.assumed_range_m) {
      r.centre = h.legs[i];
      r.centre_sigma = sigma[i];
    } else {
      r.points = &c.points;
      r.silhouette = h.leg_fits[i].silhouette;
      // A leg placed by one outline edge: that edge's bearing is less certain by the bloom, as
      // in the legs' chi-square (ModelChoiceChiSquare). Independent generator seeds 1-4001 +8
      // scenes right first, `bloom.yaml` +17, our own scenes within 3 a sample either way.
      if (r.silhouette.edge_side != 0) {
        r.silhouette.sigma_rad = std::hypot(r.silhouette.sigma_rad, OneEdgeBloomForChoice(h, in));
      }
      r.range_sigma_m = in.range_noise_m;
      r.mixed = h.leg_fits[i].mixed;
      // A blooming scanner's beams return a leg they pass within their spot, from the part of it
      // the spot reaches: on either side of the beam half the bloom the legs show (the bloom is
      // what the spots add to a leg's width, one edge each). Independent generator seeds 1 /
      // 1001 / 2001 / 3001 / 4001: centre p95 at 10 mm 7.2 / 7.0 / 7.5 / 7.8 / 7.9 -> 6.2 / 6.2 /
      // 5.8 / 6.1 / 6.4 mm, right first +0 / +3 / +3 / +1 / -1 scenes.
      r.spot_half_rad = in.config.shelf_fit.spot_bloom_share * h.record.width_bloom_rad;
    }
    out.push_back(r);
  }
  return out;
}

// Widens the range noise of each leg of `returns` (SetReturns of `set`) with a surface close
// behind it by that surface's pull (BackgroundMixVariance), as LegSigmas does for
// RefineShelfPose: the pull is one error shared by the leg's returns, so spread over them as if
// each had n times its variance. False when no leg has such a surface.
bool WidenForBackground(std::vector<LegReturns>& returns, const LegSet& set,
                        const ScoreInputs& in) {
  bool widened = false;
  for (int i = 0; i < set.count; ++i) {
    LegReturns& r = returns[static_cast<std::size_t>(i)];
    if (r.points == nullptr) continue;
    const Cluster& c = in.pre.candidates[set.legs[i]];
    const double n = static_cast<double>(c.points.size());
    const double mix2 = BackgroundMixVariance(c, in.config.shelf_fit, in.pre.blends_every_echo);
    const double sigma = std::sqrt(in.range_noise_m * in.range_noise_m + n * mix2);
    if (sigma > r.range_sigma_m) {
      r.range_sigma_m = sigma;
      widened = true;
    }
  }
  return widened;
}

// Fits one points-model pair (3.3 leg centres, 3.4 shelf pose), screens it and weighs the
// scan's evidence. The record's verdict says whether it stays in the competition for legs
// (kReturned for now) or why not.
Hypothesis Score(const LegSet& set, const geometry::ShelfModel& model, int model_index, double hint,
                 const ScoreInputs& in, LegFitCache& cache) {
  const DetectorConfig& config = in.config;
  Hypothesis h;
  h.set = set;
  h.model = &model;
  HypothesisRecord& rec = h.record;
  rec.model = model.name;
  std::array<Eigen::Vector2d, 4>& legs = h.legs;
  for (int i = 0; i < set.count; ++i) {
    const Cluster& c = in.pre.candidates[set.legs[i]];
    // A leg seen only blended with its background (CompleteLegSets): on its returns' bearing,
    // at the range the completed shelf puts it.
    if (c.assumed_range_m) {
      legs[i] = AssumedCentre(c);
    } else {
      h.leg_fits[i] =
          cache.Get(set.legs[i], model, hint, in.pre.candidates, config.leg_fit, in.range_noise_m);
      legs[i] = h.leg_fits[i].centre;
    }
    rec.legs_blended.push_back(c.assumed_range_m.has_value());
    rec.legs_flush.push_back(c.flush);
    const MixedEdges& mixed = h.leg_fits[i].mixed;
    rec.legs_edge_blends.push_back(config.leg_fit.mixed_edge_share > 0.0
                                       ? static_cast<int>(mixed.first_gap_m > 0.0) +
                                             static_cast<int>(mixed.last_gap_m > 0.0)
                                       : 0);
  }
  rec.legs.assign(legs.begin(), legs.begin() + set.count);
  const auto fit = FitShelf(legs, set.count, model, config.shelf_fit);
  if (!fit || !fit->converged || fit->rms_m > config.shelf_fit.max_rms_m) {
    rec.verdict = Verdict::kFit;
    return h;
  }
  h.corner_of_leg = fit->corner_of_leg;
  // The pose the fitted legs support best, each weighed by its returns; every check below reads
  // it, and its chi-square makes the confidence.
  const std::array<LegSigma, 4> sigma = LegSigmas(legs, set, in);
  const ShelfRefineResult refined_pose = RefineShelfPose(legs, set.count, model, *fit, sigma);
  const geometry::Pose2& T_lidar_shelf = refined_pose.T_lidar_shelf;
  rec.T_lidar_shelf = T_lidar_shelf;
  // Eq. 2 again on the fitted (unbiased) leg centres: this is what tells close models apart.
  const ModelPair refined = ScoreModel(MeasureEdges(legs, set.count), model, model_index);
  rec.err_sum = refined.err_sum;
  if (!PassesThresholds(refined, config.model_match)) {
    rec.verdict = Verdict::kModel;
    return h;
  }
  // Two edges constrain a shelf less than four: a 3-leg set must match more tightly. The preset
  // lets it match less tightly near where it says, but not a set the preset already vouched for
  // by completing it (a TiM571's blended return behind a round leg, at a 1075x883's corner:
  // eval-layouts --scenes-per-class 1000 --seed0 40001, 1 phantom; 9 right shelves of 36000
  // lost).
  // The map vouches for a shelf only where it says one stands, within its own error; a shelf
  // farther off (pushed about, or no shelf at all: three posts in clutter near an empty slot)
  // is held to what the scan alone shows, as without a preset (eval-layouts --scenes-per-class
  // 1000, seed0 1 / 20001 / 40001: clutter detections 4 / 6 / 6 -> 1 / 2 / 2, all of them within
  // the 0.5 m gate but 0.35-0.48 m and 0.29-0.35 rad off; no right shelf lost).
  const bool vouched =
      in.T_lidar_preset &&
      WithinPreset(T_lidar_shelf, *in.T_lidar_preset, config.preset_gate.map_error_m,
                   config.preset_gate.map_error_yaw_rad, model.HeadingPeriod());
  const double three_leg_bound = vouched && !in.completed
                                     ? config.model_match.three_leg_err_sum_preset_m
                                     : config.model_match.three_leg_err_sum_m;
  if (set.count == 3 && refined.err_sum > three_leg_bound) {
    rec.verdict = Verdict::kThreeLegError;
    return h;
  }
  // A leg seen only blended with its background (CompleteLegSets) gives its bearing, not its
  // range: a set leaning on one is held to a tighter err_sum and a higher confidence. Before
  // CompleteLegSets refused returns the search had taken as a leg, blended completions made 7
  // phantoms on eval-layouts --scenes-per-class 1000, seed0 1 / 20001 / 40001, all beyond these
  // two bounds; with that rule none shows on those seeds and 5001 either way, and the bounds cost
  // 5 of 36000 right shelves. They stay as the margin for sensors and scenes not measured.
  const int blends =
      static_cast<int>(std::count_if(set.legs.begin(), set.legs.begin() + set.count, [&](int leg) {
        return in.pre.candidates[leg].assumed_range_m.has_value();
      }));
  const bool blended = blends > 0;
  // Only two legs' ranges, at the least, measure the shelf's size (completion.min_measured_legs):
  // with one, the blends stand where the pose puts them and any model fits. On the independent
  // generator's seed 6001 (against_wall 171) a 900 x 810 on one leg and two blends, a three-leg
  // subset of a completed four-leg set, beat the real 1080 x 856 for its legs at confidence 0.99
  // (97.74 -> 97.81 % right first, 1 -> 0 phantom scenes; seeds 1-4001 identical); the receiver
  // variants' 26 samples 229 -> 225 phantom scenes (noise_growing person_beside_leg 5272, three
  // under blend_any) and 126706 -> 126694 right first; eval-layouts seed0 5001 / 20001 / 40001
  // -1 each (round or wall-side legs found on one leg and blends), the 100000 scenes identical.
  if (set.count - blends < config.completion.min_measured_legs) {
    rec.verdict = Verdict::kBlendedLegs;
    return h;
  }
  if (blended && refined.err_sum > config.completion.blended_max_err_sum_m) {
    rec.verdict = Verdict::kModel;
    return h;
  }
  std::array<int, 4> corner_candidate{-1, -1, -1, -1};
  for (int i = 0; i < set.count; ++i) corner_candidate[fit->corner_of_leg[i]] = set.legs[i];
  // How well the pose places a corner no leg stands for (GatherEvidence's corner_error_m): half
  // the legs' RMS off their fitted corners (a corner predicted from three legs errs across the
  // view by about 0.8 of that RMS at one std). With none of it, round-legged shelves 0.7 m away,
  // their legs fitted 2-3 cm off under a scanner's range bias, lost their fourth leg; with all of
  // it, posts beside an empty corner of three posts passed for its leg again (eval-layouts over
  // the receiver variants of config/lidar_variants/, seeds 1 and seed0 5001: phantom scenes -6 /
  // -5 / -2 with none / half / all of it, right first under range_bias.yaml -3 / -1 / 0).
  constexpr double kCornerErrorShareOfRms = 0.5;
  ShelfEvidence ev =
      GatherEvidence(fit->T_lidar_shelf, model, corner_candidate,
                     {in.pre, in.span_roles, in.angle_increment_rad, in.narrowest_leg_m}, vouched,
                     config.evidence, kCornerErrorShareOfRms * fit->rms_m);
  // A shelf the map vouches for may stand off its drawing by its build tolerance, and a leg placed
  // by one bloomed edge by that bloom (ConfidenceChiSquare); legs that only the scan vouches for
  // must match the drawing.
  const double confidence_chi2 =
      vouched ? ConfidenceChiSquare(h, refined_pose, ev, sigma, in) : refined_pose.chi2;
  ev.confidence = ShelfConfidence(ev, confidence_chi2, set.count, config.evidence);
  h.corners_present =
      static_cast<int>(std::count(ev.legs.begin(), ev.legs.end(), LegView::kPresent));
  rec.confidence = ev.confidence;
  rec.legs_visible = ev.legs_seen;
  rec.legs_occluded = ev.legs_occluded;
  rec.legs_seen_through = ev.legs_seen_through;
  rec.interior_points = ev.interior_points;
  rec.foreign_legs_inside = ev.foreign_legs_inside;
  rec.leg_width_error_m = ev.leg_width_error_m;
  rec.leg_width_bias_m = ev.leg_width_bias_m;
  rec.width_bloom_rad = ev.width_bloom_rad;
  // A beam wider than a thin leg (a TiM571's 0.87 deg spot on a 26 mm leg at 2-4 m) returns one
  // echo between the leg and what stands close behind it: a candidate centimetres behind the
  // leg. Two such legs of a round-legged shelf in front of a wall made rectangular shelves of
  // the wrong model and size (phantoms 0.1-0.2 m off, their legs 12-17 mm narrower than the
  // model's on average). Legs that may be blends and look too thin for the model: not this shelf
  // (eval-layouts seeds 1 and --scenes-per-class 1000 seed0 20001 / 40001 / 5001 / 60001 / 80001:
  // phantoms 1 / 2 / 3 / 1 / 3 / 6 -> 0 / 1 / 1 / 1 / 3 / 5, right first +1 / 0 / 0 / -2 / -3 /
  // -1; a shelf against a wall, legs of its own model's width, is not affected).
  if (ev.legs_maybe_blended >= 2 && ev.leg_width_bias_m < -config.evidence.blend_narrow_bias_m) {
    rec.verdict = Verdict::kBlendedLegs;
    return h;
  }
  // A leg that beams pass straight through is not there: whatever made the other legs, it is
  // not this shelf (clutter forming a right triangle, or legs of two shelves).
  if (ev.legs_seen_through > 0) {
    rec.verdict = Verdict::kLegSeenThrough;
    return h;
  }
  // Without a preset, three legs whose fourth is hidden behind something else (not one of its
  // own legs, as when seen along a side) or left unexplained inside the field of view (beams
  // looked there, none returned near it) are not a shelf to return: nothing in the scan or the
  // map vouches for that leg, and in clutter three posts and anything in front of the fourth
  // corner make such a triangle (eval-layouts, 2000 clutter scenes seeds 1000-2999: 56 such
  // detections without a preset; 20 with the hidden-leg part, 12 with both). A fourth leg
  // outside the field of view (the sensor under a shelf) is excused. With the shelf where the
  // preset says, the map vouches for it (`vouched`, above).
  // Without a preset such a triangle is still most likely what made its legs: it goes on
  // through the checks and, when it passes them, competes for its legs without being returned.
  // In a row seen without a preset, the fourth leg of every shelf but the nearest hides behind
  // a neighbour's leg; with those shelves out of the competition, a phantom standing in a gap on
  // two neighbours' legs (its own fourth leg hidden behind one of its own) took the legs of the
  // one shelf that could be returned (eval-layouts --class row aisle mixed_neighbours
  // --scenes-per-class 3000 --seed0 5001 --no-preset: scenes with a phantom 19 -> 8; with
  // --row-gaps 0.05 1.2, some gaps as wide as a shelf, 117 -> 36). With a preset the map vouches
  // for the shelf near it, and such a triangle off it took that shelf's legs now and then (two
  // right shelves lost on the sensor variants of config/lidar_variants/, none gained anywhere).
  h.unreturnable = !vouched && set.count == 3 &&
                   (ev.legs_hidden_by_other > 0 || ev.legs_unobserved_in_view > 0 ||
                    ev.legs_in_large_object > 0);
  if (h.unreturnable && (!config.evidence.hidden_leg_competes || in.T_lidar_preset)) {
    rec.verdict = Verdict::kHiddenLegNoPreset;
    return h;
  }
  // Three legs that only the scan vouches for (no preset, or the shelf beyond the map's error)
  // and whose fourth leg the scan never saw must be surer than min_confidence: in clutter, posts
  // around the sensor make a shelf over it whose fourth corner lies in the blind sector behind.
  double min_confidence = config.evidence.min_confidence;
  if (set.count == 3 && !vouched && ev.legs_seen < 4) {
    min_confidence = std::max(min_confidence, config.evidence.min_confidence_unvouched);
  }
  // So is a set leaning on a leg cut out of a wider candidate (completion.merged_candidates): the
  // search took those returns for part of something else.
  const bool cut_from_candidate =
      std::any_of(set.legs.begin(), set.legs.begin() + set.count,
                  [&](int leg) { return in.pre.candidates[leg].cut_from_candidate; });
  if (blended || cut_from_candidate) {
    min_confidence = std::max(min_confidence, config.completion.blended_min_confidence);
  }
  if (ev.confidence < min_confidence) {
    rec.verdict = Verdict::kLowConfidence;
    return h;
  }
  rec.verdict = Verdict::kReturned;
  h.T_legs = T_lidar_shelf;
  h.legs_chi2 = ModelChoiceChiSquare(h, refined_pose, sigma, in);
  Detection& d = h.detection;
  d.model = model.name;
  // The pose the competition reads (a returned shelf's is then fitted to its legs' returns):
  // each leg weighed by its returns and by the surface close behind it (LegSigmas); every decision
  // above read the pose on the returns alone, so this changes where a shelf is, not which
  // (eval-layouts --class against_wall --scenes-per-class 1000
  // --seed0 5001: centre / heading p95 at 10 mm 10.3 -> 8.2 mm, 8.2 -> 6.7 mrad; used in the
  // chi-square too, it made a clutter detection of three posts before a box on seed0 5001 and
  // 20001).
  d.T_lidar_shelf =
      RefineShelfPose(legs, set.count, model, *fit, LegSigmas(legs, set, in, true)).T_lidar_shelf;
  rec.T_lidar_shelf = d.T_lidar_shelf;
  d.length_m = fit->length_m;
  d.width_m = fit->width_m;
  d.legs = rec.legs;
  d.legs_used = set.count;
  d.err_sum = refined.err_sum;
  d.cost = fit->cost;
  d.covariance = fit->covariance;
  d.confidence = ev.confidence;
  d.legs_visible = ev.legs_seen;
  d.legs_occluded = ev.legs_occluded;
  d.interior_points = ev.interior_points;
  d.leg_width_error_m = ev.leg_width_error_m;
  d.leg_width_bias_m = ev.leg_width_bias_m;
  const double reference =
      in.T_lidar_preset ? in.T_lidar_preset->yaw : std::atan2(d.T_lidar_shelf.y, d.T_lidar_shelf.x);
  d.T_lidar_shelf.yaw = ResolveHeading(d.T_lidar_shelf.yaw, reference, model.HeadingPeriod());
  geometry::Pose2 T_fit = fit->T_lidar_shelf;
  T_fit.yaw = ResolveHeading(T_fit.yaw, d.T_lidar_shelf.yaw, model.HeadingPeriod());
  d.T_lidar_shelf_fit = T_fit;
  return h;
}

// The preset gate (PresetGateConfig): the paper picks the detection nearest the preset; a shelf
// that is neither near it nor turned like it is not the one the map expects there. d's heading
// is already resolved toward the preset's (ResolveHeading), so the difference modulo pi is the
// true one modulo the shelf's symmetry.
bool NearPreset(const Detection& d, const geometry::Pose2& preset, double max_offset_m,
                double max_yaw_rad) {
  return WithinPreset(d.T_lidar_shelf, preset, max_offset_m, max_yaw_rad, std::numbers::pi);
}

}  // namespace

const char* VerdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kReturned:
      return "returned";
    case Verdict::kFit:
      return "fit";
    case Verdict::kModel:
      return "model";
    case Verdict::kThreeLegError:
      return "three_leg_error";
    case Verdict::kHiddenLegNoPreset:
      return "hidden_leg_no_preset";
    case Verdict::kLegSeenThrough:
      return "leg_seen_through";
    case Verdict::kBlendedLegs:
      return "blended_legs";
    case Verdict::kLowConfidence:
      return "low_confidence";
    case Verdict::kLostLegs:
      return "lost_legs";
    case Verdict::kOffPreset:
      return "off_preset";
  }
  return "unknown";
}

double ResolveHeading(double yaw_rad, double reference_rad, double period_rad) {
  const double k = std::round(geometry::AngleDiff(reference_rad, yaw_rad) / period_rad);
  return geometry::WrapAngle(yaw_rad + k * period_rad);
}

Detector::Detector(std::vector<geometry::ShelfModel> models, DetectorConfig config)
    : models_(std::move(models)), config_(config), narrowest_leg_m_(NarrowestLegSection(models_)) {
  if (models_.empty()) throw std::invalid_argument("models: at least one shelf model is needed");
  if (const auto v = FindConfigViolation(config_)) {
    throw std::invalid_argument(v->key + ": must be " + v->requirement);
  }
}

DetectionResult Detector::Detect(const geometry::LaserScan& scan,
                                 const std::optional<geometry::Pose2>& T_lidar_preset,
                                 bool explain) const {
  return DetectPoints(ScanToPoints(scan), scan.angle_increment, T_lidar_preset, explain);
}

DetectionResult Detector::DetectPoints(const std::vector<ScanPoint>& points,
                                       double angle_increment_rad,
                                       const std::optional<geometry::Pose2>& T_lidar_preset,
                                       bool explain) const {
  DetectionResult result;
  DetectionStats& stats = result.stats;
  stats.valid_points = static_cast<int>(points.size());

  // 3.1 preprocessing.
  PreprocessOutput pre =
      Preprocess(points, angle_increment_rad, T_lidar_preset, models_, config_.preprocess);
  pre.width_bloom_rad = EstimateWidthBloom(points, pre.points, pre.spans, angle_increment_rad,
                                           narrowest_leg_m_, config_.evidence)
                            .bloom_rad;
  stats.roi_points = pre.roi_points;
  stats.clusters = pre.clusters;
  stats.trailing_removed = pre.trailing_removed;
  stats.leg_candidates = static_cast<int>(pre.candidates.size());
  stats.range_noise_m = pre.range_noise_m;
  stats.width_bloom_rad = pre.width_bloom_rad;
  stats.depth_steps = pre.edge_blending.steps;
  stats.bridged_steps = pre.edge_blending.bridged;
  stats.stray_returns = pre.stray_returns;
  std::vector<Eigen::Vector2d> centres;
  centres.reserve(pre.candidates.size());
  // The points lie on a leg's near side, so its centroid sits short of its centre by about half
  // the leg's depth along the view; at close range (the sensor beside or under a large shelf)
  // that bias alone can break Eq. 2's tolerances. The search uses centroids pushed back by the
  // smallest leg's half depth (no model is known yet), the fits then find the true centres.
  double half_depth = std::numeric_limits<double>::infinity();
  for (const auto& m : models_) half_depth = std::min(half_depth, 0.5 * m.leg.width_m);
  auto search_centre = [half_depth](const Cluster& c) -> Eigen::Vector2d {
    if (c.assumed_range_m) return AssumedCentre(c);  // a blended leg
    const double r = c.centroid.norm();
    return r > half_depth ? Eigen::Vector2d(c.centroid * (1.0 + half_depth / r)) : c.centroid;
  };
  for (const auto& c : pre.candidates) centres.push_back(search_centre(c));

  // 3.2 geometric search.
  const std::vector<LegSet> sets = SearchLegSets(centres, models_, config_.leg_search);
  stats.leg_sets = static_cast<int>(sets.size());

  LegFitCache cache;
  // The legs of shelf-shaped groups, for the free-space check: a span is a whole leg when one
  // of its candidates in some set has its outline uncut on both sides.
  std::vector<SpanRole> span_roles(pre.spans.size(), SpanRole::kOther);
  for (const LegSet& set : sets) {
    for (int i = 0; i < set.count; ++i) {
      const Cluster& c = pre.candidates[set.legs[i]];
      if (c.span < 0) continue;
      SpanRole& role = span_roles[static_cast<std::size_t>(c.span)];
      if (role == SpanRole::kLeg) continue;
      role = c.edges.cut() ? SpanRole::kPartlyHiddenLeg : SpanRole::kLeg;
    }
  }
  for (const Cluster& c : pre.candidates) {
    if (c.span < 0 || c.edges.cut()) continue;
    SpanRole& role = span_roles[static_cast<std::size_t>(c.span)];
    if (role == SpanRole::kOther) role = SpanRole::kLoneLeg;
  }
  ScoreInputs inputs{pre,
                     span_roles,
                     angle_increment_rad,
                     T_lidar_preset,
                     config_,
                     pre.range_noise_m > 0.0 ? pre.range_noise_m : config_.leg_fit.range_sigma_m,
                     narrowest_leg_m_};
  // The shelf fitted to a hypothesis' legs' returns (FitShelfToReturns), made once.
  auto on_returns = [&](Hypothesis& h) -> const ShelfReturnFitResult& {
    if (!h.on_returns) {
      h.on_returns = FitShelfToReturns(SetReturns(h, inputs), *h.model, h.T_legs, config_.leg_fit);
    }
    return *h.on_returns;
  };
  // Scores one leg set against every model its cluster centres pass Eq. 2 for; the returned
  // hypothesis of the best model, if any. `weighed` tells whether some hypothesis got past the
  // geometry (fit and Eq. 2) to the scan's evidence.
  auto score_set = [&](const LegSet& set, bool& weighed) -> std::optional<Hypothesis> {
    std::array<Eigen::Vector2d, 4> rough{};
    for (int i = 0; i < set.count; ++i) rough[i] = centres[set.legs[i]];
    const EdgeSizes edges = MeasureEdges(rough, set.count);
    // Eq. 2 screening on the cluster centres.
    const std::vector<ModelPair> pairs = MatchModels(edges, models_, config_.model_match);
    stats.model_pairs += static_cast<int>(pairs.size());
    const Eigen::Vector2d long_edge = edges.first_edge_long ? Eigen::Vector2d(rough[1] - rough[0])
                                                            : Eigen::Vector2d(rough[2] - rough[1]);
    const double hint = std::atan2(long_edge.y(), long_edge.x());
    // The model of a leg set is the one its legs match best (the smaller chi-square, below);
    // the evidence, which barely differs between close models, does not choose it.
    std::optional<Hypothesis> best;
    for (const ModelPair& pair : pairs) {
      ++stats.hypotheses;
      Hypothesis h = Score(set, models_[pair.model], pair.model, hint, inputs, cache);
      weighed =
          weighed || (h.record.verdict != Verdict::kFit && h.record.verdict != Verdict::kModel &&
                      h.record.verdict != Verdict::kBlendedLegs);
      if (h.record.verdict == Verdict::kReturned) {
        if (!best) {
          best = std::move(h);
          continue;
        }
        // A model the set could be returned as comes before one it could not.
        if (h.unreturnable != best->unreturnable) {
          if (best->unreturnable) std::swap(h, *best);
          h.record.verdict = Verdict::kHiddenLegNoPreset;
          Count(h.record.verdict, stats.rejected);
          if (explain) result.hypotheses.push_back(std::move(h.record));
          continue;
        }
        // Models the legs tell apart clearly are chosen on the legs' chi-square (a leg placed by
        // one bloomed outline edge less certain across its beam: ModelChoiceChiSquare); close ones
        // (1075x883 and 1080x856: 5 and 27 mm apart) on the shelf fitted to the legs' returns,
        // which holds a far leg seen by one or two returns where the other legs put it rather
        // than where its own outline and the weak prior of the leg fit did.
        double chi2 = h.legs_chi2;
        double best_chi2 = best->legs_chi2;
        if (std::abs(chi2 - best_chi2) < config_.shelf_fit.returns_chi2_margin) {
          chi2 = on_returns(h).chi2;
          best_chi2 = on_returns(*best).chi2;
        }
        if (chi2 < best_chi2) {
          std::swap(h, *best);
          std::swap(chi2, best_chi2);
        }
        std::optional<RunnerUp>& runner_up = best->detection.runner_up;
        const double margin = chi2 - best_chi2;
        if (!runner_up || margin < runner_up->chi2_margin) {
          runner_up = RunnerUp{h.detection.model, margin};
        }
        h.record.verdict = Verdict::kModel;  // the same legs fit another model better
      }
      Count(h.record.verdict, stats.rejected);
      if (explain) result.hypotheses.push_back(std::move(h.record));
    }
    return best;
  };
  // A hypothesis that will not compete: counted and, when asked, explained.
  auto retire = [&](HypothesisRecord& record, Verdict verdict) {
    record.verdict = verdict;
    Count(verdict, stats.rejected);
    if (explain) result.hypotheses.push_back(std::move(record));
  };
  std::vector<Hypothesis> hypotheses;
  // Weighs one leg set; its best hypothesis, if any, joins the competition.
  auto consider = [&](const LegSet& set) {
    bool weighed = false;
    std::optional<Hypothesis> best = score_set(set, weighed);
    // One leg of four may be wrong (a mixed echo behind a far leg, a post beside a corner) and
    // spoil the fit or Eq. 2 for all four; the search only offers the three-leg sets of corners
    // without a fourth leg, so a four-leg set that yields nothing gets its three-leg subsets
    // (in cyclic order, so the corner opposite the dropped leg stays in the middle). A subset
    // counts only when the dropped leg's returns still stand at its corner's range (a leg
    // measured badly); a cluster in front of the corner or beside it was something else, and
    // in clutter four posts near a rectangle would otherwise pass as three legs and a hidden
    // fourth. Only a set the geometry failed gets them, or one whose legs may be blends
    // (blended_legs: two blends' ranges are no measurement, three other legs may be): when the
    // scan's evidence spoke against the four legs, it speaks against their shelf with one leg
    // fewer too. And only with a preset: without the map's word, four posts a few centimetres
    // off a rectangle are as likely as a shelf with one leg measured badly. The most confident
    // subset stands for the set.
    if (!best && !weighed && set.count == 4 && T_lidar_preset) {
      for (int k = 0; k < 4; ++k) {
        const LegSet sub{{set.legs[(k + 1) % 4], set.legs[(k + 2) % 4], set.legs[(k + 3) % 4], -1},
                         3};
        bool sub_weighed = false;
        std::optional<Hypothesis> h = score_set(sub, sub_weighed);
        if (!h) continue;
        // The dropped leg's returns are not at its corner, or another subset is better.
        if (h->corners_present == 0 ||
            (best && h->detection.confidence <= best->detection.confidence)) {
          retire(h->record, Verdict::kLostLegs);
          continue;
        }
        if (best) retire(best->record, Verdict::kLostLegs);
        best = std::move(h);
      }
    }
    if (best) hypotheses.push_back(std::move(*best));
  };
  for (const LegSet& set : sets) consider(set);

  // Hypotheses compete for legs: the disjoint set with the most support wins. The weight is
  // the confidence times four, i.e. the expected number of legs it stands for, so two real
  // neighbours outweigh a phantom made of their legs, and four seen legs outweigh three.
  // Two shelves cannot stand in one place either: hypotheses whose footprints overlap exclude
  // each other like hypotheses that share a leg (a phantom of a person's legs and a neighbour's
  // lying across a real shelf loses to it; eval-layouts --scenes-per-class 1000 --seed0 5001:
  // phantoms 7 -> 6, recall unchanged). The leg rectangles are shrunk by overlap_margin_m so
  // that fit errors of touching neighbours do not count.
  auto compete = [&](double max_offset_m, double max_yaw_rad) {
    std::vector<std::array<int, 4>> legs;
    std::vector<double> weights;
    std::vector<OrientedRect> footprints;
    for (const Hypothesis& h : hypotheses) {
      legs.push_back(h.set.legs);
      weights.push_back(4.0 * h.detection.confidence);
      const double m = config_.evidence.overlap_margin_m;
      footprints.push_back(
          {h.detection.T_lidar_shelf, 0.5 * h.model->length_m - m, 0.5 * h.model->width_m - m});
    }
    std::vector<std::vector<char>> overlap(hypotheses.size(),
                                           std::vector<char>(hypotheses.size(), 0));
    for (std::size_t i = 0; i < footprints.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        overlap[i][j] = overlap[j][i] = RectsOverlap(footprints[i], footprints[j]) ? 1 : 0;
      }
    }
    const std::vector<int> picked = SelectDisjoint(legs, weights, overlap);
    std::vector<Detection> kept;
    for (std::size_t i = 0; i < hypotheses.size(); ++i) {
      Hypothesis& h = hypotheses[i];
      const bool won = std::find(picked.begin(), picked.end(), static_cast<int>(i)) != picked.end();
      if (h.unreturnable) {
        h.record.verdict = Verdict::kHiddenLegNoPreset;
      } else if (!won) {
        h.record.verdict = Verdict::kLostLegs;
      } else if (T_lidar_preset &&
                 !NearPreset(h.detection, *T_lidar_preset, max_offset_m, max_yaw_rad)) {
        h.record.verdict = Verdict::kOffPreset;
      }
      if (h.record.verdict == Verdict::kReturned) {
        // The returned pose: the shelf fitted to its legs' returns, each leg's range counted
        // less certain by the pull of a surface close behind it (as LegSigmas does).
        geometry::Pose2 T = on_returns(h).T_lidar_shelf;
        std::vector<LegReturns> returns = SetReturns(h, inputs);
        if (WidenForBackground(returns, h.set, inputs)) {
          T = FitShelfToReturns(returns, *h.model, T, config_.leg_fit).T_lidar_shelf;
        }
        T.yaw = ResolveHeading(T.yaw, h.detection.T_lidar_shelf.yaw, h.model->HeadingPeriod());
        h.detection.T_lidar_shelf = T;
        h.record.T_lidar_shelf = T;
      }
      Count(h.record.verdict, stats.rejected);
      if (explain) result.hypotheses.push_back(h.record);
      if (h.record.verdict == Verdict::kReturned) kept.push_back(std::move(h.detection));
    }
    // Ranking: with a preset, nearest to it first (paper 3.2); otherwise the most confident.
    std::stable_sort(kept.begin(), kept.end(), [&](const Detection& a, const Detection& b) {
      if (T_lidar_preset) {
        return geometry::Distance(a.T_lidar_shelf, *T_lidar_preset) <
               geometry::Distance(b.T_lidar_shelf, *T_lidar_preset);
      }
      if (a.legs_visible != b.legs_visible) return a.legs_visible > b.legs_visible;
      return a.confidence > b.confidence;
    });
    return kept;
  };
  const PresetGateConfig& gate = config_.preset_gate;
  result.detections = compete(gate.max_offset_m, gate.max_yaw_offset_rad);

  // Nothing near the preset, yet the map says a shelf stands there: a leg in sight may have
  // never become a candidate (one return beside an occluder, a return the trailing filter took
  // for a mixed point, a leg merged with a person's). Two candidates and the preset fix where
  // the shelf's other legs stand; the scan's returns there are cut out as legs, and the sets
  // go through the same fit, screening, evidence and competition as any other.
  if (result.detections.empty() && T_lidar_preset && config_.completion.enabled) {
    const CompletedLegSets completed =
        CompleteLegSets(points, pre, centres, models_, *T_lidar_preset, config_.completion, gate,
                        config_.leg_search, config_.preprocess);
    for (const Cluster& c : completed.legs) {
      centres.push_back(search_centre(c));
      pre.candidates.push_back(c);
    }
    stats.completed_sets = static_cast<int>(completed.sets.size());
    hypotheses.clear();
    inputs.completed = true;
    for (const LegSet& set : completed.sets) consider(set);
    // Returned only within the map's own error (PresetGateConfig::map_error_m).
    result.detections = compete(gate.map_error_m, gate.map_error_yaw_rad);
  }
  if (explain) {
    const int scanned = stats.leg_candidates;
    for (std::size_t i = 0; i < pre.candidates.size(); ++i) {
      const Cluster& c = pre.candidates[i];
      CandidateRecord r;
      r.centre = centres[i];
      r.returns = static_cast<int>(c.points.size());
      r.first_beam = c.points.front().beam;  // a candidate has returns
      r.last_beam = c.points.back().beam;
      r.extent_m = c.extent_m;
      r.completed = static_cast<int>(i) >= scanned;
      r.blended = c.assumed_range_m.has_value();
      r.flush = c.flush;
      result.candidates.push_back(r);
    }
  }
  return result;
}

}  // namespace shelfdock::perception
