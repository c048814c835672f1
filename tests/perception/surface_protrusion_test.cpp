// SurfaceProtrusions (src/perception/surface_protrusion.cpp): a leg a few centimetres in front
// of a wall, inside the wall's cluster, is cut out; a bare wall's range noise is not. Synthetic
// returns on the kWlrAlpha beam fan with seeded Gaussian range noise.
#include "perception/surface_protrusion.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "test_scenes.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kAlpha = testing::kWlrAlpha;
constexpr double kNoise = 0.01;     // [m] range noise
constexpr double kWallRange = 2.0;  // [m] along the wall's normal (beam 50)
constexpr int kLegFirst = 48;       // beams on the leg: a 40 mm leg at 2 m spans about 4
constexpr int kLegLast = 51;

ProtrusionLimits Limits() {
  ProtrusionLimits l;
  l.max_extent_m = 0.1;
  l.min_step_m = std::max(0.03, 2.0 * std::sqrt(2.0) * kNoise);
  l.min_offset_m = 0.04;
  l.offset_sigmas = 4.0;
  l.range_noise_m = kNoise;
  l.surface_points = 4;
  l.surface_rms_m = 3.0 * kNoise;
  return l;
}

// Beams [first, last] of a wall square to beam 50 at kWallRange, the leg's beams `offset_m`
// nearer (a leg face in front of the wall), with noise; `skip` beams are missing.
std::vector<ScanPoint> WallWithLeg(int first, int last, double offset_m, std::uint64_t seed,
                                   const std::vector<int>& skip = {}) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, kNoise);
  std::vector<ScanPoint> pts;
  for (int b = first; b <= last; ++b) {
    if (std::find(skip.begin(), skip.end(), b) != skip.end()) continue;
    double r = kWallRange / std::cos((b - 50) * kAlpha);
    if (b >= kLegFirst && b <= kLegLast) r -= offset_m;
    pts.push_back(testing::BeamPoint(b, r + noise(rng)));
  }
  return pts;
}

ClusterSpan Span(std::size_t begin, std::size_t end) {
  ClusterSpan s;
  s.begin = begin;
  s.end = end;
  return s;
}

// Beams of a piece.
int FirstBeam(const std::vector<ScanPoint>& pts, const PieceRange& r) { return pts[r.begin].beam; }
int LastBeam(const std::vector<ScanPoint>& pts, const PieceRange& r) { return pts[r.end - 1].beam; }

// A leg 8 cm in front of the wall, in the middle of its cluster: one piece, the leg's four
// beams (one beam either way tolerated: a noisy edge return may join or leave it), every seed.
TEST(SurfaceProtrusionTest, ALegInFrontOfAWallInsideItsClusterIsCutOut) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto pts = WallWithLeg(20, 80, 0.08, seed);
    const auto pieces = SurfaceProtrusions(pts, Span(0, pts.size()), Limits());
    ASSERT_EQ(pieces.size(), 1u) << "seed " << seed;
    EXPECT_NEAR(FirstBeam(pts, pieces[0]), kLegFirst, 1) << "seed " << seed;
    EXPECT_NEAR(LastBeam(pts, pieces[0]), kLegLast, 1) << "seed " << seed;
  }
}

// The same wall without the leg: its range noise makes no piece in 200 seeds.
TEST(SurfaceProtrusionTest, ABareWallsNoiseIsNoPiece) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const auto pts = WallWithLeg(20, 80, 0.0, seed);
    EXPECT_TRUE(SurfaceProtrusions(pts, Span(0, pts.size()), Limits()).empty()) << "seed " << seed;
  }
}

// A leg only 2 cm in front of the wall stands out by less than min_offset_m: no piece (such a
// leg is left to the completion from the map, which judges blends).
TEST(SurfaceProtrusionTest, ALegBarelyInFrontOfTheWallIsNoPiece) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto pts = WallWithLeg(20, 80, 0.02, seed);
    EXPECT_TRUE(SurfaceProtrusions(pts, Span(0, pts.size()), Limits()).empty()) << "seed " << seed;
  }
}

// The wall's return just past the leg was dropped (the trailing filter takes it for a mixed
// point), which ends the cluster at the leg's last beam: the wall beyond the break still gives
// the surface on that side, and the leg at the cluster's end is cut out.
TEST(SurfaceProtrusionTest, TheSurfaceMayGoOnBeyondTheClustersEnd) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto pts = WallWithLeg(20, 80, 0.08, seed, {kLegLast + 1});
    const std::size_t end = static_cast<std::size_t>(kLegLast - 20 + 1);  // beams 20..51
    ASSERT_EQ(pts[end - 1].beam, kLegLast);
    const auto pieces = SurfaceProtrusions(pts, Span(0, end), Limits());
    ASSERT_EQ(pieces.size(), 1u) << "seed " << seed;
    EXPECT_NEAR(FirstBeam(pts, pieces[0]), kLegFirst, 1) << "seed " << seed;
    EXPECT_EQ(LastBeam(pts, pieces[0]), kLegLast) << "seed " << seed;
  }
}

// Nothing beyond the leg (the wall ends there, open space behind): no surface on that side, so
// no piece here (FrontEndPieces judges a cluster's ends by their step alone).
TEST(SurfaceProtrusionTest, NoSurfaceOnOneSideIsNoPiece) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto pts = WallWithLeg(20, kLegLast, 0.08, seed);
    EXPECT_TRUE(SurfaceProtrusions(pts, Span(0, pts.size()), Limits()).empty()) << "seed " << seed;
  }
}

