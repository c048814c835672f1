// Completing a shelf from two leg candidates and the preset (CompleteLegSets, and the detector's
// second pass): a leg in sight whose returns never became a candidate is cut from the scan at
// the corner the two legs predict, unless those returns could be something else.
//
// The scene, noise free, a WLR-716 fan from angle 0: a 1075 x 883 shelf 1.7 m out at bearing
// 0.5 rad, turned along the ray, so its front legs (corners 0 and 3 of LegCentres) stand 1.2 m
// out and its back legs (1 and 2) 2.3 m out. A wide box at 0.9 m hides back leg 2 whole;
// another, beside back leg 1, leaves that leg one return (the outer one, next to the background
// at 6 m); the beam between that return and the box is a dropout, or (in the mixed-point case)
// the box itself.
#include "perception/leg_completion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "perception/detector.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::BeamPoint;
using testing::kWlrAlpha;
using testing::PaperModels;
using testing::RayBoxRange;
using testing::SymmetricYawError;

constexpr double kBackground_m = 6.0;
constexpr double kOccluder_m = 0.9;
constexpr int kBeams = 271;    // 0 to 90 degrees
constexpr int kHiddenLeg = 2;  // corner (LegCentres) hidden whole
constexpr int kLoneLeg = 1;    // corner seen by one return

const geometry::ShelfModel& Shelf() {
  static const geometry::ShelfModel model = PaperModels()[1];  // t1-rect-1075x883
  return model;
}

geometry::Pose2 TrueShelfPose() { return {1.7 * std::cos(0.5), 1.7 * std::sin(0.5), 0.5}; }

enum class BesideTheLoneReturn { kDropout, kOccluder };

// The beams of corner k's leg, first to last.
std::pair<int, int> LegBeams(const std::array<std::optional<double>, kBeams>& leg_range) {
  int first = -1, last = -1;
  for (int b = 0; b < kBeams; ++b) {
    if (!leg_range[b]) continue;
    if (first < 0) first = b;
    last = b;
  }
  return {first, last};
}

// `lone_shift_m` moves the lone return that far along its beam (away from the sensor).
std::vector<ScanPoint> Scene(BesideTheLoneReturn beside, double lone_shift_m = 0.0) {
  const geometry::Pose2 T = TrueShelfPose();
  const auto corners = Shelf().LegCentres();
  std::array<std::optional<double>, kBeams> range{};
  std::array<std::array<std::optional<double>, kBeams>, 4> leg{};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d c = T * corners[k];
    const geometry::Pose2 T_leg(c.x(), c.y(), T.yaw);
    for (int b = 0; b < kBeams; ++b) {
      leg[k][b] = RayBoxRange(T_leg, Shelf().leg.length_m, Shelf().leg.width_m, b * kWlrAlpha);
      if (leg[k][b] && (!range[b] || *leg[k][b] < *range[b])) range[b] = leg[k][b];
    }
  }
  std::array<bool, kBeams> dropout{};
  // A box 25 beams wide (0.13 m at 0.9 m, too wide for a leg) hides one back leg.
  const auto [first_hidden, last_hidden] = LegBeams(leg[kHiddenLeg]);
  for (int b = first_hidden - 11; b <= last_hidden + 11; ++b) range[b] = kOccluder_m;
  // The other back leg (at the lower bearing) keeps its first beam's return; a box covers the
  // leg's other beams and 25 beyond, toward the shelf's middle.
  const auto [first, last] = LegBeams(leg[kLoneLeg]);
  EXPECT_GE(last - first, 2) << "the leg must span three beams or more";
  const int box_begin = beside == BesideTheLoneReturn::kDropout ? first + 2 : first + 1;
  if (beside == BesideTheLoneReturn::kDropout) dropout[first + 1] = true;
  for (int b = box_begin; b <= last + 25; ++b) range[b] = kOccluder_m;
  *range[first] += lone_shift_m;

  std::vector<ScanPoint> points;
  for (int b = 0; b < kBeams; ++b) {
    if (!dropout[b]) points.push_back(BeamPoint(b, range[b].value_or(kBackground_m)));
  }
  return points;
}

