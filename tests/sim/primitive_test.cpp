#include "sim/primitive.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace shelfdock::sim {
namespace {

Ray2 MakeRay(double ox, double oy, double yaw) {
  Ray2 r;
  r.origin = Eigen::Vector2d(ox, oy);
  r.dir = Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
  return r;
}

TEST(PrimitiveTest, RayHitsCircleAtCentreDistanceMinusRadius) {
  const auto circle = Primitive::Circle(Eigen::Vector2d(3.0, 0.0), 0.5);
  EXPECT_NEAR(IntersectRay(MakeRay(0, 0, 0), circle), 2.5, 1e-12);
}

TEST(PrimitiveTest, OffAxisRayHitsCircleAtChordPoint) {
  // Ray along y = 0.3 towards a unit circle at (4, 0): hit at x = 4 - sqrt(1 - 0.09).
  const auto circle = Primitive::Circle(Eigen::Vector2d(4.0, 0.0), 1.0);
  const double expected = 4.0 - std::sqrt(1.0 - 0.3 * 0.3);
  EXPECT_NEAR(IntersectRay(MakeRay(0, 0.3, 0), circle), expected, 1e-12);
}

TEST(PrimitiveTest, RayMissesCircleJustOutsideTangent) {
  const auto circle = Primitive::Circle(Eigen::Vector2d(4.0, 0.0), 1.0);
  EXPECT_TRUE(std::isinf(IntersectRay(MakeRay(0, 1.0 + 1e-9, 0), circle)));
  // Exactly tangent: one touching point at x = 4.
  EXPECT_NEAR(IntersectRay(MakeRay(0, 1.0, 0), circle), 4.0, 1e-6);
}

TEST(PrimitiveTest, CircleBehindRayIsMissed) {
  const auto circle = Primitive::Circle(Eigen::Vector2d(-3.0, 0.0), 0.5);
  EXPECT_TRUE(std::isinf(IntersectRay(MakeRay(0, 0, 0), circle)));
}

TEST(PrimitiveTest, RayFromInsideCircleSeesFarWall) {
  const auto circle = Primitive::Circle(Eigen::Vector2d(0.0, 0.0), 2.0);
  EXPECT_NEAR(IntersectRay(MakeRay(0.5, 0, 0), circle), 1.5, 1e-12);
}

TEST(PrimitiveTest, SegmentHitAtObliqueAngle) {
  // Vertical segment x = 2, y in [-1, 1]; ray at 20 deg hits at y = 2 tan 20, distance 2/cos 20.
  const auto seg = Primitive::Segment(Eigen::Vector2d(2, -1), Eigen::Vector2d(2, 1));
  const double yaw = M_PI / 9.0;
  EXPECT_NEAR(IntersectRay(MakeRay(0, 0, yaw), seg), 2.0 / std::cos(yaw), 1e-12);
}

TEST(PrimitiveTest, SegmentMissedPastItsEndAndWhenParallel) {
  const auto seg = Primitive::Segment(Eigen::Vector2d(2, -1), Eigen::Vector2d(2, 1));
  EXPECT_TRUE(std::isinf(IntersectRay(MakeRay(0, 0, std::atan2(1.01, 2.0)), seg)));
  // A grazing ray along the segment's own line does not see a surface.
  EXPECT_TRUE(std::isinf(IntersectRay(MakeRay(2, -3, M_PI / 2), seg)));
}

TEST(PrimitiveTest, SurfaceNormalFacesTheViewer) {
  const auto seg = Primitive::Segment(Eigen::Vector2d(2, -1), Eigen::Vector2d(2, 1));
  const Eigen::Vector2d n = SurfaceNormal(seg, Eigen::Vector2d(2, 0), Eigen::Vector2d(0, 0));
  EXPECT_NEAR(n.x(), -1.0, 1e-12);
  EXPECT_NEAR(n.y(), 0.0, 1e-12);
}

}  // namespace
}  // namespace shelfdock::sim
