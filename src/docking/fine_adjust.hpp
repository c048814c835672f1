#pragma once

#include <deque>

#include "docking/docking_config.hpp"
#include "docking/path_tracker.hpp"

namespace shelfdock::docking {

/// The fine adjustment after the code check (paper 3.5: "adjust the position of the device").
/// The offset to correct is a few millimetres and milliradians, and under the shelf there is no
/// room for a curve, so the correction is done in place on odometry with small moves:
///   - mostly along the axis (lateral error below lateral_tolerance_m): one short straight move
///     forward or backward, then a rotation to the final heading;
///   - otherwise: a short straight move along the current heading (the "lever") so that the
///     corrected point lies at most max_lever_angle_rad off the heading, a rotation toward it, a
///     straight move onto it, and a rotation to the final heading. The lever goes whichever way
///     (forward or backward) gives the shorter total path.
/// Each move follows a time-optimal stopping profile v = min(v_max, sqrt(2 a |e|), 0.6 |e| / dt):
/// the square root brakes at the deceleration limit, the dead-beat tail covers 60% of the
/// remaining error per control step, so a move settles in a few steps without overshoot.
class FineAdjust {
 public:
  explicit FineAdjust(const VerifyConfig& config = {}) : config_(config) {}

  /// Plans the moves that take the robot at `T_odom_base` to `T_odom_goal`.
  void Start(const geometry::Pose2& T_odom_base, const geometry::Pose2& T_odom_goal);

  /// A single turn on the spot to `yaw_rad` (a manoeuvre on the way to the shelf).
  void StartTurn(double yaw_rad);
  /// A single straight move along the current heading (forward or reversing) to `T_odom_to`'s
  /// position.
  void StartStraight(const geometry::Pose2& T_odom_base, const geometry::Pose2& T_odom_to);

  /// One control step of period dt_s; `done` once every move has finished.
  VelocityCommand Update(const geometry::Pose2& T_odom_base, double dt_s, bool* done);

  /// Number of moves still to do (for tests).
  std::size_t moves_left() const { return moves_.size(); }

 private:
  enum class Kind { kStraightTo, kRotateTo };
  struct Move {
    Kind kind;
    geometry::Pose2 target;  ///< straight: reach the target's position; rotate: its yaw
    double sign = 0.0;       ///< straight: +1 forward, -1 backward (fixed when planned)
  };
  void AddStraight(const geometry::Pose2& from, const geometry::Pose2& to);

  VerifyConfig config_;
  std::deque<Move> moves_;
};

}  // namespace shelfdock::docking
