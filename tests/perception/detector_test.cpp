// End-to-end tests of the detector on simulated scans (sim::World + sim::Lidar, WLR-716
// defaults: 811 beams, 10 mm noise, mixed points, dropouts) against the world's ground truth.
#include "perception/detector.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "perception/frames.hpp"
#include "scene_builder.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

using testing::PaperModels;
using testing::PlaceShelf;
using testing::SimScan;
using testing::SymmetricYawError;

constexpr double kCentreTol = 0.02;  // [m] single scans at up to 4 m
constexpr double kYawTol = 0.03;     // [rad]

TEST(DetectorTest, RejectsImpossibleConfigNamingTheKey) {
  DetectorConfig c;
  c.preprocess.cluster_gap_m = -1.0;
  try {
    Detector d(PaperModels(), c);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("preprocess.cluster_gap_m"), std::string::npos);
  }
  EXPECT_THROW(Detector({}, {}), std::invalid_argument);
}

TEST(DetectorTest, EmptyAndInvalidScansGiveNoDetection) {
  const Detector detector(PaperModels());
  geometry::LaserScan scan;
  scan.angle_min = -1.0;
  scan.angle_increment = 0.01;
  scan.range_min = 0.05;
  scan.range_max = 25.0;
  EXPECT_TRUE(detector.Detect(scan).detections.empty());
  scan.ranges = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                 0.0, 30.0, 0.01};
  const DetectionResult r = detector.Detect(scan);
  EXPECT_TRUE(r.detections.empty());
  EXPECT_EQ(r.stats.valid_points, 0);
  scan.ranges = {1.0};
  EXPECT_TRUE(detector.Detect(scan).detections.empty());
}

// The four Table 1 models, standoffs 0.5-4 m, headings all round, no preset.
TEST(DetectorTest, FindsEveryModelAtAllDistancesAndHeadings) {
  const auto models = PaperModels();
  const Detector detector(models);
  int cases = 0, found = 0;
  double worst_centre = 0.0, worst_yaw = 0.0;
  std::uint64_t seed = 1;
  for (const auto& model : models) {
    for (double standoff : {0.5, 1.0, 2.0, 3.0, 4.0}) {
      for (int k = 0; k < 8; ++k) {
        const double yaw = geometry::WrapAngle(-M_PI + k * M_PI / 4.0 + 0.1);
        const double bearing = (k % 3 - 1) * 0.4;
        const geometry::Pose2 truth = PlaceShelf(model, standoff, bearing, yaw);
        sim::World world;
        testing::AddRoom(world);
        world.AddShelf(1, model, truth);
        const DetectionResult r = detector.Detect(SimScan(world, {}, seed++));
        ++cases;
        if (r.detections.size() != 1 || r.detections[0].model != model.name) {
          std::printf("[ e2e grid ] missed: ");
          std::cout << model.name << " standoff " << standoff << " yaw " << yaw << ": "
                    << r.detections.size() << " detections"
                    << (r.detections.empty() ? "" : " first " + r.detections[0].model) << "\n";
          continue;
        }
        const Detection& d = r.detections[0];
        const double e_c = geometry::Distance(d.T_lidar_shelf, truth);
        const double e_y = SymmetricYawError(d.T_lidar_shelf.yaw, truth.yaw, model);
        worst_centre = std::max(worst_centre, e_c);
        worst_yaw = std::max(worst_yaw, e_y);
        EXPECT_LT(e_c, kCentreTol) << model.name << " standoff " << standoff << " yaw " << yaw;
        EXPECT_LT(e_y, kYawTol) << model.name << " standoff " << standoff << " yaw " << yaw;
        // The robust fit's pose (the one the covariance describes) is as close to the truth,
        // and its heading resolved the same way as the refined pose's (not a half turn off).
        ASSERT_TRUE(d.T_lidar_shelf_fit.has_value());
        EXPECT_LT(geometry::Distance(*d.T_lidar_shelf_fit, truth), kCentreTol) << model.name;
        EXPECT_LT(std::abs(geometry::AngleDiff(d.T_lidar_shelf_fit->yaw, d.T_lidar_shelf.yaw)),
                  kYawTol)
            << model.name << " standoff " << standoff << " yaw " << yaw;
        // Heading convention without a preset: x axis away from the sensor.
        const double bearing_c = std::atan2(d.T_lidar_shelf.y, d.T_lidar_shelf.x);
        EXPECT_GE(std::cos(d.T_lidar_shelf.yaw - bearing_c), model.IsSquare() ? 0.7 : -1e-9);
        ++found;
      }
    }
  }
  std::printf("[ e2e grid ] %d/%d found; worst centre %.4f m, worst heading %.4f rad\n", found,
              cases, worst_centre, worst_yaw);
  // Without a preset, out to 4 m (beyond the 3.5 m of the accuracy figures). Measured: 155/160;
  // the misses are three 1075x883 / 1080x856 confusions at 3-4 m, one round-leg shelf at 4 m and
  // the 1250x1250 at 0.5 m with the sensor under it (3 legs in view; rejected without a preset).
  // Every detection made must be accurate (asserted above); at least 95 % must be made.
  EXPECT_GE(found, cases * 95 / 100);
}

