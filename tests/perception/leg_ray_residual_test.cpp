// The ray-cast residuals of one beam against a leg section (leg_ray_residual.hpp), against the
// geometry worked out by hand: a beam that hits a face, and one that passes beside the section.
#include "perception/leg_ray_residual.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <gtest/gtest.h>

namespace shelfdock::perception {
namespace {

// A 40 mm square leg 1.6 m straight ahead, its faces square to the beams (yaw 0).
constexpr double kHalf = 0.02;
constexpr double kCentre[2] = {1.6, 0.0};

// The residuals (range, miss) of a return at `range` on the beam at `bearing`, its spot
// `spot_m` wide on each side of the beam at the leg.
std::array<double, 2> Box(double bearing, double range, double yaw = 0.0, double spot_m = 0.0) {
  std::array<double, 2> r{};
  BoxRayResidual(kCentre, std::cos(bearing), std::sin(bearing), range, std::cos(yaw), std::sin(yaw),
                 kHalf, kHalf, r.data(), spot_m);
  return r;
}

// A corner of the leg turned by `yaw`, at (sx, sy) half-sizes from its centre in its own axes
// (sx -1: the front, the side facing the sensor; sy 1: the left).
std::array<double, 2> Corner(double yaw, double sx, double sy) {
  return {kCentre[0] + std::cos(yaw) * sx * kHalf - std::sin(yaw) * sy * kHalf,
          kCentre[1] + std::sin(yaw) * sx * kHalf + std::cos(yaw) * sy * kHalf};
}

// A beam through the front face: the range residual is the measured range less the distance to
// the face along the beam, and it misses by nothing.
TEST(LegRayResidualTest, ABeamThroughTheFrontFaceIsMeasuredAlongIt) {
  const double bearing = 0.005;  // hits the face 8 mm off its middle
  const double face = (kCentre[0] - kHalf) / std::cos(bearing);
  const auto r = Box(bearing, face + 0.003);
  EXPECT_NEAR(r[0], 0.003, 1e-12);
  EXPECT_EQ(r[1], 0.0);
}

// A beam that passes 12 mm beside the leg's side face, nearly parallel to it (the return a wide
// beam spot draws past a leg's edge): it misses by its distance across the beam from the nearest
// corner (the front corner on its side), and its range is measured against that corner's
// distance along the beam. The slab test's gap between the slabs (about 1 m here: the beam
// reaches the side face's plane only 2.6 m out) is no miss distance.
TEST(LegRayResidualTest, ABeamBesideTheSectionMissesItByItsDistanceAcrossTheBeam) {
  const double y = kHalf + 0.012;  // where the beam passes the front face's plane
  const double bearing = std::atan2(y, kCentre[0] - kHalf);
  const double ux = std::cos(bearing), uy = std::sin(bearing);
  // The nearest corner: the front one on the beam's side, (1.58, 0.02).
  const double cx = kCentre[0] - kHalf, cy = kHalf;
  const double across = std::abs(ux * cy - uy * cx);
  const double along = ux * cx + uy * cy;
  EXPECT_NEAR(across, 0.012, 1e-3);  // 12 mm beside the corner, the beam almost along x
  const auto r = Box(bearing, 1.59);
  EXPECT_NEAR(r[1], across, 1e-12);
  EXPECT_NEAR(r[0], 1.59 - along, 1e-12);
}

// Across the silhouette's edge the residuals run on without a jump: a beam just inside the
// corner hits the face at the corner's distance, one just outside misses by next to nothing.
TEST(LegRayResidualTest, TheResidualsAreContinuousAcrossTheSilhouette) {
  for (const double yaw : {0.0, 0.3, -0.7}) {
    SCOPED_TRACE(yaw);
    // The silhouette's edge: the largest bearing of the section's corners.
    double edge = -1.0;
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        const auto p = Corner(yaw, sx, sy);
        edge = std::max(edge, std::atan2(p[1], p[0]));
      }
    }
    const double eps = 1e-7;
    const auto inside = Box(edge - eps, 1.6, yaw);
    const auto outside = Box(edge + eps, 1.6, yaw);
    EXPECT_EQ(inside[1], 0.0);
    EXPECT_GT(outside[1], 0.0);
    EXPECT_LT(outside[1], 1e-6);
    EXPECT_NEAR(inside[0], outside[0], 1e-4);
  }
}