// The detector's search centres: centroids pushed back by the smallest leg's half depth.
std::vector<Eigen::Vector2d> Centres(const PreprocessOutput& pre) {
  std::vector<Eigen::Vector2d> centres;
  for (const Cluster& c : pre.candidates) {
    const double r = c.centroid.norm();
    centres.push_back(c.centroid * (1.0 + 0.013 / r));
  }
  return centres;
}

CompletedLegSets Complete(const std::vector<ScanPoint>& points, const geometry::Pose2& preset,
                          const DetectorConfig& config = {}) {
  const PreprocessOutput pre =
      Preprocess(points, kWlrAlpha, preset, PaperModels(), config.preprocess);
  return CompleteLegSets(points, pre, Centres(pre), PaperModels(), preset, config.completion,
                         config.preset_gate, config.leg_search, config.preprocess);
}

TEST(LegCompletionTest, TheSceneLeavesTwoLegCandidatesSoTheSearchFindsNothing) {
  const auto points = Scene(BesideTheLoneReturn::kDropout);
  const Detector detector(PaperModels(), [] {
    DetectorConfig c;
    c.completion.enabled = false;
    return c;
  }());
  const DetectionResult r = detector.DetectPoints(points, kWlrAlpha, TrueShelfPose());
  EXPECT_TRUE(r.detections.empty());
  EXPECT_EQ(r.stats.leg_sets, 0);
}

TEST(LegCompletionTest, ALoneReturnBesideADropoutCompletesTheShelfAtItsCorner) {
  const auto points = Scene(BesideTheLoneReturn::kDropout);
  const CompletedLegSets completed = Complete(points, TrueShelfPose());
  ASSERT_FALSE(completed.sets.empty());
  // The completed leg is the lone return, within the leg's half extent of its corner.
  const Eigen::Vector2d corner = TrueShelfPose() * Shelf().LegCentres()[kLoneLeg];
  bool found = false;
  for (const Cluster& leg : completed.legs) {
    if (leg.points.size() == 1 && (leg.points.front().p - corner).norm() < 0.03) found = true;
  }
  EXPECT_TRUE(found);
}

TEST(LegCompletionTest, TheDetectorReturnsTheCompletedShelfAtItsTruePose) {
  const auto points = Scene(BesideTheLoneReturn::kDropout);
  // The preset 0.1 m and 0.05 rad off, as a map would be.
  const geometry::Pose2 truth = TrueShelfPose();
  const geometry::Pose2 preset(truth.x + 0.1, truth.y, truth.yaw + 0.05);
  const Detector detector(PaperModels());
  const DetectionResult r = detector.DetectPoints(points, kWlrAlpha, preset);
  ASSERT_EQ(r.detections.size(), 1u);
  const Detection& d = r.detections.front();
  EXPECT_EQ(d.model, Shelf().name);
  EXPECT_EQ(d.legs_used, 3);
  EXPECT_GT(r.stats.completed_sets, 0);
  // Noise free, one leg by a single return: within 1 cm and 10 mrad of the truth.
  EXPECT_LT((d.T_lidar_shelf.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, truth.yaw, Shelf()), 0.01);
}

