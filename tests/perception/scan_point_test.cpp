// The beams around a bearing (BeamWindow) on fans of every width and direction: the window's
// beams are the ones whose bearing lies within the half-width, whichever side of the first beam
// the bearing lies on.
#include "perception/scan_point.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/angle.hpp"

namespace shelfdock::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A fan of `count` returns at 2 m from `start` [rad] by `increment` [rad], each bearing start +
// i * increment, unwrapped, as ScanToPoints gives them.
std::vector<ScanPoint> Fan(double start, double increment, int count) {
  std::vector<ScanPoint> points;
  for (int i = 0; i < count; ++i) {
    ScanPoint q;
    q.beam = i;
    q.angle = start + i * increment;
    q.range = 2.0;
    q.p = q.range * Eigen::Vector2d(std::cos(q.angle), std::sin(q.angle));
    points.push_back(q);
  }
  return points;
}

// The beam whose bearing is `bearing`, straight from the fan's parameters.
double BeamOf(double bearing, double start, double increment) {
  double offset = bearing - start;
  while (offset * increment < 0.0) offset += std::copysign(2.0 * kPi, increment);
  return offset / increment;
}

TEST(BeamWindowTest, A270DegreeFanFindsBearingsMoreThanPiFromItsFirstBeam) {
  // The TiM571's and WLR-716's fan: -135 to +135 deg. A bearing of 48 deg is 183 deg from the
  // first beam; wrapping that about the first beam put the window 177 deg the other way, off
  // the scan (a leg there was never looked at).
  const double start = -0.75 * kPi;
  const double inc = 1.5 * kPi / 810.0;
  const auto fan = Fan(start, inc, 811);
  for (const double bearing : {-2.3, -1.0, 0.0, 0.84, 2.0, 2.35}) {
    const auto w = BeamWindow(fan, bearing, 3.0 * inc);
    ASSERT_TRUE(w.has_value());
    const double beam = BeamOf(bearing, start, inc);  // tolerance: the window's rounding, 1 beam
    EXPECT_NEAR(0.5 * (w->first + w->second), beam, 1.0) << "bearing " << bearing;
    EXPECT_GE(w->second - w->first, 4) << "bearing " << bearing;
    EXPECT_LE(w->second - w->first, 6) << "bearing " << bearing;
  }
}

TEST(BeamWindowTest, FullTurnFansAndAClockwiseOneFindEveryBearing) {
  // 360 deg from -pi and from 0 (drivers differ), and a fan scanning clockwise from +135 deg.
  const double inc = 2.0 * kPi / 1440.0;
  for (const double start : {-kPi, 0.0}) {
    const auto full = Fan(start, inc, 1440);
    for (const double bearing : {-3.0, -0.5, 1.5, 3.1}) {
      const auto w = BeamWindow(full, bearing, 0.0);
      ASSERT_TRUE(w.has_value());
      EXPECT_NEAR(0.5 * (w->first + w->second), BeamOf(bearing, start, inc), 1.0)
          << "start " << start << " bearing " << bearing;
    }
  }
  const double cw = -1.5 * kPi / 810.0;
  const auto reversed = Fan(0.75 * kPi, cw, 811);
  for (const double bearing : {2.0, 0.0, -0.84, -2.3}) {
    const auto w = BeamWindow(reversed, bearing, 2.0 * std::abs(cw));
    ASSERT_TRUE(w.has_value());
    EXPECT_NEAR(0.5 * (w->first + w->second), BeamOf(bearing, 0.75 * kPi, cw), 1.0) << bearing;
  }
}

TEST(BeamWindowTest, FewerThanTwoBeamsGiveNoWindow) {
  EXPECT_FALSE(BeamWindow({}, 0.0, 0.1).has_value());
  EXPECT_FALSE(BeamWindow(Fan(0.0, 0.01, 1), 0.0, 0.1).has_value());
}

}  // namespace
}  // namespace shelfdock::perception
