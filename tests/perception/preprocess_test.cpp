// Paper 3.1 stage tests: points, Eq. 1 trailing filter, clustering, ROI and size screening.
#include "perception/preprocess.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = testing::kWlrAlpha;

ScanPoint At(int beam, double range) { return testing::BeamPoint(beam, range); }

// Distance from `leg` to the nearest leg candidate's centroid [m]; infinity without candidates.
double NearestCandidate(const PreprocessOutput& out, const Eigen::Vector2d& leg) {
  double best = std::numeric_limits<double>::infinity();
  for (const Cluster& c : out.candidates) best = std::min(best, (c.centroid - leg).norm());
  return best;
}

TEST(PreprocessTest, ScanToPointsSkipsInvalidReturns) {
  geometry::LaserScan scan;
  scan.angle_min = -0.5;
  scan.angle_increment = 0.25;
  scan.range_min = 0.05;
  scan.range_max = 10.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  scan.ranges = {2.0, nan, inf, 0.0, 0.01, 11.0, 3.0};
  const auto points = ScanToPoints(scan);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].beam, 0);
  EXPECT_EQ(points[1].beam, 6);
  // Beam 6 at -0.5 + 6 * 0.25 = 1.0 rad, range 3.
  EXPECT_NEAR(points[1].p.x(), 3.0 * std::cos(1.0), 1e-12);
  EXPECT_NEAR(points[1].p.y(), 3.0 * std::sin(1.0), 1e-12);
  scan.ranges = {nan, nan, -1.0};
  EXPECT_TRUE(ScanToPoints(scan).empty());
  scan.ranges.clear();
  EXPECT_TRUE(ScanToPoints(scan).empty());
}

TEST(PreprocessTest, TrailingAngleMatchesEquationOne) {
  // Equal ranges: the triangle O-A-B is isosceles, beta = (pi - alpha) / 2.
  EXPECT_NEAR(TrailingAngle(2.0, 2.0, kAlpha), 0.5 * (M_PI - kAlpha), 1e-12);
  // Eq. 1 directly, OA = 3, OB = 2.
  const double expected = std::atan(2.0 * std::sin(kAlpha) / (3.0 - 2.0 * std::cos(kAlpha)));
  EXPECT_NEAR(TrailingAngle(3.0, 2.0, kAlpha), expected, 1e-12);
  // A far point right behind its neighbour leaves almost no angle.
  EXPECT_LT(TrailingAngle(5.0, 2.0, kAlpha), 0.01);
}

TEST(PreprocessTest, TrailingFilterDropsTheFartherPointOfADepthJump) {
  // A leg at 2 m (beams 10-14), a mixed point at 3 m (beam 15), the wall at 5 m (16-20).
  std::vector<ScanPoint> pts;
  for (int b = 10; b <= 14; ++b) pts.push_back(At(b, 2.0 + 0.002 * (b % 2)));
  pts.push_back(At(15, 3.0));
  for (int b = 16; b <= 20; ++b) pts.push_back(At(b, 5.0));
  const PreprocessConfig config;
  const int removed = RemoveTrailingPoints(pts, kAlpha, config);
  // The mixed point and the first wall point (both the far side of a jump) go; the leg stays.
  EXPECT_EQ(removed, 2);
  for (const auto& q : pts) EXPECT_NE(q.beam, 15);
  int leg = 0;
  for (const auto& q : pts) leg += q.range < 2.1;
  EXPECT_EQ(leg, 5);
  // Range noise on one surface is no depth edge.
  std::vector<ScanPoint> wall;
  for (int b = 0; b < 20; ++b) wall.push_back(At(b, 0.5 + 0.01 * (b % 3)));
  EXPECT_EQ(RemoveTrailingPoints(wall, kAlpha, config), 0);
  std::vector<ScanPoint> one{At(0, 1.0)};
  EXPECT_EQ(RemoveTrailingPoints(one, kAlpha, config), 0);
}

