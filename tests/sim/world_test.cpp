#include "sim/world.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"

namespace shelfdock::sim {
namespace {

TEST(WorldTest, LegFootprintsAreTheModelsLegCentresInTheWorld) {
  World world;
  const geometry::Pose2 T_world_shelf(2.0, -1.0, 0.3);
  world.AddShelf(7, shelfdock::testing::PaperShelf2(), T_world_shelf);
  const auto legs = world.LegFootprints(7);
  ASSERT_EQ(legs.size(), 4u);
  const auto centres = shelfdock::testing::PaperShelf2().LegCentres();
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d expected = T_world_shelf * centres[i];
    EXPECT_NEAR((legs[i].T_world_leg.translation() - expected).norm(), 0.0, 1e-12);
    EXPECT_NEAR(legs[i].T_world_leg.yaw, 0.3, 1e-12);
    // Every corner is half the leg's diagonal from its centre.
    for (const auto& c : legs[i].Corners()) {
      EXPECT_NEAR((c - expected).norm(), std::hypot(0.02, 0.02), 1e-12);
    }
  }
  // Rectangle legs become 4 segments each; the static grid holds them all.
  EXPECT_EQ(world.static_grid().primitives().size(), 16u);
  EXPECT_TRUE(world.LegFootprints(8).empty());
}

// A shelf as built: leg 1 stands 8 mm and -5 mm off its design place in the shelf's frame and
// turned by 0.1 rad, the others where the model puts them; the ray-castable outline moves with it.
// A call naming an unknown shelf among others changes none of them.
TEST(WorldTest, LegsAsBuiltMoveAndTurnEachLeg) {
  World world;
  const geometry::Pose2 T_world_shelf(2.0, -1.0, 0.3);
  world.AddShelf(7, shelfdock::testing::PaperShelf2(), T_world_shelf);
  const auto design = world.LegFootprints(7);
  const auto before = world.static_grid().primitives();
  std::vector<geometry::Pose2> built(4);
  built[1] = geometry::Pose2(0.008, -0.005, 0.1);
  EXPECT_FALSE(world.SetLegsAsBuilt({{7, built}, {8, built}}));
  EXPECT_EQ(world.LegFootprints(7)[1].T_world_leg.yaw, design[1].T_world_leg.yaw);
  ASSERT_TRUE(world.SetLegsAsBuilt({{7, built}}));
  const auto legs = world.LegFootprints(7);
  ASSERT_EQ(legs.size(), 4u);
  const auto centres = shelfdock::testing::PaperShelf2().LegCentres();
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d offset =
        i == 1 ? Eigen::Vector2d(0.008, -0.005) : Eigen::Vector2d::Zero();
    const Eigen::Vector2d expected = T_world_shelf * Eigen::Vector2d(centres[i] + offset);
    EXPECT_NEAR((legs[i].T_world_leg.translation() - expected).norm(), 0.0, 1e-12);
    EXPECT_NEAR(legs[i].T_world_leg.yaw, i == 1 ? 0.4 : 0.3, 1e-12);
  }
  // The grid holds the moved outline: leg 1's four segments changed, the others' did not.
  const auto after = world.static_grid().primitives();
  ASSERT_EQ(after.size(), before.size());
  int moved = 0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    if ((after[k].a - before[k].a).norm() > 1e-6) ++moved;
  }
  EXPECT_EQ(moved, 4);
  EXPECT_NEAR((legs[0].T_world_leg.translation() - design[0].T_world_leg.translation()).norm(), 0.0,
              1e-12);
}

TEST(WorldTest, MovingAndRemovingShelves) {
  World world;
  world.AddShelf(1, shelfdock::testing::PaperShelf2(), geometry::Pose2());
  ASSERT_TRUE(world.SetShelfPose(1, geometry::Pose2(5.0, 0.0, 0.0)));
  EXPECT_NEAR(world.Shelf(1)->T_world_shelf.x, 5.0, 1e-12);
  EXPECT_FALSE(world.SetShelfPose(2, geometry::Pose2()));
  ASSERT_TRUE(world.RemoveShelf(1));
  EXPECT_TRUE(world.static_grid().primitives().empty());
}

TEST(WorldTest, PersonWalksBackAndForthAtSpeed) {
  Person p;
  p.path.waypoints = {{0.0, 0.0}, {4.0, 0.0}};
  p.path.speed_mps = 1.0;
  EXPECT_NEAR(p.path.PoseAt(1.5).x, 1.5, 1e-12);
  EXPECT_NEAR(p.path.PoseAt(1.5).yaw, 0.0, 1e-12);
  // After 5 s it has turned at x = 4 and walked 1 m back, facing -x.
  EXPECT_NEAR(p.path.PoseAt(5.0).x, 3.0, 1e-12);
  EXPECT_NEAR(std::abs(p.path.PoseAt(5.0).yaw), std::numbers::pi, 1e-12);
  // The legs straddle the path, leg_spacing apart across it, and swing within the stride.
  const auto legs = p.LegCentresAt(1.5);
  EXPECT_NEAR(std::abs(legs[0].y() - legs[1].y()), p.leg_spacing_m, 1e-12);
  EXPECT_LE(std::abs(legs[0].x() - 1.5), 0.5 * p.stride_m + 1e-12);
  EXPECT_NEAR(legs[0].x() - 1.5, -(legs[1].x() - 1.5), 1e-12);
}

TEST(WorldTest, ClosedPathLoops) {
  PathMotion m;
  m.waypoints = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  m.closed = true;
  m.speed_mps = 0.5;
  EXPECT_NEAR(m.Length(), 4.0, 1e-12);
  const auto p = m.PoseAt(9.0);  // 4.5 m: half a metre into the loop again
  EXPECT_NEAR(p.x, 0.5, 1e-12);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
}

TEST(WorldTest, ObstaclesAtTimeIncludeMovingOnes) {
  World world;
  world.AddRoundPost(Eigen::Vector2d(1.0, 1.0), 0.1);
  Person person;
  person.path.waypoints = {{0.0, 0.0}, {10.0, 0.0}};
  world.AddPerson(person);
  MovingRobot robot;
  robot.path.waypoints = {{0.0, 5.0}, {10.0, 5.0}};
  world.AddRobot(robot);
  const auto obstacles = world.ObstaclesAt(2.0);
  ASSERT_EQ(obstacles.size(), 1u + 2u + 4u);  // post, two legs, robot box
  EXPECT_EQ(obstacles[1].kind, ObjectKind::kPerson);
  EXPECT_EQ(obstacles[3].kind, ObjectKind::kRobot);
  EXPECT_NEAR(0.5 * (obstacles[1].a.x() + obstacles[2].a.x()), 2.0, 1e-12);
}

}  // namespace
}  // namespace shelfdock::sim
