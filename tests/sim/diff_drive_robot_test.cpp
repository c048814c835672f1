#include "sim/diff_drive_robot.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::sim {
namespace {

constexpr double kDt = 0.02;  // 50 Hz, the default control rate

/// Limits so loose that every command is reached within one step: isolates the integration.
DiffDriveConfig Unlimited() {
  DiffDriveConfig c;
  c.max_v_mps = 100.0;
  c.max_w_radps = 100.0;
  c.max_accel_mps2 = 1e9;
  c.max_alpha_radps2 = 1e9;
  return c;
}

TEST(DiffDriveRobot, VelocityCommandsAreClampedToTheLimits) {
  const DiffDriveConfig config;
  DiffDriveRobot robot(config, geometry::Pose2(), 1);
  for (int i = 0; i < 500; ++i) robot.Step(5.0, -10.0, kDt);
  EXPECT_DOUBLE_EQ(robot.v(), config.max_v_mps);
  EXPECT_DOUBLE_EQ(robot.w(), -config.max_w_radps);
  for (int i = 0; i < 500; ++i) robot.Step(-5.0, 10.0, kDt);
  EXPECT_DOUBLE_EQ(robot.v(), -config.max_v_mps);
  EXPECT_DOUBLE_EQ(robot.w(), config.max_w_radps);
}

TEST(DiffDriveRobot, AccelerationIsLimitedEveryStep) {
  const DiffDriveConfig config;
  DiffDriveRobot robot(config, geometry::Pose2(), 2);
  double v_prev = 0.0;
  double w_prev = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double v_cmd = (i / 50) % 2 == 0 ? 1.0 : -1.0;  // a square wave: hard reversals
    const double w_cmd = (i / 25) % 2 == 0 ? 1.5 : -1.5;
    robot.Step(v_cmd, w_cmd, kDt);
    EXPECT_LE(std::abs(robot.v() - v_prev), config.max_accel_mps2 * kDt + 1e-12) << i;
    EXPECT_LE(std::abs(robot.w() - w_prev), config.max_alpha_radps2 * kDt + 1e-12) << i;
    v_prev = robot.v();
    w_prev = robot.w();
  }
  // From rest, full speed takes max_v / max_accel seconds: after 1 s we are at 0.5 m/s.
  DiffDriveRobot fresh(config, geometry::Pose2(), 3);
  for (int i = 0; i < 50; ++i) fresh.Step(1.0, 0.0, kDt);
  EXPECT_NEAR(fresh.v(), config.max_accel_mps2 * 50 * kDt, 1e-12);
}

TEST(DiffDriveRobot, IntegratesArcsExactly) {
  // v = 0.5 m/s, w = 0.5 rad/s: a circle of radius 1 m around (x0, y0 + 1), counter-clockwise.
  const double v = 0.5, w = 0.5, radius = v / w;
  const geometry::Pose2 start(2.0, -1.0, 0.0);
  DiffDriveRobot robot(Unlimited(), start, 4);
  const int quarter_steps = static_cast<int>(std::lround(0.5 * std::numbers::pi / w / 0.01));
  for (int i = 0; i < quarter_steps; ++i) robot.Step(v, w, 0.01);
  const double t = quarter_steps * 0.01;
  const double theta = w * t;
  EXPECT_NEAR(robot.T_world_base().x, start.x + radius * std::sin(theta), 1e-9);
  EXPECT_NEAR(robot.T_world_base().y, start.y + radius * (1.0 - std::cos(theta)), 1e-9);
  EXPECT_NEAR(geometry::AngleDiff(robot.T_world_base().yaw, theta), 0.0, 1e-9);

  // Exactness means the step size does not matter: one big step lands on the same pose.
  const geometry::Pose2 one_step = IntegrateArc(start, v, w, t);
  EXPECT_NEAR(one_step.x, robot.T_world_base().x, 1e-9);
  EXPECT_NEAR(one_step.y, robot.T_world_base().y, 1e-9);
}

TEST(DiffDriveRobot, StraightLineAndTurnInPlace) {
  DiffDriveRobot robot(Unlimited(), geometry::Pose2(0.0, 0.0, std::numbers::pi / 2), 5);
  for (int i = 0; i < 100; ++i) robot.Step(0.4, 0.0, kDt);  // 2 s at 0.4 m/s along +y
  EXPECT_NEAR(robot.T_world_base().x, 0.0, 1e-12);
  EXPECT_NEAR(robot.T_world_base().y, 0.8, 1e-12);
  EXPECT_NEAR(robot.distance_travelled_m(), 0.8, 1e-12);
  for (int i = 0; i < 100; ++i) robot.Step(0.0, 1.0, kDt);  // turn 2 rad in place
  EXPECT_NEAR(robot.T_world_base().y, 0.8, 1e-12);
  EXPECT_NEAR(geometry::AngleDiff(robot.T_world_base().yaw, std::numbers::pi / 2 + 2.0), 0.0,
              1e-12);
}

