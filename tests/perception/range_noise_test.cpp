// EstimateRangeNoise (src/perception/range_noise.cpp): the scan's own range noise from second
// differences of consecutive-beam ranges, against the true sigma of synthesized points (flat
// wall, walls turning 90 degrees) and of the simulator's LiDAR (LidarConfig::range_noise_sigma_m).
#include "perception/range_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = 0.005817764173314432;  // WLR-716: 1/3 degree
constexpr double kDeg = M_PI / 180.0;

// The estimate must lie within 15 % of the true sigma. Its own spread (measured on 20000 draws
// of Gaussian noise; consecutive triplets share points) is 8.2 % of sigma from 300 triplets,
// 5.0 % from 800 (one full 811-beam scan) and 4.1 % from 1200: the synthetic scenes below hold
// > 1000 triplets so that 15 % is > 3.5 of its standard deviations. A wrong scale fails it
// (without the 1.4826: -33 %; sqrt 3 in place of sqrt 6: +41 %).
constexpr double kRelTol = 0.15;
// With exact ranges only the surfaces' own curvature is left (r * alpha^2 terms, < 1 mm).
constexpr double kNoiseFreeTol = 0.001;  // [m]

// Exact points of a fan of beams (sensor at the origin) on a polyline: each beam's nearest hit,
// beams without a hit skipped (their index is still used up, as in a real scan). `segment`, if
// given, gets the index of the polyline segment each point lies on.
std::vector<ScanPoint> CastPolyline(const std::vector<Eigen::Vector2d>& poly, double first_rad,
                                    int beams, double increment,
                                    std::vector<int>* segment = nullptr) {
  std::vector<ScanPoint> out;
  for (int b = 0; b < beams; ++b) {
    const double a = first_rad + b * increment;
    const Eigen::Vector2d u(std::cos(a), std::sin(a));
    double best = std::numeric_limits<double>::infinity();
    int best_segment = -1;
    for (std::size_t s = 0; s + 1 < poly.size(); ++s) {
      const Eigen::Vector2d p = poly[s], d = poly[s + 1] - poly[s];
      // t u = p + w d  ->  [u, -d] (t, w)^T = p
      const double det = u.x() * (-d.y()) - u.y() * (-d.x());
      if (std::abs(det) < 1e-12) continue;
      const double t = (p.x() * (-d.y()) - p.y() * (-d.x())) / det;
      const double w = (u.x() * p.y() - u.y() * p.x()) / det;
      if (t > 0.0 && w >= 0.0 && w <= 1.0 && t < best) {
        best = t;
        best_segment = static_cast<int>(s);
      }
    }
    if (!std::isfinite(best)) continue;
    out.push_back({best * u, best, a, b});
    if (segment) segment->push_back(best_segment);
  }
  return out;
}

// `n` Gaussian range errors of std `sigma`.
std::vector<double> Noise(std::size_t n, double sigma, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  std::vector<double> e(n);
  for (double& x : e) x = gauss(rng);
  return e;
}

// The points with `noise` added to their ranges (each point moves along its beam).
std::vector<ScanPoint> WithNoise(std::vector<ScanPoint> pts, const std::vector<double>& noise) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    pts[i].range += noise.at(i);
    pts[i].p = pts[i].range * Eigen::Vector2d(std::cos(pts[i].angle), std::sin(pts[i].angle));
  }
  return pts;
}

// The scenes' point sets one after another as separate clusters (scans of the same scene from
// several distances, say): beams renumbered so that no triplet joins two of them.
void Append(const std::vector<ScanPoint>& part, std::vector<ScanPoint>* pts,
            std::vector<ClusterSpan>* spans) {
  ClusterSpan s;
  s.begin = pts->size();
  const int offset = pts->empty() ? 0 : pts->back().beam + 10;
  for (ScanPoint q : part) {
    q.beam += offset;
    pts->push_back(q);
  }
  s.end = pts->size();
  spans->push_back(s);
}

// One span over all points (the estimator itself skips triplets across a dropped beam).
std::vector<ClusterSpan> OneSpan(const std::vector<ScanPoint>& pts) {
  ClusterSpan s;
  s.begin = 0;
  s.end = pts.size();
  return {s};
}