// The paper's 1075 x 883 in a room at `truth` (lidar frame) with a thin wall segment (too long for
// a leg) between the LiDAR and the shelf's first leg, whose centre is `hidden`; the detector of the
// paper's models and a preset 0.14 m / 0.05 rad off the truth.
struct OneLegHiddenScene {
  std::vector<geometry::ShelfModel> models = PaperModels();
  Detector detector{models};
  geometry::ShelfModel model = models[1];
  geometry::Pose2 truth{2.5, 0.3, 0.6};
  geometry::Pose2 preset = truth * geometry::Pose2(0.1, -0.1, 0.05);
  Eigen::Vector2d hidden = truth * model.LegCentres()[0];
  sim::World world;

  OneLegHiddenScene() {
    testing::AddRoom(world);
    world.AddShelf(1, model, truth);
    const Eigen::Vector2d mid = 0.8 * hidden;
    const Eigen::Vector2d across(-hidden.normalized().y(), hidden.normalized().x());
    world.AddWall({mid - 0.07 * across, mid + 0.07 * across});
  }
};

TEST(DetectorTest, OneLegHiddenGivesAThreeLegDetection) {
  const OneLegHiddenScene s;
  const DetectionResult r = s.detector.Detect(SimScan(s.world, {}, 7), s.preset);
  ASSERT_FALSE(r.detections.empty());
  const Detection& d = r.detections[0];
  EXPECT_EQ(d.model, s.model.name);
  EXPECT_EQ(d.legs_used, 3);
  EXPECT_LT(geometry::Distance(d.T_lidar_shelf, s.truth), kCentreTol);
  EXPECT_LT(std::abs(geometry::AngleDiff(d.T_lidar_shelf.yaw, s.truth.yaw)), kYawTol);
}

// `detect --explain` lists the leg candidates the search saw, so a user can tell a leg that never
// became a candidate from one that stood off its place. The same shelf with one leg hidden behind
// a thin wall: the three visible legs are each a candidate whose search centre lies within 2 cm of
// the true leg centre (the returns' mean pushed back by half the thinnest leg's depth; 3 mm range
// noise), the hidden one none within 10 cm; every candidate was the scan's own (none completed),
// and there are as many as stats.leg_candidates. Without explain the list stays empty.
TEST(DetectorTest, ExplainListsTheCandidatesTheSearchSaw) {
  const OneLegHiddenScene s;
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.003;
  const geometry::LaserScan scan = SimScan(s.world, {}, 7, lidar);
  const DetectionResult r = s.detector.Detect(scan, s.preset, /*explain=*/true);
  ASSERT_FALSE(r.detections.empty());
  ASSERT_EQ(static_cast<int>(r.candidates.size()), r.stats.leg_candidates);
  auto nearest = [&](const Eigen::Vector2d& leg) {
    double best = std::numeric_limits<double>::infinity();
    for (const CandidateRecord& c : r.candidates) best = std::min(best, (c.centre - leg).norm());
    return best;
  };
  const auto corners = s.model.LegCentres();
  for (std::size_t k = 1; k < corners.size(); ++k) {
    EXPECT_LT(nearest(s.truth * corners[k]), 0.02) << "leg " << k;
  }
  EXPECT_GT(nearest(s.hidden), 0.10);
  for (const CandidateRecord& c : r.candidates) {
    EXPECT_FALSE(c.completed);
    EXPECT_GE(c.returns, 1);
    EXPECT_GE(c.last_beam, c.first_beam);
  }
  EXPECT_TRUE(s.detector.Detect(scan, s.preset).candidates.empty());
}

// 1075 x 883 and 1080 x 856 differ by 5 mm in length and 27 mm in width: legs near both pass
// Eq. 2 for both, the legs' chi-square picks one, and the detection names the other as runner-up
// with the chi-square margin. A shelf measuring halfway between them (1.5 m out, 10 mm noise,
// five seeds) leaves a smaller margin than a true 1080 x 856 in the same scan: the margin says
// how clearly the returns tell the two apart. The round-legged 900 x 810 has no close model and
// no runner-up.
TEST(DetectorTest, CloseModelsNameTheRunnerUpAndItsMargin) {
  const auto models = PaperModels();
  const Detector detector(models);
  auto detect = [&](const geometry::ShelfModel& model, std::uint64_t seed) {
    const geometry::Pose2 truth = PlaceShelf(model, 1.5, 0.2, 0.3);
    sim::World world;
    testing::AddRoom(world);
    world.AddShelf(1, model, truth);
    const DetectionResult r = detector.Detect(SimScan(world, {}, seed));
    EXPECT_EQ(r.detections.size(), 1u) << model.name;
    if (r.detections.empty()) return Detection{};
    EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth), kCentreTol);
    return r.detections[0];
  };
  auto is_close_model = [&](const std::string& name) {
    return name == models[1].name || name == models[3].name;
  };
  geometry::ShelfModel halfway = models[1];
  halfway.name = "halfway";
  halfway.length_m = 0.5 * (models[1].length_m + models[3].length_m);
  halfway.width_m = 0.5 * (models[1].width_m + models[3].width_m);
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Detection between = detect(halfway, seed);
    const Detection exact = detect(models[3], seed);
    ASSERT_TRUE(between.runner_up.has_value()) << seed;
    EXPECT_TRUE(is_close_model(between.model)) << between.model;
    EXPECT_TRUE(is_close_model(between.runner_up->model)) << between.runner_up->model;
    EXPECT_NE(between.runner_up->model, between.model);
    EXPECT_GE(between.runner_up->chi2_margin, 0.0);
    EXPECT_EQ(exact.model, models[3].name) << seed;
    if (exact.runner_up) {
      EXPECT_EQ(exact.runner_up->model, models[1].name);
      EXPECT_LT(between.runner_up->chi2_margin, exact.runner_up->chi2_margin) << seed;
      ++compared;
    }
  }
  EXPECT_GE(compared, 3);  // the others: 1075 x 883 already beyond lambda_m on the centres
  const Detection round = detect(models[0], 1);
  EXPECT_EQ(round.model, models[0].name);
  EXPECT_FALSE(round.runner_up.has_value());
}

