#pragma once

// Small helpers shared by the Docker's stage files (docker*.cpp); not part of the public API.

#include <cstdio>
#include <string>
#include <vector>

#include "geometry/angle.hpp"
#include "geometry/pose2.hpp"

namespace shelfdock::docking::detail {

/// A number for an event or a failure reason.
inline std::string Fmt(double v, int decimals = 3) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

/// Mean of poses around the first one (yaw averaged as differences, no wrap issues).
inline geometry::Pose2 MeanPose(const std::vector<geometry::Pose2>& poses) {
  double x = 0.0, y = 0.0, dyaw = 0.0;
  for (const geometry::Pose2& p : poses) {
    x += p.x;
    y += p.y;
    dyaw += geometry::AngleDiff(p.yaw, poses.front().yaw);
  }
  const double n = static_cast<double>(poses.size());
  return {x / n, y / n, poses.front().yaw + dyaw / n};
}

}  // namespace shelfdock::docking::detail
