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

/// Degrees to radians and back.
inline constexpr double DegToRad(double deg) { return deg * std::numbers::pi / 180.0; }
inline constexpr double RadToDeg(double rad) { return rad * 180.0 / std::numbers::pi; }

}  // namespace shelfdock::geometry