// Docking report (b): driving in, a front and a back leg line up as seen from the LiDAR and the
// back one is partly or wholly hidden. The shelf must stay detected (3 or 4 legs) throughout.
// The LiDAR looks along the shelf's left side from 1.5-3 m before the front leg, offset
// sideways by -60..+60 mm (legs 40 mm, default dark paint 0.15, walls 0.6).
TEST(DetectorTest, FrontAndBackLegInLineStillDetected) {
  const auto models = PaperModels();
  const Detector detector(models);
  const auto& model = models[1];
  const geometry::Pose2 T_world_shelf(0.0, 0.0, 0.0);
  const Eigen::Vector2d front = T_world_shelf * model.LegCentres()[3];  // (-L/2, +W/2)
  int cases = 0, found = 0, neighbouring_misses = 0;
  std::uint64_t seed = 300;
  for (double back_off : {1.5, 2.0, 2.5, 3.0}) {
    bool missed_previous = false;
    for (int k = -6; k <= 6; ++k) {
      const geometry::Pose2 T_world_lidar(front.x() - back_off, front.y() + 0.01 * k, 0.0);
      sim::World world;
      testing::AddRoom(world);
      world.AddShelf(1, model, T_world_shelf);
      const geometry::Pose2 truth = T_world_lidar.inverse() * T_world_shelf;
      const DetectionResult r = detector.Detect(SimScan(world, T_world_lidar, seed++),
                                                truth * geometry::Pose2(0.1, 0.05, 0.05));
      ++cases;
      const bool miss = r.detections.empty() || r.detections[0].model != model.name;
      if (miss && missed_previous) ++neighbouring_misses;
      missed_previous = miss;
      if (miss) {
        std::printf("[ in line ] missed at %.1f m, offset %+d cm: %zu detections\n", back_off, k,
                    r.detections.size());
        std::printf("    stats: clusters %d candidates %d sets %d pairs %d trailing %d\n",
                    r.stats.clusters, r.stats.leg_candidates, r.stats.leg_sets, r.stats.model_pairs,
                    r.stats.trailing_removed);
        continue;
      }
      EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth), kCentreTol);
      ++found;
    }
  }
  std::printf("[ in line ] %d/%d found\n", found, cases);
  // The occlusion is handled by 3-leg sets: every offset is found (measured 52/52).
  EXPECT_EQ(found, cases);
  EXPECT_EQ(neighbouring_misses, 0);
}

TEST(DetectorTest, ThreeLegsAroundTheSensorAreAShelf) {
  // The LiDAR under a 1250x1250 shelf whose fourth leg lies behind it, outside the 270-degree
  // field of view: three legs in view around the sensor. The fourth leg is unobserved, not
  // contradicted, so the shelf is found with or without a preset. Tolerance: kCentreTol.
  const auto models = PaperModels();
  const geometry::ShelfModel& model = models[2];
  const geometry::Pose2 truth(-0.1, 0.2, 0.0);
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, model, truth);
  const Detector detector(models);
  const geometry::LaserScan scan = SimScan(world, {}, 5);
  for (const auto& preset : {std::optional<geometry::Pose2>(),
                             std::optional(truth * geometry::Pose2(0.05, -0.05, 0.05))}) {
    const DetectionResult r = detector.Detect(scan, preset);
    ASSERT_FALSE(r.detections.empty());
    EXPECT_EQ(r.detections[0].model, model.name);
    EXPECT_EQ(r.detections[0].legs_used, 3);
    EXPECT_EQ(r.detections[0].legs_visible, 3);
    EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth), kCentreTol);
  }
}

// Three shelves of `model` side by side 2.2 m ahead, 0.3 m between neighbouring legs, in a
// room; `truth` gets their poses (left to right seen from the sensor: -y, 0, +y).
sim::World RowOfThree(const geometry::ShelfModel& model, std::vector<geometry::Pose2>* truth) {
  const double pitch = model.width_m + model.leg.width_m + 0.3;
  sim::World world;
  testing::AddRoom(world);
  for (int i = -1; i <= 1; ++i) {
    truth->emplace_back(2.2, i * pitch, 0.0);
    world.AddShelf(i + 2, model, truth->back());
  }
  return world;
}

TEST(DetectorTest, PresetPicksTheMiddleOfThreeShelvesSideBySide) {
  const auto models = PaperModels();
  const Detector detector(models);
  const auto& model = models[3];
  std::vector<geometry::Pose2> truth;
  const geometry::LaserScan scan = SimScan(RowOfThree(model, &truth), {}, 11);
  const geometry::Pose2 preset = truth[1] * geometry::Pose2(-0.15, 0.12, -0.08);
  const DetectionResult r = detector.Detect(scan, preset);
  ASSERT_FALSE(r.detections.empty());
  EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth[1]), kCentreTol);
  EXPECT_LT(std::abs(geometry::AngleDiff(r.detections[0].T_lidar_shelf.yaw, truth[1].yaw)),
            kYawTol);
  // Without a preset: every detection is a distinct one of the three shelves, of the right
  // model, within kCentreTol; none is made of two neighbours' legs. The middle shelf faces the
  // sensor with all four legs in sight and must be among them.
  const DetectionResult all = detector.Detect(scan);
  std::vector<int> matched;
  for (const auto& d : all.detections) {
    int best = -1;
    for (int t = 0; t < 3; ++t) {
      if (geometry::Distance(d.T_lidar_shelf, truth[t]) < kCentreTol) best = t;
    }
    ASSERT_GE(best, 0) << "a detection at " << d.T_lidar_shelf.x << ", " << d.T_lidar_shelf.y
                       << " is none of the shelves";
    EXPECT_EQ(d.model, model.name);
    EXPECT_EQ(std::count(matched.begin(), matched.end(), best), 0) << "shelf returned twice";
    matched.push_back(best);
  }
  EXPECT_EQ(std::count(matched.begin(), matched.end(), 1), 1);
}

