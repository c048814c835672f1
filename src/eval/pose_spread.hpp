#pragma once

#include <limits>
#include <vector>

#include "geometry/pose2.hpp"

namespace shelfdock::eval {

/// How much one quantity fluctuates over a set of samples. The paper's Fig. 7 gives one number
/// per axis without defining it; both common readings are kept.
struct Spread {
  double range = std::numeric_limits<double>::quiet_NaN();   ///< max - min
  double stddev = std::numeric_limits<double>::quiet_NaN();  ///< sample standard deviation
};

/// Spread of x, y and yaw of a set of shelf poses (in one frame).
struct PoseSpread {
  int samples = 0;
  Spread x, y, yaw;  ///< [m, m, rad]
};

/// Spread of the poses. Yaw is taken relative to the first pose, folded by `yaw_symmetry_rad`
/// (pi for a rectangle: a heading and its opposite are the same shelf), so a flip or a wrap at
/// +-pi is not a fluctuation. Fewer than 2 poses: NaN spreads.
PoseSpread SpreadOf(const std::vector<geometry::Pose2>& poses, double yaw_symmetry_rad);

}  // namespace shelfdock::eval
