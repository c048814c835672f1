// Statistical sweep of the detector on simulated WLR-716 scans (811 beams, 10 mm range noise,
// mixed points at depth edges, dropouts): the acceptance figures, printed and asserted.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "perception/detector.hpp"
#include "scene_builder.hpp"
#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::min<double>(v.size() - 1, q * (v.size() - 1) + 0.5))];
}

// Random model, standoff 0.5-3.5 m, heading all round, bearing within +-0.8 rad; the preset is
// off by up to 0.2 m and 0.1 rad. "Found" = the first detection has the right model and lies
// within 0.05 m of the truth.
TEST(DetectorStatsTest, RightShelfAndAccuracyWithin3p5m) {
  const auto models = testing::PaperModels();
  const Detector detector(models);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  constexpr int kCases = 400;
  std::vector<int> found_per_model(models.size(), 0), cases_per_model(models.size(), 0);
  std::vector<double> centre_err, yaw_err;
  for (int i = 0; i < kCases; ++i) {
    const int mi = i % static_cast<int>(models.size());
    const auto& model = models[mi];
    const double standoff = 0.5 + 3.0 * u01(rng);
    const double yaw = -M_PI + 2.0 * M_PI * u01(rng);
    const double bearing = -0.8 + 1.6 * u01(rng);
    const geometry::Pose2 truth = testing::PlaceShelf(model, standoff, bearing, yaw);
    const double r = 0.2 * std::sqrt(u01(rng)), phi = 2.0 * M_PI * u01(rng);
    const geometry::Pose2 preset(truth.x + r * std::cos(phi), truth.y + r * std::sin(phi),
                                 truth.yaw + (-0.1 + 0.2 * u01(rng)));
    sim::World world;
    testing::AddRoom(world);
    world.AddShelf(1, model, truth);
    const DetectionResult res = detector.Detect(testing::SimScan(world, {}, 1000 + i), preset);
    ++cases_per_model[mi];
    const double e_c = res.detections.empty()
                           ? std::numeric_limits<double>::infinity()
                           : geometry::Distance(res.detections[0].T_lidar_shelf, truth);
    if (res.detections.empty() || res.detections[0].model != model.name || e_c > 0.05) {
      std::printf(
          "[ stats ] missed %s standoff %.2f m bearing %.2f yaw %.2f: %s (legs %d); leg "
          "candidates %d, sets %d, pairs %d; rejected fit %d model %d 3-leg %d through %d "
          "confidence %d lost %d\n",
          model.name.c_str(), standoff, bearing, yaw,
          res.detections.empty() ? "none" : res.detections[0].model.c_str(),
          res.detections.empty() ? 0 : res.detections[0].legs_used, res.stats.leg_candidates,
          res.stats.leg_sets, res.stats.model_pairs, res.stats.rejected.fit,
          res.stats.rejected.model, res.stats.rejected.three_leg_error,
          res.stats.rejected.leg_seen_through, res.stats.rejected.low_confidence,
          res.stats.rejected.lost_legs);
      continue;
    }
    const Detection& d = res.detections[0];
    ++found_per_model[mi];
    centre_err.push_back(e_c);
    yaw_err.push_back(std::abs(geometry::AngleDiff(d.T_lidar_shelf.yaw, truth.yaw)));
  }
  int found = 0;
  for (std::size_t m = 0; m < models.size(); ++m) {
    found += found_per_model[m];
    std::printf("[ stats ] %-18s found %3d/%3d\n", models[m].name.c_str(), found_per_model[m],
                cases_per_model[m]);
  }
  const double rate = static_cast<double>(found) / kCases;
  const double c95 = Percentile(centre_err, 0.95), y95 = Percentile(yaw_err, 0.95);
  std::printf(
      "[ stats ] found %.1f%%, centre error p50 %.1f mm p95 %.1f mm, heading error p50 "
      "%.1f mrad p95 %.1f mrad\n",
      100.0 * rate, 1e3 * Percentile(centre_err, 0.5), 1e3 * c95, 1e3 * Percentile(yaw_err, 0.5),
      1e3 * y95);
  // The figures: the right shelf found in >= 98 % of cases, centre error p95 <= 10 mm and
  // heading error p95 <= 10 mrad. Measured (seed 42, 3a6d954): 99.5 % (round 100 %, 1075x883 99 %,
  // 1250x1250 100 %, 1080x856 99 %), 6.6 mm, 7.3 mrad. The legs' errors along their beams are
  // at the range-noise floor (10 mm / sqrt(beams on the leg)); fitting the shelf to legs with
  // exact positions across the beam and only that noise along it gives about 6.5 mm p95.
  // The misses left are 1075x883 / 1080x856 confusions (27 mm apart in width) with far legs seen
  // by one or two beams, and round 26 mm legs lost to dropouts and partial beam cover at 2-3 m.
  EXPECT_GE(rate, 0.98);
  EXPECT_LE(c95, 0.010);
  EXPECT_LE(y95, 0.010);
}