// The preset gate: in the same row of three, a preset on the middle shelf returns only it (its
// neighbours stand a pitch, > 0.5 m, away and are counted off_preset); a preset 0.3 m off and
// 0.1 rad turned (a map that is that wrong) still returns the shelf; one turned 0.6 rad against
// the shelf, or 0.7 m away from every shelf, returns none; with the gate off (0) the neighbours
// come back. The ROI is widened (roi_gamma 2) so that the neighbours are searched at all.
TEST(DetectorTest, PresetGateReturnsOnlyTheShelfTheMapExpects) {
  const auto models = PaperModels();
  const auto& model = models[3];
  const double pitch = model.width_m + model.leg.width_m + 0.3;
  std::vector<geometry::Pose2> truth;
  const geometry::LaserScan scan = SimScan(RowOfThree(model, &truth), {}, 11);
  DetectorConfig wide;
  wide.preprocess.roi_gamma = 2.0;
  const Detector detector(models, wide);
  const DetectionResult r = detector.Detect(scan, truth[1]);
  ASSERT_EQ(r.detections.size(), 1u);
  EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth[1]), kCentreTol);
  EXPECT_GE(r.stats.rejected.off_preset, 1);

  const DetectionResult off = detector.Detect(scan, truth[1] * geometry::Pose2(0.3, 0.0, 0.1));
  ASSERT_EQ(off.detections.size(), 1u);
  EXPECT_LT(geometry::Distance(off.detections[0].T_lidar_shelf, truth[1]), kCentreTol);

  EXPECT_TRUE(detector.Detect(scan, truth[1] * geometry::Pose2(0.0, 0.0, 0.6)).detections.empty());
  EXPECT_TRUE(detector.Detect(scan, geometry::Pose2(1.5, 0.5 * pitch, 0.0)).detections.empty());

  DetectorConfig open = wide;
  open.preset_gate.max_offset_m = 0.0;
  open.preset_gate.max_yaw_offset_rad = 0.0;
  const DetectionResult all = Detector(models, open).Detect(scan, truth[1]);
  ASSERT_GE(all.detections.size(), 2u);
  EXPECT_LT(geometry::Distance(all.detections[0].T_lidar_shelf, truth[1]), kCentreTol);
  EXPECT_EQ(all.stats.rejected.off_preset, 0);
}

TEST(DetectorTest, PresetHeadingResolvesTheAmbiguity) {
  const auto models = PaperModels();
  const Detector detector(models);
  for (const auto& model : models) {
    const geometry::Pose2 truth(2.0, -0.2, 2.9);  // x axis toward the sensor
    sim::World world;
    testing::AddRoom(world);
    world.AddShelf(1, model, truth);
    const DetectionResult r =
        detector.Detect(SimScan(world, {}, 5), truth * geometry::Pose2(0.05, 0.05, 0.1));
    ASSERT_FALSE(r.detections.empty()) << model.name;
    EXPECT_LT(std::abs(geometry::AngleDiff(r.detections[0].T_lidar_shelf.yaw, truth.yaw)), kYawTol)
        << model.name;
  }
}

// Leg-sized and larger round posts, none three of which form a right triangle of any model
// (checked here from the ground truth positions): nothing may be reported.
TEST(DetectorTest, ClutterOfRoundPostsGivesNoDetection) {
  const auto models = PaperModels();
  const Detector detector(models);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ux(0.5, 4.5), uy(-3.0, 3.0), ur(0.012, 0.08);
  int false_positives = 0;
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Eigen::Vector2d> posts;
    while (posts.size() < 40) {
      const Eigen::Vector2d p(ux(rng), uy(rng));
      bool shelf_like = false;
      for (std::size_t a = 0; a < posts.size() && !shelf_like; ++a) {
        for (std::size_t b = 0; b < posts.size() && !shelf_like; ++b) {
          if (a == b) continue;
          for (const auto& m : models) {
            for (const auto& [v, o1, o2] :
                 {std::tuple{p, posts[a], posts[b]}, std::tuple{posts[a], p, posts[b]}}) {
              const double s1 = (o1 - v).norm(), s2 = (o2 - v).norm();
              const double hyp = (o1 - o2).norm();
              const bool sides =
                  (std::abs(s1 - m.length_m) < 0.15 && std::abs(s2 - m.width_m) < 0.15) ||
                  (std::abs(s1 - m.width_m) < 0.15 && std::abs(s2 - m.length_m) < 0.15);
              if (sides && std::abs(hyp - std::hypot(s1, s2)) < 0.15) shelf_like = true;
            }
          }
        }
      }
      if (!shelf_like) posts.push_back(p);
    }
    sim::World world;
    testing::AddRoom(world);
    for (const auto& p : posts) world.AddRoundPost(p, ur(rng));
    const DetectionResult r = detector.Detect(SimScan(world, {}, 100 + trial));
    for (const auto& d : r.detections) {
      std::printf("[ clutter ] false detection %s legs %d err_sum %.4f at (%.2f, %.2f)\n",
                  d.model.c_str(), d.legs_used, d.err_sum, d.T_lidar_shelf.x, d.T_lidar_shelf.y);
      for (const auto& l : d.legs) std::printf("    leg %.3f %.3f\n", l.x(), l.y());
    }
    for (const auto& p : posts)
      std::printf(r.detections.empty() ? "" : "    post %.3f %.3f\n", p.x(), p.y());
    false_positives += static_cast<int>(r.detections.size());
  }
  EXPECT_EQ(false_positives, 0);
}

