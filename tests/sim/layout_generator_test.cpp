// The warehouse layout generator: deterministic for a seed, and each class builds what it says
// (gaps, standoffs, presets, an occluded leg really hidden, a person really beside a leg).
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "geometry/angle.hpp"
#include "sim/layout_generator.hpp"
#include "sim/layout_rows.hpp"
#include "sim/line_of_sight.hpp"

namespace shelfdock::sim {
namespace {

using shelfdock::testing::PaperModels;
constexpr double kEps = 1e-9;

TEST(LayoutGeneratorTest, SameSeedSameSceneAndScan) {
  const auto models = PaperModels();
  for (LayoutClass c : kAllLayoutClasses) {
    const LayoutScene a = GenerateLayoutScene(c, 17, models);
    const LayoutScene b = GenerateLayoutScene(c, 17, models);
    const LayoutScene other = GenerateLayoutScene(c, 18, models);
    SCOPED_TRACE(std::string(LayoutClassName(c)));
    EXPECT_EQ(a.T_world_lidar.x, b.T_world_lidar.x);
    EXPECT_EQ(a.T_world_lidar.yaw, b.T_world_lidar.yaw);
    EXPECT_EQ(a.scan_seed, b.scan_seed);
    EXPECT_EQ(a.world.shelves().size(), b.world.shelves().size());
    EXPECT_EQ(a.world.static_grid().primitives().size(), b.world.static_grid().primitives().size());
    EXPECT_EQ(a.target_legs_in_sight, b.target_legs_in_sight);
    const auto scan_a = SimulateLayoutScan(a);
    const auto scan_b = SimulateLayoutScan(b);
    ASSERT_EQ(scan_a.ranges.size(), scan_b.ranges.size());
    for (std::size_t i = 0; i < scan_a.ranges.size(); ++i) {
      ASSERT_TRUE(scan_a.ranges[i] == scan_b.ranges[i] ||
                  (std::isnan(scan_a.ranges[i]) && std::isnan(scan_b.ranges[i])));
    }
    EXPECT_NE(a.scan_seed, other.scan_seed);
    EXPECT_NE(a.T_world_lidar.yaw, other.T_world_lidar.yaw);
  }
}

// Shelves as built (LayoutConfig::leg_build_error_m, leg_build_twist_rad): every leg of every
// shelf moved within the bounds in the shelf's frame and turned within the twist, the legs
// drawn apart from the scene, so that the sensor, the shelves' poses, the preset and the scan's
// seed are those of the as-designed twin.
TEST(LayoutGeneratorTest, AsBuiltLegsMoveOnlyTheLegs) {
  const auto models = PaperModels();
  LayoutConfig built;
  built.leg_build_error_m = 0.01;
  built.leg_build_twist_rad = 0.05;
  for (LayoutClass c : {LayoutClass::kOpen, LayoutClass::kAisle, LayoutClass::kLargeClose}) {
    SCOPED_TRACE(std::string(LayoutClassName(c)));
    const LayoutScene designed = GenerateLayoutScene(c, 5, models);
    const LayoutScene scene = GenerateLayoutScene(c, 5, models, built);
    EXPECT_EQ(scene.T_world_lidar.x, designed.T_world_lidar.x);
    EXPECT_EQ(scene.T_world_lidar.yaw, designed.T_world_lidar.yaw);
    EXPECT_EQ(scene.scan_seed, designed.scan_seed);
    ASSERT_TRUE(scene.T_world_preset && designed.T_world_preset);
    EXPECT_EQ(scene.T_world_preset->x, designed.T_world_preset->x);
    ASSERT_EQ(scene.world.shelves().size(), designed.world.shelves().size());
    double largest_m = 0.0;
    for (std::size_t k = 0; k < scene.world.shelves().size(); ++k) {
      const ShelfInstance& s = scene.world.shelves()[k];
      const ShelfInstance& d = designed.world.shelves()[k];
      EXPECT_EQ(s.T_world_shelf.x, d.T_world_shelf.x);
      EXPECT_EQ(s.T_world_shelf.yaw, d.T_world_shelf.yaw);
      EXPECT_TRUE(d.legs_as_built.empty());
      ASSERT_EQ(s.legs_as_built.size(), 4u);
      const auto legs = ShelfLegFootprints(s);
      const auto design = ShelfLegFootprints(d);
      for (std::size_t i = 0; i < legs.size(); ++i) {
        // The offset read back in the shelf frame, where the bounds are drawn.
        const Eigen::Vector2d off =
            s.T_world_shelf.rotation().transpose() *
            (legs[i].T_world_leg.translation() - design[i].T_world_leg.translation());
        EXPECT_LE(std::abs(off.x()), built.leg_build_error_m + kEps);
        EXPECT_LE(std::abs(off.y()), built.leg_build_error_m + kEps);
        EXPECT_LE(std::abs(geometry::AngleDiff(legs[i].T_world_leg.yaw, s.T_world_shelf.yaw)),
                  built.leg_build_twist_rad + kEps);
        largest_m = std::max(largest_m, off.norm());
      }
    }
    EXPECT_GT(largest_m, 0.2 * built.leg_build_error_m);  // the legs did move
  }
}

TEST(LayoutGeneratorTest, ClassNamesRoundTrip) {
  for (LayoutClass c : kAllLayoutClasses) EXPECT_EQ(ParseLayoutClass(LayoutClassName(c)), c);
  EXPECT_FALSE(ParseLayoutClass("warehouse").has_value());
}

// Standoff, bearing and preset error within the configured ranges, for every shelf class.
TEST(LayoutGeneratorTest, SensorAndPresetWithinRanges) {
  const auto models = PaperModels();
  const LayoutConfig config;
  for (LayoutClass c : kAllLayoutClasses) {
    if (c == LayoutClass::kClutter) continue;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      const LayoutScene s = GenerateLayoutScene(c, seed, models, config);
      SCOPED_TRACE(std::string(LayoutClassName(c)) + " seed " + std::to_string(seed));
      const auto target = s.Target();
      ASSERT_TRUE(target.has_value());
      ASSERT_TRUE(s.T_world_preset.has_value());
      EXPECT_LE(geometry::Distance(*s.T_world_preset, target->T_world_shelf),
                config.preset_error_xy_m + kEps);
      EXPECT_LE(geometry::AngleDiffModulo(s.T_world_preset->yaw, target->T_world_shelf.yaw,
                                          target->model.HeadingPeriod()),
                config.preset_error_yaw_rad + kEps);
      const Eigen::Vector2d p_lidar =
          s.T_world_lidar.inverse() * target->T_world_shelf.translation();
      if (c == LayoutClass::kLargeClose) {
        EXPECT_EQ(target->model.name, "t1-rect-1250x1250");
        EXPECT_LE(p_lidar.norm(), config.large_close_radius_m + kEps);
        continue;
      }
      EXPECT_GE(s.target_standoff_m, config.min_standoff_m - 1e-3);
      EXPECT_LE(s.target_standoff_m, config.max_standoff_m + 1e-3);
      EXPECT_LE(std::abs(std::atan2(p_lidar.y(), p_lidar.x())), config.max_bearing_rad + kEps);
    }
  }
}

TEST(LayoutGeneratorTest, NoiseRoundLegsAndSensors) {
  const auto models = PaperModels();
  LayoutConfig config;
  NamedLidar coarse;
  coarse.name = "coarse";
  coarse.config.angle_increment_rad = 0.01;
  coarse.config.num_beams = 471;
  config.lidars.push_back(coarse);
  int high = 0, coarse_scenes = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const LayoutScene round = GenerateLayoutScene(LayoutClass::kRoundNoisy, seed, models, config);
    EXPECT_EQ(round.Target()->model.leg.shape, geometry::LegShape::kCircle);
    EXPECT_EQ(round.lidar.range_noise_sigma_m, config.high_noise_sigma_m);
    const LayoutScene row = GenerateLayoutScene(LayoutClass::kRow, seed, models, config);
    high += row.lidar.range_noise_sigma_m == config.high_noise_sigma_m ? 1 : 0;
    coarse_scenes += row.lidar_name == "coarse" ? 1 : 0;
    EXPECT_EQ(row.lidar.num_beams, row.lidar_name == "coarse" ? 471 : 811);
  }
  // A share of the scenes at the high noise, both sensors drawn.
  EXPECT_GT(high, 0);
  EXPECT_LT(high, 60);
  EXPECT_GT(coarse_scenes, 0);
  EXPECT_LT(coarse_scenes, 60);
}