TEST(DiffDriveRobot, PoseHistoryMatchesAFinerSimulation) {
  // The same commands at half the step: its poses at the in-between instants are what
  // T_world_base_at must report (motion during a LiDAR scan).
  DiffDriveRobot coarse(Unlimited(), geometry::Pose2(1.0, 2.0, 0.3), 6);
  DiffDriveRobot fine(Unlimited(), geometry::Pose2(1.0, 2.0, 0.3), 6);
  for (int i = 0; i < 40; ++i) {
    const double v = 0.3 + 0.01 * i, w = 0.8 * std::sin(0.2 * i);
    coarse.Step(v, w, kDt);
    fine.Step(v, w, 0.5 * kDt);
    const double t_mid = fine.time_s();
    fine.Step(v, w, 0.5 * kDt);
    const geometry::Pose2 mid_fine = fine.T_world_base_at(t_mid);  // exercise lookups too
    if (i >= 10) {
      const geometry::Pose2 mid = coarse.T_world_base_at(t_mid);
      EXPECT_NEAR(mid.x, mid_fine.x, 1e-9) << i;
      EXPECT_NEAR(mid.y, mid_fine.y, 1e-9) << i;
      EXPECT_NEAR(geometry::AngleDiff(mid.yaw, mid_fine.yaw), 0.0, 1e-9) << i;
    }
  }
  // Now: the current pose. Before the start (0.8 s < history_s, all kept): the start pose.
  EXPECT_NEAR(coarse.T_world_base_at(coarse.time_s()).x, coarse.T_world_base().x, 1e-12);
  EXPECT_EQ(coarse.T_world_base_at(-10.0).x, 1.0);
  EXPECT_EQ(coarse.T_world_base_at(-10.0).y, 2.0);
  // Later than now: extrapolated at the current velocity.
  const geometry::Pose2 ahead = coarse.T_world_base_at(coarse.time_s() + 0.1);
  const geometry::Pose2 expected = IntegrateArc(coarse.T_world_base(), coarse.v(), coarse.w(), 0.1);
  EXPECT_NEAR(ahead.x, expected.x, 1e-12);
  EXPECT_NEAR(ahead.y, expected.y, 1e-12);
}

TEST(DiffDriveRobot, HistoryKeepsAtLeastHistorySeconds) {
  DiffDriveConfig config = Unlimited();
  DiffDriveRobot robot(config, geometry::Pose2(), 8);
  const double v = 0.5;
  for (int i = 0; i < 500; ++i) robot.Step(v, 0.0, kDt);  // 10 s along +x
  // Within the history the straight line is exact; before it, the answer is clamped to a pose
  // at most one step older than history_s.
  const double t = robot.time_s() - config.history_s;
  EXPECT_NEAR(robot.T_world_base_at(t).x, v * t, 1e-9);
  const double clamped_x = robot.T_world_base_at(0.0).x;
  EXPECT_LE(clamped_x, v * t + 1e-9);
  EXPECT_GE(clamped_x, v * (t - kDt) - 1e-9);
}

TEST(DiffDriveRobot, DefaultFootprintFitsBetweenTheLegsOfShelfTwo) {
  // Shelf 2 of the paper's Table 1: 1.075 x 0.883 m leg centre to leg centre, 0.04 m legs.
  const double inner_width_m = 0.883 - 0.04;
  const double inner_length_m = 1.075 - 0.04;
  const DiffDriveConfig config;
  EXPECT_LT(config.footprint_width_m, inner_width_m);
  EXPECT_LT(config.footprint_length_m, inner_length_m);

  DiffDriveRobot robot(config, geometry::Pose2(1.0, 1.0, std::numbers::pi / 2), 7);
  const auto corners = robot.FootprintCorners();
  // Facing +y, the front-left corner is at (x - width/2, y + length/2).
  EXPECT_NEAR(corners[0].x(), 1.0 - 0.5 * config.footprint_width_m, 1e-12);
  EXPECT_NEAR(corners[0].y(), 1.0 + 0.5 * config.footprint_length_m, 1e-12);
  EXPECT_NEAR((corners[0] - corners[2]).norm(),
              std::hypot(config.footprint_length_m, config.footprint_width_m), 1e-12);
}

TEST(DiffDriveRobot, SameSeedSameSensors) {
  DiffDriveRobot a(DiffDriveConfig{}, geometry::Pose2(), 42);
  DiffDriveRobot b(DiffDriveConfig{}, geometry::Pose2(), 42);
  DiffDriveRobot c(DiffDriveConfig{}, geometry::Pose2(), 43);
  for (int i = 0; i < 300; ++i) {
    a.Step(0.5, 0.2, kDt);
    b.Step(0.5, 0.2, kDt);
    c.Step(0.5, 0.2, kDt);
  }
  EXPECT_EQ(a.T_odom_base().x, b.T_odom_base().x);
  EXPECT_EQ(a.T_map_base_estimate().y, b.T_map_base_estimate().y);
  EXPECT_NE(a.T_odom_base().x, c.T_odom_base().x);
  EXPECT_EQ(a.T_world_base().x, c.T_world_base().x);  // noise never moves the true robot
}

}  // namespace
}  // namespace shelfdock::sim