TEST(DetectorTest, FramesComposeExtrinsicAndRobotPose) {
  const auto models = PaperModels();
  const Detector detector(models);
  const geometry::Pose2 T_map_base(3.0, -1.0, 0.7), T_base_lidar(0.3, 0.0, 0.0);
  const geometry::Pose2 T_map_shelf(5.0, 0.5, 0.9);
  sim::World world;  // world frame == map frame
  world.AddShelf(1, models[2], T_map_shelf);
  const geometry::Pose2 T_map_lidar = T_map_base * T_base_lidar;
  const DetectionResult r =
      detector.Detect(SimScan(world, T_map_lidar, 9), T_map_lidar.inverse() * T_map_shelf);
  ASSERT_FALSE(r.detections.empty());
  const geometry::Pose2 in_map = ShelfInMap(r.detections[0], T_base_lidar, T_map_base);
  EXPECT_LT(geometry::Distance(in_map, T_map_shelf), kCentreTol);
  EXPECT_LT(std::abs(geometry::AngleDiff(in_map.yaw, T_map_shelf.yaw)), kYawTol);
  const geometry::Pose2 in_base = ShelfInBase(r.detections[0], T_base_lidar);
  EXPECT_LT(geometry::Distance(in_base, T_map_base.inverse() * T_map_shelf), kCentreTol);
  const Detection moved = ExpressIn(r.detections[0], T_map_lidar);
  EXPECT_LT(geometry::Distance(moved.T_lidar_shelf, T_map_shelf), kCentreTol);
  EXPECT_NEAR(moved.covariance.trace(), r.detections[0].covariance.trace(), 1e-12);
}

// A person's leg (a round post, r = `radius` m) beside the shelf's nearest leg, on the side away
// from the shelf's centre: its silhouette edge `gap_beams` beyond the leg's (so that no beam
// reaches the background between them and they form one cluster) and its nearest surface
// `depth` behind (+) or in front of (-) the leg's nearest corner. `leg` gets that leg's centre.
sim::World ShelfWithPersonsLeg(const geometry::ShelfModel& model, const geometry::Pose2& truth,
                               double depth, double gap_beams, Eigen::Vector2d* leg,
                               double radius = 0.06) {
  const double kRadius = radius;
  sim::World world;
  testing::AddRoom(world);
  world.AddShelf(1, model, truth);
  const auto footprints = world.LegFootprints(1);
  const sim::LegFootprint* nearest = &footprints.front();
  for (const auto& f : footprints) {
    if (f.T_world_leg.translation().norm() < nearest->T_world_leg.translation().norm()) {
      nearest = &f;
    }
  }
  *leg = nearest->T_world_leg.translation();
  const double side = std::atan2(leg->y(), leg->x()) > std::atan2(truth.y, truth.x) ? 1.0 : -1.0;
  double edge = -side * M_PI, near_range = 1e9;
  for (const Eigen::Vector2d& c : nearest->Corners()) {
    const double b = std::atan2(c.y(), c.x());
    edge = side > 0 ? std::max(edge, b) : std::min(edge, b);
    near_range = std::min(near_range, c.norm());
  }
  const double range = near_range + depth + kRadius;
  const double bearing = edge + side * (gap_beams * sim::LidarConfig{}.angle_increment_rad +
                                        std::asin(kRadius / range));
  world.AddRoundPost(range * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)), kRadius);
  return world;
}

// Where a person's leg stands against the shelf leg it touches (see ShelfWithPersonsLeg):
// 6, 8 or 10 cm behind, or 8 or 10 cm in front of it; a quarter of a beam apart when behind,
// half a beam when in front (a nearer round leg closer than that is cut less reliably, below).
struct PersonsLegPlacement {
  double depth;  ///< [m]
  double gap;    ///< [beams]
};
constexpr PersonsLegPlacement kPersonsLegPlacements[] = {
    {0.06, 0.25}, {0.08, 0.25}, {0.10, 0.25}, {-0.08, 0.5}, {-0.10, 0.5}};

// The default detector config with the depth-step split off, and the completion from two legs
// (which cuts a merged leg's returns at its corner as well) with it: these tests show what the
// split alone does.
DetectorConfig NoSplit() {
  DetectorConfig config;
  config.preprocess.split_max_extra_m = 0.0;
  config.preprocess.split_end_pieces = false;
  config.completion.enabled = false;
  return config;
}

