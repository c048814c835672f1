#pragma once

#include <cmath>
#include <numbers>

namespace shelfdock::geometry {

/// Wraps an angle to [-pi, pi).
inline double WrapAngle(double angle_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double wrapped = std::fmod(angle_rad + std::numbers::pi, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  return wrapped - std::numbers::pi;
}

/// Signed smallest difference a - b, in [-pi, pi).
inline double AngleDiff(double a_rad, double b_rad) { return WrapAngle(a_rad - b_rad); }

/// |a - b| modulo `period_rad`: the smallest difference between two headings of something that
/// looks the same turned by period_rad (pi for a rectangular shelf, pi/2 for a square one).
inline double AngleDiffModulo(double a_rad, double b_rad, double period_rad) {
  const double d = AngleDiff(a_rad, b_rad);
  return std::abs(d - period_rad * std::round(d / period_rad));
}

/// Degrees to radians and back.
inline constexpr double DegToRad(double deg) { return deg * std::numbers::pi / 180.0; }
inline constexpr double RadToDeg(double rad) { return rad * 180.0 / std::numbers::pi; }

}  // namespace shelfdock::geometry
