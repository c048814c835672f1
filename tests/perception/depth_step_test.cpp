// StrongestDepthStep (src/perception/depth_step.cpp): where a cluster is cut when something
// touches a leg. Exact synthetic ranges (no noise), so the expected index is known exactly.
#include "perception/depth_step.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = testing::kWlrAlpha;

ScanPoint At(int beam, double range) { return testing::BeamPoint(beam, range); }

ClusterSpan Span(std::size_t begin, std::size_t end) {
  ClusterSpan s;
  s.begin = begin;
  s.end = end;
  return s;
}

// A span of 8 points at 2.00 m whose last 4 stand 5 cm deeper: the step is between the 4th and
// the 5th point of the span. The span starts at index 3 of the vector (three points of another
// cluster before it, with a larger step into the span that must not count): the index returned
// is into `points`, 3 + 4 = 7.
TEST(DepthStepTest, ClearStepGivesItsIndex) {
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 3; ++b) pts.push_back(At(b, 1.0));  // another cluster, 1 m step to 2 m
  for (int b = 3; b < 7; ++b) pts.push_back(At(b, 2.00));
  for (int b = 7; b < 11; ++b) pts.push_back(At(b, 2.05));
  const auto k = StrongestDepthStep(pts, Span(3, 11), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 7u);
  // A step toward the sensor counts the same (|r[k] - r[k-1]|).
  for (std::size_t i = 7; i < 11; ++i) pts[i] = At(pts[i].beam, 1.95);
  const auto k_near = StrongestDepthStep(pts, Span(3, 11), 0.03);
  ASSERT_TRUE(k_near.has_value());
  EXPECT_EQ(*k_near, 7u);
  // The 5 cm step is below a 6 cm threshold: none.
  EXPECT_FALSE(StrongestDepthStep(pts, Span(3, 11), 0.06).has_value());
}

// A smooth surface: the range grows by 1 mm per beam over 20 beams (19 mm in all, far more
// than one step but never 3 cm at once): no step for min step 3 cm. One point or none: nothing
// to compare.
TEST(DepthStepTest, SmoothRampGivesNone) {
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 20; ++b) pts.push_back(At(b, 2.0 + 0.001 * b));
  EXPECT_FALSE(StrongestDepthStep(pts, Span(0, 20), 0.03).has_value());
  // The same ramp does have 1 mm steps: with a 0.5 mm threshold one is found (the first of the
  // equal ones or another; any index in (begin, end)).
  const auto tiny = StrongestDepthStep(pts, Span(0, 20), 0.0005);
  ASSERT_TRUE(tiny.has_value());
  EXPECT_GT(*tiny, 0u);
  EXPECT_LT(*tiny, 20u);
  EXPECT_FALSE(StrongestDepthStep(pts, Span(5, 6), 0.03).has_value());
  EXPECT_FALSE(StrongestDepthStep(pts, Span(5, 5), 0.03).has_value());
}

// Two steps above the threshold, 4 cm then 9 cm (and in the other order, and with the larger
// one toward the sensor): the larger is chosen. The step is measured between consecutive
// points, not against the span's first range: a 1 mm/beam ramp before it does not add up.
TEST(DepthStepTest, LargestOfTwoStepsIsChosen) {
  // Points 0-3 at 2.00, 4-7 at 2.04 (4 cm step at 4), 8-11 at 2.13 (9 cm step at 8).
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 12; ++b) pts.push_back(At(b, b < 4 ? 2.00 : b < 8 ? 2.04 : 2.13));
  auto k = StrongestDepthStep(pts, Span(0, 12), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 8u);
  // 9 cm first (at 4), then 4 cm (at 8).
  for (int b = 0; b < 12; ++b) pts[b] = At(b, b < 4 ? 2.00 : b < 8 ? 2.09 : 2.13);
  k = StrongestDepthStep(pts, Span(0, 12), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 4u);
  // 4 cm deeper at 4, then 9 cm nearer at 8 (a person's leg in front of the wall behind).
  for (int b = 0; b < 12; ++b) pts[b] = At(b, b < 4 ? 2.00 : b < 8 ? 2.04 : 1.95);
  k = StrongestDepthStep(pts, Span(0, 12), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 8u);
  // Inside the span [0, 8) only the 4 cm step lies: the 9 cm one beyond its end is not seen.
  k = StrongestDepthStep(pts, Span(0, 8), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 4u);
  // A ramp of 1 mm per beam, then a 3.5 cm step: 3.5 cm is found, the ramp's total (10 mm
  // over the span, more than each single step) is not a step.
  pts.clear();
  for (int b = 0; b < 10; ++b) pts.push_back(At(b, 2.0 + 0.001 * b));
  for (int b = 10; b < 14; ++b) pts.push_back(At(b, 2.044 + 0.001 * (b - 10)));
  k = StrongestDepthStep(pts, Span(0, 14), 0.03);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(*k, 10u);
}

// A leg 4 cm in front of a wall at 2 m, closer than the break distance: beams 0-2 on the leg
// (2.00 m), 3-19 on the wall (2.06 m). The leg is the front end piece, ending at index 3; no
// back piece (the wall's last points step nowhere). Mirrored, it is the back piece from 17.
TEST(DepthStepTest, LegInFrontOfAWallIsAnEndPiece) {
  std::vector<ScanPoint> pts;
  for (int b = 0; b < 20; ++b) pts.push_back(At(b, b < 3 ? 2.00 : 2.06));
  const double max_extent = 0.1;
  EndPieces ends = FrontEndPieces(pts, Span(0, 20), max_extent, 0.03);
  ASSERT_TRUE(ends.front_end.has_value());
  EXPECT_EQ(*ends.front_end, 3u);
  EXPECT_FALSE(ends.back_begin.has_value());
  for (int b = 0; b < 20; ++b) pts[b] = At(b, b >= 17 ? 2.00 : 2.06);
  ends = FrontEndPieces(pts, Span(0, 20), max_extent, 0.03);
  EXPECT_FALSE(ends.front_end.has_value());
  ASSERT_TRUE(ends.back_begin.has_value());
  EXPECT_EQ(*ends.back_begin, 17u);
  // A step away from the sensor at the end (the wall nearer than what ends it) is no piece in
  // front, and neither is a step below the threshold.
  for (int b = 0; b < 20; ++b) pts[b] = At(b, b >= 17 ? 2.12 : 2.06);
  EXPECT_FALSE(FrontEndPieces(pts, Span(0, 20), max_extent, 0.03).back_begin.has_value());
  for (int b = 0; b < 20; ++b) pts[b] = At(b, b >= 17 ? 2.04 : 2.06);
  EXPECT_FALSE(FrontEndPieces(pts, Span(0, 20), max_extent, 0.03).back_begin.has_value());
  // A piece wider than max_extent is no leg: 6 beams at 2 m span about 6 cm.
  for (int b = 0; b < 20; ++b) pts[b] = At(b, b < 6 ? 2.00 : 2.06);
  EXPECT_TRUE(FrontEndPieces(pts, Span(0, 20), max_extent, 0.03).front_end.has_value());
  EXPECT_FALSE(FrontEndPieces(pts, Span(0, 20), 0.05, 0.03).front_end.has_value());
}

}  // namespace
}  // namespace shelfdock::perception