// True when, without the split, no leg candidate of the scan lies within 3 cm of `leg`: the
// leg and the person's leg formed one cluster. (In some scans dropouts on the dark leg or the
// noise separate them, and then there is nothing to split.)
bool LegMergedWithPersonsLeg(const geometry::LaserScan& scan, const Eigen::Vector2d& leg,
                             const geometry::Pose2& preset) {
  const PreprocessOutput pre = Preprocess(ScanToPoints(scan), scan.angle_increment, preset,
                                          PaperModels(), NoSplit().preprocess);
  for (const Cluster& c : pre.candidates) {
    if ((c.centroid - leg).norm() < 0.03) return false;
  }
  return true;
}

// Calls `check` for every scan of ShelfWithPersonsLeg over both close models (1075x883,
// 1080x856) 2 m ahead turned `yaw`, every placement and seeds 1-5 (3 mm range noise), with the
// truth, a preset 7 cm and 0.03 rad off it, the touched leg's centre and a label for messages.
template <typename Check>
void ForEachPersonsLegScan(double yaw, Check check) {
  const auto models = PaperModels();
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.003;
  for (const int mi : {1, 3}) {
    const auto& model = models[mi];
    const geometry::Pose2 truth = PlaceShelf(model, 2.0, 0.1, yaw);
    const geometry::Pose2 preset = truth * geometry::Pose2(0.05, -0.05, 0.03);
    for (const PersonsLegPlacement& pl : kPersonsLegPlacements) {
      Eigen::Vector2d leg;
      const sim::World world = ShelfWithPersonsLeg(model, truth, pl.depth, pl.gap, &leg);
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const std::string where =
            model.name + " depth " + std::to_string(pl.depth) + " seed " + std::to_string(seed);
        check(model, truth, preset, leg, SimScan(world, {}, seed, lidar), where);
      }
    }
  }
}

// The shelf (1075x883 and 1080x856) 2 m ahead, turned 0.3 rad so that one back leg stands
// behind a front leg: three legs in view. A person's leg touches the nearest one
// (kPersonsLegPlacements; scans with 3 mm range noise, five seeds each; preset 7 cm and 0.03
// rad off the truth). With the default split the touched leg is cut out again and the shelf is
// found on its three visible legs, the touched one among them: right model, centre within
// kCentreTol, heading within kYawTol. With split_max_extra_m = 0, in every scan where the leg
// and the person's leg form one cluster, two legs are left and no shelf is returned; that must
// be most scans (>= 80 %), or the test shows nothing.
// Not asserted, measured over 20 seeds: with the person's leg 6 cm in front of the leg (its
// centre then at about the leg's depth) the shelf was found in only 10-17 of 20 scans
// (1075x883) and 4-7 of 20 (1080x856): the beam footprint's mixed points spread the depth step
// at the junction over two or three beams, none of them reaching split_min_step_m (3 cm).
TEST(DetectorTest, PersonsLegTouchingALegIsSplitOff) {
  const auto models = PaperModels();
  const Detector detector(models);
  const Detector unsplit(models, NoSplit());
  int scans = 0, merged = 0;
  ForEachPersonsLegScan(0.3, [&](const geometry::ShelfModel& model, const geometry::Pose2& truth,
                                 const geometry::Pose2& preset, const Eigen::Vector2d& leg,
                                 const geometry::LaserScan& scan, const std::string& where) {
    const DetectionResult r = detector.Detect(scan, preset);
    ++scans;
    ASSERT_FALSE(r.detections.empty()) << where;
    const Detection& d = r.detections[0];
    EXPECT_EQ(d.model, model.name) << where;
    EXPECT_LT(geometry::Distance(d.T_lidar_shelf, truth), kCentreTol) << where;
    EXPECT_LT(std::abs(geometry::AngleDiff(d.T_lidar_shelf.yaw, truth.yaw)), kYawTol) << where;
    EXPECT_EQ(d.legs_used, 3) << where;
    EXPECT_EQ(d.legs_visible, 3) << where;
    bool touched_leg_used = false;
    for (const auto& l : d.legs) touched_leg_used |= (l - leg).norm() < kCentreTol;
    EXPECT_TRUE(touched_leg_used) << where;
    if (!LegMergedWithPersonsLeg(scan, leg, preset)) return;
    ++merged;
    const DetectionResult u = unsplit.Detect(scan, preset);
    EXPECT_TRUE(u.detections.empty()) << where << ": " << u.detections.size() << " detections";
  });
  std::printf("[ person's leg ] 3 legs in view: merged with the leg in %d of %d scans\n", merged,
              scans);
  EXPECT_GE(merged, scans * 8 / 10);
}