TEST(PreprocessTest, ClustersSplitAtGapsAndLongHoles) {
  const PreprocessConfig config;
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 5; ++b) pts.push_back(At(b, 2.0));
  for (int b = 5; b < 10; ++b) pts.push_back(At(b, 2.5));  // 0.5 m depth step
  // Two dropped beams inside one surface: still one cluster.
  for (int b = 12; b < 15; ++b) pts.push_back(At(b, 2.5));
  // Docking report (a): no wall behind the shelf, the next return is 60 beams on at the same
  // range (another leg, 0.7 m away). A gap widened by 60 beam spacings would join them.
  for (int b = 75; b < 80; ++b) pts.push_back(At(b, 2.5));
  const auto clusters = ClusterPoints(pts, kAlpha, config);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0].points.size(), 5u);
  EXPECT_EQ(clusters[1].points.size(), 8u);
  EXPECT_EQ(clusters[2].points.size(), 5u);
  // Centroid = mean (Eq. 3).
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int b = 0; b < 5; ++b) mean += At(b, 2.0).p / 5.0;
  EXPECT_NEAR((clusters[0].centroid - mean).norm(), 0.0, 1e-12);
  EXPECT_TRUE(ClusterPoints({}, kAlpha, config).empty());
}

TEST(PreprocessTest, RoiAndSizeScreeningKeepOnlyLegsNearThePreset) {
  const auto models = testing::PaperModels();
  const PreprocessConfig config;
  std::vector<ScanPoint> pts;
  // A 40 mm leg at 2 m (about 3 beams) and a 1 m wall piece at 2 m elsewhere.
  for (int b = 0; b < 4; ++b) pts.push_back(At(b, 2.0));
  for (int b = 100; b < 186; ++b) pts.push_back(At(b, 2.0));
  // A second leg 3 m away from the first (outside any ROI around the first).
  for (int b = 300; b < 303; ++b) pts.push_back(At(b, 2.0));
  const auto all = Preprocess(pts, kAlpha, std::nullopt, models, config);
  EXPECT_EQ(all.clusters, 3);
  ASSERT_EQ(all.candidates.size(), 2u);  // the wall is too long for a leg
  const geometry::Pose2 preset(2.0, 0.2, 0.0);
  const auto near = Preprocess(pts, kAlpha, preset, models, config);
  ASSERT_EQ(near.candidates.size(), 1u);
  EXPECT_EQ(near.candidates[0].points.front().beam, 0);
  // Empty and one-point inputs.
  EXPECT_TRUE(Preprocess({}, kAlpha, std::nullopt, models, config).candidates.empty());
  const auto one = Preprocess({At(0, 3.0)}, kAlpha, std::nullopt, models, config);
  EXPECT_EQ(one.clusters, 1);
}

// A wall 3 m away across beams 0-60 and one return on beam 30 in front of it. The narrowest Table
// 1 leg (26 mm round) spans 26 mm / (r * alpha) beams: 3.0 at r = 1.5 m, 1.1 at 4 m.
//  - at 1.5 m with the wall clean on both sides, the beams beside would have hit any leg there
//    too: a stray echo, no candidate (stray_returns 1); with lone_return_max_beams = 0 it is one;
//  - at 4 m before a wall at 6 m a 26 mm leg is seen by one beam: a candidate;
//  - 0.15 m in front of the wall (less than lone_return_min_step_m) a thin leg's edge beams blend
//    into the surface close behind: a candidate;
//  - with a return between it and the wall on the next beam (an edge beam's blend) it may be a
//    leg whose edge beams blended with the wall: a candidate.
TEST(PreprocessTest, ALoneReturnNoLegCouldMakeIsNoCandidate) {
  const auto models = testing::PaperModels();
  const PreprocessConfig config;
  auto scan = [](double wall_m, double lone_m, std::optional<double> beside_m = std::nullopt) {
    std::vector<ScanPoint> pts;
    for (int b = 0; b <= 60; ++b) {
      double r = b == 30 ? lone_m : wall_m;
      if (b == 31 && beside_m) r = *beside_m;
      pts.push_back(At(b, r));
    }
    return pts;
  };
  auto candidate_at = [&](const std::vector<ScanPoint>& pts, const PreprocessConfig& c) {
    const auto out = Preprocess(pts, kAlpha, std::nullopt, models, c);
    return std::make_pair(NearestCandidate(out, pts[30].p) < 1e-9, out.stray_returns);
  };
  const auto stray = candidate_at(scan(3.0, 1.5), config);
  EXPECT_FALSE(stray.first);
  EXPECT_EQ(stray.second, 1);
  PreprocessConfig off = config;
  off.lone_return_max_beams = 0.0;
  EXPECT_TRUE(candidate_at(scan(3.0, 1.5), off).first);
  EXPECT_TRUE(candidate_at(scan(6.0, 4.0), config).first);
  EXPECT_TRUE(candidate_at(scan(1.65, 1.5), config).first);
  EXPECT_TRUE(candidate_at(scan(3.0, 1.5, 2.2), config).first);
}