// Neighbouring footprints in every row are row_min_gap_m..row_max_gap_m apart along the row,
// rows hold 3-6 shelves (aisles 4-7), and mixed rows alternate models.
TEST(LayoutGeneratorTest, RowGapsAndCounts) {
  const auto models = PaperModels();
  const LayoutConfig config;
  for (LayoutClass c : {LayoutClass::kRow, LayoutClass::kAisle, LayoutClass::kMixedNeighbours}) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
      const LayoutScene s = GenerateLayoutScene(c, seed, models, config);
      ASSERT_FALSE(s.rows.empty());
      for (const LayoutRow& row : s.rows) {
        const auto n = static_cast<int>(row.shelf_ids.size());
        EXPECT_GE(n, c == LayoutClass::kAisle ? 4 : config.row_min_shelves);
        EXPECT_LE(n, c == LayoutClass::kAisle ? 7 : config.row_max_shelves);
        for (std::size_t i = 1; i < row.shelf_ids.size(); ++i) {
          const ShelfInstance a = *s.world.Shelf(row.shelf_ids[i - 1]);
          const ShelfInstance b = *s.world.Shelf(row.shelf_ids[i]);
          const geometry::Pose2 T_row_a = row.T_world_row.inverse() * a.T_world_shelf;
          const geometry::Pose2 T_row_b = row.T_world_row.inverse() * b.T_world_shelf;
          Eigen::Vector2d lo_a, hi_a, lo_b, hi_b;
          layout::FootprintExtents(a.model, T_row_a.yaw, &lo_a, &hi_a);
          layout::FootprintExtents(b.model, T_row_b.yaw, &lo_b, &hi_b);
          const double gap = (T_row_b.x + lo_b.x()) - (T_row_a.x + hi_a.x());
          EXPECT_GE(gap, config.row_min_gap_m - kEps);
          EXPECT_LE(gap, config.row_max_gap_m + kEps);
          if (c == LayoutClass::kMixedNeighbours) {
            EXPECT_NE(a.model.name, b.model.name);
          }
        }
      }
      if (c == LayoutClass::kAisle) {
        // The opposite row faces back across the aisle; the sensor stands between the rows.
        const double width = s.rows[1].T_world_row.y - s.rows[0].T_world_row.y;
        EXPECT_GE(width, config.aisle_min_width_m);
        EXPECT_LE(width, config.aisle_max_width_m);
        EXPECT_GT(s.T_world_lidar.y, 0.0);
        EXPECT_LT(s.T_world_lidar.y, width);
      }
    }
  }
}

