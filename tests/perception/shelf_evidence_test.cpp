// What the scan says about a hypothesis: legs seen, hidden or seen through, free space inside
// the footprint, leg sizes. Scenes from the simulated WLR-716 (10 mm noise, mixed points).
#include "perception/shelf_evidence.hpp"

#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "perception/detector.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::PaperModels;
using testing::SimScan;

constexpr double kCentreTol = 0.02;  // [m] single-scan centre error allowed in these scenes

// Three 40 mm square posts at three corners of the 1080x856 model, 2.2 m ahead: a right
// triangle of model size whose corner `empty` (a back corner here) has nothing, with a wall
// behind it.
constexpr int kEmptyCorner = 1;
sim::World ThreeCornerPosts(const geometry::Pose2& T_shelf) {
  const auto model = PaperModels()[3];
  sim::World world;
  testing::AddRoom(world);
  const auto corners = model.LegCentres();
  for (int k = 0; k < 4; ++k) {
    if (k == kEmptyCorner) continue;
    const Eigen::Vector2d c = T_shelf * corners[k];
    world.AddSquarePost(geometry::Pose2(c.x(), c.y(), T_shelf.yaw), 0.04);
  }
  world.AddWall({{4.5, -3.0}, {4.5, 3.0}});
  return world;
}

TEST(ShelfEvidenceTest, EmptyFourthCornerIsSeenThroughAndRejected) {
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  sim::World world = ThreeCornerPosts(T_shelf);
  const Detector detector(models);
  const DetectionResult r = detector.Detect(SimScan(world, {}, 3), T_shelf);
  EXPECT_TRUE(r.detections.empty());
  EXPECT_GE(r.stats.rejected.leg_seen_through, 1);
}

// The same posts with a 0.2 m box 0.3 m in front of the empty back corner (toward the sensor,
// so under the shelf): the corner is hidden, not contradicted.
sim::World ThreeCornerPostsAndABox(const geometry::Pose2& T_shelf) {
  sim::World world = ThreeCornerPosts(T_shelf);
  const Eigen::Vector2d hidden = T_shelf * PaperModels()[3].LegCentres()[kEmptyCorner];
  const Eigen::Vector2d box = hidden - 0.3 * hidden.normalized();
  world.AddBox({geometry::Pose2(box.x(), box.y(), 0.0), 0.2, 0.2});
  return world;
}

TEST(ShelfEvidenceTest, FourthCornerBehindABoxIsExcused) {
  // With a preset the box explains the hidden corner, so it does not count against the free
  // space either: the three legs make a shelf.
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  sim::World world = ThreeCornerPostsAndABox(T_shelf);
  const Detector detector(models);
  const DetectionResult r = detector.Detect(SimScan(world, {}, 3), T_shelf);
  ASSERT_FALSE(r.detections.empty());
  EXPECT_EQ(r.detections[0].model, models[3].name);
  EXPECT_EQ(r.detections[0].legs_visible, 3);
  EXPECT_EQ(r.detections[0].legs_occluded, 1);
  EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
}

