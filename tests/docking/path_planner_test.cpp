#include "docking/path_planner.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

TEST(PathPlanner, EndsAtGoalAlignedWithStraightFinalSegment) {
  const PlannerConfig config;
  const Pose2 goal(3.0, 1.0, 0.3);
  for (double dy : {-0.4, -0.1, 0.0, 0.2, 0.5}) {
    for (double dyaw : {-0.2, 0.0, 0.25}) {
      const Pose2 start = goal * Pose2(-4.5, dy, dyaw);
      const PlanResult plan = PlanDockingPath(start, goal, config);
      ASSERT_TRUE(plan.ok) << plan.reason;
      const Path& path = plan.path;
      EXPECT_LT(geometry::Distance(path.points.front().pose, start), 1e-9);
      EXPECT_LT(geometry::Distance(path.Goal(), goal), 1e-9);
      EXPECT_NEAR(geometry::AngleDiff(path.Goal().yaw, goal.yaw), 0.0, 1e-9);
      EXPECT_NEAR(plan.straight_m, config.final_straight_m, 1e-9);
      EXPECT_LE(path.MaxAbsCurvature(), config.max_curvature_1pm);
      // The final straight lies on the goal's axis: zero lateral offset and heading error.
      for (const PathPoint& p : path.points) {
        if (p.s < path.Length() - plan.straight_m + 1e-9) continue;
        const Pose2 local = goal.inverse() * p.pose;
        EXPECT_NEAR(local.y, 0.0, 1e-9);
        EXPECT_NEAR(local.yaw, 0.0, 1e-9);
      }
      // Samples are dense and arc length grows monotonically.
      for (std::size_t i = 1; i < path.points.size(); ++i) {
        const double ds = path.points[i].s - path.points[i - 1].s;
        EXPECT_GT(ds, 0.0);
        EXPECT_LE(ds, 2.0 * config.sample_step_m);
      }
    }
  }
}

TEST(PathPlanner, CurvatureMatchesFiniteDifferenceOfHeading) {
  const PlannerConfig config;
  const Pose2 goal(0.0, 0.0, 0.0);
  const PlanResult plan = PlanDockingPath(Pose2(-3.0, 0.6, -0.2), goal, config);
  ASSERT_TRUE(plan.ok);
  const auto& pts = plan.path.points;
  for (std::size_t i = 1; i + 1 < pts.size(); i += 10) {
    const double ds = pts[i + 1].s - pts[i - 1].s;
    const double k_fd = geometry::AngleDiff(pts[i + 1].pose.yaw, pts[i - 1].pose.yaw) / ds;
    EXPECT_NEAR(pts[i].curvature, k_fd, 0.02 + 0.02 * std::abs(k_fd)) << "at s=" << pts[i].s;
  }
}

TEST(PathPlanner, ShortensStraightWhenCloseAndRefusesImpossibleStarts) {
  PlannerConfig config;
  const Pose2 goal(0.0, 0.0, 0.0);
  // Close in with a small offset: a shorter straight, still within the bound.
  const PlanResult close = PlanDockingPath(Pose2(-0.6, 0.01, 0.0), goal, config);
  ASSERT_TRUE(close.ok) << close.reason;
  EXPECT_LT(close.straight_m, config.final_straight_m);
  EXPECT_GE(close.straight_m, config.min_final_straight_m);
  EXPECT_LE(close.path.MaxAbsCurvature(), config.max_curvature_1pm);
  // Beside the goal: no forward path can enter aligned.
  EXPECT_FALSE(PlanDockingPath(Pose2(-0.2, 1.0, 0.0), goal, config).ok);
  // Past the goal or facing away.
  EXPECT_FALSE(PlanDockingPath(Pose2(0.5, 0.0, 0.0), goal, config).ok);
  EXPECT_FALSE(PlanDockingPath(Pose2(-3.0, 0.0, 3.0), goal, config).ok);
}

}  // namespace
}  // namespace shelfdock::docking