// A wall perpendicular to the middle beam at `distance`, seen over +-50 degrees (301 beams).
std::vector<ScanPoint> FlatWall(double distance = 2.0) {
  return CastPolyline({{distance, -10.0 * distance}, {distance, 10.0 * distance}}, -50.0 * kDeg,
                      301, kAlpha);
}

// The wall from 1, 2, 3 and 4 m: four clusters, 4 x 299 = 1196 triplets; range noise 2-50 mm,
// three draws each, every estimate within kRelTol.
TEST(RangeNoiseTest, FlatWallGivesTheTrueSigma) {
  std::vector<ScanPoint> walls;
  std::vector<ClusterSpan> spans;
  for (const double d : {1.0, 2.0, 3.0, 4.0}) Append(FlatWall(d), &walls, &spans);
  ASSERT_EQ(walls.size(), 4u * 301u);
  for (const double sigma : {0.002, 0.005, 0.01, 0.02, 0.05}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const auto pts = WithNoise(walls, Noise(walls.size(), sigma, seed));
      const RangeNoiseEstimate e = EstimateRangeNoise(pts, spans);
      EXPECT_EQ(e.samples, 4 * 299);  // every triplet of 301 consecutive beams, per wall
      EXPECT_NEAR(e.sigma_m, sigma, kRelTol * sigma) << "sigma " << sigma << " seed " << seed;
    }
  }
}

TEST(RangeNoiseTest, NoNoiseGivesAboutZero) {
  std::vector<ScanPoint> walls;
  std::vector<ClusterSpan> spans;
  for (const double d : {1.0, 2.0, 3.0, 4.0}) Append(FlatWall(d), &walls, &spans);
  const RangeNoiseEstimate e = EstimateRangeNoise(walls, spans);
  EXPECT_EQ(e.samples, 4 * 299);
  EXPECT_GE(e.sigma_m, 0.0);
  EXPECT_LT(e.sigma_m, kNoiseFreeTol);
  // The same on the simulator's room with every flaw off (exact ranges, 811 beams).
  sim::World world;
  testing::AddRoom(world);
  const auto pts = ScanToPoints(testing::SimScan(world, {}, 1, sim::IdealLidarConfig()));
  ASSERT_EQ(pts.size(), 811u);
  const RangeNoiseEstimate r = EstimateRangeNoise(pts, OneSpan(pts));
  EXPECT_EQ(r.samples, 809);
  EXPECT_LT(r.sigma_m, kNoiseFreeTol);
}

TEST(RangeNoiseTest, TooFewSamplesGiveZeroButAreCounted) {
  const auto clean = FlatWall();
  const auto wall = WithNoise(clean, Noise(clean.size(), 0.01, 7));
  // 20 consecutive points: 18 triplets, below the default 30.
  std::vector<ScanPoint> few(wall.begin(), wall.begin() + 20);
  RangeNoiseEstimate e = EstimateRangeNoise(few, OneSpan(few));
  EXPECT_EQ(e.samples, 18);
  EXPECT_EQ(e.sigma_m, 0.0);
  // The same points with the bar lowered to 18 give an estimate (exactly at the bar).
  e = EstimateRangeNoise(few, OneSpan(few), 18);
  EXPECT_EQ(e.samples, 18);
  EXPECT_GT(e.sigma_m, 0.0);
  // Triplets never straddle two clusters, nor a dropped beam: 40 points as two spans of 20
  // give 2 x 18; then every 10th beam dropped from the first 40 (36 points, four runs of 9
  // consecutive beams, one span) gives 4 x 7 = 28 < 30.
  std::vector<ScanPoint> two(wall.begin(), wall.begin() + 40);
  ClusterSpan a, b;
  a.begin = 0;
  a.end = 20;
  b.begin = 20;
  b.end = 40;
  e = EstimateRangeNoise(two, {a, b});
  EXPECT_EQ(e.samples, 36);
  EXPECT_GT(e.sigma_m, 0.0);
  std::vector<ScanPoint> holes;
  for (const ScanPoint& q : two) {
    if (q.beam % 10 != 9) holes.push_back(q);
  }
  ASSERT_EQ(holes.size(), 36u);
  e = EstimateRangeNoise(holes, OneSpan(holes));
  EXPECT_EQ(e.samples, 28);
  EXPECT_EQ(e.sigma_m, 0.0);
  // Nothing at all.
  e = EstimateRangeNoise({}, {});
  EXPECT_EQ(e.samples, 0);
  EXPECT_EQ(e.sigma_m, 0.0);
}

