#include "sim/odometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"
#include "sim/diff_drive_robot.hpp"

namespace shelfdock::sim {
namespace {

constexpr double kWheelBase = 0.5;
constexpr int kRuns = 300;  // std estimates good to ~1/sqrt(2 * 300) = 4 %: tolerate 15 %

struct Stats {
  double mean = 0.0;
  double std = 0.0;
};

Stats Summarise(const std::vector<double>& values) {
  Stats s;
  for (const double v : values) s.mean += v;
  s.mean /= static_cast<double>(values.size());
  for (const double v : values) s.std += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(s.std / static_cast<double>(values.size() - 1));
  return s;
}

/// End poses of kRuns seeded runs driving `length_m` straight ahead in `step_m` increments.
std::vector<geometry::Pose2> StraightRuns(const OdometryNoiseConfig& config, double length_m) {
  constexpr double kStep = 0.02;
  const int steps = static_cast<int>(std::lround(length_m / kStep));
  std::vector<geometry::Pose2> ends;
  for (int run = 0; run < kRuns; ++run) {
    WheelOdometry odometry(config, kWheelBase, 1000 + static_cast<uint64_t>(run));
    for (int i = 0; i < steps; ++i) odometry.Update(kStep, 0.0);
    ends.push_back(odometry.T_odom_base());
  }
  return ends;
}

TEST(WheelOdometry, WithoutNoiseFollowsTheTrueMotion) {
  DiffDriveConfig config;
  config.odometry = OdometryNoiseConfig{0.0, 0.0, 0.0};
  const geometry::Pose2 start(3.0, -2.0, 1.0);
  DiffDriveRobot robot(config, start, 9);
  for (int i = 0; i < 600; ++i) robot.Step(0.6, 1.2 * std::sin(0.01 * i), 0.02);
  // The odom frame starts at the identity: odometry reports the motion since the start.
  const geometry::Pose2 moved = start.inverse() * robot.T_world_base();
  EXPECT_NEAR(robot.T_odom_base().x, moved.x, 1e-9);
  EXPECT_NEAR(robot.T_odom_base().y, moved.y, 1e-9);
  EXPECT_NEAR(geometry::AngleDiff(robot.T_odom_base().yaw, moved.yaw), 0.0, 1e-9);
}

TEST(WheelOdometry, SlipDriftMatchesItsRandomWalk) {
  // Slip only: each wheel's distance error is N(0, s^2 L). Along-track error is their mean,
  // std s sqrt(L / 2); heading error their difference over the track, std s sqrt(2 L) / b;
  // the lateral error integrates that heading random walk, variance 2 s^2 L^3 / (3 b^2).
  const OdometryNoiseConfig config{0.0, 0.0, 0.003};
  const double length = 10.0;
  const double s = config.slip_std_m_per_sqrt_m;
  std::vector<double> along, lateral, heading;
  for (const geometry::Pose2& end : StraightRuns(config, length)) {
    along.push_back(end.x - length);
    lateral.push_back(end.y);
    heading.push_back(end.yaw);
  }
  const Stats a = Summarise(along), l = Summarise(lateral), h = Summarise(heading);
  const double along_std = s * std::sqrt(length / 2.0);
  const double heading_std = s * std::sqrt(2.0 * length) / kWheelBase;
  const double lateral_std = s * std::sqrt(2.0 * std::pow(length, 3) / 3.0) / kWheelBase;
  EXPECT_NEAR(a.std, along_std, 0.15 * along_std);
  EXPECT_NEAR(h.std, heading_std, 0.15 * heading_std);
  EXPECT_NEAR(l.std, lateral_std, 0.15 * lateral_std);
  // Means within 4 standard errors of their expectation. Along track the wandering heading
  // shortens the forward progress by E[theta(s)^2] / 2 = s^2 s' / b^2 per metre s', a bias of
  // -s^2 L^2 / (2 b^2); the others are unbiased.
  const double along_bias = -s * s * length * length / (2.0 * kWheelBase * kWheelBase);
  EXPECT_NEAR(a.mean, along_bias, 4.0 * along_std / std::sqrt(kRuns));
  EXPECT_NEAR(h.mean, 0.0, 4.0 * heading_std / std::sqrt(kRuns));
  EXPECT_NEAR(l.mean, 0.0, 4.0 * lateral_std / std::sqrt(kRuns));
}

TEST(WheelOdometry, ScaleErrorDriftGrowsWithDistance) {
  // Wheel scale errors e_l, e_r ~ N(0, e^2), fixed per run: the odometry drives an arc. Its
  // length error (e_l + e_r) L / 2 has std e L / sqrt(2) and shows in the distance from the
  // start (the chord, shorter than the arc by theta^2 / 24, negligible here); heading error
  // (e_r - e_l) L / b, std sqrt(2) e L / b; lateral error (e_r - e_l) L^2 / (2 b), std
  // e L^2 / (sqrt(2) b).
  const OdometryNoiseConfig config{0.002, 0.0, 0.0};
  const double length = 10.0;
  const double e = config.wheel_scale_std;
  std::vector<double> along, lateral, heading;
  for (const geometry::Pose2& end : StraightRuns(config, length)) {
    along.push_back(std::hypot(end.x, end.y) - length);
    lateral.push_back(end.y);
    heading.push_back(end.yaw);
  }
  const double along_std = e * length / std::sqrt(2.0);
  const double heading_std = std::sqrt(2.0) * e * length / kWheelBase;
  const double lateral_std = e * length * length / (std::sqrt(2.0) * kWheelBase);
  // Heading errors are small here (< 0.2 rad), so the lateral small-angle formula holds to ~1 %.
  EXPECT_NEAR(Summarise(along).std, along_std, 0.15 * along_std);
  EXPECT_NEAR(Summarise(heading).std, heading_std, 0.15 * heading_std);
  EXPECT_NEAR(Summarise(lateral).std, lateral_std, 0.15 * lateral_std);
}

TEST(WheelOdometry, TrackWidthErrorMakesTurnsDrift) {
  // Turning in place by 2 pi with a believed track b (1 + k): the heading reads 2 pi / (1 + k),
  // an error of about -2 pi k, std 2 pi k_std. Straight driving is unaffected.
  const OdometryNoiseConfig config{0.0, 0.005, 0.0};
  std::vector<double> heading_error;
  for (int run = 0; run < kRuns; ++run) {
    WheelOdometry odometry(config, kWheelBase, 5000 + static_cast<uint64_t>(run));
    const int steps = 200;
    double unwrapped = 0.0;
    for (int i = 0; i < steps; ++i) {
      const double before = odometry.T_odom_base().yaw;
      odometry.Update(0.0, 2.0 * std::numbers::pi / steps);
      unwrapped += geometry::AngleDiff(odometry.T_odom_base().yaw, before);
    }
    heading_error.push_back(unwrapped - 2.0 * std::numbers::pi);
  }
  const double expected_std = 2.0 * std::numbers::pi * config.wheel_base_scale_std;
  EXPECT_NEAR(Summarise(heading_error).std, expected_std, 0.15 * expected_std);

  WheelOdometry straight(config, kWheelBase, 77);
  for (int i = 0; i < 100; ++i) straight.Update(0.05, 0.0);
  EXPECT_NEAR(straight.T_odom_base().x, 5.0, 1e-9);
  EXPECT_NEAR(straight.T_odom_base().y, 0.0, 1e-9);
}

TEST(WheelOdometry, DefaultNoiseCombinesScaleAndSlip) {
  // Scale errors and slip are independent: the variances of the two tests above add up. Over
  // the paper's 4.5 m docking run this is the drift that re-detection has to correct.
  const OdometryNoiseConfig config;
  const double length = 4.5;
  const double e = config.wheel_scale_std, s = config.slip_std_m_per_sqrt_m;
  const double heading_var = 2.0 * e * e * length * length / (kWheelBase * kWheelBase) +
                             2.0 * s * s * length / (kWheelBase * kWheelBase);
  const double lateral_var = e * e * std::pow(length, 4) / (2.0 * kWheelBase * kWheelBase) +
                             2.0 * s * s * std::pow(length, 3) / (3.0 * kWheelBase * kWheelBase);
  std::vector<double> lateral, heading;
  for (const geometry::Pose2& end : StraightRuns(config, length)) {
    lateral.push_back(end.y);
    heading.push_back(end.yaw);
  }
  EXPECT_NEAR(Summarise(heading).std, std::sqrt(heading_var), 0.15 * std::sqrt(heading_var));
  EXPECT_NEAR(Summarise(lateral).std, std::sqrt(lateral_var), 0.15 * std::sqrt(lateral_var));
}

}  // namespace
}  // namespace shelfdock::sim
