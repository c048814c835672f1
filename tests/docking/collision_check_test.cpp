#include "docking/collision_check.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "docking/path_planner.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

TEST(CollisionCheck, FootprintDistanceIsTheBoxSignedDistance) {
  SafetyConfig s;
  s.robot_length_m = 0.6;
  s.robot_width_m = 0.4;
  EXPECT_NEAR(FootprintDistance({0.5, 0.0}, s), 0.2, 1e-12);                   // ahead of the front
  EXPECT_NEAR(FootprintDistance({0.0, -0.5}, s), 0.3, 1e-12);                  // beside
  EXPECT_NEAR(FootprintDistance({0.4, 0.3}, s), std::hypot(0.1, 0.1), 1e-12);  // corner
  EXPECT_NEAR(FootprintDistance({0.0, 0.0}, s), -0.2, 1e-12);                  // inside
}

TEST(CollisionCheck, CentredDockClearsLegsByTheGeometricGap) {
  const SafetyConfig s;
  const geometry::ShelfModel shelf = shelfdock::testing::PaperShelf2();
  const Pose2 T_map_shelf(2.0, 1.0, 0.4);
  const PlanResult plan =
      PlanDockingPath(T_map_shelf * Pose2(-4.0, 0.0, 0.0), T_map_shelf, PlannerConfig{});
  ASSERT_TRUE(plan.ok);
  const ClearanceResult c = CheckPathAgainstLegs(plan.path, LegDiscs(shelf, T_map_shelf), s);
  // Driving straight in along the long side: the side gap is W/2 - half width - leg radius.
  const double leg_r = 0.5 * std::hypot(0.04, 0.04);
  const double gap = 0.5 * shelf.width_m - 0.5 * s.robot_width_m - leg_r;
  EXPECT_NEAR(c.min_clearance_m, gap, 1e-6);
  EXPECT_EQ(c.ok, gap >= s.leg_margin_m);
}

TEST(CollisionCheck, OffsetGoalIsRefused) {
  const SafetyConfig s;
  const geometry::ShelfModel shelf = shelfdock::testing::PaperShelf2();
  const Pose2 T_map_shelf;
  const Pose2 goal(0.0, 0.15, 0.0);  // 15 cm to the side of the centre
  const PlanResult plan = PlanDockingPath(Pose2(-4.0, 0.15, 0.0), goal, PlannerConfig{});
  const ClearanceResult c = CheckPathAgainstLegs(plan.path, LegDiscs(shelf, T_map_shelf), s);
  EXPECT_FALSE(c.ok);
  EXPECT_LT(c.min_clearance_m, s.leg_margin_m);
}

TEST(CollisionCheck, ObstaclePointsBlockButShelfLegPointsDoNot) {
  const SafetyConfig s;
  const PlanResult plan = PlanDockingPath(Pose2(-3.0, 0.0, 0.0), Pose2(), PlannerConfig{});
  const std::vector<LegDisc> legs{{Eigen::Vector2d(-0.5, 0.44), 0.03}};
  // A point on a leg, and a point beside the path: clear.
  EXPECT_LT(FirstBlockedArcLength(plan.path, 0.0, {{-0.5, 0.45}, {-2.0, 1.0}}, legs, s), 0.0);
  // A person's leg on the path 0.8 m ahead: blocked before reaching it.
  const double s_blocked = FirstBlockedArcLength(plan.path, 0.0, {{-2.2, 0.0}}, legs, s);
  ASSERT_GE(s_blocked, 0.0);
  EXPECT_LT(s_blocked, 0.8);
  // Outside the lookahead: not reported yet.
  EXPECT_LT(FirstBlockedArcLength(plan.path, 0.0, {{-0.3, 0.0}}, legs, s), 0.0);
}

}  // namespace
}  // namespace shelfdock::docking