// A person's leg (a round post, r = 0.06 m) touching the side of a 40 mm square leg 2 m ahead
// in the scan: its silhouette edge a quarter or half a beam beyond the leg's, so that no beam
// reaches the background between them and the two form one cluster, too wide for a leg
// (about 0.16 m). Its nearest surface stands 6, 8 or 10 cm behind the leg's front face, or 8
// or 10 cm in front of it; on either side; five scans each (simulated WLR-716, range noise
// 3 mm; mixed points, dropouts and quantisation as by default).
//  - split_max_extra_m = 0 (no split): no candidate's centroid lies within kNear of the leg's
//    true centre (the merged cluster is no leg, the person's leg alone is none either);
//  - defaults: one does, and split_candidates >= 1.
// kNear = 3 cm: the leg's visible face lies 2 cm (half the leg) in front of its centre, so the
// centroid of its own points is about 2 cm off (measured 1.2-2.5 cm); 1 cm more for noise and
// a mixed point at the cut. The person's leg's centre is > 8 cm from the leg's (asserted).
// Not asserted, measured with 10 seeds: 6 cm in front fails (the person's leg's centre is
// then at the leg's depth: its flank meets the leg's face at about the same range, and the
// beam footprint's mixed points spread what step there is over two or three returns, none
// reaching split_min_step_m; the leg was cut out in 0-7 of 10 scans); so do 8 cm in front with
// the silhouettes closer than half a beam (5-10 of 10). Farther apart than about 3/4 of a beam
// the two are separate clusters and there is nothing to split.
TEST(PreprocessTest, SplitCutsALegOutOfAPersonsLegTouchingIt) {
  constexpr double kNear = 0.03;  // [m]
  const auto models = testing::PaperModels();
  const Eigen::Vector2d leg(2.0, 0.0);
  const double leg_edge = std::atan2(0.02, 1.98);  // bearing of the leg's front corner
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.003;
  PreprocessConfig no_split;
  no_split.split_max_extra_m = 0.0;
  no_split.split_end_pieces = false;
  no_split.split_inner_pieces = false;
  struct Placement {
    double depth;  ///< [m] person's leg's nearest surface minus the leg's front face
    double gap;    ///< [beams] between the two silhouettes' edges
  };
  int scenes = 0;
  for (const Placement& pl : {Placement{0.06, 0.25}, Placement{0.08, 0.25}, Placement{0.10, 0.25},
                              Placement{-0.08, 0.5}, Placement{-0.10, 0.5}}) {
    const double range = 1.98 + pl.depth + 0.06;  // of the person's leg's centre
    const double bearing = leg_edge + pl.gap * kAlpha + std::asin(0.06 / range);
    for (const double side : {1.0, -1.0}) {
      const Eigen::Vector2d person(range * std::cos(bearing), side * range * std::sin(bearing));
      ASSERT_GT((person - leg).norm(), 0.08);
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        sim::World world;
        testing::AddRoom(world);
        world.AddSquarePost(geometry::Pose2(leg.x(), leg.y(), 0.0), 0.04);
        world.AddRoundPost(person, 0.06);
        const geometry::LaserScan scan = testing::SimScan(world, {}, seed, lidar);
        const auto points = ScanToPoints(scan);
        const std::string where = "depth " + std::to_string(pl.depth) + " side " +
                                  std::to_string(side) + " seed " + std::to_string(seed);
        const PreprocessOutput off =
            Preprocess(points, scan.angle_increment, std::nullopt, models, no_split);
        EXPECT_GT(NearestCandidate(off, leg), kNear) << where;
        EXPECT_EQ(off.split_candidates, 0) << where;
        const PreprocessOutput on =
            Preprocess(points, scan.angle_increment, std::nullopt, models, PreprocessConfig{});
        EXPECT_LT(NearestCandidate(on, leg), kNear) << where;
        EXPECT_GE(on.split_candidates, 1) << where;
        ++scenes;
      }
    }
  }
  EXPECT_EQ(scenes, 50);
}