TEST(LegCompletionTest, ACompletedShelfMatchesTheModelAsTightlyAsWithoutAPreset) {
  // The lone return 2 cm and 5 cm beyond the leg's face: the set's err_sum grows with it. The
  // preset vouched for the completed set already, so it gets the no-preset bound (0.04 m), not
  // the preset's (0.06 m).
  const Detector detector(PaperModels());
  const DetectorConfig config;
  const DetectionResult near =
      detector.DetectPoints(Scene(BesideTheLoneReturn::kDropout, 0.02), kWlrAlpha, TrueShelfPose(),
                            /*explain=*/true);
  ASSERT_EQ(near.detections.size(), 1u);
  EXPECT_LT(near.detections.front().err_sum, config.model_match.three_leg_err_sum_m);
  const DetectionResult far =
      detector.DetectPoints(Scene(BesideTheLoneReturn::kDropout, 0.05), kWlrAlpha, TrueShelfPose(),
                            /*explain=*/true);
  EXPECT_TRUE(far.detections.empty());
  bool between_bounds = false;
  for (const HypothesisRecord& h : far.hypotheses) {
    between_bounds |= h.verdict == Verdict::kThreeLegError &&
                      h.err_sum > config.model_match.three_leg_err_sum_m &&
                      h.err_sum < config.model_match.three_leg_err_sum_preset_m;
  }
  EXPECT_TRUE(between_bounds) << "a completed set with err_sum between the two bounds";
}

TEST(LegCompletionTest, WithoutAPresetNothingIsCompleted) {
  const Detector detector(PaperModels());
  const DetectionResult r =
      detector.DetectPoints(Scene(BesideTheLoneReturn::kDropout), kWlrAlpha, std::nullopt);
  EXPECT_TRUE(r.detections.empty());
  EXPECT_EQ(r.stats.completed_sets, 0);
}

TEST(LegCompletionTest, ALoneReturnBesideANearerBoxAtTheLegsRangeCompletesTheShelf) {
  // The lone return sits right beside the box, as a mixed point of the box's edge would, but at
  // the range where the two other legs and the preset put the leg's face: it is the leg.
  const auto points = Scene(BesideTheLoneReturn::kOccluder);
  const geometry::Pose2 truth = TrueShelfPose();
  EXPECT_FALSE(Complete(points, truth).sets.empty());
  const Detector detector(PaperModels());
  const DetectionResult r = detector.DetectPoints(points, kWlrAlpha, truth);
  ASSERT_EQ(r.detections.size(), 1u);
  const Detection& d = r.detections.front();
  EXPECT_EQ(d.model, Shelf().name);
  // Noise free, one leg by a single return: within 1 cm and 10 mrad of the truth.
  EXPECT_LT((d.T_lidar_shelf.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, truth.yaw, Shelf()), 0.01);
}

TEST(LegCompletionTest, ALoneReturnBesideANearerBoxOffTheLegsRangeMayBeMixedAndDoesNotComplete) {
  // 5.5 and 7 cm beyond the leg's face (3.5 and 5 cm beyond its centre's range), still within
  // reach of the corner (half the leg's extent plus corner_margin_m): where a mixed point of the
  // box's edge and the background may lie, beyond lone_return_tolerance_m of any range the leg
  // returns from (the scene is noise free).
  const Detector detector(PaperModels());
  for (double shift : {0.055, 0.07}) {
    const auto points = Scene(BesideTheLoneReturn::kOccluder, shift);
    EXPECT_TRUE(Complete(points, TrueShelfPose()).sets.empty()) << shift;
    EXPECT_TRUE(detector.DetectPoints(points, kWlrAlpha, TrueShelfPose()).detections.empty())
        << shift;
  }
  // With the rule off, not even the return at the leg's range completes the shelf.
  DetectorConfig off;
  off.completion.lone_return_tolerance_m = 0.0;
  off.completion.lone_return_sigmas = 0.0;
  EXPECT_TRUE(Complete(Scene(BesideTheLoneReturn::kOccluder), TrueShelfPose(), off).sets.empty());
}