// Walls turning 90 degrees: a triplet astride a corner sees the surface turn (a second
// difference of about 2 r alpha, 23 mm at 2 m), not the noise; the median must ignore it.
// Scenes (1/3 degree beams, the WLR-716's), each seen from several distances, one cluster
// each, so that there are > 1000 triplets; incidence on every face stays at most 70 degrees
// (beyond about 80 degrees the faces' own curvature, not the corners, adds to the estimate):
//  - the inside corner of a room, 1.5, 2 and 3 m to each wall (one corner per cluster);
//  - the outside corner of a large block pointing at the sensor from 1-4 m (one per cluster);
//  - a folded screen 1.5-5 m ahead, turning 90 degrees every 0.56 m along it (concave and
//    convex in turn; at 2 m a corner every 48 beams, about 8 % of the triplets astride one).
// Each estimate must lie within kRelTol of the true sigma (range noise 3-20 mm). The corners'
// own share, the estimate minus that of the same noisy points with every cluster also cut at
// its corners (no triplet astride one), must stay below `max_shift` of sigma: 5 % for one
// corner per cluster, 10 % for the screen (measured up to 6.4 %, at 5 mm noise).
// Denser corners do bias it: a corner every 0.14 m along the screen gave +12 % at 10 mm noise
// and +32 % at 3 mm, every 0.07 m +24 % and +97 % (the median ignores corners only while they
// are a small share of the triplets); not asserted.
struct CornerScene {
  std::string name;
  double max_shift = 0.0;  ///< [-] of sigma, the corners' share
  std::vector<ScanPoint> pts;
  std::vector<ClusterSpan> spans;  ///< one per view, corners inside
  std::vector<ClusterSpan> faces;  ///< the same cut at every corner
};

// Adds one view of `poly` to the scene.
void AddView(const std::vector<Eigen::Vector2d>& poly, double first_rad, int beams,
             CornerScene* s) {
  std::vector<int> segment;
  const auto part = CastPolyline(poly, first_rad, beams, kAlpha, &segment);
  const std::size_t base = s->pts.size();
  Append(part, &s->pts, &s->spans);
  ClusterSpan face;
  face.begin = base;
  for (std::size_t i = 1; i <= part.size(); ++i) {
    if (i < part.size() && segment[i] == segment[i - 1]) continue;
    face.end = base + i;
    s->faces.push_back(face);
    face.begin = face.end;
  }
}

CornerScene RoomCorner() {
  CornerScene s{"room corner", 0.05, {}, {}, {}};
  // Bearings -60..150 degrees: incidence at most 60 degrees on either wall.
  for (const double d : {1.5, 2.0, 3.0}) {
    AddView({{d, -2.0 * d}, {d, d}, {-2.0 * d, d}}, -60.0 * kDeg, 631, &s);
  }
  return s;
}

CornerScene BlockCorner() {
  CornerScene s{"block corner", 0.05, {}, {}, {}};
  // Faces at +-45 degrees to the middle beam, bearings +-20 degrees: incidence <= 65 degrees.
  for (double d = 1.0; d < 4.01; d += 0.25) {
    AddView({{d + 3.0, -3.0}, {d, 0.0}, {d + 3.0, 3.0}}, -20.0 * kDeg, 121, &s);
  }
  return s;
}

