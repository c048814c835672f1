#include "geometry/pose2.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"
#include "geometry/shelf_model.hpp"

namespace shelfdock::geometry {
namespace {

constexpr double kTol = 1e-12;

TEST(WrapAngle, KeepsHalfOpenInterval) {
  EXPECT_NEAR(WrapAngle(0.0), 0.0, kTol);
  EXPECT_NEAR(WrapAngle(std::numbers::pi), -std::numbers::pi, kTol);
  EXPECT_NEAR(WrapAngle(-std::numbers::pi), -std::numbers::pi, kTol);
  EXPECT_NEAR(WrapAngle(3.0 * std::numbers::pi / 2.0), -std::numbers::pi / 2.0, kTol);
  EXPECT_NEAR(WrapAngle(-7.0), -7.0 + 2.0 * std::numbers::pi, kTol);
  EXPECT_NEAR(AngleDiff(3.1, -3.1), 6.2 - 2.0 * std::numbers::pi, kTol);
}

TEST(Pose2, ComposeThenInverseIsIdentity) {
  const Pose2 T_a_b(1.0, -2.0, 0.7);
  const Pose2 T_b_c(-0.3, 0.5, 2.9);
  const Pose2 T_a_c = T_a_b * T_b_c;
  const Pose2 back = T_a_b.inverse() * T_a_c;
  EXPECT_NEAR(back.x, T_b_c.x, kTol);
  EXPECT_NEAR(back.y, T_b_c.y, kTol);
  EXPECT_NEAR(AngleDiff(back.yaw, T_b_c.yaw), 0.0, kTol);
  EXPECT_GE(T_a_c.yaw, -std::numbers::pi);
  EXPECT_LT(T_a_c.yaw, std::numbers::pi);
}

TEST(Pose2, TransformsPointsLikeRotationThenTranslation) {
  const Pose2 T(2.0, 1.0, std::numbers::pi / 2.0);
  const Eigen::Vector2d p = T * Eigen::Vector2d(1.0, 0.0);
  EXPECT_NEAR(p.x(), 2.0, kTol);
  EXPECT_NEAR(p.y(), 2.0, kTol);
  const Eigen::Vector2d q = T.inverse() * p;
  EXPECT_NEAR(q.x(), 1.0, kTol);
  EXPECT_NEAR(q.y(), 0.0, kTol);
}

TEST(ShelfModel, LegCentresSpanLengthAndWidth) {
  ShelfModel m;
  m.length_m = 1.075;
  m.width_m = 0.883;
  const auto legs = m.LegCentres();
  EXPECT_NEAR((legs[1] - legs[0]).norm(), m.length_m, kTol);
  EXPECT_NEAR((legs[3] - legs[0]).norm(), m.width_m, kTol);
  EXPECT_NEAR((legs[2] - legs[0]).norm(), std::hypot(1.075, 0.883), kTol);
  EXPECT_NEAR(m.Diagonal(), std::hypot(1.075, 0.883), kTol);
}

}  // namespace
}  // namespace shelfdock::geometry