TEST(LegCompletionTest, AWallThroughTheCornerIsNoLeg) {
  // Instead of the lone leg, a wall through its corner, facing the sensor, seen on the beams
  // outside the box (the leg's own and 10 more): the returns within reach of the corner are a
  // piece of a surface.
  auto points = Scene(BesideTheLoneReturn::kDropout);
  const Eigen::Vector2d corner = TrueShelfPose() * Shelf().LegCentres()[kLoneLeg];
  const double bearing = std::atan2(corner.y(), corner.x());
  const Eigen::Vector2d normal(std::cos(bearing), std::sin(bearing));
  const int lone_beam = [&] {
    for (const ScanPoint& q : points) {
      if ((q.p - corner).norm() < 0.05) return q.beam;
    }
    return -1;
  }();
  ASSERT_GE(lone_beam, 0);
  for (ScanPoint& q : points) {
    if (q.beam < lone_beam - 10 || q.beam > lone_beam) continue;
    const Eigen::Vector2d u(std::cos(q.angle), std::sin(q.angle));
    q = BeamPoint(q.beam, corner.dot(normal) / u.dot(normal));
  }
  EXPECT_TRUE(Complete(points, TrueShelfPose()).sets.empty());
}

TEST(LegCompletionTest, BeyondTheMapsErrorNothingIsCompleted) {
  const geometry::Pose2 truth = TrueShelfPose();
  DetectorConfig config;
  // 0.3 m off: inside the preset gate (0.5 m), beyond the map's error (0.25 m).
  const geometry::Pose2 preset(truth.x + 0.3, truth.y, truth.yaw);
  EXPECT_TRUE(Complete(Scene(BesideTheLoneReturn::kDropout), preset, config).sets.empty());
  // 0.2 rad turned: inside the gate's 0.35 rad, beyond the map's error (0.15 rad).
  const geometry::Pose2 turned(truth.x, truth.y, truth.yaw + 0.2);
  EXPECT_TRUE(Complete(Scene(BesideTheLoneReturn::kDropout), turned, config).sets.empty());
}

// A TiM571-like beam (0.87 deg spot, noise free, no dropouts) on a round-leg 900 x 810 shelf
// whose back legs stand 2 m out with a wall `gap` behind them: the spot is wider than a 26 mm leg
// there, so each back leg returns only blends of leg and wall, centimetres behind the leg, and
// the search of paper 3.2 finds no shelf. The front legs and the preset complete it: the blended
// returns give the back legs' bearings (CompletedLegSets with assumed ranges), and the shelf is
// returned within 1 cm / 10 mrad of the truth. With max_blend_m 0 it is not.
sim::LidarConfig WideBeam() {
  sim::LidarConfig c;
  c.enable_range_noise = false;
  c.enable_dropouts = false;
  c.beam_divergence_rad = 0.0153;
  return c;
}

TEST(LegCompletionTest, ALegSeenOnlyBlendedWithItsBackgroundIsPlacedByItsBearing) {
  const geometry::ShelfModel round = PaperModels()[0];
  const geometry::Pose2 T_shelf(1.55, 0.05, 0.02);
  sim::World world;
  world.AddShelf(1, round, T_shelf);
  world.AddWall({{2.3, -3.0}, {2.3, 3.0}});
  const auto scan = testing::SimScan(world, {}, 1, WideBeam());
  const geometry::Pose2 preset(T_shelf.x + 0.1, T_shelf.y - 0.05, T_shelf.yaw + 0.05);
  const DetectionResult r = Detector(PaperModels()).Detect(scan, preset);
  ASSERT_EQ(r.detections.size(), 1u);
  EXPECT_GT(r.stats.completed_sets, 0);
  const Detection& d = r.detections[0];
  EXPECT_EQ(d.model, round.name);
  EXPECT_LT(geometry::Distance(d.T_lidar_shelf, T_shelf), 0.01);
  EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, T_shelf.yaw, round), 0.01);
  DetectorConfig off;
  off.completion.max_blend_m = 0.0;
  const DetectionResult without = Detector(PaperModels(), off).Detect(scan, preset);
  for (const Detection& w : without.detections) {
    EXPECT_GT(geometry::Distance(w.T_lidar_shelf, T_shelf), 0.05) << w.model;
  }
  EXPECT_TRUE(without.detections.empty());
}

const geometry::ShelfModel& RoundShelf() {
  static const geometry::ShelfModel model = PaperModels()[0];  // round legs, 900 x 810
  return model;
}

