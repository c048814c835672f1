// eval::HarshLidar: the harsh sensor switches on and sets each flaw; scans of the same
// world show them against the nominal sensor (more dropouts, the tilted plane meets the floor).
#include "eval/harsh_lidar.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "../common/paper_models.hpp"
#include "sim/lidar.hpp"
#include "sim/world.hpp"

namespace shelfdock::eval {
namespace {

TEST(HarshLidarTest, SetsEveryFlaw) {
  sim::LidarConfig nominal = sim::IdealLidarConfig();
  const sim::LidarConfig harsh = HarshLidar(nominal);
  EXPECT_TRUE(harsh.enable_range_noise && harsh.enable_footprint && harsh.enable_dropouts &&
              harsh.enable_tilt);
  EXPECT_DOUBLE_EQ(harsh.range_noise_sigma_m, 0.020);
  EXPECT_NEAR(harsh.tilt_pitch_rad, M_PI / 180.0, 1e-15);
  EXPECT_GT(harsh.beam_divergence_rad, sim::LidarConfig{}.beam_divergence_rad);
  EXPECT_GT(harsh.dropout_probability, sim::LidarConfig{}.dropout_probability);
  EXPECT_FALSE(sim::FindConfigViolation(harsh).has_value());
  // Geometry is the nominal sensor's.
  EXPECT_EQ(harsh.num_beams, nominal.num_beams);
}

// Walls within reach of every beam: beams without a return are dropouts.
TEST(HarshLidarTest, DropsMoreBeams) {
  sim::World world;
  world.AddWall({{-4.0, -4.0}, {4.0, -4.0}, {4.0, 4.0}, {-4.0, 4.0}}, true);
  world.AddShelf(1, testing::PaperShelf2(), geometry::Pose2(1.5, 0.0, 0.0));
  const sim::LidarConfig nominal;
  const sim::LidarConfig harsh = HarshLidar(nominal);
  int nominal_missing = 0, harsh_missing = 0, beams = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    for (double r : sim::Lidar(nominal, seed).Scan(world, geometry::Pose2()).ranges) {
      nominal_missing += !std::isfinite(r);
      ++beams;
    }
    for (double r : sim::Lidar(harsh, seed).Scan(world, geometry::Pose2()).ranges) {
      harsh_missing += !std::isfinite(r);
    }
  }
  // At least the any-beam dropout rate more (2 % against 0.2 %), less a margin for chance.
  EXPECT_GT(harsh_missing - nominal_missing,
            0.5 * (harsh.dropout_probability - nominal.dropout_probability) * beams);
}

// A room too large for the tilted plane: straight ahead it meets the floor at h / tan(1 deg)
// (11.46 m) before the walls 30 m away.
TEST(HarshLidarTest, TiltedPlaneMeetsTheFloor) {
  sim::World world;
  world.AddWall({{-30.0, -30.0}, {30.0, -30.0}, {30.0, 30.0}, {-30.0, 30.0}}, true);
  const sim::LidarConfig harsh = HarshLidar(sim::LidarConfig{});
  const double floor_range = harsh.mount_height_m / std::tan(harsh.tilt_pitch_rad);
  const auto scan = sim::Lidar(harsh, 3).Scan(world, geometry::Pose2());
  int ahead = 0, on_floor = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    // Within 0.1 rad of straight ahead the depression is 1 deg * cos(angle): within 0.5 %.
    if (std::abs(scan.BeamAngle(i)) > 0.1) continue;
    ++ahead;
    const double r = scan.ranges[i];
    on_floor += std::isfinite(r) && std::abs(r - floor_range) < 0.15;
  }
  EXPECT_GE(on_floor, ahead * 8 / 10) << ahead;
}

}  // namespace
}  // namespace shelfdock::eval
