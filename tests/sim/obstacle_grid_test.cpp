#include "sim/obstacle_grid.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace shelfdock::sim {
namespace {

/// A random clutter of circles and segments over a 30 m x 20 m area.
std::vector<Primitive> RandomClutter(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> x(-15.0, 15.0), y(-10.0, 10.0), len(-1.5, 1.5),
      rad(0.01, 0.4);
  std::vector<Primitive> prims;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2d a(x(rng), y(rng));
    if (i % 2 == 0) {
      prims.push_back(Primitive::Circle(a, rad(rng)));
    } else {
      prims.push_back(Primitive::Segment(a, a + Eigen::Vector2d(len(rng), len(rng))));
    }
  }
  return prims;
}

TEST(ObstacleGridTest, GridCastEqualsBruteForceOnRandomRays) {
  std::mt19937_64 rng(7);
  const auto prims = RandomClutter(rng, 300);
  const ObstacleGrid grid(prims, 0.5);
  std::uniform_real_distribution<double> x(-20.0, 20.0), y(-14.0, 14.0), yaw(-M_PI, M_PI),
      reach(1.0, 40.0);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    CastQuery q;
    q.ray.origin = Eigen::Vector2d(x(rng), y(rng));
    const double a = yaw(rng);
    q.ray.dir = Eigen::Vector2d(std::cos(a), std::sin(a));
    q.max_t_m = reach(rng);
    const RayHit brute = CastAll(q, prims);
    const RayHit fast = grid.Cast(q);
    ASSERT_EQ(brute.primitive == nullptr, fast.primitive == nullptr) << "ray " << i;
    if (brute.primitive != nullptr) {
      ++hits;
      EXPECT_NEAR(fast.t_m, brute.t_m, 1e-12) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 100);  // the comparison covered many hits, not just misses
}

TEST(ObstacleGridTest, AxisAlignedRaysAlongCellEdges) {
  // Rays exactly along grid lines (dir with a zero component) must still find the wall.
  std::vector<Primitive> prims{Primitive::Segment({5.0, -2.0}, {5.0, 2.0}),
                               Primitive::Segment({-2.0, 4.0}, {2.0, 4.0})};
  const ObstacleGrid grid(prims, 0.5);
  CastQuery q;
  q.ray.origin = Eigen::Vector2d(0.0, 0.0);
  q.ray.dir = Eigen::Vector2d(1.0, 0.0);
  EXPECT_NEAR(grid.Cast(q).t_m, 5.0, 1e-12);
  q.ray.dir = Eigen::Vector2d(0.0, 1.0);
  EXPECT_NEAR(grid.Cast(q).t_m, 4.0, 1e-12);
  q.ray.dir = Eigen::Vector2d(-1.0, 0.0);
  EXPECT_EQ(grid.Cast(q).primitive, nullptr);
}

TEST(ObstacleGridTest, BeamPassesOverLowPrimitives) {
  Primitive low = Primitive::Segment({3.0, -1.0}, {3.0, 1.0});
  low.height_m = 0.1;
  const ObstacleGrid grid({low}, 0.5);
  CastQuery q;
  q.z0_m = 0.2;  // beam above the 0.1 m box
  EXPECT_EQ(grid.Cast(q).primitive, nullptr);
  q.dz_dt = -0.05;  // sinking 5 cm per metre: 0.05 m high at x = 3
  EXPECT_NEAR(grid.Cast(q).t_m, 3.0, 1e-12);
}

}  // namespace
}  // namespace shelfdock::sim
