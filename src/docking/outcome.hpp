#pragma once

#include <string>
#include <string_view>

namespace shelfdock::docking {

/// How a docking attempt ended. Every failure is an expected outcome, reported as a value with a
/// sentence that says why (Nav2's typed docking failures, without the exceptions).
enum class OutcomeCode {
  kPending,  ///< not finished yet: the value an Outcome holds until the Docker sets it
  kSuccess,
  kShelfNotFound,   ///< no shelf detected before the robot had to commit to the goal
  kDetectionLost,   ///< the shelf (or the LiDAR) was lost while it was still needed
  kWouldCollide,    ///< a path exists but its swept footprint would touch a leg, or an obstacle
                    ///< blocks it for too long
  kNoPath,          ///< no drivable path to the docking area or the goal within the robot's limits
  kTrackingFailed,  ///< the robot left the path it was following (slip, a push, bad odometry)
  kWrongShelf,      ///< the code under the shelf carries another shelf's ID
  kCodeNotFound,    ///< the camera saw no code where the shelf centre should be
  kTimeout,         ///< the whole attempt took longer than its time budget
  kTooManyReplans,  ///< the goal kept moving: more re-plans than allowed
};

/// Stable snake_case name, used in JSON output ("success", "shelf_not_found", ...).
std::string_view ToString(OutcomeCode code);

/// How a docking attempt ended: the code and a human-readable reason.
struct Outcome {
  OutcomeCode code = OutcomeCode::kPending;
  std::string reason;  ///< one sentence for people

  bool ok() const { return code == OutcomeCode::kSuccess; }
};

}  // namespace shelfdock::docking
