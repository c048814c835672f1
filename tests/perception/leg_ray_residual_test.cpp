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

// The residuals (range, miss) of a return at `range` on the beam at `bearing`.
std::array<double, 2> Box(double bearing, double range, double yaw = 0.0) {
  std::array<double, 2> r{};
  BoxRayResidual(kCentre, std::cos(bearing), std::sin(bearing), range, std::cos(yaw), std::sin(yaw),
                 kHalf, kHalf, r.data());
  return r;
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
        const double px = kCentre[0] + std::cos(yaw) * sx * kHalf - std::sin(yaw) * sy * kHalf;
        const double py = kCentre[1] + std::sin(yaw) * sx * kHalf + std::cos(yaw) * sy * kHalf;
        edge = std::max(edge, std::atan2(py, px));
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

}  // namespace
}  // namespace shelfdock::perception
