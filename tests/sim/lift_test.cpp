#include "sim/lift.hpp"

#include <gtest/gtest.h>

#include "sim/diff_drive_robot.hpp"

namespace shelfdock::sim {
namespace {

TEST(Lift, TakesItsDuration) {
  DiffDriveConfig config;
  config.lift_duration_s = 2.0;
  DiffDriveRobot robot(config, geometry::Pose2(), 1);
  constexpr double kDt = 0.02;
  for (int i = 0; i < 50; ++i) robot.Step(0.0, 0.0, kDt);
  EXPECT_FALSE(robot.LiftDone());
  EXPECT_EQ(robot.LiftProgress(), 0.0);

  robot.StartLift();  // at t = 1 s
  const int steps = static_cast<int>(config.lift_duration_s / kDt + 0.5);
  for (int i = 0; i < steps - 1; ++i) {
    robot.Step(0.0, 0.0, kDt);
    if (i == steps / 2 - 1) {
      EXPECT_NEAR(robot.LiftProgress(), 0.5, 1e-9);
    }
    robot.StartLift();  // restarting while lifting changes nothing
    EXPECT_FALSE(robot.LiftDone()) << "step " << i;
  }
  robot.Step(0.0, 0.0, kDt);
  EXPECT_TRUE(robot.LiftDone());
  EXPECT_EQ(robot.LiftProgress(), 1.0);
}

TEST(Lift, ZeroDurationIsDoneAtOnce) {
  Lift lift(0.0);
  EXPECT_FALSE(lift.Done(5.0));
  lift.Start(5.0);
  EXPECT_TRUE(lift.Done(5.0));
}

}  // namespace
}  // namespace shelfdock::sim