// Paper Table 1 setting: the LiDAR faces the shelf with its front legs about 0.5 m away
// ("multiple recognitions were conducted and the size of the fitted shelf was calculated": one
// fitted size per model, the mean over the recognitions). Either side of the shelf in front.
// Legs: the simulator's default dark paint (reflectivity 0.15), walls 0.6.
TEST(DetectorStatsTest, FittedSizeAtHalfMetre) {
  const auto models = testing::PaperModels();
  const Detector detector(models);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  constexpr int kPerModel = 30;
  int missed = 0;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const auto& model = models[m];
    double sum_length = 0.0, sum_width = 0.0;
    std::vector<double> single;
    int n = 0;
    for (int i = 0; i < kPerModel; ++i) {
      const bool broadside = i % 2 == 1;  // long side across the view
      const double yaw = (broadside ? 0.5 * M_PI : 0.0) + u(rng);
      const double bearing = u(rng);
      // Centre behind the front leg line: 0.5 m plus half the depth of the shelf.
      const double depth = broadside ? model.width_m : model.length_m;
      const double d = 0.5 + 0.5 * depth;
      const geometry::Pose2 truth(d * std::cos(bearing), d * std::sin(bearing), bearing + yaw);
      sim::World world;
      testing::AddRoom(world);
      world.AddShelf(1, model, truth);
      const std::uint64_t seed = 5000 + 100 * m + i;
      const DetectionResult res = detector.Detect(testing::SimScan(world, {}, seed), truth);
      if (res.detections.empty() || res.detections[0].model != model.name) {
        ++missed;
        continue;
      }
      const Detection& det = res.detections[0];
      sum_length += det.length_m;
      sum_width += det.width_m;
      single.push_back(std::max(std::abs(det.length_m / model.length_m - 1),
                                std::abs(det.width_m / model.width_m - 1)));
      ++n;
    }
    ASSERT_GT(n, 0) << model.name;
    const double length_err = sum_length / n / model.length_m - 1;
    const double width_err = sum_width / n / model.width_m - 1;
    std::printf(
        "[ size@0.5m ] %-18s mean length %.4f m (%+.2f%%), width %.4f m (%+.2f%%); single "
        "scans p95 %.2f%%, worst %.2f%%\n",
        model.name.c_str(), sum_length / n, 100 * length_err, sum_width / n, 100 * width_err,
        100 * Percentile(single, 0.95), 100 * Percentile(single, 1.0));
    // Issue: the fitted size within 1 % of the model at 0.5 m standoff.
    EXPECT_LE(std::abs(length_err), 0.01) << model.name;
    EXPECT_LE(std::abs(width_err), 0.01) << model.name;
  }
  EXPECT_EQ(missed, 0);
}

}  // namespace
}  // namespace shelfdock::perception
