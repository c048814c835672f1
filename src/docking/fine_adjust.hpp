#pragma once

#include <deque>

#include "docking/docking_config.hpp"
#include "docking/path_tracker.hpp"

namespace shelfdock::docking {

/// The fine adjustment after the code check (paper 3.5: "adjust the position of the device"):
/// under the shelf there is no room for a curve, so the correction is a short sequence of
/// rotations in place and straight moves on odometry: reverse a little (only when the lateral
/// offset needs an angle of approach), turn toward the corrected goal, drive to it, turn to its
/// heading. Each move is a proportional law saturated at small speeds.
class FineAdjust {
 public:
  explicit FineAdjust(const VerifyConfig& config = {}) : config_(config) {}

  /// Plans the moves that take the robot at `T_odom_base` to `T_odom_goal`.
  void Start(const geometry::Pose2& T_odom_base, const geometry::Pose2& T_odom_goal);

  /// One control step; `done` once every move has finished.
  VelocityCommand Update(const geometry::Pose2& T_odom_base, bool* done);

 private:
  enum class Kind { kStraightTo, kRotateTo };
  struct Move {
    Kind kind;
    geometry::Pose2 target;  ///< straight: reach the target's position; rotate: its yaw
    bool reverse = false;
  };

  VerifyConfig config_;
  std::deque<Move> moves_;
};

}  // namespace shelfdock::docking
