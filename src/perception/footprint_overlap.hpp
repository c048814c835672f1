#pragma once

#include "geometry/pose2.hpp"

namespace shelfdock::perception {

/// A rectangle in the plane: its centre and heading, and half its sides along its own x and y.
struct OrientedRect {
  geometry::Pose2 pose;
  double half_x_m = 0.0;
  double half_y_m = 0.0;
};

/// Whether two rectangles share interior area (touching edges do not count): the separating
/// axis test over the two rectangles' four edge directions.
bool RectsOverlap(const OrientedRect& a, const OrientedRect& b);

}  // namespace shelfdock::perception