// The leg turned by 0.1 rad, so that its left side face shows at grazing incidence and the back
// left corner, not the front one, is the silhouette's edge on that side (its bearing is the
// larger). A beam 5 mm past that edge misses the leg by 5 mm across it either way. Without a
// spot its range is measured against the back corner, a leg's depth behind the face that a
// beam's spot meets first; with a spot 15 mm wide on each side (a 9 mrad beam at 3.3 m), which
// reaches the front left corner, against that corner; with one too narrow to reach it, against
// the back corner still.
TEST(LegRayResidualTest, ABeamPastTheEdgeIsMeasuredAtTheNearestCornerItsSpotReaches) {
  const double yaw = 0.1;
  const auto front = Corner(yaw, -1.0, 1.0);
  const auto back = Corner(yaw, 1.0, 1.0);
  ASSERT_GT(std::atan2(back[1], back[0]), std::atan2(front[1], front[0]));
  const double bearing = std::atan2(back[1], back[0]) + 0.005 / std::hypot(back[0], back[1]);
  const double ux = std::cos(bearing), uy = std::sin(bearing);
  auto along = [&](const std::array<double, 2>& p) { return ux * p[0] + uy * p[1]; };
  auto across = [&](const std::array<double, 2>& p) { return std::abs(ux * p[1] - uy * p[0]); };
  EXPECT_NEAR(across(back), 0.005, 1e-4);
  ASSERT_GT(across(front), across(back));
  ASSERT_LT(across(front), 0.015);
  const double range = along(front) + 0.002;
  const auto plain = Box(bearing, range, yaw);
  const auto wide = Box(bearing, range, yaw, 0.015);
  const auto narrow = Box(bearing, range, yaw, 0.5 * (across(back) + across(front)) - 0.001);
  EXPECT_NEAR(plain[1], across(back), 1e-12);
  EXPECT_EQ(wide[1], plain[1]);
  EXPECT_NEAR(plain[0], range - along(back), 1e-12);
  EXPECT_NEAR(wide[0], 0.002, 1e-12);
  EXPECT_NEAR(narrow[0], plain[0], 1e-12);
  EXPECT_LT(plain[0], -0.03);  // a leg's depth, less the 2 mm beyond the front corner
}

// A round 26 mm leg 2 m out, a beam passing 4 mm beyond its tangent: it misses by 4 mm. Without
// a spot its range is measured at the tangent point, level with the centre along the beam; with
// a spot 10 mm wide on each side, at the circle's nearest point within it, 17 - 10 = 7 mm across
// the beam from the centre (r = 13 mm: sqrt(13^2 - 7^2) = 11.0 mm in front of the centre); with a
// spot wider than the miss plus the radius, at the circle's front (13 mm in front of it).
TEST(LegRayResidualTest, ABeamPastARoundLegIsMeasuredAtTheNearestPointItsSpotReaches) {
  const double c[2] = {2.0, 0.0};
  const double radius = 0.013;
  const double bearing = std::asin((radius + 0.004) / 2.0);
  const double ux = std::cos(bearing), uy = std::sin(bearing);
  const double b = ux * c[0] + uy * c[1];
  auto residual = [&](double spot_m) {
    std::array<double, 2> r{};
    CircleRayResidual(c, ux, uy, 2.0, radius, r.data(), spot_m);
    return r;
  };
  const auto plain = residual(0.0);
  const auto wide = residual(0.010);
  const auto widest = residual(0.05);
  EXPECT_NEAR(plain[1], 0.004, 1e-9);
  EXPECT_EQ(wide[1], plain[1]);
  EXPECT_NEAR(plain[0], 2.0 - b, 1e-12);
  EXPECT_NEAR(wide[0], 2.0 - (b - std::sqrt(radius * radius - 0.007 * 0.007)), 1e-9);
  EXPECT_NEAR(widest[0], 2.0 - (b - radius), 1e-9);
}

}  // namespace
}  // namespace shelfdock::perception