const geometry::Pose2 kPostsShelf(1.55, 0.05, 0.02);

// The TiM571-like scan of round posts at corners `legs` of the round-legged shelf at kPostsShelf,
// a wall at 2.8 m, and a post `behind_m` behind empty corner `behind` on its bearing: a 40 mm
// square post (`square`) or one of the legs' size.
geometry::LaserScan PostBehindCornerScan(const std::vector<int>& legs, int behind, double behind_m,
                                         bool square) {
  const auto corners = RoundShelf().LegCentres();
  sim::World world;
  for (int k : legs) world.AddRoundPost(kPostsShelf * corners[k], RoundShelf().leg.Radius());
  const Eigen::Vector2d empty = kPostsShelf * corners[behind];
  const Eigen::Vector2d post = empty + behind_m * empty.normalized();
  if (square) {
    world.AddSquarePost(geometry::Pose2(post.x(), post.y(), 0.3), 0.04);
  } else {
    world.AddRoundPost(post, RoundShelf().leg.Radius());
  }
  world.AddWall({{2.8, -3.0}, {2.8, 3.0}});
  return testing::SimScan(world, {}, 1, WideBeam());
}

const geometry::Pose2 kPostsPreset(kPostsShelf.x + 0.1, kPostsShelf.y - 0.05,
                                   kPostsShelf.yaw + 0.05);

// The shelf's front legs as posts, its back corners empty, and a 40 mm post 0.25 m behind back
// corner `behind` on its bearing (no model fits the three posts): the search took that post as a
// leg at its own range, so it is no blended view of a leg at the corner, and no shelf is returned
// (a neighbour's leg behind an empty corner made a phantom before this rule). With such posts
// behind both back corners, lined up with the front pair, the two would be taken for the back
// legs seen blended, as a TiM571 sees a shelf's two far legs: a blend of a leg and its
// background cannot be told from a post behind it by range alone.
TEST(LegCompletionTest, ALegCandidateBehindAnEmptyCornerIsNoBlend) {
  for (const int behind : {1, 2}) {
    const auto scan = PostBehindCornerScan({0, 3}, behind, 0.25, /*square=*/true);
    const DetectionResult r = Detector(PaperModels()).Detect(scan, kPostsPreset);
    EXPECT_TRUE(r.detections.empty()) << "post behind corner " << behind;
  }
}

// One shelf returned from `scan` with the posts' preset, completed from two legs and the preset:
// the round-legged model within 2 cm / 20 mrad of kPostsShelf (`behind`: the corner the scene
// put a post behind, for the messages).
void ExpectCompletedPostsShelf(const geometry::LaserScan& scan, int behind) {
  const DetectionResult r = Detector(PaperModels()).Detect(scan, kPostsPreset);
  ASSERT_EQ(r.detections.size(), 1u) << "post behind corner " << behind;
  EXPECT_GT(r.stats.completed_sets, 0);
  const Detection& d = r.detections[0];
  EXPECT_EQ(d.model, RoundShelf().name);
  EXPECT_LT(geometry::Distance(d.T_lidar_shelf, kPostsShelf), 0.02) << "behind " << behind;
  EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, kPostsShelf.yaw, RoundShelf()), 0.02);
}

// Three legs in sight and, 6 cm behind the fourth corner `behind` on its bearing, a post of the
// legs' size, which the search took as a leg candidate (and, at its own range, as no leg of this
// shelf). No leg of a neighbour stands that close behind a corner (shelves in rows stand 0.2 m
// apart or more), so two returns or more all within completion.candidate_blend_max_m behind it
// are taken as that leg's blend: the shelf is completed by the corner's bearing, within 2 cm /
// 20 mrad of the truth. With candidate_blend_max_m 0 it is not returned.
TEST(LegCompletionTest, ACandidateCloseBehindAnEmptyCornerIsItsLegSeenBlended) {
  for (const int behind : {1, 2}) {
    const int other_back = behind == 1 ? 2 : 1;
    const auto scan = PostBehindCornerScan({0, other_back, 3}, behind, 0.06, /*square=*/false);
    ExpectCompletedPostsShelf(scan, behind);
    DetectorConfig off;
    off.completion.candidate_blend_max_m = 0.0;
    const DetectionResult without = Detector(PaperModels(), off).Detect(scan, kPostsPreset);
    for (const Detection& w : without.detections) {
      EXPECT_GT(geometry::Distance(w.T_lidar_shelf, kPostsShelf), 0.02) << w.model;
    }
  }
}