// The same person's leg with all four legs in view (heading 0): without the split the shelf is
// still found but on three legs (the touched one lost) where the two formed one cluster; with
// the split, on all four, whenever the touched leg returned at least two points (a piece cut
// off needs two; the dark leg's dropouts left fewer in 4 of these 50 scans, at most 10 % is
// allowed). Both within kCentreTol, right model. As above, the two must have formed one
// cluster in >= 80 % of the scans.
TEST(DetectorTest, PersonsLegTouchingALegOfAFullyVisibleShelf) {
  const auto models = PaperModels();
  const Detector detector(models);
  const Detector unsplit(models, NoSplit());
  int scans = 0, merged = 0, few_returns = 0;
  ForEachPersonsLegScan(0.0, [&](const geometry::ShelfModel& model, const geometry::Pose2& truth,
                                 const geometry::Pose2& preset, const Eigen::Vector2d& leg,
                                 const geometry::LaserScan& scan, const std::string& where) {
    const DetectionResult r = detector.Detect(scan, preset);
    const DetectionResult u = unsplit.Detect(scan, preset);
    ++scans;
    ASSERT_FALSE(r.detections.empty()) << where;
    ASSERT_FALSE(u.detections.empty()) << where;
    EXPECT_EQ(r.detections[0].model, model.name) << where;
    EXPECT_EQ(u.detections[0].model, model.name) << where;
    EXPECT_LT(geometry::Distance(r.detections[0].T_lidar_shelf, truth), kCentreTol) << where;
    EXPECT_LT(geometry::Distance(u.detections[0].T_lidar_shelf, truth), kCentreTol) << where;
    int leg_returns = 0;
    for (const ScanPoint& q : ScanToPoints(scan)) leg_returns += (q.p - leg).norm() < 0.035;
    if (leg_returns >= 2) {
      EXPECT_EQ(r.detections[0].legs_used, 4) << where;
    } else {
      ++few_returns;
    }
    if (!LegMergedWithPersonsLeg(scan, leg, preset)) return;
    ++merged;
    EXPECT_EQ(u.detections[0].legs_used, 3) << where;
  });
  std::printf(
      "[ person's leg ] 4 legs in view: merged with the leg in %d of %d scans, %d with < 2 "
      "returns on it\n",
      merged, scans, few_returns);
  EXPECT_GE(merged, scans * 8 / 10);
  EXPECT_LE(few_returns, scans / 10);
}

// What the detector made of a round post touching a shelf's nearest leg (ShelfWithPersonsLeg).
struct TouchingPostCounts {
  int scans = 0;
  int found = 0;          ///< the right model first (its pose checked in every first detection)
  int found_without = 0;  ///< ... by a detector with the rule under test off
  int returned = 0;       ///< first detections of the detector with the rule
  int flush_legs = 0;     ///< legs taken flush by returned hypotheses (explain's legs_flush)
  int merged = 0;         ///< scans where the post and the leg form one candidate
};

// Both close models (1075x883, 1080x856) 2 m ahead turned 0.3 rad (three legs in view), a post of
// `radius` touching the nearest leg `depth` before (-) or behind it, seeds 1-20 each (3 mm range
// noise), preset 7 cm and 0.03 rad off the truth; each scan detected by the default detector and
// by one with `off`. Every first detection of either must stand within kCentreTol and kYawTol of
// the truth, and every leg the default detector's returned hypotheses took flush within 2 cm of
// the touched leg.
TouchingPostCounts DetectWithATouchingPost(const DetectorConfig& off, double depth, double radius) {
  const auto models = PaperModels();
  const Detector detector(models);
  const Detector without(models, off);
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.003;
  TouchingPostCounts n;
  auto right = [&](const DetectionResult& r, const geometry::ShelfModel& model,
                   const geometry::Pose2& truth, const std::string& where) {
    if (r.detections.empty()) return false;
    const Detection& d = r.detections[0];
    EXPECT_LT(geometry::Distance(d.T_lidar_shelf, truth), kCentreTol) << where;
    EXPECT_LT(std::abs(geometry::AngleDiff(d.T_lidar_shelf.yaw, truth.yaw)), kYawTol) << where;
    return d.model == model.name;
  };
  for (const int mi : {1, 3}) {
    const auto& model = models[mi];
    const geometry::Pose2 truth = PlaceShelf(model, 2.0, 0.1, 0.3);
    const geometry::Pose2 preset = truth * geometry::Pose2(0.05, -0.05, 0.03);
    Eigen::Vector2d leg;
    const sim::World world = ShelfWithPersonsLeg(model, truth, depth, 0.5, &leg, radius);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::string where = model.name + " seed " + std::to_string(seed);
      const geometry::LaserScan scan = SimScan(world, {}, seed, lidar);
      ++n.scans;
      n.merged += LegMergedWithPersonsLeg(scan, leg, preset);
      const DetectionResult with = detector.Detect(scan, preset, /*explain=*/true);
      n.returned += with.detections.empty() ? 0 : 1;
      n.found += right(with, model, truth, where);
      for (const HypothesisRecord& h : with.hypotheses) {
        if (h.verdict != Verdict::kReturned) continue;
        EXPECT_EQ(h.legs_flush.size(), h.legs.size()) << where;
        for (std::size_t i = 0; i < h.legs.size() && i < h.legs_flush.size(); ++i) {
          if (!h.legs_flush[i]) continue;
          ++n.flush_legs;
          EXPECT_LT((h.legs[i] - leg).norm(), 0.02) << where;
        }
      }
      n.found_without += right(without.Detect(scan, preset), model, truth, where + " (rule off)");
    }
  }
  return n;
}

// A person's leg (r = 6 cm) 6 cm in front of the leg it touches (its centre then at about the
// leg's depth, see PersonsLegTouchingALegIsSplitOff): no depth step tells the two apart, and the
// two are too wide together for a leg candidate. With three legs in view the shelf is found only
// by completing the merged corner from the other two legs and the preset, and there the returns'
// object goes on past the corner on the person's side. completion.flush_object_max_m takes them
// for the leg all the same when that object ends within it and the other side's outline ends at
// the leg's silhouette (DetectWithATouchingPost; measured: 38 of 40 found with the rule, the
// other two returned as the close model, 1075 x 883 for a 1080 x 856 on the same place; 18
// without); at least 30 must be, and more than without the rule, and at least one leg taken
// flush per scan the rule gained (measured: 23 over the 40 scans).
TEST(DetectorTest, PersonsLegFlushWithALegIsToldByTheLegsOutline) {
  DetectorConfig off;
  off.completion.flush_object_max_m = 0.0;
  const TouchingPostCounts n = DetectWithATouchingPost(off, -0.06, 0.06);
  std::printf(
      "[ person's leg flush ] found %d of %d scans, %d without the rule (%d shelves returned, %d "
      "legs taken flush)\n",
      n.found, n.scans, n.found_without, n.returned, n.flush_legs);
  EXPECT_GE(n.found, 30);
  EXPECT_GT(n.found, n.found_without);
  EXPECT_GE(n.flush_legs, n.found - n.found_without);
}