// against_wall: one row (or a lone shelf) with the sensor in front of it and a wall, or a
// rack's front uprights, wall_min_setback_m..wall_max_setback_m behind its back.
TEST(LayoutGeneratorTest, AgainstWallPutsAWallJustBehindTheRow) {
  const auto models = PaperModels();
  const LayoutConfig config;
  int racks = 0;
  int walls = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const LayoutScene s = GenerateLayoutScene(LayoutClass::kAgainstWall, seed, models, config);
    ASSERT_EQ(s.rows.size(), 1u) << "seed " << seed;
    const geometry::Pose2 T_row_world = s.rows[0].T_world_row.inverse();
    double back = std::numeric_limits<double>::infinity();
    for (int id : s.rows[0].shelf_ids) {
      const ShelfInstance shelf = *s.world.Shelf(id);
      const geometry::Pose2 T_row_shelf = T_row_world * shelf.T_world_shelf;
      Eigen::Vector2d lo, hi;
      layout::FootprintExtents(shelf.model, T_row_shelf.yaw, &lo, &hi);
      back = std::min(back, T_row_shelf.y + lo.y());
    }
    auto within = [&](double near_y) {
      const double gap = back - near_y;
      return gap >= config.wall_min_setback_m - kEps && gap <= config.wall_max_setback_m + kEps;
    };
    bool found = false;
    for (const Wall& wall : s.world.walls()) {
      if (wall.closed || wall.points.size() != 2) continue;  // the room
      const Eigen::Vector2d a = T_row_world * wall.points[0];
      const Eigen::Vector2d b = T_row_world * wall.points[1];
      if (std::abs(a.y() - b.y()) < kEps && within(a.y())) {
        found = true;
        ++walls;
      }
    }
    for (const Box& box : s.world.boxes()) {
      const geometry::Pose2 T_row_box = T_row_world * box.T_world_box;
      if (!found && within(T_row_box.y + 0.5 * box.width_m)) {
        found = true;
        ++racks;
      }
    }
    EXPECT_TRUE(found) << "seed " << seed;
    EXPECT_GT((T_row_world * s.T_world_lidar).y, 0.0) << "seed " << seed;
  }
  EXPECT_GT(walls, 0);
  EXPECT_GT(racks, 0);
}