// A leg 2 cm in front of a box 0.6 m wide, at its end: the break distance joins them, and the
// cluster is far wider than a leg with something touching it. The leg is cut off at the step
// to the box behind it (split_end_pieces); without that rule it is lost.
TEST(PreprocessTest, EndPieceCutsALegOffTheBoxBehindIt) {
  constexpr double kNear = 0.03;  // [m]
  const auto models = testing::PaperModels();
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.005;
  PreprocessConfig no_ends;
  no_ends.split_end_pieces = false;
  int scenes = 0;
  for (const double side : {1.0, -1.0}) {
    // The box's near face at x = 2.06, from y = 0 away from the leg over 0.6 m; the leg (back
    // face at x = 2.04) sticks out 1 cm past the box's end.
    const Eigen::Vector2d leg(2.02, side * 0.01);
    sim::Box box;
    box.T_world_box = geometry::Pose2(2.11, side * 0.3, 0.0);
    box.length_m = 0.1;
    box.width_m = 0.6;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      sim::World world;
      testing::AddRoom(world);
      world.AddSquarePost(geometry::Pose2(leg.x(), leg.y(), 0.0), 0.04);
      world.AddBox(box);
      const geometry::LaserScan scan = testing::SimScan(world, {}, seed, lidar);
      const auto points = ScanToPoints(scan);
      const std::string where = "side " + std::to_string(side) + " seed " + std::to_string(seed);
      const PreprocessOutput off =
          Preprocess(points, scan.angle_increment, std::nullopt, models, no_ends);
      EXPECT_GT(NearestCandidate(off, leg), kNear) << where;
      const PreprocessOutput on =
          Preprocess(points, scan.angle_increment, std::nullopt, models, PreprocessConfig{});
      EXPECT_LT(NearestCandidate(on, leg), kNear) << where;
      ++scenes;
    }
  }
  EXPECT_EQ(scenes, 20);
}

// 20 mm range noise at half a metre, where beams are 3 mm apart, breaks a 40 mm leg into
// fragments; joining noise breaks offers the whole leg again. A person's leg 2 cm beside the
// shelf leg is no fragment of it: the two together never make a candidate.
TEST(PreprocessTest, JoiningNoiseBreaksGivesBackTheWholeLeg) {
  const auto models = testing::PaperModels();
  const Eigen::Vector2d leg(0.52, 0.0);  // centre of a 40 mm square post, face-on
  const double expected_width = 0.04;    // [m] its silhouette across the view
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.02;
  PreprocessConfig no_join;
  no_join.join_noise_breaks = false;
  // The widest candidate within 3 cm of the leg's front face, as a width across the view [m].
  const Eigen::Vector2d face(leg.x() - 0.02, 0.0);
  auto widest_near_leg = [&](const PreprocessOutput& out) {
    double widest = 0.0;
    for (const Cluster& c : out.candidates) {
      if ((c.centroid - face).norm() > 0.03) continue;
      const double span = std::abs(c.points.back().angle - c.points.front().angle);
      widest = std::max(widest, c.centroid.norm() * span);
    }
    return widest;
  };
  int fragmented = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    sim::World world;
    testing::AddRoom(world);
    world.AddSquarePost(geometry::Pose2(leg.x(), leg.y(), 0.0), 0.04);
    world.AddRoundPost(Eigen::Vector2d(0.60, 0.13), 0.06);  // a person's leg beside it
    const geometry::LaserScan scan = testing::SimScan(world, {}, seed, lidar);
    const auto points = ScanToPoints(scan);
    const PreprocessOutput off =
        Preprocess(points, scan.angle_increment, std::nullopt, models, no_join);
    const PreprocessOutput on =
        Preprocess(points, scan.angle_increment, std::nullopt, models, PreprocessConfig{});
    EXPECT_EQ(off.joined_candidates, 0);
    // Joined or not, no candidate holds returns of both the shelf leg and the person's leg.
    for (const Cluster& c : on.candidates) {
      const auto near = [&c](const Eigen::Vector2d& centre, double radius) {
        return std::any_of(c.points.begin(), c.points.end(),
                           [&](const ScanPoint& q) { return (q.p - centre).norm() < radius; });
      };
      EXPECT_FALSE(near(leg, 0.045) && near(Eigen::Vector2d(0.60, 0.13), 0.075)) << "seed " << seed;
    }
    const double w_off = widest_near_leg(off);
    const double w_on = widest_near_leg(on);
    EXPECT_GE(w_on, w_off) << "seed " << seed;  // joining only adds candidates
    if (w_off < expected_width - 0.012) {
      // Fragmented: the joined candidate is within a beam and a half of the leg's width.
      ++fragmented;
      EXPECT_GE(on.joined_candidates, 1) << "seed " << seed;
      EXPECT_GT(w_on, expected_width - 0.012) << "seed " << seed;
    }
  }
  // The noise must fragment the leg in a good share of these scans for the test to mean anything.
  EXPECT_GE(fragmented, 5);
}

