// eval::SpreadOf: max-min and sample standard deviation per axis, yaw folded by the shelf's
// symmetry so that a heading flip or a wrap at +-pi is not a fluctuation.
#include "eval/pose_spread.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace shelfdock::eval {
namespace {

TEST(PoseSpreadTest, RangeAndStddevPerAxis) {
  const std::vector<geometry::Pose2> poses = {{1.0, 2.0, 0.1}, {1.2, 2.0, 0.2}, {1.1, 2.3, 0.3}};
  const PoseSpread s = SpreadOf(poses, std::numbers::pi);
  EXPECT_EQ(s.samples, 3);
  EXPECT_NEAR(s.x.range, 0.2, 1e-12);
  EXPECT_NEAR(s.y.range, 0.3, 1e-12);
  EXPECT_NEAR(s.yaw.range, 0.2, 1e-12);
  // x: 1.0, 1.2, 1.1 -> mean 1.1, squared deviations 0.01 + 0.01 + 0 over n - 1 = 2.
  EXPECT_NEAR(s.x.stddev, std::sqrt(0.02 / 2.0), 1e-12);
  EXPECT_NEAR(s.y.stddev, std::sqrt((0.01 + 0.01 + 0.04) / 2.0), 1e-12);
}

TEST(PoseSpreadTest, HeadingWrapAndFlipAreNotFluctuation) {
  const double pi = std::numbers::pi;
  // Either side of +-pi, and the same shelf seen with its heading flipped by pi.
  const std::vector<geometry::Pose2> poses = {
      {0.0, 0.0, pi - 0.01}, {0.0, 0.0, -pi + 0.01}, {0.0, 0.0, 0.0 - 0.01}};
  const PoseSpread s = SpreadOf(poses, pi);
  EXPECT_NEAR(s.yaw.range, 0.02, 1e-9);
  // A square shelf is the same every pi/2.
  const PoseSpread sq = SpreadOf({{0.0, 0.0, 0.0}, {0.0, 0.0, 0.5 * pi + 0.003}}, 0.5 * pi);
  EXPECT_NEAR(sq.yaw.range, 0.003, 1e-9);
}

TEST(PoseSpreadTest, FewerThanTwoPosesHaveNoSpread) {
  EXPECT_TRUE(std::isnan(SpreadOf({}, std::numbers::pi).x.range));
  const PoseSpread one = SpreadOf({{1.0, 1.0, 0.0}}, std::numbers::pi);
  EXPECT_EQ(one.samples, 1);
  EXPECT_TRUE(std::isnan(one.yaw.stddev));
}

}  // namespace
}  // namespace shelfdock::eval