// The round-legged shelf's front legs as posts; back corner `behind`'s leg a post 12 cm behind
// the corner on its bearing (a leg whose fit a blend pushed back, or a neighbour's post: beyond
// candidate_blend_max_m, so only a blend before a background close behind it counts,
// completion.candidate_blend_far_max_m 0.15 m); the other back corner hidden behind a 12 cm post
// 0.4 m in front of it; a wall `wall_behind_m` behind the post. Clean returns (no beam footprint,
// no noise), so the post is a leg candidate the search fits into no shelf.
geometry::LaserScan FarPostScan(int behind, double wall_behind_m) {
  const auto corners = RoundShelf().LegCentres();
  const int hidden = behind == 1 ? 2 : 1;
  sim::World world;
  for (int k : {0, 3}) world.AddRoundPost(kPostsShelf * corners[k], RoundShelf().leg.Radius());
  const Eigen::Vector2d corner = kPostsShelf * corners[behind];
  const Eigen::Vector2d post = corner + 0.12 * corner.normalized();
  world.AddRoundPost(post, RoundShelf().leg.Radius());
  const Eigen::Vector2d hidden_corner = kPostsShelf * corners[hidden];
  world.AddRoundPost(hidden_corner - 0.4 * hidden_corner.normalized(), 0.06);
  world.AddWall({{post.x() + wall_behind_m, -3.0}, {post.x() + wall_behind_m, 3.0}});
  sim::LidarConfig clean = WideBeam();
  clean.enable_footprint = false;
  return testing::SimScan(world, {}, 1, clean);
}

// With the wall 0.2 m behind the post (its returns a depth step in front of the wall, near enough
// to blend with it) the shelf is completed on three legs, the post's by the corner's bearing,
// within 2 cm / 20 mrad; with the far bound off, or the wall 0.6 m behind the post, it is not.
TEST(LegCompletionTest, ACandidateFartherBehindAnEmptyCornerIsABlendOnlyBeforeACloseBackground) {
  DetectorConfig off;
  off.completion.candidate_blend_far_max_m = 0.0;
  for (const int behind : {1, 2}) {
    const auto close_wall = FarPostScan(behind, 0.2);
    ExpectCompletedPostsShelf(close_wall, behind);
    EXPECT_TRUE(Detector(PaperModels(), off).Detect(close_wall, kPostsPreset).detections.empty())
        << "behind " << behind;
    EXPECT_TRUE(
        Detector(PaperModels()).Detect(FarPostScan(behind, 0.6), kPostsPreset).detections.empty())
        << "behind " << behind;
  }
}

// Shelves pushed back against a wall, seen by a TiM571-like beam (0.87 deg spot, 0.33 deg steps,
// 10 mm noise, no dropouts): a 1075 x 883 from 3 m, its back legs' back faces 1.5 cm in front
// of the wall (their front faces 5.5 cm), and a round-legged 900 x 810 from 2.5 m, its back legs
// 1.5 cm in front of the wall (front faces 4.1 cm). Each back leg's few returns, blended with the
// wall, lie within the noise-widened depth step of the wall beside them or on its line (or, with
// no return at the leg, a blend within a step of the wall), so they seldom become a candidate,
// and the front legs alone leave the search nothing. With the preset, the completion fits the
// wall's line beside each back corner and takes the returns standing out from it
// (LegCompletionConfig::surface_offset_sigmas) as the legs, by their bearing. Over 40 seeds
// each, every shelf returned is the right model within 2 cm / 20 mrad of the truth; the rule
// finds most shelves, without it few are.
struct WallCase {
  int model;          // PaperModels() index
  double x_m;         // [m] the shelf's centre straight ahead
  int min_found;      // of 40, with the rule
  int max_found_off;  // of 40, without it
};