TEST(PreprocessTest, RangeNoiseWidensTheLegExtentItAllows) {
  const auto models = testing::PaperModels();
  const double diagonal = models[1].leg.Extent();  // 40 mm square leg: 57 mm
  PreprocessConfig config;
  EXPECT_DOUBLE_EQ(MaxLegExtent(models, config, 0.0), diagonal + config.leg_extent_margin_m);
  EXPECT_DOUBLE_EQ(MaxLegExtent(models, config, 0.02),
                   diagonal + config.leg_extent_noise_sigmas * std::sqrt(2.0) * 0.02);
  // A 40 mm square leg seen corner-on at 1.2 m under 30 mm range noise: its returns spread in
  // depth over the leg's diagonal and the noise. It stays a candidate whenever its returns are
  // one cluster, also in the scans where they spread past the fixed margin.
  const Eigen::Vector2d leg(1.2, 0.2);
  sim::LidarConfig lidar;
  lidar.range_noise_sigma_m = 0.03;
  PreprocessConfig fixed_margin;
  fixed_margin.leg_extent_noise_sigmas = 0.0;
  int wide = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    sim::World world;
    testing::AddRoom(world);
    const double view = std::atan2(leg.y(), leg.x());
    world.AddSquarePost(geometry::Pose2(leg.x(), leg.y(), view + 0.25 * M_PI), 0.04);
    const geometry::LaserScan scan = testing::SimScan(world, {}, seed, lidar);
    const auto points = ScanToPoints(scan);
    const PreprocessOutput out =
        Preprocess(points, scan.angle_increment, std::nullopt, models, config);
    const PreprocessOutput fixed =
        Preprocess(points, scan.angle_increment, std::nullopt, models, fixed_margin);
    // The leg's returns, as the clustering cut them.
    const auto it = std::find_if(out.spans.begin(), out.spans.end(), [&](const ClusterSpan& s) {
      return (s.centroid - leg).norm() < 0.06 && s.size() >= 2;
    });
    if (it == out.spans.end() || it->extent_m > MaxLegExtent(models, config, out.range_noise_m)) {
      continue;  // fragmented or joined to a mixed point: not what this test is about
    }
    auto has_leg = [&](const PreprocessOutput& o) {
      return std::any_of(o.candidates.begin(), o.candidates.end(), [&](const Cluster& c) {
        return (c.centroid - leg).norm() < 0.06 && c.points.size() == it->size();
      });
    };
    EXPECT_TRUE(has_leg(out)) << "seed " << seed;
    if (it->extent_m > diagonal + config.leg_extent_margin_m) {
      ++wide;
      EXPECT_FALSE(has_leg(fixed)) << "seed " << seed;  // the fixed margin loses it
    }
  }
  // The noise must stretch the leg past the fixed margin in some of these scans.
  EXPECT_GE(wide, 3);
}

}  // namespace
}  // namespace shelfdock::perception
