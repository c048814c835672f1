#include "sim/localisation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::sim {
namespace {

constexpr int kRuns = 300;  // std estimates good to ~4 %: tolerate 15 %

double Std(const std::vector<double>& values) {
  double mean = 0.0;
  for (const double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  double var = 0.0;
  for (const double v : values) var += (v - mean) * (v - mean);
  return std::sqrt(var / static_cast<double>(values.size() - 1));
}

TEST(LocalisationError, BiasHasItsStationaryStdAndWandersSlowly) {
  const LocalisationNoiseConfig config;
  const double lag_s = 2.0;
  std::vector<double> bias_x, bias_yaw, change_x;
  for (int run = 0; run < kRuns; ++run) {
    LocalisationError error(config, 100 + static_cast<uint64_t>(run));
    for (int i = 0; i < 1500; ++i) error.Advance(0.02);  // 30 s
    const geometry::Pose2 before = error.bias();
    for (int i = 0; i < static_cast<int>(lag_s / 0.02 + 0.5); ++i) error.Advance(0.02);
    bias_x.push_back(before.x);
    bias_yaw.push_back(before.yaw);
    change_x.push_back(error.bias().x - before.x);
  }
  EXPECT_NEAR(Std(bias_x), config.bias_std_m, 0.15 * config.bias_std_m);
  EXPECT_NEAR(Std(bias_yaw), config.bias_std_rad, 0.15 * config.bias_std_rad);
  // Ornstein-Uhlenbeck: b(t + d) - b(t) has std s sqrt(2 (1 - exp(-d / tau))), much less than
  // s for d << tau: the estimate is biased, but the bias is nearly constant over a docking.
  const double change_std =
      config.bias_std_m * std::sqrt(2.0 * (1.0 - std::exp(-lag_s / config.bias_time_constant_s)));
  EXPECT_NEAR(Std(change_x), change_std, 0.15 * change_std);
  EXPECT_LT(change_std, 0.5 * config.bias_std_m);
}

TEST(LocalisationError, BiasStaysWithinBoundsOverALongRun) {
  // Ten minutes, 6000 updates: a random walk would leave; the OU bias stays within 5 sigma.
  const LocalisationNoiseConfig config;
  LocalisationError error(config, 7);
  double max_abs_x = 0.0, max_abs_yaw = 0.0;
  for (int i = 0; i < 30000; ++i) {
    error.Advance(0.02);
    max_abs_x = std::max(max_abs_x, std::abs(error.bias().x));
    max_abs_yaw = std::max(max_abs_yaw, std::abs(error.bias().yaw));
  }
  EXPECT_LT(max_abs_x, 5.0 * config.bias_std_m);
  EXPECT_LT(max_abs_yaw, 5.0 * config.bias_std_rad);
  EXPECT_GT(max_abs_x, 1.0 * config.bias_std_m);  // it does wander
}

TEST(LocalisationError, EstimateErrorIsBiasPlusWhiteNoise) {
  const LocalisationNoiseConfig config;
  const geometry::Pose2 truth(5.0, -3.0, 3.1);  // near +-pi: the yaw error must wrap
  std::vector<double> err_y, err_yaw;
  for (int run = 0; run < kRuns; ++run) {
    LocalisationError error(config, 900 + static_cast<uint64_t>(run));
    error.Advance(1.0);
    const geometry::Pose2 estimate = error.Apply(truth);
    err_y.push_back(estimate.y - truth.y);
    err_yaw.push_back(geometry::AngleDiff(estimate.yaw, truth.yaw));
  }
  const double y_std = std::hypot(config.bias_std_m, config.noise_std_m);
  const double yaw_std = std::hypot(config.bias_std_rad, config.noise_std_rad);
  EXPECT_NEAR(Std(err_y), y_std, 0.15 * y_std);
  EXPECT_NEAR(Std(err_yaw), yaw_std, 0.15 * yaw_std);
}

TEST(LocalisationError, HoldsBetweenUpdatesAndIsDeterministic) {
  const LocalisationNoiseConfig config;  // 10 Hz updates
  LocalisationError a(config, 3), b(config, 3);
  const geometry::Pose2 truth(1.0, 2.0, 0.0);
  a.Advance(0.05);  // half an update period: nothing refreshed
  EXPECT_EQ(a.Apply(truth).x, b.Apply(truth).x);
  a.Advance(0.05);
  b.Advance(0.1);
  EXPECT_EQ(a.Apply(truth).x, b.Apply(truth).x);
  EXPECT_EQ(a.Apply(truth).yaw, b.Apply(truth).yaw);
  LocalisationError c(config, 4);
  c.Advance(0.1);
  EXPECT_NE(a.Apply(truth).x, c.Apply(truth).x);
}

}  // namespace
}  // namespace shelfdock::sim