// ProtrusionSigmas on one return (a leg at a corner the completion predicts, seen by one beam):
// 5 cm in front of the wall it stands out by 5 cm over the noise of one return and of the
// wall's line, about 4.9 sigmas, so it passes 3.5 sigmas (LegCompletionConfig::
// surface_offset_sigmas) with probability 0.92 (asserted: 170 of 200 seeds or more); the bare
// wall's own return passes in at most 1 of 200 seeds (one-sided Gaussian tail: 2.3e-4 each).
TEST(SurfaceProtrusionTest, OneReturnInFrontOfTheWallStandsOutByItsOffsetOverTheNoise) {
  ProtrusionLimits l = Limits();
  l.min_offset_m = 0.025;
  const std::size_t leg = static_cast<std::size_t>(50 - 20);  // beam 50's index
  int leg_passed = 0;
  int bare_passed = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    auto pts = WallWithLeg(20, 80, 0.0, seed);
    ASSERT_EQ(pts[leg].beam, 50);
    const auto bare = ProtrusionSigmas(pts, leg, leg + 1, l);
    if (bare && *bare >= 3.5) ++bare_passed;
    pts[leg] = testing::BeamPoint(50, pts[leg].range - 0.05);
    const auto z = ProtrusionSigmas(pts, leg, leg + 1, l);
    if (z && *z >= 3.5) ++leg_passed;
  }
  EXPECT_GE(leg_passed, 170);
  EXPECT_LE(bare_passed, 1);
}

// A nearer object (a front leg 0.9 m closer) two beams beside the return cuts that side of the
// wall short. By default (both sides need three points on the wall, beam neighbours whatever
// their range) the return stands out from nothing; with surface_max_step_m the side ends at the
// occluder and, allowed one point there, the wall's line comes from the long side and a return
// 8 cm in front stands out by more than 3.5 sigmas in every seed.
TEST(SurfaceProtrusionTest, AnOccluderMayCutOneSideOfTheWallShort) {
  ProtrusionLimits strict = Limits();
  strict.min_offset_m = 0.025;
  ProtrusionLimits loose = strict;
  loose.surface_max_step_m = 0.25;
  loose.short_side_points = 1;
  const std::size_t leg = static_cast<std::size_t>(50 - 20);
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    auto pts = WallWithLeg(20, 80, 0.0, seed);
    pts[leg] = testing::BeamPoint(50, pts[leg].range - 0.08);
    for (std::size_t i = leg - 4; i <= leg - 2; ++i) {
      pts[i] = testing::BeamPoint(pts[i].beam, pts[i].range - 0.9);
    }
    EXPECT_FALSE(ProtrusionSigmas(pts, leg, leg + 1, strict).has_value()) << "seed " << seed;
    const auto z = ProtrusionSigmas(pts, leg, leg + 1, loose);
    ASSERT_TRUE(z.has_value()) << "seed " << seed;
    EXPECT_GT(*z, 3.5) << "seed " << seed;
  }
}

// The leg at the end of what it touches (a person's leg beside it: here the wall ends at the
// leg), the background 4 m behind past it. Both sides needed (the default), the leg 5 cm in
// front stands out from nothing, in every seed; with open_end the wall's line comes from the side
// it has, and the leg stands out by 3.5 sigmas or more in at least 190 of 200 seeds (5 cm over
// the noise of 4 returns and the line's 12 is about 8.7 sigmas; the line's tilt, extrapolated,
// takes some: 198 measured), the wall's own end with no leg in front in at most 2 (1 measured).
// A nearer return past the piece (an occluder: the wall may go on behind it) opens no end.
TEST(SurfaceProtrusionTest, AtTheEndOfItsObjectALegMayStandOutFromOneSide) {
  ProtrusionLimits both = Limits();
  both.min_offset_m = 0.025;
  both.surface_max_step_m = 0.25;
  both.short_side_points = 1;
  ProtrusionLimits open = both;
  open.open_end = true;
  const std::size_t begin = static_cast<std::size_t>(kLegFirst - 20);
  const std::size_t end = static_cast<std::size_t>(kLegLast - 20 + 1);
  auto with_past = [](std::vector<ScanPoint> pts, double range) {
    for (int b = kLegLast + 1; b <= kLegLast + 5; ++b) pts.push_back(testing::BeamPoint(b, range));
    return pts;
  };
  int leg_passed = 0;
  int bare_passed = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const auto leg = with_past(WallWithLeg(20, kLegLast, 0.05, seed), 6.0);
    ASSERT_EQ(leg[begin].beam, kLegFirst);
    EXPECT_FALSE(ProtrusionSigmas(leg, begin, end, both).has_value()) << "seed " << seed;
    const auto z = ProtrusionSigmas(leg, begin, end, open);
    if (z && *z >= 3.5) ++leg_passed;
    const auto occluded = with_past(WallWithLeg(20, kLegLast, 0.05, seed), 1.0);
    EXPECT_FALSE(ProtrusionSigmas(occluded, begin, end, open).has_value()) << "seed " << seed;
    const auto bare =
        ProtrusionSigmas(with_past(WallWithLeg(20, kLegLast, 0.0, seed), 6.0), begin, end, open);
    if (bare && *bare >= 3.5) ++bare_passed;
  }
  EXPECT_GE(leg_passed, 190);
  EXPECT_LE(bare_passed, 2);
}

}  // namespace
}  // namespace shelfdock::perception