void ExpectBackLegsCutFromTheWall(const WallCase& w) {
  const geometry::ShelfModel model = PaperModels()[w.model];
  const geometry::Pose2 T_shelf(w.x_m, 0.1, 0.03);
  sim::World world;
  world.AddShelf(1, model, T_shelf);
  // The back legs' centres stand half a length behind the centre (turned 0.03 rad: within
  // 1.4 cm of it), their back faces half a leg behind that; the wall 1.5 cm behind those.
  const double wall_x = T_shelf.x + 0.5 * model.length_m + 0.5 * model.leg.length_m + 0.014 + 0.015;
  world.AddWall({{wall_x, -3.0}, {wall_x + 0.05, 3.0}});
  sim::LidarConfig tim;
  tim.enable_dropouts = false;
  tim.beam_divergence_rad = 0.0153;
  tim.range_noise_sigma_m = 0.01;
  const geometry::Pose2 preset(T_shelf.x + 0.1, T_shelf.y - 0.05, T_shelf.yaw + 0.05);
  DetectorConfig off;
  off.completion.surface_offset_sigmas = 0.0;
  int found_on = 0;
  int found_off = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto scan = testing::SimScan(world, {}, seed, tim);
    const DetectionResult on = Detector(PaperModels()).Detect(scan, preset);
    for (const Detection& d : on.detections) {
      EXPECT_EQ(d.model, model.name) << "seed " << seed;
      EXPECT_LT(geometry::Distance(d.T_lidar_shelf, T_shelf), 0.02) << "seed " << seed;
      EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, T_shelf.yaw, model), 0.02)
          << "seed " << seed;
    }
    found_on += on.detections.empty() ? 0 : 1;
    found_off += Detector(PaperModels(), off).Detect(scan, preset).detections.empty() ? 0 : 1;
  }
  EXPECT_GE(found_on, w.min_found) << model.name;
  EXPECT_LE(found_off, w.max_found_off) << model.name;
}

// Measured: 40 of 40 returned (within 1.1 cm / 16.4 mrad), 4 without the rule.
TEST(LegCompletionTest, SquareBackLegsJustInFrontOfAWallAreCutFromIt) {
  ExpectBackLegsCutFromTheWall({1, 3.0, 36, 10});
}

// Measured: 35 of 40 returned (within 0.8 cm / 11.1 mrad), 6 without the rule.
TEST(LegCompletionTest, RoundBackLegsJustInFrontOfAWallAreCutFromIt) {
  ExpectBackLegsCutFromTheWall({0, 2.5, 30, 10});
}