// The occluded leg gets fewer than the in-sight beams, whichever leg it is.
TEST(LayoutGeneratorTest, OccludedLegIsHidden) {
  const auto models = PaperModels();
  const LayoutConfig config;
  std::array<int, 4> legs{};
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    const LayoutScene s = GenerateLayoutScene(LayoutClass::kOccludedLeg, seed, models, config);
    ASSERT_GE(s.occluded_leg, 0);
    ASSERT_LT(s.occluded_leg, 4);
    ++legs[static_cast<std::size_t>(s.occluded_leg)];
    EXPECT_LT(s.target_sight.beams[static_cast<std::size_t>(s.occluded_leg)],
              config.min_beams_in_sight)
        << "seed " << seed;
  }
  for (int n : legs) EXPECT_GT(n, 0);
}

TEST(LayoutGeneratorTest, PersonStandsBesideATargetLeg) {
  const auto models = PaperModels();
  const LayoutConfig config;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const LayoutScene s = GenerateLayoutScene(LayoutClass::kPersonBesideLeg, seed, models, config);
    ASSERT_EQ(s.world.people().size(), 1u);
    const auto person_legs = s.world.people()[0].LegCentresAt(0.0);
    double nearest = 1e9;
    for (const Eigen::Vector2d& c : s.Target()->model.LegCentres()) {
      for (const Eigen::Vector2d& p : person_legs) {
        nearest = std::min(nearest, (s.Target()->T_world_shelf * c - p).norm());
      }
    }
    EXPECT_GE(nearest, config.person_min_distance_m - kEps);
    EXPECT_LE(nearest, config.person_max_distance_m + kEps);
  }
}

TEST(LayoutGeneratorTest, ClutterHasNoShelfButLegLikePosts) {
  const auto models = PaperModels();
  const LayoutConfig config;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const LayoutScene s = GenerateLayoutScene(LayoutClass::kClutter, seed, models, config);
    EXPECT_TRUE(s.world.shelves().empty());
    EXPECT_EQ(s.target_shelf_id, -1);
    int posts = static_cast<int>(s.world.round_posts().size());
    for (const Box& b : s.world.boxes()) {
      posts += b.length_m <= config.clutter_max_post_m && b.width_m <= config.clutter_max_post_m;
    }
    EXPECT_GE(posts, config.clutter_min_posts);
  }
}

// Line of sight: a shelf in the open shows four legs; a wall across two of them leaves two.
TEST(LayoutGeneratorTest, LegsInSightCountsUnhiddenLegs) {
  const auto model = PaperModels()[1];
  World world;
  world.AddShelf(7, model, geometry::Pose2(2.0, 0.0, 0.0));
  const LidarConfig lidar;
  const LegSight open = ComputeLegSight(world, {}, lidar, 7);
  EXPECT_EQ(open.LegsInSight(2), 4);
  EXPECT_EQ(ComputeLegSight(world, {}, lidar, 8).LegsInSight(1), 0);  // no such shelf
  // A wall 1 m ahead covering the left half of the view hides the legs at y > 0.
  world.AddWall({{1.0, 0.05}, {1.0, 3.0}});
  const LegSight half = ComputeLegSight(world, {}, lidar, 7);
  EXPECT_EQ(half.LegsInSight(2), 2);
  EXPECT_EQ(half.beams[2] + half.beams[3], 0);
  // The threshold: a leg hit by one beam is not in sight at two beams.
  LegSight counted;
  counted.beams = {5, 1, 2, 0};
  EXPECT_EQ(counted.LegsInSight(2), 2);
  EXPECT_EQ(counted.LegsInSight(1), 3);
}

}  // namespace
}  // namespace shelfdock::sim