CornerScene FoldedScreen() {
  constexpr double kPitch = 0.56;  // [m] along the screen between corners
  CornerScene s{"folded screen", 0.10, {}, {}, {}};
  // Faces at +-45 degrees to the screen's line, bearings +-25 degrees: incidence <= 70.
  for (double d = 1.5; d < 5.01; d += 0.5) {
    std::vector<Eigen::Vector2d> screen;
    const int n = static_cast<int>(std::ceil(d / kPitch));
    for (int k = -n; k <= n; ++k) screen.emplace_back(d + kPitch * (k & 1), kPitch * k);
    AddView(screen, -25.0 * kDeg, 151, &s);
  }
  return s;
}

TEST(RangeNoiseTest, CornersDoNotBiasTheEstimate) {
  for (const CornerScene& s : {RoomCorner(), BlockCorner(), FoldedScreen()}) {
    const RangeNoiseEstimate exact = EstimateRangeNoise(s.pts, s.spans);
    std::printf("[ corners ] %-13s: %zu corners, %d triplets; noise-free estimate %.5f m\n",
                s.name.c_str(), s.faces.size() - s.spans.size(), exact.samples, exact.sigma_m);
    ASSERT_GT(exact.samples, 1000) << s.name;
    EXPECT_LT(exact.sigma_m, kNoiseFreeTol) << s.name;
    for (const double sigma : {0.003, 0.005, 0.01, 0.02}) {
      for (std::uint64_t seed : {11u, 12u, 13u}) {
        const auto pts = WithNoise(s.pts, Noise(s.pts.size(), sigma, seed));
        const RangeNoiseEstimate e = EstimateRangeNoise(pts, s.spans);
        const RangeNoiseEstimate cut = EstimateRangeNoise(pts, s.faces);
        EXPECT_NEAR(e.sigma_m, sigma, kRelTol * sigma) << s.name << " sigma " << sigma;
        EXPECT_NEAR(e.sigma_m, cut.sigma_m, s.max_shift * sigma) << s.name << " sigma " << sigma;
      }
    }
  }
}

// The simulator's LiDAR (WLR-716 defaults: 811 beams, 1 mm quantisation, mixed points,
// dropouts) in a 12 m x 10 m room (walls at 5-8.6 m, four inside corners), its range noise set
// to 0.01 and 0.02 m (the brief), and 0.002 and 0.005 m. Preprocess reports the estimate it made
// on its own clusters; both it and a direct call must lie within kRelTol of the configured sigma
// for three scans each (about 750 triplets: kRelTol is 3 standard deviations of the estimate).
// Ranges quantised to 1 mm make every second difference a whole number of millimetres, so the
// estimate moves in steps of kQuantumStep (0.61 mm: at 2 mm noise it reads 1.82 or 2.42 mm, -9
// or +21 %); the tolerance is the larger of kRelTol * sigma and that step.
constexpr double kQuantumStep = 1.4826 * 0.001 / 2.449489742783178;  // [m] 1 mm / sqrt 6, scaled

TEST(RangeNoiseTest, SimulatedRoomGivesTheConfiguredSigma) {
  sim::World world;
  testing::AddRoom(world);
  const auto models = testing::PaperModels();
  for (const double sigma : {0.002, 0.005, 0.01, 0.02}) {
    sim::LidarConfig lidar;
    lidar.range_noise_sigma_m = sigma;
    const double tol = std::max(kRelTol * sigma, kQuantumStep);
    for (std::uint64_t seed : {21u, 22u, 23u}) {
      const geometry::LaserScan scan = testing::SimScan(world, {}, seed, lidar);
      const PreprocessOutput pre = Preprocess(ScanToPoints(scan), scan.angle_increment,
                                              std::nullopt, models, PreprocessConfig{});
      const RangeNoiseEstimate e = EstimateRangeNoise(pre.points, pre.spans);
      std::printf("[ sim room ] sigma %.3f seed %d: estimate %.5f from %d triplets\n", sigma,
                  static_cast<int>(seed), e.sigma_m, e.samples);
      EXPECT_GT(e.samples, 600);
      EXPECT_NEAR(e.sigma_m, sigma, tol) << "seed " << seed;
      EXPECT_DOUBLE_EQ(pre.range_noise_m, e.sigma_m);
    }
  }
}

}  // namespace
}  // namespace shelfdock::perception