// The back legs of a 1075 x 883 pushed back near a wall (0.12-0.25 m behind their back faces),
// seen by a TiM571-like beam (0.87 deg spot, 0.33 deg steps, 10 mm noise, no dropouts) from
// 2.5-3 m: a 40 mm leg's few returns blend with the wall behind, so its fit lands centimetres
// behind the corner and the search fits no shelf; the completion cuts the corner from the two
// front legs and finds there the search's own leg, behind the corner's centre with the wall a
// depth step behind it (LegCompletionConfig::blended_candidate_max_returns), and places that leg
// by its bearing. Over 10 seeds per case every shelf returned is the right model within 2 cm /
// 20 mrad; with the rule all 40 are returned, without it fewer (measured: 40 of 40, 22 without).
TEST(LegCompletionTest, ASearchLegBlendedWithAWallCloseBehindCompletesTheCornerByItsBearing) {
  const geometry::ShelfModel model = PaperModels()[1];  // t1-rect-1075x883
  sim::LidarConfig tim;
  tim.enable_dropouts = false;
  tim.beam_divergence_rad = 0.0153;
  tim.range_noise_sigma_m = 0.01;
  DetectorConfig off;
  off.completion.blended_candidate_max_returns = 0;
  int found_on = 0;
  int found_off = 0;
  for (const auto& [x_m, gap_m] : {std::pair{2.5, 0.16}, {2.5, 0.25}, {3.0, 0.12}, {3.0, 0.16}}) {
    const geometry::Pose2 T_shelf(x_m, 0.1, 0.03);
    sim::World world;
    world.AddShelf(1, model, T_shelf);
    // The back legs' back faces stand half a length and half a leg behind the centre (within
    // 1.4 cm more, turned 0.03 rad); the wall `gap_m` behind those.
    const double wall_x =
        T_shelf.x + 0.5 * model.length_m + 0.5 * model.leg.length_m + 0.014 + gap_m;
    world.AddWall({{wall_x, -3.0}, {wall_x + 0.05, 3.0}});
    const geometry::Pose2 preset(T_shelf.x + 0.1, T_shelf.y - 0.05, T_shelf.yaw + 0.05);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto scan = testing::SimScan(world, {}, seed, tim);
      const DetectionResult on = Detector(PaperModels()).Detect(scan, preset);
      for (const Detection& d : on.detections) {
        EXPECT_EQ(d.model, model.name) << x_m << " m, gap " << gap_m << ", seed " << seed;
        EXPECT_LT(geometry::Distance(d.T_lidar_shelf, T_shelf), 0.02)
            << x_m << " m, gap " << gap_m << ", seed " << seed;
        EXPECT_LT(SymmetricYawError(d.T_lidar_shelf.yaw, T_shelf.yaw, model), 0.02)
            << x_m << " m, gap " << gap_m << ", seed " << seed;
      }
      found_on += on.detections.empty() ? 0 : 1;
      found_off += Detector(PaperModels(), off).Detect(scan, preset).detections.empty() ? 0 : 1;
    }
  }
  EXPECT_EQ(found_on, 40);
  EXPECT_LE(found_off, 30);
}

// A post of the legs' size 3 cm behind each empty back corner of the round-legged shelf (the
// front legs posts at their corners), the wall 0.8 m behind them: the posts' returns lie behind
// the corners' centres, within the corners' cut, but a background that far behind returns its
// own echo, so they are no blend of a leg at the corner (blended_candidate_max_step_m, 0.3 m)
// and complete nothing. Were any background allowed (2 m), the four posts would be taken for
// the shelf.
TEST(LegCompletionTest, ASearchLegBehindACornerWithTheBackgroundFarBehindIsNoBlend) {
  const auto corners = RoundShelf().LegCentres();
  std::vector<std::pair<double, int>> by_range;
  for (int k = 0; k < 4; ++k) by_range.push_back({(kPostsShelf * corners[k]).norm(), k});
  std::sort(by_range.begin(), by_range.end());
  sim::World world;
  double farthest = 0.0;
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector2d c = kPostsShelf * corners[by_range[n].second];
    const Eigen::Vector2d post = n < 2 ? c : Eigen::Vector2d(c + 0.03 * c.normalized());
    world.AddRoundPost(post, RoundShelf().leg.Radius());
    farthest = std::max(farthest, post.x());
  }
  world.AddWall({{farthest + 0.8, -3.0}, {farthest + 0.8, 3.0}});
  const auto scan = testing::SimScan(world, {}, 1, WideBeam());
  EXPECT_TRUE(Detector(PaperModels()).Detect(scan, kPostsPreset).detections.empty());
  DetectorConfig any_background;
  any_background.completion.blended_candidate_max_step_m = 2.0;
  EXPECT_FALSE(
      Detector(PaperModels(), any_background).Detect(scan, kPostsPreset).detections.empty());
}

}  // namespace
}  // namespace shelfdock::perception