// A 30 mm post 0.3 m in front of the empty corner (the three posts 1 m ahead, an ideal sensor:
// no noise, no footprint, no dropouts, so the beams fall where the geometry puts them). Right
// on the corner's line of sight it hides the corner: excused, the three posts are returned as
// the shelf the preset expects (as a box would). Beside the line of sight (18 mrad off) it
// still covers the outer beams of the corner's window, but the beams through where the leg
// would stand reach the wall behind: the corner is seen through, nothing is returned. Before
// this rule anything nearer in the window excused the corner (eval-layouts
// --scenes-per-class 1000 --seed0 5001: 9 -> 8 clutter phantoms).
TEST(ShelfEvidenceTest, APostBesideTheLineOfSightDoesNotHideAnEmptyCorner) {
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(1.0, 0.1, 0.3);
  const Eigen::Vector2d corner = T_shelf * models[3].LegCentres()[kEmptyCorner];
  sim::LidarConfig ideal;
  ideal.enable_range_noise = false;
  ideal.enable_footprint = false;
  ideal.enable_dropouts = false;
  const Detector detector(models);
  auto scan_with_post = [&](double bearing_offset_rad) {
    sim::World world = ThreeCornerPosts(T_shelf);
    const double range = corner.norm() - 0.3;
    const double bearing = std::atan2(corner.y(), corner.x()) + bearing_offset_rad;
    world.AddRoundPost(Eigen::Vector2d(range * std::cos(bearing), range * std::sin(bearing)),
                       0.015);
    return SimScan(world, {}, 3, ideal);
  };
  const DetectionResult hidden = detector.Detect(scan_with_post(0.0), T_shelf);
  ASSERT_EQ(hidden.detections.size(), 1u);
  EXPECT_EQ(hidden.detections[0].model, models[3].name);
  EXPECT_EQ(hidden.detections[0].legs_occluded, 1);
  EXPECT_LT(geometry::Distance(hidden.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
  const DetectionResult beside = detector.Detect(scan_with_post(0.018), T_shelf);
  EXPECT_TRUE(beside.detections.empty());
  EXPECT_GE(beside.stats.rejected.leg_seen_through, 1);
}

// The three posts 1.5 m ahead (the ideal sensor as above) and a 0.15 m box beside the empty
// corner: its near face 5 cm in front of the corner's range, its side 2 cm off the corner's
// line of sight, inside the window around the corner but clear of its core. Its edge returns lie
// at the leg's range, yet the beams through where the leg would stand reach the wall behind: the
// corner is seen through and nothing is returned (evidence.present_in_core). Without the rule
// those returns counted as the fourth leg, present, and the three posts were returned (as with
// a post beside the corner of three posts in clutter: eval-layouts --no-preset --class clutter
// --scenes-per-class 3000, seed 1 clutter 2481). A box covering the core stands where the leg
// would: present, the shelf returned.
TEST(ShelfEvidenceTest, ReturnsBesideAnEmptyCornerAreNoLegThere) {
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(1.5, 0.1, 0.3);
  const Eigen::Vector2d corner = T_shelf * models[3].LegCentres()[kEmptyCorner];
  const Eigen::Vector2d along = corner.normalized();
  const Eigen::Vector2d across(-along.y(), along.x());
  sim::LidarConfig ideal;
  ideal.enable_range_noise = false;
  ideal.enable_footprint = false;
  ideal.enable_dropouts = false;
  constexpr double kSide = 0.15;
  auto scan_with_box = [&](double side_off_line_m) {
    sim::World world = ThreeCornerPosts(T_shelf);
    const Eigen::Vector2d centre =
        corner + (0.5 * kSide - 0.05) * along + (side_off_line_m + 0.5 * kSide) * across;
    world.AddBox(
        {geometry::Pose2(centre.x(), centre.y(), std::atan2(along.y(), along.x())), kSide, kSide});
    return SimScan(world, {}, 3, ideal);
  };
  const Detector detector(models);
  const auto beside = scan_with_box(0.02);
  const DetectionResult r = detector.Detect(beside, T_shelf);
  EXPECT_TRUE(r.detections.empty());
  EXPECT_GE(r.stats.rejected.leg_seen_through, 1);
  DetectorConfig off;
  off.evidence.present_in_core = false;
  const DetectionResult without_rule = Detector(models, off).Detect(beside, T_shelf);
  ASSERT_EQ(without_rule.detections.size(), 1u);
  EXPECT_EQ(without_rule.detections[0].legs_visible, 4);
  EXPECT_LT(geometry::Distance(without_rule.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
  // The box's side across the corner's line of sight, 2 cm past it: the core's beams hit it.
  const DetectionResult covering = detector.Detect(scan_with_box(-0.02), T_shelf);
  ASSERT_EQ(covering.detections.size(), 1u);
  EXPECT_EQ(covering.detections[0].legs_visible, 4);
  EXPECT_LT(geometry::Distance(covering.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
}

// The core's allowance for the corner's error (GatherEvidence's corner_error_m), on a hand-made
// scan around an empty corner 1.8 m away: its three middle beams pass through to the background
// 2 m behind, the next beam either side (21 mm off the corner's line) returns from an object at
// the corner's range. With the corner known to 5 mm, beams through its core passed: seen through.
// With the corner known only to 12 mm (a shelf whose legs fit its model a couple of centimetres
// off) the core keeps one beam, and the returns beside it may be its leg: present; so too with
// evidence.present_in_core off.
TEST(ShelfEvidenceTest, TheCoreAllowsForTheCornersError) {
  const geometry::ShelfModel model = PaperModels()[1];
  constexpr int kCornerBeam = 40;
  constexpr double kRange = 1.8;
  const Eigen::Vector2d corner = testing::BeamPoint(kCornerBeam, kRange).p;
  const Eigen::Vector2d leg0 = model.LegCentres()[0];
  const geometry::Pose2 T_lidar_shelf(corner.x() - leg0.x(), corner.y() - leg0.y(), 0.0);
  PreprocessOutput pre;
  for (int j = -4; j <= 4; ++j) {
    const double range = std::abs(j) == 2 ? kRange - 0.03 : kRange + 2.0;
    pre.points.push_back(testing::BeamPoint(kCornerBeam + j, range));
  }
  auto view = [&](double corner_error_m, bool rule) {
    EvidenceConfig config;
    config.present_in_core = rule;
    return GatherEvidence(T_lidar_shelf, model, {-1, -1, -1, -1}, {pre, {}, testing::kWlrAlpha},
                          false, config, corner_error_m)
        .legs[0];
  };
  EXPECT_EQ(view(0.0, true), LegView::kSeenThrough);
  EXPECT_EQ(view(0.012, true), LegView::kPresent);
  EXPECT_EQ(view(0.0, false), LegView::kPresent);
}

TEST(ShelfEvidenceTest, WithoutAPresetAFourthCornerBehindSomethingElseVouchesForNothing) {
  // The scene above without a preset: nothing says a shelf stands there, and three posts with a
  // box in front of the fourth corner are what clutter makes. Not returned, and counted.
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  sim::World world = ThreeCornerPostsAndABox(T_shelf);
  const Detector detector(models);
  const DetectionResult r = detector.Detect(SimScan(world, {}, 3));
  EXPECT_TRUE(r.detections.empty());
  EXPECT_GE(r.stats.rejected.hidden_leg_no_preset, 1);
  // A real shelf seen along its side hides a back leg behind its own front leg: that one needs
  // no preset (the sensor on the line of one long side: its back leg stands behind the front).
  sim::World side;
  testing::AddRoom(side);
  const geometry::Pose2 T_side(2.5, -0.5 * models[3].width_m, 0.0);
  side.AddShelf(1, models[3], T_side);
  const DetectionResult rs = detector.Detect(SimScan(side, {}, 4));
  ASSERT_FALSE(rs.detections.empty());
  EXPECT_LT(geometry::Distance(rs.detections[0].T_lidar_shelf, T_side), kCentreTol);
  EXPECT_EQ(rs.detections[0].legs_used, 3);
  EXPECT_EQ(rs.detections[0].legs_occluded, 1);
  EXPECT_EQ(rs.stats.rejected.hidden_leg_no_preset, 0);
}

// Three posts and, where the fourth leg should stand, the face of a 0.6 m box (a crate, a rack
// upright with its panel): returns at the leg's range, but of an object far wider than a leg.
// Without a preset that vouches for nothing (hidden_leg_no_preset; with the rule off,
// max_present_object_m 0, the three posts are returned). A real shelf whose fourth leg has a
// person's leg touching it (one cluster, too wide for a leg candidate) is still returned
// without a preset: that cluster is narrower than max_present_object_m (0.4 m).
TEST(ShelfEvidenceTest, WithoutAPresetABoxWhereTheFourthLegShouldBeVouchesForNothing) {
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  sim::World world = ThreeCornerPosts(T_shelf);
  const Eigen::Vector2d corner = T_shelf * models[3].LegCentres()[kEmptyCorner];
  const Eigen::Vector2d centre = corner + 0.15 * corner.normalized();
  const double facing = std::atan2(corner.y(), corner.x());
  world.AddBox({geometry::Pose2(centre.x(), centre.y(), facing), 0.3, 0.6});
  const auto scan = SimScan(world, {}, 3);
  const DetectionResult r = Detector(models).Detect(scan);
  EXPECT_TRUE(r.detections.empty());
  EXPECT_GE(r.stats.rejected.hidden_leg_no_preset, 1);
  DetectorConfig off;
  off.evidence.max_present_object_m = 0.0;
  const DetectionResult without_rule = Detector(models, off).Detect(scan);
  ASSERT_EQ(without_rule.detections.size(), 1u);
  EXPECT_LT(geometry::Distance(without_rule.detections[0].T_lidar_shelf, T_shelf), kCentreTol);

  sim::World shelf_and_person;
  testing::AddRoom(shelf_and_person);
  shelf_and_person.AddShelf(1, models[3], T_shelf);
  shelf_and_person.AddWall({{4.5, -3.0}, {4.5, 3.0}});
  const Eigen::Vector2d across(-corner.normalized().y(), corner.normalized().x());
  shelf_and_person.AddRoundPost(corner + (0.02 + 0.06 + 0.005) * across, 0.06);
  const DetectionResult rp = Detector(models).Detect(SimScan(shelf_and_person, {}, 3));
  ASSERT_EQ(rp.detections.size(), 1u);
  EXPECT_EQ(rp.detections[0].model, models[3].name);
  EXPECT_LT(geometry::Distance(rp.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
  EXPECT_EQ(rp.detections[0].legs_used, 3);     // the merged leg is no candidate ...
  EXPECT_EQ(rp.detections[0].legs_visible, 4);  // ... but its returns are at the corner
  // With the bound at a bare leg's size, that shelf is lost too: the bound is what keeps it.
  DetectorConfig tight;
  tight.evidence.max_present_object_m = 0.05;
  EXPECT_TRUE(Detector(models, tight).Detect(SimScan(shelf_and_person, {}, 3)).detections.empty());
}

TEST(ShelfEvidenceTest, APresetVouchesForAHiddenFourthCornerOnlyWithinTheMapsError) {
  // The same three posts and box. A preset 0.1 m / 0.05 rad off (inside the map's error, 0.25 m
  // and 0.15 rad) vouches for the hidden fourth leg; one 0.35 m off, inside the 0.5 m preset gate
  // but beyond the map's error, does not: the scan alone then decides, as without a preset.
  const auto models = PaperModels();
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  const auto scan = SimScan(ThreeCornerPostsAndABox(T_shelf), {}, 3);
  const Detector detector(models);
  const DetectionResult near = detector.Detect(scan, geometry::Pose2(2.3, 0.1, 0.35));
  ASSERT_EQ(near.detections.size(), 1u);
  EXPECT_EQ(near.detections[0].model, models[3].name);
  EXPECT_LT(geometry::Distance(near.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
  const DetectionResult far = detector.Detect(scan, geometry::Pose2(2.2, 0.45, 0.3));
  EXPECT_TRUE(far.detections.empty());
  EXPECT_GE(far.stats.rejected.hidden_leg_no_preset, 1);
  // The same preset with the map's error widened to 0.4 m: vouched for again.
  DetectorConfig wide;
  wide.preset_gate.map_error_m = 0.4;
  const DetectionResult widened =
      Detector(models, wide).Detect(scan, geometry::Pose2(2.2, 0.45, 0.3));
  ASSERT_EQ(widened.detections.size(), 1u);
  EXPECT_LT(geometry::Distance(widened.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
}

TEST(ShelfEvidenceTest, ThreeLegsNoMapVouchesForMustBeSurer) {
  // A 1250x1250 shelf over the sensor, one leg in the blind sector behind it (the WLR-716 sees
  // +-135 deg): three legs seen, the fourth unobserved. Without a preset only the scan vouches
  // for the shelf, and posts around the sensor in clutter look the same: such a 3-leg shelf must
  // reach evidence.min_confidence_unvouched, not just min_confidence. With a preset at the
  // shelf, min_confidence is enough.
  const auto models = PaperModels();
  const geometry::ShelfModel& large = models[2];
  const geometry::Pose2 T_shelf(0.1, 0.3, 0.0);
  const Eigen::Vector2d blind = T_shelf * large.LegCentres()[0];
  ASSERT_GT(std::abs(std::atan2(blind.y(), blind.x())), 2.4);  // behind the 135 deg edge
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, large, T_shelf);
  const auto scan = SimScan(world, {}, 5);
  const DetectionResult found = Detector(models).Detect(scan);
  ASSERT_EQ(found.detections.size(), 1u);
  const Detection& d = found.detections[0];
  EXPECT_EQ(d.model, large.name);
  EXPECT_EQ(d.legs_used, 3);
  EXPECT_LT(geometry::Distance(d.T_lidar_shelf, T_shelf), kCentreTol);
  EXPECT_GE(d.confidence, DetectorConfig{}.evidence.min_confidence_unvouched);
  // The bar just above this shelf's confidence: not returned without a preset ...
  DetectorConfig strict;
  strict.evidence.min_confidence_unvouched = std::min(0.99, d.confidence + 0.01);
  const DetectionResult unvouched = Detector(models, strict).Detect(scan);
  EXPECT_TRUE(unvouched.detections.empty());
  EXPECT_GE(unvouched.stats.rejected.low_confidence, 1);
  // ... and returned with the map's preset 0.1 m / 0.05 rad off.
  const DetectionResult vouched =
      Detector(models, strict).Detect(scan, geometry::Pose2(0.2, 0.3, 0.05));
  ASSERT_EQ(vouched.detections.size(), 1u);
  EXPECT_LT(geometry::Distance(vouched.detections[0].T_lidar_shelf, T_shelf), kCentreTol);
}

// A 3-leg set whose fitted legs miss the model by 4-6 cm (err_sum; one post moved outward, as
// far legs under 20 mm range noise can come out): with a preset it is within
// three_leg_err_sum_preset_m and goes on to the evidence (returned, or rejected for a reason of
// its own), without one it is beyond the stricter three_leg_err_sum_m: three_leg_error.
TEST(ShelfEvidenceTest, ThreeLegBoundIsWiderWithAPreset) {
  const auto models = PaperModels();
  const geometry::ShelfModel& model = models[3];
  const DetectorConfig config;
  const Detector detector(models, config);
  const geometry::Pose2 T_shelf(2.2, 0.1, 0.3);
  const auto corners = model.LegCentres();
  // The verdict of the scene's 3-leg hypothesis of `model` and its err_sum.
  auto three_leg = [&](const DetectionResult& r) {
    std::pair<Verdict, double> out{Verdict::kFit, 0.0};
    for (const auto& h : r.hypotheses) {
      if (h.model == model.name && h.legs.size() == 3) out = {h.verdict, h.err_sum};
    }
    return out;
  };
  int between = 0;
  for (double shift = 0.0; shift <= 0.06; shift += 0.0025) {
    sim::World world;
    testing::AddRoom(world);
    for (int k = 0; k < 4; ++k) {
      if (k == kEmptyCorner) continue;
      Eigen::Vector2d c = corners[k];
      if (k == 3) c.y() -= shift;  // moved outward along the short side
      const Eigen::Vector2d w = T_shelf * c;
      world.AddSquarePost(geometry::Pose2(w.x(), w.y(), T_shelf.yaw), 0.04);
    }
    const Eigen::Vector2d hidden = T_shelf * corners[kEmptyCorner];
    const Eigen::Vector2d box = hidden - 0.3 * hidden.normalized();
    world.AddBox({geometry::Pose2(box.x(), box.y(), 0.0), 0.2, 0.2});
    const geometry::LaserScan scan = SimScan(world, {}, 3);
    const auto [verdict_with, err] = three_leg(detector.Detect(scan, T_shelf, true));
    if (err <= config.model_match.three_leg_err_sum_m + 0.002 ||
        err >= config.model_match.three_leg_err_sum_preset_m - 0.002) {
      continue;
    }
    ++between;
    EXPECT_NE(verdict_with, Verdict::kThreeLegError) << "shift " << shift << " err " << err;
    const DetectionResult without = detector.Detect(scan, std::nullopt, true);
    EXPECT_EQ(three_leg(without).first, Verdict::kThreeLegError) << "shift " << shift;
    for (const auto& d : without.detections) {
      EXPECT_GT(geometry::Distance(d.T_lidar_shelf, T_shelf), 0.1) << "shift " << shift;
    }
  }
  EXPECT_GE(between, 1) << "no shift put err_sum between the two bounds";
}

TEST(ShelfEvidenceTest, PostInsideTheFootprintLowersConfidence) {
  const auto models = PaperModels();
  const geometry::ShelfModel& model = models[3];
  const geometry::Pose2 T_shelf(2.0, 0.0, 0.0);
  sim::World clear;
  testing::AddRoom(clear);
  clear.AddShelf(1, model, T_shelf);
  sim::World blocked = clear;
  blocked.AddSquarePost(geometry::Pose2(2.0, 0.1, 0.0), 0.04);  // a leg-sized post inside
  const Detector detector(models);
  const DetectionResult a = detector.Detect(SimScan(clear, {}, 4), T_shelf);
  const DetectionResult b = detector.Detect(SimScan(blocked, {}, 4), T_shelf);
  ASSERT_FALSE(a.detections.empty());
  EXPECT_EQ(a.detections[0].legs_visible, 4);
  EXPECT_EQ(a.detections[0].interior_points, 0);
  EXPECT_GT(a.detections[0].confidence, 0.6);
  // With the post inside: either not returned, or returned with its points counted and a lower
  // confidence.
  if (!b.detections.empty()) {
    EXPECT_GT(b.detections[0].interior_points, 0);
    EXPECT_LT(b.detections[0].confidence, a.detections[0].confidence);
  }
}

TEST(ShelfEvidenceTest, LegSilhouetteAngle) {
  geometry::LegModel square;  // 40 x 40 mm
  // Face-on 2 m away: the near corners at 1.98 m bound it; along the diagonal: the side corners.
  EXPECT_NEAR(LegSilhouetteAngle(square, 0.0, {2.0, 0.0}), 2.0 * std::atan(0.02 / 1.98), 1e-12);
  EXPECT_NEAR(LegSilhouetteAngle(square, M_PI / 4, {2.0, 0.0}),
              2.0 * std::atan(0.02 * std::sqrt(2.0) / 2.0), 1e-12);
  // 0.2 m away, turned by 0.3 rad: the angle between the outermost corner bearings, whatever
  // their depth.
  const double yaw = 0.3;
  double lo = 1e9, hi = -1e9;
  for (const double sx : {-0.02, 0.02}) {
    for (const double sy : {-0.02, 0.02}) {
      const double b = std::atan2(0.1 + std::sin(yaw) * sx + std::cos(yaw) * sy,
                                  0.2 + std::cos(yaw) * sx - std::sin(yaw) * sy);
      lo = std::min(lo, b);
      hi = std::max(hi, b);
    }
  }
  EXPECT_NEAR(LegSilhouetteAngle(square, yaw, {0.2, 0.1}), hi - lo, 1e-12);
  geometry::LegModel round{geometry::LegShape::kCircle, 0.026, 0.026};
  EXPECT_NEAR(LegSilhouetteAngle(round, 0.7, {1.0, 1.0}), 2.0 * std::asin(0.013 / std::sqrt(2.0)),
              1e-12);
}

// Three exact 40 mm legs of the 1075x883 model 2 m ahead (the fourth corner empty); the first
// leg keeps only its last return, as behind a dropout or an occluder. With that side of its
// outline open the narrow leg is only a lower bound on its width and costs nothing; with both
// sides closed (the beams beside it passed it) it is 3-4 cm narrower than the model's leg, beyond
// a beam plus leg_width_slack_m, and lowers the confidence.
TEST(ShelfEvidenceTest, ALegOpenOnOneSideIsOnlyALowerBoundOnItsWidth) {
  const geometry::ShelfModel model = PaperModels()[1];
  const geometry::Pose2 T_lidar_shelf(2.0, 0.2, 0.3);
  const double alpha = testing::kWlrAlpha;
  const EvidenceConfig config;
  auto evidence = [&](bool cut_side_open) {
    PreprocessOutput pre;
    const auto corners = model.LegCentres();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d c = T_lidar_shelf * corners[static_cast<std::size_t>(k)];
      Cluster leg;
      leg.points = testing::CastBox(geometry::Pose2(c.x(), c.y(), T_lidar_shelf.yaw),
                                    model.leg.length_m, model.leg.width_m, alpha);
      if (k == 0) leg.points.erase(leg.points.begin(), leg.points.end() - 1);
      for (const auto& q : leg.points) leg.centroid += q.p / static_cast<double>(leg.points.size());
      if (k != 0 || !cut_side_open) leg.edges.before_rad = leg.points.front().angle - 0.5 * alpha;
      leg.edges.after_rad = leg.points.back().angle + 0.5 * alpha;
      pre.candidates.push_back(leg);
    }
    return GatherEvidence(T_lidar_shelf, model, {0, 1, 2, -1}, {pre, {}, alpha}, false, config);
  };
  const ShelfEvidence open = evidence(true);
  const ShelfEvidence closed = evidence(false);
  EXPECT_EQ(open.legs_seen, 3);
  EXPECT_DOUBLE_EQ(open.leg_width_error_m, 0.0);
  EXPECT_DOUBLE_EQ(open.leg_width_bias_excess_m, 0.0);
  EXPECT_GT(closed.leg_width_error_m, 0.0);
  EXPECT_LT(ShelfConfidence(closed, 0.0, 3, config), ShelfConfidence(open, 0.0, 3, config));
}

TEST(ShelfEvidenceTest, ConfidenceIsOneForAPerfectShelfAndFallsWithEachFlaw) {
  const EvidenceConfig config;
  ShelfEvidence ev;
  ev.legs_seen = 4;
  EXPECT_DOUBLE_EQ(ShelfConfidence(ev, 0.0, 4, config), 1.0);
  ShelfEvidence hidden = ev;
  hidden.legs_seen = 3;
  hidden.legs_occluded = 1;
  EXPECT_NEAR(ShelfConfidence(hidden, 0.0, 4, config), (3 + config.occluded_credit) / 4, 1e-12);
  // The legs' chi-square halves it at fit_chi2_* per degree of freedom (5 with four legs, 3
  // with three).
  EXPECT_NEAR(ShelfConfidence(ev, 5.0 * config.fit_chi2_four_legs, 4, config), 0.5, 1e-12);
  ShelfEvidence three = ev;
  three.legs_seen = 3;
  const double three_support = (3 + config.unobserved_credit) / 4;
  EXPECT_NEAR(ShelfConfidence(three, 0.0, 3, config), three_support, 1e-12);
  EXPECT_NEAR(ShelfConfidence(three, 3.0 * config.fit_chi2_three_legs, 3, config),
              0.5 * three_support, 1e-12);
  // Points of foreign legs count in full, those of other objects a quarter with four legs seen.
  ShelfEvidence inside = ev;
  inside.interior_points = static_cast<int>(config.interior_scale_points);
  inside.interior_leg_points = inside.interior_points;
  EXPECT_NEAR(ShelfConfidence(inside, 0.0, 4, config), 0.5, 1e-12);
  ShelfEvidence object = ev;
  object.interior_object_points = config.interior_scale_points / config.object_point_weight;
  EXPECT_NEAR(ShelfConfidence(object, 0.0, 4, config), 0.5, 1e-12);
  ShelfEvidence through = ev;
  through.legs_seen = 3;
  through.legs_seen_through = 1;
  EXPECT_NEAR(ShelfConfidence(through, 0.0, 4, config), 0.75, 1e-12);
  // The legs' mean width beyond its slack halves it at leg_width_scale_m.
  ShelfEvidence thin = ev;
  thin.leg_width_bias_excess_m = config.leg_width_scale_m;
  EXPECT_NEAR(ShelfConfidence(thin, 0.0, 4, config), 0.5, 1e-12);
}

// Four legs at the corners of the 1075x883 model (40 mm square legs), turned 45 degrees to the
// sensor so a square leg shows its 57 mm diagonal, 1.5 m ahead: made of 40 mm square posts the
// legs' mean seen width matches the model's; made of 26 mm round posts (the round model's legs)
// it is about 30 mm short, which one leg's beam-quantised width could not show but the mean of
// four does, and the confidence falls.
TEST(ShelfEvidenceTest, LegsOfAnotherSectionLowerTheConfidence) {
  const auto models = PaperModels();
  const auto& model = models[1];
  ASSERT_EQ(model.name, "t1-rect-1075x883");
  const geometry::Pose2 T_shelf(1.5 + 0.5 * model.length_m, 0.05, 0.0);
  auto detect = [&](bool round_legs) {
    sim::World world;
    testing::AddRoom(world);
    for (const Eigen::Vector2d& corner : model.LegCentres()) {
      const Eigen::Vector2d c = T_shelf * corner;
      if (round_legs) {
        world.AddRoundPost(c, 0.013);
      } else {
        world.AddSquarePost(geometry::Pose2(c.x(), c.y(), M_PI / 4), 0.04);
      }
    }
    return Detector(models).Detect(SimScan(world, {}, 5), T_shelf);
  };
  const DetectionResult square = detect(false);
  ASSERT_FALSE(square.detections.empty());
  EXPECT_EQ(square.detections.front().model, model.name);
  EXPECT_NEAR(square.detections.front().leg_width_bias_m, 0.0, 0.01);
  const DetectionResult round = detect(true);
  const bool same_model = !round.detections.empty() && round.detections.front().model == model.name;
  // Either not returned at all (below min_confidence) or returned with the lower confidence.
  if (same_model) {
    EXPECT_LT(round.detections.front().leg_width_bias_m, -0.015);
    EXPECT_LT(round.detections.front().confidence, 0.6 * square.detections.front().confidence);
  }
}

// A 1075x883 shelf 1.8 m ahead, all four legs in sight, and a 40 mm post standing on the line
// between its two front legs (0.44 m from each, 2 cm in front of the line), where the shrunk
// footprint of the free-space check does not reach: it stands on the edge, so it counts as a
// leg inside (evidence.edge_band_m) and its returns lower the confidence (the leg itself is
// excused here: four legs measured and the preset vouch, evidence.foreign_legs_excused). Two such
// posts 0.25 m apart are
// taken for a person's legs (evidence.edge_partner_m) and do not count.
TEST(ShelfEvidenceTest, ALoneLegOnAnEdgeLineCountsAsInside) {
  const auto models = PaperModels();
  const auto& model = models[1];
  const geometry::Pose2 T_shelf(1.8 + 0.5 * model.length_m, 0.0, 0.0);
  auto best = [&](std::vector<double> post_y) {
    sim::World world;
    testing::AddRoom(world);
    world.AddShelf(1, model, T_shelf);
    for (double y : post_y) world.AddSquarePost(geometry::Pose2(1.78, y, 0.0), 0.04);
    const DetectionResult r = Detector(models).Detect(SimScan(world, {}, 11), T_shelf, true);
    std::optional<HypothesisRecord> found;
    for (const auto& h : r.hypotheses) {
      if (h.model == model.name && h.legs.size() == 4 &&
          (h.T_lidar_shelf.translation() - T_shelf.translation()).norm() < kCentreTol &&
          (!found || h.confidence > found->confidence)) {
        found = h;
      }
    }
    return found;
  };
  const auto clear = best({});
  const auto lone = best({0.0});
  const auto pair = best({-0.1, 0.15});
  ASSERT_TRUE(clear && lone && pair);
  EXPECT_EQ(clear->foreign_legs_inside, 0);
  EXPECT_EQ(lone->foreign_legs_inside, 1);
  EXPECT_LT(lone->confidence, 0.75 * clear->confidence);
  EXPECT_GT(pair->confidence, 0.9 * clear->confidence);
  EXPECT_EQ(pair->foreign_legs_inside, 0);
}

// A person (two 10 cm legs, 0.2 m apart) standing inside the footprint near a front leg of a
// shelf seen with all four legs, 1.8 m ahead, at spots 0.1-0.25 m in from the leg. A person's
// leg is not a shelf leg: it must never count as a foreign leg inside (the signature of a phantom
// made of two shelves' legs), only as an object, and the shelf is returned where it stands.
TEST(ShelfEvidenceTest, PersonInsideTheFootprintIsNotAForeignLeg) {
  const auto models = PaperModels();
  const auto& model = models[1];
  const geometry::Pose2 T_shelf(1.8 + 0.5 * model.length_m, 0.1, 0.15);
  Eigen::Vector2d front(-0.5 * model.length_m, 0.5 * model.width_m);  // near left leg
  int seeds = 0;
  for (double dx : {0.1, 0.15, 0.2, 0.25}) {
    for (double dy : {-0.2, -0.25}) {
      sim::World world;
      testing::AddRoom(world);
      world.AddShelf(1, model, T_shelf);
      // A person standing still: two round legs.
      world.AddRoundPost(T_shelf * Eigen::Vector2d(front.x() + dx, front.y() + dy), 0.05);
      world.AddRoundPost(T_shelf * Eigen::Vector2d(front.x() + dx + 0.2, front.y() + dy), 0.05);
      const DetectionResult r =
          Detector(models).Detect(SimScan(world, {}, 7 + seeds++), T_shelf, true);
      ASSERT_FALSE(r.detections.empty()) << dx << ", " << dy;
      const Detection& d = r.detections.front();
      EXPECT_EQ(d.model, model.name);
      EXPECT_LT(geometry::Distance(d.T_lidar_shelf, T_shelf), kCentreTol) << dx << ", " << dy;
      EXPECT_GT(d.interior_points, 0);
      for (const auto& h : r.hypotheses) {
        if (h.verdict == Verdict::kReturned) {
          EXPECT_EQ(h.foreign_legs_inside, 0) << dx << ", " << dy;
        }
      }
    }
  }
}

// Adds `count` exact returns at `centre`'s range on the beams around its bearing (kWlrAlpha
// steps) as span `pre.spans.size()`; spans must be added in beam order.
void AddSpan(PreprocessOutput& pre, const Eigen::Vector2d& centre, int count) {
  ClusterSpan span;
  span.begin = pre.points.size();
  const double alpha = testing::kWlrAlpha;
  const int middle = static_cast<int>(std::lround(std::atan2(centre.y(), centre.x()) / alpha));
  for (int k = 0; k < count; ++k) {
    pre.points.push_back(testing::BeamPoint(middle - count / 2 + k, centre.norm()));
  }
  span.end = pre.points.size();
  for (std::size_t i = span.begin; i < span.end; ++i) {
    span.centroid += pre.points[i].p / static_cast<double>(count);
  }
  span.extent_m = (pre.points[span.end - 1].p - pre.points[span.begin].p).norm();
  pre.spans.push_back(span);
}

// A leg-sized sliver inside the footprint of a 1075x883 shelf 2 m ahead (three returns, 3 cm
// across, 0.2 m in from a front leg) that some leg set of the search uses, next in the scan to a
// cluster in front of it: the shelf's own front leg, or a post that is no leg of the shelf. Whole,
// it is a foreign leg, the phantom's signature, vouched or not. Partly hidden, it is taken for the
// visible part of a larger object (a person's leg behind the shelf's own) only when the shelf's
// own leg hides it and the map vouches for the shelf: its points still count, as an object's.
TEST(ShelfEvidenceTest, ASliverItsOwnLegPartlyHidesInsideAVouchedShelfIsNoForeignLeg) {
  const geometry::ShelfModel model = PaperModels()[1];
  const geometry::Pose2 T_lidar_shelf(2.0 + 0.5 * model.length_m, 0.0, 0.0);
  const double alpha = testing::kWlrAlpha;
  // Span 0 the sliver, span 1 the cluster beside it in front: the front leg at corner 3
  // (LegCentres: -length / 2, +width / 2), its near face 2 cm in front of its centre.
  PreprocessOutput pre;
  AddSpan(pre, T_lidar_shelf * Eigen::Vector2d(-0.5 * model.length_m + 0.2, 0.2), 3);
  const Eigen::Vector2d front = T_lidar_shelf * model.LegCentres()[3];
  AddSpan(pre, front - 0.02 * front.normalized(), 4);
  ASSERT_LT(pre.points[2].beam, pre.points[3].beam);  // beam order
  Cluster leg;
  leg.points.assign(pre.points.begin() + 3, pre.points.end());
  leg.centroid = pre.spans[1].centroid;
  leg.span = 1;
  pre.candidates.push_back(leg);
  const EvidenceConfig config;
  // `own`: the cluster in front is the shelf's corner 3 (else a post no leg of the shelf).
  auto evidence = [&](SpanRole role, bool vouched, bool own) {
    const std::array<int, 4> corners =
        own ? std::array<int, 4>{-1, -1, -1, 0} : std::array<int, 4>{-1, -1, -1, -1};
    return GatherEvidence(T_lidar_shelf, model, corners, {pre, {role, SpanRole::kLeg}, alpha},
                          vouched, config);
  };
  for (const bool vouched : {false, true}) {
    const ShelfEvidence whole = evidence(SpanRole::kLeg, vouched, true);
    EXPECT_EQ(whole.foreign_legs_inside, 1) << vouched;
    EXPECT_EQ(whole.interior_leg_points, 3) << vouched;
    const ShelfEvidence other = evidence(SpanRole::kOther, vouched, true);
    EXPECT_EQ(other.foreign_legs_inside, 0) << vouched;
    EXPECT_EQ(other.interior_points, 3) << vouched;
  }
  EXPECT_EQ(evidence(SpanRole::kPartlyHiddenLeg, false, true).foreign_legs_inside, 1);
  EXPECT_EQ(evidence(SpanRole::kPartlyHiddenLeg, true, false).foreign_legs_inside, 1);
  const ShelfEvidence vouched = evidence(SpanRole::kPartlyHiddenLeg, true, true);
  EXPECT_EQ(vouched.foreign_legs_inside, 0);
  EXPECT_EQ(vouched.interior_leg_points, 0);
  EXPECT_EQ(vouched.interior_points, 3);
}

// Three legs seen, the fourth unobserved, and a person's legs inside (eight points' worth): without
// a map they count in full, as they must to tell furniture from a shelf; where the map vouches for
// the shelf they weigh object_point_weight each, as under a shelf with four legs seen.
TEST(ShelfEvidenceTest, ObjectsUnderAShelfTheMapVouchesForWeighLess) {
  const EvidenceConfig config;
  ShelfEvidence ev;
  ev.legs_seen = 3;
  ev.interior_object_points = 8.0;
  const double alone = ShelfConfidence(ev, 0.0, 3, config);
  ev.vouched = true;
  const double vouched = ShelfConfidence(ev, 0.0, 3, config);
  const double support = (3.0 + config.unobserved_credit) / 4.0;
  EXPECT_NEAR(alone, support / (1.0 + 8.0 / config.interior_scale_points), 1e-12);
  EXPECT_NEAR(vouched,
              support / (1.0 + config.object_point_weight * 8.0 / config.interior_scale_points),
              1e-12);
  ev.legs_seen = 4;
  ev.vouched = false;
  EXPECT_NEAR(ShelfConfidence(ev, 0.0, 4, config), 1.0 / (1.0 + 2.0 / config.interior_scale_points),
              1e-12);
}

// An object inside the footprint of a 1250x1250 shelf (a 12 cm arc of 30 returns across the
// footprint's near part, 0.6 m from the sensor, and the same arc at 2.5 m): its points count the
// surface they cover, each min(1, beam spacing / object_point_spacing_m), so the near object
// counts about what it would farther off, not five times as much; with the spacing 0 every
// return counts 1.
TEST(ShelfEvidenceTest, AnObjectsPointsCountTheSurfaceTheyCover) {
  const geometry::ShelfModel model = PaperModels()[2];
  const double alpha = testing::kWlrAlpha;
  auto evidence = [&](double range, int returns, double spacing_m) {
    // The shelf centred on the object, so every return lies inside its footprint.
    const geometry::Pose2 T_lidar_shelf(range, 0.0, 0.0);
    PreprocessOutput pre;
    for (int k = 0; k < returns; ++k) {
      ScanPoint q;
      q.angle = (k - 0.5 * (returns - 1)) * alpha;
      q.range = range;
      q.p = range * Eigen::Vector2d(std::cos(q.angle), std::sin(q.angle));
      q.beam = 400 + k;
      pre.points.push_back(q);
    }
    ClusterSpan span;
    span.end = pre.points.size();
    for (const ScanPoint& q : pre.points) span.centroid += q.p / static_cast<double>(returns);
    span.extent_m = (pre.points.back().p - pre.points.front().p).norm();
    pre.spans.push_back(span);
    EvidenceConfig config;
    config.object_point_spacing_m = spacing_m;
    return GatherEvidence(T_lidar_shelf, model, {-1, -1, -1, -1}, {pre, {}, alpha}, false, config);
  };
  const double spacing = EvidenceConfig{}.object_point_spacing_m;
  const ShelfEvidence near = evidence(0.6, 30, spacing);
  EXPECT_EQ(near.interior_points, 30);
  EXPECT_NEAR(near.interior_object_points, 30 * 0.6 * alpha / spacing, 1e-9);
  const ShelfEvidence far = evidence(2.5, 8, spacing);  // 2.5 m * alpha > 1 cm: 1 each
  EXPECT_EQ(far.interior_points, 8);
  EXPECT_NEAR(far.interior_object_points, 8.0, 1e-12);
  EXPECT_NEAR(evidence(0.6, 30, 0.0).interior_object_points, 30.0, 1e-12);
}

// MayBeBlend: a cluster of at most blend_max_returns returns whose beams either side returned from
// behind it, at most blend_max_step_m: one echo of a thin leg and what stands close behind it
// would look so. Not with more returns, a background farther off, something nearer beside it, a
// dropout beside it, a cluster already placed by its bearing, or with the rule off.
TEST(ShelfEvidenceTest, ALegOfFewReturnsCloseInFrontOfItsBackgroundMayBeABlend) {
  const EvidenceConfig config;
  auto leg = [](int returns, std::optional<double> before, std::optional<double> after) {
    Cluster c;
    for (int k = 0; k < returns; ++k) c.points.push_back(testing::BeamPoint(300 + k, 3.5));
    c.edges.before_step_m = before;
    c.edges.after_step_m = after;
    return c;
  };
  EXPECT_TRUE(MayBeBlend(leg(1, 0.2, 0.25), config));
  EXPECT_TRUE(MayBeBlend(leg(2, 0.05, config.blend_max_step_m), config));
  EXPECT_FALSE(MayBeBlend(leg(3, 0.2, 0.25), config));
  EXPECT_FALSE(MayBeBlend(leg(2, 0.2, config.blend_max_step_m + 0.01), config));
  EXPECT_FALSE(MayBeBlend(leg(2, 0.2, -0.5), config));
  EXPECT_FALSE(MayBeBlend(leg(2, 0.2, std::nullopt), config));
  Cluster placed = leg(2, 0.2, 0.25);
  placed.assumed_range_m = 3.3;
  EXPECT_FALSE(MayBeBlend(placed, config));
  EvidenceConfig off;
  off.blend_max_returns = 0;
  EXPECT_FALSE(MayBeBlend(leg(1, 0.2, 0.25), off));
}

// Hand-made returns (AddSpan, three per cluster) around a 1075x883 shelf (by default 2.5 m ahead,
// square to the sensor) whose back-left leg (corner 2) has no cluster: its other legs' near faces
// 2 cm in front of their centres, and whatever a test adds between them, in beam order.
class HiddenBackLeftLeg {
 public:
  HiddenBackLeftLeg() : HiddenBackLeftLeg(2.5, 0.0) {}
  // The front edge `front_m` ahead, the shelf's centre `left_m` to the left.
  HiddenBackLeftLeg(double front_m, double left_m)
      : model_(PaperModels()[1]), T_lidar_shelf_(front_m + 0.5 * model_.length_m, left_m, 0.0) {}

  const geometry::Pose2& T_lidar_shelf() const { return T_lidar_shelf_; }
  // Corner k in the LiDAR frame (LegCentres: 0 front right, 1 back right, 2 back left, 3 front
  // left).
  Eigen::Vector2d Corner(int k) const {
    return T_lidar_shelf_ * model_.LegCentres()[static_cast<std::size_t>(k)];
  }
  // The shelf's own leg at corner k (0, 1 or 3), with `returns` returns; the candidate for
  // further settings.
  Cluster& AddLeg(int k, int returns = 3) {
    const Eigen::Vector2d c = Corner(k);
    Add(c - 0.02 * c.normalized(), SpanRole::kLeg, returns);
    const ClusterSpan& span = pre_.spans.back();
    Cluster leg;
    leg.points.assign(pre_.points.begin() + static_cast<std::ptrdiff_t>(span.begin),
                      pre_.points.begin() + static_cast<std::ptrdiff_t>(span.end));
    leg.centroid = span.centroid;
    leg.span = static_cast<int>(pre_.spans.size()) - 1;
    corner_candidate_[static_cast<std::size_t>(k)] = static_cast<int>(pre_.candidates.size());
    pre_.candidates.push_back(leg);
    return pre_.candidates.back();
  }
  // The same, its outline closed by a far background on both sides (its width counts in the legs'
  // mean), seen only blended with that background when `blended` (as CompleteLegSets marks such a
  // leg: on its bearing, at the range the pose puts it).
  void AddClosedLeg(int k, int returns, bool blended) {
    Cluster& leg = AddLeg(k, returns);
    const double half_beam = 0.5 * testing::kWlrAlpha;
    leg.edges.before_rad =
        std::atan2(leg.points.front().p.y(), leg.points.front().p.x()) - half_beam;
    leg.edges.after_rad = std::atan2(leg.points.back().p.y(), leg.points.back().p.x()) + half_beam;
    leg.edges.before_step_m = 2.0;
    leg.edges.after_step_m = 2.0;
    if (blended) leg.assumed_range_m = Corner(k).norm();
  }
  void Add(const Eigen::Vector2d& centre, SpanRole role, int returns = 3) {
    AddSpan(pre_, centre, returns);
    roles_.push_back(role);
  }
  ShelfEvidence Evidence(const EvidenceConfig& config, bool vouched = true) const {
    return GatherEvidence(T_lidar_shelf_, model_, corner_candidate_,
                          {pre_, roles_, testing::kWlrAlpha}, vouched, config);
  }

 private:
  geometry::ShelfModel model_;
  geometry::Pose2 T_lidar_shelf_;
  PreprocessOutput pre_;
  std::vector<SpanRole> roles_;
  std::array<int, 4> corner_candidate_{-1, -1, -1, -1};
};

// The legs' mean width leaves out the one leg of a shelf seen only blended with its background
// where it looks too narrow (evidence.leg_width_skip_blended): its returns, here one, give its
// bearing, not its width. Too wide (a wide spot's bloom) it stays in, and with two such legs both
// stay in: the mean would rest on one measured leg.
TEST(ShelfEvidenceTest, TheOneBlendedLegsWidthLeavesTheMean) {
  // Legs 0 and 1 with three returns each, leg 3 (when `third_returns` > 0: with that many)
  // blended or not.
  auto bias = [](int blended_legs, bool skip, int third_returns = 1) {
    HiddenBackLeftLeg scene;
    scene.AddClosedLeg(0, 3, false);
    scene.AddClosedLeg(1, 3, blended_legs >= 2);
    if (third_returns > 0) scene.AddClosedLeg(3, third_returns, blended_legs >= 1);
    EvidenceConfig config;
    config.leg_width_skip_blended = skip;
    return scene.Evidence(config).leg_width_bias_m;
  };
  // One blended leg: with the rule the mean is the two measured legs' alone; without it the
  // one-return leg, two beams narrower than the others, pulls it down by more than half a beam.
  const double beam = 2.5 * testing::kWlrAlpha;  // [m] at the front legs
  EXPECT_NEAR(bias(1, true), bias(0, true, 0), 1e-12);
  EXPECT_LT(bias(1, false), bias(1, true) - 0.5 * beam);
  // Not blended, the one-return leg counts.
  EXPECT_DOUBLE_EQ(bias(0, true), bias(0, false));
  EXPECT_LT(bias(0, true), bias(1, true) - 0.5 * beam);
  // Blended but wider than the model's leg (five returns): it counts.
  EXPECT_DOUBLE_EQ(bias(1, true, 5), bias(1, false, 5));
  EXPECT_GT(bias(1, true, 5), bias(0, true, 0) + 0.25 * beam);
  // Two blended legs: both stay in either way.
  EXPECT_DOUBLE_EQ(bias(2, true), bias(2, false));
}

// The shelf's back-left leg hidden by something under the shelf: one object 0.3 m in front of the
// leg on its line of sight (excused: it explains the hidden leg) and, 0.2 m beside it and inside
// the footprint, a leg-sized cluster that some leg set of the search uses. That cluster is the
// hider's other part (a person's other leg, a trolley's other upright): an object, not a foreign
// leg, the phantom's signature (evidence.hider_partner_m). With the rule off it counts as a
// foreign leg; so too when something else stands inside as well (a crowded spot: posts in
// clutter around a corner of three, not a person).
TEST(ShelfEvidenceTest, TheOtherPartOfWhatHidesALegIsAnObject) {
  auto evidence = [](double hider_partner_m, bool crowded) {
    HiddenBackLeftLeg scene;
    const Eigen::Vector2d hidden = scene.Corner(2);
    const Eigen::Vector2d hider = hidden - 0.3 * hidden.normalized();
    scene.AddLeg(0);
    scene.AddLeg(1);
    if (crowded) scene.Add(scene.T_lidar_shelf() * Eigen::Vector2d(0.0, -0.1), SpanRole::kOther);
    scene.Add(hider - Eigen::Vector2d(0.0, 0.2), SpanRole::kLeg);  // the partner
    scene.Add(hider, SpanRole::kOther);
    scene.AddLeg(3);
    EvidenceConfig config;
    config.hider_partner_m = hider_partner_m;
    return scene.Evidence(config);
  };
  const double reach = EvidenceConfig{}.hider_partner_m;
  ASSERT_GT(reach, 0.2);
  const ShelfEvidence on = evidence(reach, false);
  EXPECT_EQ(on.legs_occluded, 1);
  EXPECT_EQ(on.foreign_legs_inside, 0);
  EXPECT_EQ(on.interior_leg_points, 0);
  EXPECT_GT(on.interior_object_points, 0.0);
  const ShelfEvidence off = evidence(0.0, false);
  EXPECT_EQ(off.legs_occluded, 1);
  EXPECT_EQ(off.foreign_legs_inside, 1);
  EXPECT_EQ(off.interior_leg_points, 3);
  EXPECT_LT(ShelfConfidence(off, 0.0, 3, EvidenceConfig{}),
            ShelfConfidence(on, 0.0, 3, EvidenceConfig{}));
  const ShelfEvidence crowded = evidence(reach, true);
  EXPECT_EQ(crowded.foreign_legs_inside, 1);
  EXPECT_EQ(crowded.interior_leg_points, 3);
}

// The shelf's back-left leg hidden by an object 1.2 m from the sensor (outside the footprint), and
// inside the footprint, next to that object in the scan and farther, a leg-sized sliver whose
// outline the object cuts (kPartlyHiddenLeg): the visible part of something larger standing
// behind the hider (a box 0.3 m in front of the leg, cut in two). Where the map vouches for the
// shelf it is an object, as a sliver its own leg cuts is (above); without the map's word, or whole
// (kLeg), it is a foreign leg. A piece of the wall behind stands between the sliver and the back
// right leg in the scan, as it would in a real one.
TEST(ShelfEvidenceTest, ASliverWhatHidesALegCutsInsideAVouchedShelfIsNoForeignLeg) {
  auto evidence = [](SpanRole role, bool vouched) {
    HiddenBackLeftLeg scene;
    const Eigen::Vector2d hidden = scene.Corner(2);
    const Eigen::Vector2d hider = 1.2 * hidden.normalized();
    // Three beams before the hider's middle beam, at 3.3 m: its last beam next to the hider's
    // first.
    const double bearing = std::atan2(hidden.y(), hidden.x()) - 3.0 * testing::kWlrAlpha;
    const Eigen::Vector2d sliver = 3.3 * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    scene.AddLeg(0);
    scene.AddLeg(1);
    scene.Add(Eigen::Vector2d(6.0, 0.0), SpanRole::kOther);  // the wall behind, between the two
    scene.Add(sliver, role);
    scene.Add(hider, SpanRole::kOther);
    scene.AddLeg(3);
    return scene.Evidence(EvidenceConfig{}, vouched);
  };
  const ShelfEvidence vouched = evidence(SpanRole::kPartlyHiddenLeg, true);
  EXPECT_EQ(vouched.legs_occluded, 1);
  EXPECT_EQ(vouched.interior_points, 3);
  EXPECT_EQ(vouched.foreign_legs_inside, 0);
  EXPECT_GT(vouched.interior_object_points, 0.0);
  EXPECT_EQ(evidence(SpanRole::kPartlyHiddenLeg, false).foreign_legs_inside, 1);
  EXPECT_EQ(evidence(SpanRole::kLeg, true).foreign_legs_inside, 1);
}

// Inside the footprint, 3.3 m out, a leg-sized sliver whose outline an object larger than a leg
// cuts: 18 returns 2 m out (0.2 m across, outside the footprint), its last beam next to the
// sliver's first. The sliver shows how little of what stands behind that object the scan sees,
// not how large it is: where the map vouches for the shelf it is an object, no foreign leg.
// Without the map's word it is one, and so it is when that larger object stands behind the
// sliver (4 m out), which then cuts nothing. A piece of the wall behind stands between the sliver
// and the front left leg in the scan.
TEST(ShelfEvidenceTest, ASliverALargerObjectInFrontCutsInsideAVouchedShelfIsNoForeignLeg) {
  auto evidence = [](double object_range_m, bool vouched) {
    HiddenBackLeftLeg scene;
    const double alpha = testing::kWlrAlpha;
    auto at = [&](double range, int beam) {
      return Eigen::Vector2d(range * std::cos(beam * alpha), range * std::sin(beam * alpha));
    };
    scene.AddLeg(0);
    scene.AddLeg(1);
    scene.Add(at(object_range_m, -6), SpanRole::kOther, 18);  // beams -15 ... 2
    scene.Add(at(3.3, 4), SpanRole::kPartlyHiddenLeg);        // beams 3 ... 5
    scene.Add(at(6.0, 12), SpanRole::kOther);  // the wall behind, before the front left leg
    scene.AddLeg(3);
    return scene.Evidence(EvidenceConfig{}, vouched);
  };
  const ShelfEvidence vouched = evidence(2.0, true);
  EXPECT_EQ(vouched.interior_points, 3);
  EXPECT_EQ(vouched.foreign_legs_inside, 0);
  EXPECT_GT(vouched.interior_object_points, 0.0);
  EXPECT_EQ(evidence(2.0, false).foreign_legs_inside, 1);
  EXPECT_EQ(evidence(4.0, true).foreign_legs_inside, 1);
}

// The shelf seen along its left side (that side on the sensor's axis): its front-left leg hides the
// back-left one, and a leg-sized cluster that some leg set uses stands inside, 0.34 m from that
// front leg. The shelf's own leg has no other part: the cluster counts as a foreign leg, as it
// would where a phantom on two neighbours' legs seen along a row keeps a skipped leg a gap from one
// of its own (evidence.hider_partner_m looks beside hiders that are not the shelf's legs).
TEST(ShelfEvidenceTest, TheShelfsOwnLegHidingAnotherHasNoOtherPart) {
  HiddenBackLeftLeg scene(2.5, -0.5 * PaperModels()[1].width_m);
  scene.AddLeg(0);
  scene.AddLeg(1);
  scene.Add(Eigen::Vector2d(2.8, -0.15), SpanRole::kLeg);
  scene.AddLeg(3);
  const ShelfEvidence ev = scene.Evidence(EvidenceConfig{});
  EXPECT_EQ(ev.legs_occluded, 1);
  EXPECT_EQ(ev.foreign_legs_inside, 1);
  EXPECT_EQ(ev.interior_leg_points, 3);
}

}  // namespace
}  // namespace shelfdock::perception
