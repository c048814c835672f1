// Two shelves cannot stand in one place: RectsOverlap against hand-checked configurations.
#include <gtest/gtest.h>

#include <cmath>

#include "perception/footprint_overlap.hpp"

namespace shelfdock::perception {
namespace {

OrientedRect Rect(double x, double y, double yaw, double half_x, double half_y) {
  return {geometry::Pose2{x, y, yaw}, half_x, half_y};
}

TEST(FootprintOverlapTest, AxisAlignedOverlapAndSeparation) {
  const OrientedRect a = Rect(0.0, 0.0, 0.0, 0.5, 0.4);
  EXPECT_TRUE(RectsOverlap(a, Rect(0.9, 0.0, 0.0, 0.5, 0.4)));   // 0.1 m shared
  EXPECT_FALSE(RectsOverlap(a, Rect(1.1, 0.0, 0.0, 0.5, 0.4)));  // 0.1 m gap
  EXPECT_FALSE(RectsOverlap(a, Rect(0.0, 0.85, 0.0, 0.5, 0.4)));
  EXPECT_TRUE(RectsOverlap(a, Rect(0.1, 0.1, 0.0, 0.1, 0.1)));  // one inside the other
  EXPECT_TRUE(RectsOverlap(Rect(0.1, 0.1, 0.0, 0.1, 0.1), a));  // and the other way round
}

TEST(FootprintOverlapTest, TouchingEdgesDoNotCount) {
  // Neighbours in a row whose shrunk rectangles just meet are two shelves, not one place.
  const OrientedRect a = Rect(0.0, 0.0, 0.0, 0.5, 0.4);
  EXPECT_FALSE(RectsOverlap(a, Rect(1.0, 0.0, 0.0, 0.5, 0.4)));
  EXPECT_FALSE(RectsOverlap(a, Rect(0.0, -0.8, 0.0, 0.5, 0.4)));
}

TEST(FootprintOverlapTest, RotatedRectanglesUseTheirOwnAxes) {
  // A square turned by 45 deg with a corner pointing at a along x touches a when its centre is
  // 0.5 + 0.3 * sqrt(2) m away (a's own x axis separates them).
  const OrientedRect a = Rect(0.0, 0.0, 0.0, 0.5, 0.5);
  const double touch = 0.5 + 0.3 * std::sqrt(2.0);
  EXPECT_TRUE(RectsOverlap(a, Rect(touch - 0.01, 0.0, M_PI / 4.0, 0.3, 0.3)));
  EXPECT_FALSE(RectsOverlap(a, Rect(touch + 0.01, 0.0, M_PI / 4.0, 0.3, 0.3)));
  // On the diagonal an edge of the turned square faces a's corner (0.5, 0.5): only the turned
  // square's own axis separates them. Along it a reaches 0.5 * sqrt(2) = 0.707 m and the square
  // 0.3 m from its centre, so centres 0.636 m apart overlap and 1.061 m apart do not, although
  // on a's axes both placements overlap.
  EXPECT_TRUE(RectsOverlap(a, Rect(0.45, 0.45, M_PI / 4.0, 0.3, 0.3)));
  EXPECT_FALSE(RectsOverlap(a, Rect(0.75, 0.75, M_PI / 4.0, 0.3, 0.3)));
}

TEST(FootprintOverlapTest, HeadingsDifferingByPiAreTheSameRectangle) {
  const OrientedRect a = Rect(0.0, 0.0, 0.2, 0.6, 0.3);
  const OrientedRect b = Rect(1.0, 0.3, 0.2, 0.6, 0.3);
  const OrientedRect b_flipped = Rect(1.0, 0.3, 0.2 + M_PI, 0.6, 0.3);
  EXPECT_EQ(RectsOverlap(a, b), RectsOverlap(a, b_flipped));
}

TEST(FootprintOverlapTest, EmptyRectanglesNeverOverlap) {
  // A leg rectangle shrunk by more than its half side has no interior left.
  const OrientedRect a = Rect(0.0, 0.0, 0.0, 0.5, 0.4);
  EXPECT_FALSE(RectsOverlap(a, Rect(0.0, 0.0, 0.0, 0.0, 0.4)));
  EXPECT_FALSE(RectsOverlap(Rect(0.0, 0.0, 0.0, 0.5, -0.1), a));
}

}  // namespace
}  // namespace shelfdock::perception
