// The peer methods of `eval peers`: the exhaustive search finds what the pruned search finds
// and counts its checks as stated; the centroid-only and corner-finding peers find a simulated
// shelf, less accurately than the detector on the same scans.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "eval/monte_carlo.hpp"
#include "eval/peers/centroid_peer.hpp"
#include "eval/peers/corner_peer.hpp"
#include "eval/peers/exhaustive_leg_search.hpp"
#include "geometry/angle.hpp"
#include "perception/detector.hpp"
#include "perception/leg_search.hpp"
#include "sim/lidar.hpp"
#include "sim/world.hpp"

namespace shelfdock::eval {
namespace {

using geometry::Pose2;

std::set<std::array<int, 4>> Keys(const std::vector<perception::LegSet>& sets) {
  std::set<std::array<int, 4>> keys;
  for (const auto& s : sets) {
    std::array<int, 4> k = s.legs;
    std::sort(k.begin(), k.end());
    keys.insert(k);
  }
  return keys;
}

// The four legs of shelf 2 among random leg-like points: both searches keep the shelf's 4-leg
// set; the exhaustive one checks every 3- and 4-subset three ways, the pruned one far fewer.
TEST(ExhaustiveLegSearchTest, SameShelfManyMoreChecks) {
  const auto models = testing::PaperModels();
  const geometry::ShelfModel shelf = testing::PaperShelf2();
  const Pose2 T_lidar_shelf(2.0, 0.5, 0.3);
  std::vector<Eigen::Vector2d> centres;
  for (const auto& leg : shelf.LegCentres()) centres.push_back(T_lidar_shelf * leg);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  while (centres.size() < 30) centres.emplace_back(u(rng), u(rng));

  perception::LegSearchConfig config;
  config.max_leg_sets = 1 << 30;
  perception::LegSearchCounts pruned_counts, exhaustive_counts;
  const auto pruned = perception::SearchLegSets(centres, models, config, &pruned_counts);
  const auto exhaustive = peers::ExhaustiveLegSets(centres, models, config, &exhaustive_counts);

  const std::array<int, 4> shelf_key = {0, 1, 2, 3};
  EXPECT_TRUE(Keys(pruned).count(shelf_key));
  EXPECT_TRUE(Keys(exhaustive).count(shelf_key));
  // Every 4-leg set the pruned search keeps, the exhaustive one keeps too.
  const auto all = Keys(exhaustive);
  for (const auto& s : pruned) {
    if (s.count != 4) continue;
    std::array<int, 4> k = s.legs;
    std::sort(k.begin(), k.end());
    EXPECT_TRUE(all.count(k));
  }
  const long long n = static_cast<long long>(centres.size());
  const long long c3 = n * (n - 1) * (n - 2) / 6, c4 = c3 * (n - 3) / 4;
  EXPECT_EQ(exhaustive_counts.checks, 3 * c3 + 3 * c4);
  EXPECT_GT(pruned_counts.checks, 0);
  EXPECT_GT(exhaustive_counts.checks, 10 * pruned_counts.checks);
}

struct PeerErrors {
  std::vector<double> detector, centroid, corner;  // [m] centre errors
  int detector_found = 0, centroid_found = 0, corner_found = 0;
};

// Shelf 2 at 1-2.5 m, headings all round, preset 0.1 m / 0.05 rad off, nominal WLR-716.
PeerErrors RunPeers(int scans) {
  const auto models = testing::PaperModels();
  const geometry::ShelfModel shelf = testing::PaperShelf2();
  const perception::DetectorConfig config;
  const perception::Detector detector(models, config);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  PeerErrors out;
  for (int i = 0; i < scans; ++i) {
    const double d = 1.0 + 1.5 * u01(rng), bearing = -0.5 + u01(rng);
    const Pose2 truth(d * std::cos(bearing), d * std::sin(bearing), -M_PI + 2 * M_PI * u01(rng));
    const Pose2 preset(truth.x + 0.07, truth.y - 0.07, truth.yaw + 0.05);
    sim::World world;
    world.AddWall({{-5.0, -5.0}, {7.0, -5.0}, {7.0, 5.0}, {-5.0, 5.0}}, true);
    world.AddShelf(1, shelf, truth);
    const auto scan = sim::Lidar(sim::LidarConfig{}, 300 + i).Scan(world, Pose2());
    const auto score = [&](const std::string& model, const Pose2& p, std::vector<double>* errors,
                           int* found) {
      if (model != shelf.name) return;
      const double e = geometry::Distance(p, truth);
      if (e > 0.05) return;
      ++*found;
      errors->push_back(e);
    };
    const auto det = detector.Detect(scan, preset);
    if (!det.detections.empty()) {
      score(det.detections[0].model, det.detections[0].T_lidar_shelf, &out.detector,
            &out.detector_found);
    }
    if (const auto c = peers::CentroidPeerDetect(scan, preset, models, config)) {
      score(c->model, c->T_lidar_shelf, &out.centroid, &out.centroid_found);
    }
    if (const auto c = peers::CornerPeerDetect(scan, preset, models, config)) {
      score(c->model, c->T_lidar_shelf, &out.corner, &out.corner_found);
    }
  }
  return out;
}

TEST(PeersTest, PeersFindTheShelfLessAccurately) {
  constexpr int kScans = 40;
  const PeerErrors e = RunPeers(kScans);
  // The peers use the detector's clusters: they find most shelves within 5 cm.
  EXPECT_GE(e.detector_found, kScans * 95 / 100);
  EXPECT_GE(e.centroid_found, kScans / 2);
  EXPECT_GE(e.corner_found, kScans / 2);
  // Centroids lie on the legs' visible faces, about half a leg (2 cm) toward the sensor: the
  // peers' median error is above the detector's, whose fits remove that bias.
  EXPECT_LT(Quantile(e.detector, 0.5), Quantile(e.centroid, 0.5));
  EXPECT_LT(Quantile(e.detector, 0.5), Quantile(e.corner, 0.5));
  std::printf(
      "[ peers ] found %d / %d / %d of %d; centre error p50 %.1f / %.1f / %.1f mm "
      "(detector / centroid-only / corner-finding)\n",
      e.detector_found, e.centroid_found, e.corner_found, kScans, 1e3 * Quantile(e.detector, 0.5),
      1e3 * Quantile(e.centroid, 0.5), 1e3 * Quantile(e.corner, 0.5));
}

}  // namespace
}  // namespace shelfdock::eval
