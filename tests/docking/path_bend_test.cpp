#include "docking/path_bend.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "docking/path_planner.hpp"
#include "docking/path_tracker.hpp"
#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

// A docking path as the planner makes it: from 3 m out, 0.1 m to the side, onto the goal.
Path DockingPath() {
  const PlanResult plan = PlanDockingPath(Pose2(-3.0, 0.1, 0.0), Pose2(), PlannerConfig{});
  EXPECT_TRUE(plan.ok) << plan.reason;
  return plan.path;
}

TEST(PathBend, EndsOnTheNewGoalAndLeavesThePathBehindTheRobotAsItWas) {
  const Path path = DockingPath();
  const Pose2 goal(0.004, -0.006, 0.008);  // a new detection moved the goal
  const double s_from = 1.5;
  const auto bent = BendPathToGoal(path, s_from, goal);
  ASSERT_TRUE(bent);
  ASSERT_EQ(bent->points.size(), path.points.size());
  EXPECT_LT(geometry::Distance(bent->Goal(), goal), 1e-12);
  EXPECT_NEAR(geometry::AngleDiff(bent->Goal().yaw, goal.yaw), 0.0, 1e-12);
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    if (path.points[i].s > s_from) break;
    EXPECT_LT(geometry::Distance(bent->points[i].pose, path.points[i].pose), 1e-12) << i;
  }
  // Just ahead of the robot the path has not turned (the bend starts with zero slope), and it
  // arrives along the new goal's heading (the bend ends with zero slope: over the last 1 cm of
  // this 2 m bend the slope times the 1 cm move is below 0.2 mrad).
  const PathProjection at_robot = bent->Project(path.points[151].pose);
  EXPECT_LT(std::abs(at_robot.cross_track_m), 1e-6);
  EXPECT_LT(std::abs(at_robot.heading_error_rad), 1e-4);
  for (const PathPoint& p : bent->points) {
    if (p.s < bent->Length() - 0.01) continue;
    const Pose2 in_goal = goal.inverse() * p.pose;
    EXPECT_NEAR(in_goal.y, 0.0, 2e-5) << p.s;
    EXPECT_NEAR(in_goal.yaw, 0.0, 2e-4) << p.s;
  }
}

TEST(PathBend, ASmallMoveCloseToTheGoalBendsGently) {
  // 2 mm sideways and 2 mrad with 0.3 m to go: a lateral shift d over a span L has a curvature
  // of at most 6 d / L^2 (the smoothstep's), the turn adds about 1.5 * yaw / L: 0.13 + 0.01 1/m.
  const Path path = DockingPath();
  const double span = 0.3;
  const auto bent = BendPathToGoal(path, path.Length() - span, Pose2(0.0, 0.002, 0.002));
  ASSERT_TRUE(bent);
  const double k_max = bent->MaxAbsCurvature(path.Length() - span);
  EXPECT_LT(k_max, 6.0 * 0.002 / (span * span) + 1.5 * 0.002 / span + 0.02);
  EXPECT_GT(k_max, 0.05);  // it did bend
}

TEST(PathBend, TheTrackerFollowsTheBentPathOntoTheNewGoal) {
  // A kinematic unicycle under the path tracker: the goal moves 5 mm / 5 mrad when 0.4 m are
  // left; it stops within 1 mm and 1 mrad of the new goal.
  Path path = DockingPath();
  ControllerConfig controller;
  PathTracker tracker(controller);
  tracker.SetPath(path, 0.4, 0.0, 0.0);
  Pose2 robot(-3.0, 0.1, 0.0);
  const Pose2 new_goal(0.005, 0.005, 0.005);
  bool moved = false;
  const double dt = 0.02;
  for (int step = 0; step < 3000; ++step) {
    const TrackingStatus st = tracker.Update(robot, dt);
    ASSERT_FALSE(st.lost);
    if (st.reached) break;
    if (!moved && st.remaining_m < 0.4) {
      const auto bent = BendPathToGoal(tracker.path(), tracker.path().Project(robot).s, new_goal);
      ASSERT_TRUE(bent);
      tracker.SetPath(*bent, 0.4, 0.0, st.command.v_mps);
      moved = true;
      continue;
    }
    robot = robot * Pose2(st.command.v_mps * dt, 0.0, st.command.w_radps * dt);
  }
  ASSERT_TRUE(moved);
  const Pose2 err = new_goal.inverse() * robot;
  EXPECT_NEAR(err.x, 0.0, 0.001);
  EXPECT_NEAR(err.y, 0.0, 0.001);
  EXPECT_NEAR(err.yaw, 0.0, 0.001);
}

}  // namespace
}  // namespace shelfdock::docking