// A thinner post (r = 2.5 cm: a pole, a child's leg) 3 cm in front of the leg it touches merges
// with it into one cluster still narrow enough to be a leg candidate: the search places it at the
// middle of both, centimetres off the leg, and no set fits. completion.merged_candidates cuts the
// leg's returns out of that candidate at the corner the other two legs and the preset predict,
// under the flush rules (DetectWithATouchingPost; measured: 34 of 40 found with the rule, none
// without; with the cut trimmed to the leg's extent instead of its silhouette, 29). The post and
// the leg must form one candidate in every scan (else the scene shows nothing), at least three
// quarters of the scans must be found, more than without the rule, with at least one leg cut per
// scan the rule gained.
TEST(DetectorTest, LegMergedIntoANarrowCandidateIsCutAtItsCorner) {
  DetectorConfig off;
  off.completion.merged_candidates = false;
  const TouchingPostCounts n = DetectWithATouchingPost(off, -0.03, 0.025);
  std::printf(
      "[ merged candidate ] found %d of %d scans, %d without the rule (%d merged, %d legs cut)\n",
      n.found, n.scans, n.found_without, n.merged, n.flush_legs);
  EXPECT_EQ(n.merged, n.scans);
  EXPECT_GE(n.found, n.scans * 3 / 4);
  EXPECT_GT(n.found, n.found_without);
  EXPECT_GE(n.flush_legs, n.found - n.found_without);
}

// A blooming scanner (first echo above a low threshold, a 9 mrad spot: config/lidar_variants/
// bloom.yaml) draws a bright shelf's legs wider than they stand, while a dark thin post beside it
// returns only where a good share of the spot falls on it and is drawn true: the scan's bloom
// (EstimateWidthBloom, the low quantile of its thin objects) is then about 0 and the legs fail the
// width checks. Their own common bloom (evidence.width_bloom_own_legs) excuses them where the
// preset vouches for the shelf. Eight poses of a 1075 x 883 shelf 2-3.4 m out, all four legs in
// sight, the post 2 m out to one side; both scans seeded. Every shelf returned first within the
// single-scan tolerances; without the legs' own bloom at most half of them (measured: 1 of 8).
TEST(DetectorTest, ABrightShelfsLegsBloomingBesideADarkPostDrawnTrueAreExcused) {
  const auto models = PaperModels();
  const geometry::ShelfModel& model = models[1];
  sim::LidarConfig bright;  // config/lidar_variants/bloom.yaml
  bright.beam_divergence_rad = 0.009;
  bright.footprint_rays = 15;
  bright.min_echo_fraction = 0.01;
  const sim::LidarConfig dark;  // the WLR-716 defaults: half the spot or so must fall on it
  DetectorConfig off;
  off.evidence.width_bloom_own_legs = false;
  const Detector detector(models);
  const Detector detector_off(models, off);
  int found = 0, found_off = 0;
  for (int k = 0; k < 8; ++k) {
    const double standoff = 2.0 + 0.2 * k;
    const double bearing = (k % 2 == 0 ? 0.3 : -0.3);
    const geometry::Pose2 truth = PlaceShelf(model, standoff, bearing, 0.25 * k - 1.0);
    sim::World shelf_world;
    testing::AddRoom(shelf_world);
    shelf_world.AddShelf(0, model, truth);
    sim::World post_world;
    post_world.AddRoundPost(
        2.0 * Eigen::Vector2d(std::cos(-bearing * 3.0), std::sin(-bearing * 3.0)), 0.013);
    geometry::LaserScan scan = SimScan(shelf_world, {}, 40 + k, bright);
    const geometry::LaserScan post = SimScan(post_world, {}, 60 + k, dark);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      if (std::isfinite(post.ranges[i]) && post.ranges[i] > 0.0 &&
          !(scan.ranges[i] < post.ranges[i])) {
        scan.ranges[i] = post.ranges[i];
      }
    }
    const geometry::Pose2 preset = truth * geometry::Pose2(0.1, -0.1, 0.05);
    const DetectionResult r = detector.Detect(scan, preset);
    const DetectionResult r_off = detector_off.Detect(scan, preset);
    std::printf("[ own bloom ] pose %d: scan's bloom %.4f rad, %zu / %zu detections\n", k,
                r.stats.width_bloom_rad, r.detections.size(), r_off.detections.size());
    if (!r.detections.empty()) {
      const Detection& d = r.detections.front();
      EXPECT_LT((d.T_lidar_shelf.translation() - truth.translation()).norm(), kCentreTol) << k;
      EXPECT_LT(std::abs(SymmetricYawError(d.T_lidar_shelf.yaw, truth.yaw, model)), kYawTol) << k;
      ++found;
    }
    found_off += r_off.detections.empty() ? 0 : 1;
  }
  EXPECT_EQ(found, 8);
  EXPECT_LE(found_off, 4);
}

}  // namespace
}  // namespace shelfdock::perception
