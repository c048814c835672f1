#pragma once
// The checks every scan from outside passes (JSON files, standard input, ROS bags) before the
// detector sees it. Header-only: the ROS bag reader is built apart (C++17) and shares them.

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/laser_scan.hpp"
#include "io/input_error.hpp"
#include "io/input_limits.hpp"

namespace shelfdock::io {

/// Throws InputError (file, `where`.field) unless the scan is usable: a non-zero finite angle
/// increment, 0 <= range_min < range_max, 1..kMaxBeamsPerScan beams matching the angles, and
/// intensities empty or as many as the ranges.
inline void CheckScan(const geometry::LaserScan& s, const std::string& file,
                      const std::string& where) {
  const auto field = [&where](const char* key) { return where.empty() ? key : where + "." + key; };
  if (!std::isfinite(s.angle_min) || !std::isfinite(s.angle_max) ||
      !std::isfinite(s.angle_increment)) {
    throw InputError(file, field("angle_increment"), "angles must be finite");
  }
  if (s.angle_increment == 0.0)
    throw InputError(file, field("angle_increment"), "must be non-zero");
  if (!(s.range_min >= 0.0) || !(s.range_max > s.range_min) || !std::isfinite(s.range_max)) {
    throw InputError(file, field("range_max"), "must exceed range_min >= 0 (both finite)");
  }
  if (s.ranges.empty()) throw InputError(file, field("ranges"), "empty scan");
  if (s.ranges.size() > kMaxBeamsPerScan) {
    throw InputError(file, field("ranges"),
                     std::to_string(s.ranges.size()) + " beams exceed the limit of " +
                         std::to_string(kMaxBeamsPerScan) + " per scan");
  }
  if (!s.intensities.empty() && s.intensities.size() != s.ranges.size()) {
    throw InputError(file, field("intensities"), "length differs from ranges");
  }
  // Beam count implied by the angles; a negative increment runs from angle_min down.
  const double expected = (s.angle_max - s.angle_min) / s.angle_increment + 1.0;
  if (!(std::abs(expected - static_cast<double>(s.ranges.size())) <= 1.5)) {
    throw InputError(file, field("ranges"),
                     "holds " + std::to_string(s.ranges.size()) +
                         " beams but angle_min/angle_max/angle_increment imply " +
                         (std::isfinite(expected) && std::abs(expected) < 1e15
                              ? std::to_string(std::llround(expected))
                              : std::string("an impossible count")));
  }
}

/// A scan with a negative angle increment (a LiDAR mounted upside down sweeps clockwise) as the
/// same beams in ascending angle order, which every consumer assumes. The first beam of the
/// result was measured last, so the stamp moves to it and the time increment changes sign.
inline void MakeBeamsAscending(geometry::LaserScan& s) {
  if (s.angle_increment >= 0.0 || s.ranges.empty()) return;
  const double n_minus_1 = static_cast<double>(s.ranges.size() - 1);
  s.stamp += n_minus_1 * s.time_increment;
  s.time_increment = -s.time_increment;
  // Beam i of the result is beam n-1-i of the input: the same angles, counted from the other end.
  const double last_angle = s.angle_min + n_minus_1 * s.angle_increment;
  s.angle_max = s.angle_min;
  s.angle_min = last_angle;
  s.angle_increment = -s.angle_increment;
  std::reverse(s.ranges.begin(), s.ranges.end());
  std::reverse(s.intensities.begin(), s.intensities.end());
}

}  // namespace shelfdock::io
