#include "io/explain_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "io/detection_json.hpp"
#include "io/scan_json.hpp"
#include "perception/preprocess.hpp"

namespace shelfdock::io {
namespace {

geometry::LaserScan ExampleScan() {
  return ReadScans(std::string(SHELFDOCK_SOURCE_DIR) + "/config/example_scan.json").front();
}

// Every valid return is either a kept point (in exactly one cluster) or a removed trailing
// point, and the clusters flagged as candidates are the detector's leg candidates.
TEST(ExplainJson, AccountsForEveryReturnAndAgreesWithTheDetector) {
  const geometry::LaserScan scan = ExampleScan();
  const perception::Detector detector(testing::PaperModels());
  const perception::DetectionResult result = detector.Detect(scan);
  const nlohmann::json j = ExplainGeometryJson(scan, detector, std::nullopt);

  const std::size_t valid = perception::ScanToPoints(scan).size();
  ASSERT_GT(valid, 100u);
  EXPECT_EQ(j["points"].size() + j["trailing"].size(), valid);
  EXPECT_EQ(static_cast<int>(j["trailing"].size()), result.stats.trailing_removed);
  EXPECT_TRUE(j["roi"].is_null());

  std::size_t in_clusters = 0;
  int candidates = 0;
  for (const auto& c : j["clusters"]) {
    in_clusters += c["points"].get<std::size_t>();
    candidates += c["candidate"].get<bool>() ? 1 : 0;
    EXPECT_TRUE(c["in_roi"].get<bool>());  // no preset: the whole scan
  }
  EXPECT_EQ(in_clusters, j["points"].size());
  EXPECT_EQ(candidates, result.stats.leg_candidates);
  for (const auto& p : j["points"]) {
    const int c = p[2].get<int>();
    ASSERT_GE(c, 0);
    ASSERT_LT(c, static_cast<int>(j["clusters"].size()));
  }
}

// With a preset the ROI is roi_gamma times the longest model diagonal around the preset centre,
// and a cluster is in it when its centroid is.
TEST(ExplainJson, RoiFollowsThePreset) {
  const geometry::LaserScan scan = ExampleScan();
  const auto models = testing::PaperModels();
  const perception::Detector detector(models);
  const geometry::Pose2 preset(2.0, 0.2, 0.1);
  const nlohmann::json j = ExplainGeometryJson(scan, detector, preset);

  double diagonal = 0.0;
  for (const auto& m : models) diagonal = std::max(diagonal, std::hypot(m.length_m, m.width_m));
  const double r = perception::PreprocessConfig{}.roi_gamma * diagonal;
  ASSERT_FALSE(j["roi"].is_null());
  EXPECT_DOUBLE_EQ(j["roi"]["x"].get<double>(), preset.x);
  EXPECT_DOUBLE_EQ(j["roi"]["y"].get<double>(), preset.y);
  EXPECT_NEAR(j["roi"]["r"].get<double>(), r, 1e-12);
  int inside = 0, outside = 0;
  for (const auto& c : j["clusters"]) {
    // Centroids are written to the millimetre: skip the ones on the boundary.
    const double d = std::hypot(c["x"].get<double>() - preset.x, c["y"].get<double>() - preset.y);
    if (std::abs(d - r) < 2e-3) continue;
    EXPECT_EQ(c["in_roi"].get<bool>(), d < r) << "cluster at distance " << d;
    (d < r ? inside : outside)++;
  }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
  const perception::DetectionResult result = detector.Detect(scan, preset);
  int candidates = 0;
  for (const auto& c : j["clusters"]) candidates += c["candidate"].get<bool>() ? 1 : 0;
  EXPECT_EQ(candidates, result.stats.leg_candidates);
}

// The line `shelfdock detect` prints (DetectionResultToJson, with and without --explain):
// "stats" carries the scan's own range noise as "range_noise_m", the detector's value. The
// example scan was simulated with the WLR-716 defaults (10 mm range noise, 1 mm quantisation):
// it must lie within 15 % of 10 mm (measured 9.7 mm). A scan with no valid return has no
// estimate: 0, still written.
TEST(DetectionJson, StatsCarryTheRangeNoise) {
  const geometry::LaserScan scan = ExampleScan();
  const perception::Detector detector(testing::PaperModels());
  const perception::DetectionResult result = detector.Detect(scan);
  for (const bool explain : {false, true}) {
    const nlohmann::json j = DetectionResultToJson(result, explain);
    ASSERT_TRUE(j.contains("stats"));
    ASSERT_TRUE(j["stats"].contains("range_noise_m")) << j["stats"].dump();
    ASSERT_TRUE(j["stats"]["range_noise_m"].is_number());
    EXPECT_DOUBLE_EQ(j["stats"]["range_noise_m"].get<double>(), result.stats.range_noise_m);
  }
  EXPECT_NEAR(result.stats.range_noise_m, 0.010, 0.0015);
  // Written by DetectionStatsToJson itself, as a number.
  perception::DetectionStats stats;
  stats.range_noise_m = 0.0123;
  EXPECT_DOUBLE_EQ(DetectionStatsToJson(stats)["range_noise_m"].get<double>(), 0.0123);
  // So are the depth steps the scan shows and how many of them one mixed return bridges.
  stats.depth_steps = 17;
  stats.bridged_steps = 3;
  EXPECT_EQ(DetectionStatsToJson(stats)["depth_steps"].get<int>(), 17);
  EXPECT_EQ(DetectionStatsToJson(stats)["bridged_steps"].get<int>(), 3);
  // And the lone returns no leg could make, dropped as stray echoes.
  stats.stray_returns = 2;
  EXPECT_EQ(DetectionStatsToJson(stats)["stray_returns"].get<int>(), 2);

  geometry::LaserScan empty = scan;
  empty.ranges.assign(empty.ranges.size(), std::numeric_limits<double>::quiet_NaN());
  const nlohmann::json none = DetectionResultToJson(detector.Detect(empty), false);
  ASSERT_TRUE(none["stats"].contains("range_noise_m"));
  EXPECT_EQ(none["stats"]["range_noise_m"].get<double>(), 0.0);
}

// `detect --explain`'s hypothesis: its fitted legs and, leg by leg, whether the scan showed that
// leg only blended with what stands behind it (placed at the completed corner's range).
TEST(DetectionJson, AHypothesisSaysWhichLegsWereSeenOnlyBlended) {
  perception::HypothesisRecord h;
  h.model = "t1-rect-1250x1250";
  h.legs = {Eigen::Vector2d(2.8, 0.6), Eigen::Vector2d(2.9, -0.6), Eigen::Vector2d(4.1, -0.7),
            Eigen::Vector2d(4.1, 0.5)};
  h.legs_blended = {false, false, true, true};
  const nlohmann::json j = HypothesisToJson(h);
  ASSERT_TRUE(j.contains("legs_blended")) << j.dump();
  ASSERT_EQ(j["legs_blended"].size(), j["legs"].size());
  EXPECT_EQ(j["legs_blended"], nlohmann::json::parse("[false, false, true, true]"));
  EXPECT_EQ(j["legs"][2][0].get<double>(), 4.1);
}

// ... and, leg by leg, whether the completion took it off something flush beside it and how many
// of its outer returns its fit weighed as possible blends; and the bloom its widths were granted.
TEST(DetectionJson, AHypothesisSaysWhichLegsWereFlushAndWhichEdgesMayBeBlends) {
  perception::HypothesisRecord h;
  h.legs = {Eigen::Vector2d(2.8, 0.6), Eigen::Vector2d(2.9, -0.6), Eigen::Vector2d(4.1, -0.7)};
  h.legs_blended = {false, false, false};
  h.legs_flush = {false, true, false};
  h.legs_edge_blends = {0, 1, 2};
  h.width_bloom_rad = 0.004;
  const nlohmann::json j = HypothesisToJson(h);
  EXPECT_EQ(j["legs_flush"], nlohmann::json::parse("[false, true, false]")) << j.dump();
  EXPECT_EQ(j["legs_edge_blends"], nlohmann::json::parse("[0, 1, 2]")) << j.dump();
  EXPECT_EQ(j["width_bloom_rad"].get<double>(), 0.004);
}

// `detect --explain` also lists the leg candidates: each one's search centre, returns, first and
// last beam, extent, and whether the completion cut it (blended, flush); none without explain.
TEST(DetectionJson, ExplainListsTheLegCandidates) {
  perception::DetectionResult result;
  perception::CandidateRecord c;
  c.centre = Eigen::Vector2d(3.25, -0.5);
  c.returns = 3;
  c.first_beam = 398;
  c.last_beam = 400;
  c.extent_m = 0.04;
  c.completed = true;
  c.flush = true;
  result.candidates.push_back(c);
  const nlohmann::json j = DetectionResultToJson(result, true);
  ASSERT_TRUE(j.contains("candidates")) << j.dump();
  ASSERT_EQ(j["candidates"].size(), 1u);
  const nlohmann::json& k = j["candidates"][0];
  EXPECT_EQ(k["x"].get<double>(), 3.25);
  EXPECT_EQ(k["y"].get<double>(), -0.5);
  EXPECT_EQ(k["returns"].get<int>(), 3);
  EXPECT_EQ(k["beams"], nlohmann::json::parse("[398, 400]"));
  EXPECT_EQ(k["extent"].get<double>(), 0.04);
  EXPECT_TRUE(k["completed"].get<bool>());
  EXPECT_FALSE(k["blended"].get<bool>());
  EXPECT_TRUE(k["flush"].get<bool>());
  EXPECT_FALSE(DetectionResultToJson(result, false).contains("candidates"));
}

// stats.rejected has one count per rejection verdict, under the verdict's own name (the name
// `detect --explain` gives each hypothesis), so a user can match the two.
TEST(DetectionJson, EachRejectionCountStandsUnderItsVerdictsName) {
  perception::DetectionStats stats;
  perception::RejectionCounts& r = stats.rejected;
  const std::vector<std::pair<perception::Verdict, int*>> counts = {
      {perception::Verdict::kFit, &r.fit},
      {perception::Verdict::kModel, &r.model},
      {perception::Verdict::kThreeLegError, &r.three_leg_error},
      {perception::Verdict::kHiddenLegNoPreset, &r.hidden_leg_no_preset},
      {perception::Verdict::kLegSeenThrough, &r.leg_seen_through},
      {perception::Verdict::kBlendedLegs, &r.blended_legs},
      {perception::Verdict::kLowConfidence, &r.low_confidence},
      {perception::Verdict::kLostLegs, &r.lost_legs},
      {perception::Verdict::kOffPreset, &r.off_preset}};
  for (std::size_t i = 0; i < counts.size(); ++i) *counts[i].second = static_cast<int>(i) + 1;
  const nlohmann::json rejected = DetectionStatsToJson(stats)["rejected"];
  EXPECT_EQ(rejected.size(), counts.size()) << rejected.dump();
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const char* name = perception::VerdictName(counts[i].first);
    ASSERT_TRUE(rejected.contains(name)) << name;
    EXPECT_EQ(rejected[name].get<int>(), static_cast<int>(i) + 1) << name;
  }
}

// Each detection carries the robust fit's pose beside the refined one, as the `fit` object, with
// the values of Detection::T_lidar_shelf_fit (which the detector always sets).
TEST(DetectionJson, DetectionsCarryTheFitsPose) {
  const perception::Detector detector(testing::PaperModels());
  const perception::DetectionResult result = detector.Detect(ExampleScan());
  ASSERT_FALSE(result.detections.empty());
  const perception::Detection& d = result.detections.front();
  const nlohmann::json j = DetectionToJson(d);
  ASSERT_TRUE(d.T_lidar_shelf_fit.has_value());
  ASSERT_TRUE(j.contains("fit")) << j.dump();
  EXPECT_DOUBLE_EQ(j["fit"]["x"].get<double>(), d.T_lidar_shelf_fit->x);
  EXPECT_DOUBLE_EQ(j["fit"]["y"].get<double>(), d.T_lidar_shelf_fit->y);
  EXPECT_DOUBLE_EQ(j["fit"]["yaw"].get<double>(), d.T_lidar_shelf_fit->yaw);
}

// The runner-up model is written only when there is one, with its chi-square margin.
TEST(DetectionJson, RunnerUpOnlyWhenAnotherModelFitted) {
  perception::Detection d;
  d.model = "t1-rect-1080x856";
  EXPECT_FALSE(DetectionToJson(d).contains("runner_up"));
  d.runner_up = perception::RunnerUp{"t1-rect-1075x883", 2.5};
  const nlohmann::json j = DetectionToJson(d);
  ASSERT_TRUE(j.contains("runner_up")) << j.dump();
  EXPECT_EQ(j["runner_up"]["model"].get<std::string>(), "t1-rect-1075x883");
  EXPECT_DOUBLE_EQ(j["runner_up"]["chi2_margin"].get<double>(), 2.5);
}

}  // namespace
}  // namespace shelfdock::io
