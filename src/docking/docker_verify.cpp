// Verification (paper 3.5): the upward camera in advance on the final straight, the code check
// at the goal, and the start of the fine adjustment.
#include "docking/docker.hpp"

#include <cmath>
#include <numbers>

#include "geometry/angle.hpp"

#include "docking/docker_detail.hpp"

namespace shelfdock::docking {

using detail::Fmt;
using detail::MeanPose;
using geometry::Pose2;

Pose2 Docker::TagGoal(const Pose2& T_tag_base) const {
  // The code is at the shelf centre along its long side; the goal is T_shelf_goal_ up to the
  // code's own pi (which end the robot came from).
  return GoalBranchNearHeading(T_shelf_goal_, T_tag_base.yaw);
}

void Docker::StartLift(double t_s, Command* cmd) {
  phase_ = Phase::kLift;
  phase_start_t_ = t_s;
  cmd->start_lift = true;
  cmd->events.push_back("lift_started");
}

void Docker::StartVerify(double t_s, Command* cmd) {
  verify_.lift_after_adjust = false;
  phase_ = Phase::kVerify;
  phase_start_t_ = t_s;
  verify_.readings.clear();
  verify_.missing_frames = 0;
  cmd->camera_on = true;
}

void Docker::GuideByCode(const Observations& obs, Command* cmd) {
  const CameraGuideConfig& g = config_.camera_guide;
  if (!obs.marker || obs.marker->id != task_.shelf_id) return;  // the check at the goal reports
  // The camera sits at the base origin: the code's pose in odom from this frame's odometry.
  // Averaging over frames taken along the last decimetres (odometry drift there is sub-mm).
  guide_.tags.push_back(obs.T_odom_base * obs.marker->T_camera_tag);
  if (static_cast<int>(guide_.tags.size()) < g.frames) return;
  const Pose2 T_odom_tag = MeanPose(guide_.tags);
  const Pose2 goal = T_odom_tag * TagGoal(T_odom_tag.inverse() * obs.T_odom_base);
  const double remaining_m = -(T_odom_goal_.inverse() * obs.T_odom_base).x;
  if (remaining_m < g.min_remaining_m) return;
  const Pose2 diff = T_odom_goal_.inverse() * goal;
  if (std::hypot(diff.x, diff.y) <= g.correct_xy_m && std::abs(diff.yaw) <= g.correct_yaw_rad)
    return;
  // The path bent onto the corrected goal (BendToGoal); failing that, a short Bezier straight
  // onto it: no final straight is left at this point. Either way the curvature bound is the
  // tracker's at slow speed, not the approach's.
  PlannerConfig planner = config_.planner;
  planner.min_final_straight_m = 0.0;
  planner.final_straight_m = std::min(planner.final_straight_m, 0.5 * remaining_m);
  planner.max_curvature_1pm = g.max_curvature_1pm;
  const Pose2 lidar_goal = T_odom_goal_;
  if (!BendToGoal(obs.T_odom_base, goal, g.max_curvature_1pm, cmd) &&
      Replan(obs.T_odom_base, goal, cmd, &planner) != PlanStatus::kOk) {
    return;
  }
  if (!guide_.lidar_goal_before_camera) guide_.lidar_goal_before_camera = lidar_goal;
  ++guide_.corrections;
  cmd->events.push_back("camera_guide: goal moved " + Fmt(diff.x, 4) + "," + Fmt(diff.y, 4) + "," +
                        Fmt(diff.yaw, 4) + " from " + std::to_string(guide_.tags.size()) +
                        " code readings, " + Fmt(remaining_m, 3) + " m to go");
}

bool Docker::StartAdjustFromGuide(const Observations& obs, Command* cmd) {
  if (guide_.tags.empty() || verify_.adjust_tries >= config_.verify.max_adjust_tries) return false;
  // The code seen on the way in (paper 3.5: the camera "in advance") already tells where the goal
  // is; odometry over the last centimetres carries it to the stop. Beyond the tolerance, adjust
  // at once instead of first standing for a check; the check after the adjustment verifies.
  const Pose2 T_odom_tag = MeanPose(guide_.tags);
  const Pose2 T_odom_goal = T_odom_tag * TagGoal(T_odom_tag.inverse() * obs.T_odom_base);
  const Pose2 offset = T_odom_goal.inverse() * obs.T_odom_base;
  const VerifyConfig& v = config_.verify;
  const bool xy_ok =
      std::abs(offset.x) <= v.tolerance_xy_m && std::abs(offset.y) <= v.tolerance_xy_m;
  if (xy_ok && std::abs(offset.yaw) <= v.tolerance_yaw_rad) {
    if (!v.check_on_the_way_in || static_cast<int>(guide_.tags.size()) < v.frames) return false;
    // The readings taken on the way in are the check: standing still for more frames of the
    // same code would only cost time.
    ++verify_.code_checks;
    verify_.code_offset = offset;
    cmd->events.push_back("code_check: on the way in, " + std::to_string(guide_.tags.size()) +
                          " readings, offset " + Fmt(offset.x, 4) + "," + Fmt(offset.y, 4) + "," +
                          Fmt(offset.yaw, 4));
    phase_ = Phase::kLift;
    phase_start_t_ = obs.t_s;
    cmd->start_lift = true;
    cmd->events.push_back("lift_started");
    return true;
  }
  if (std::hypot(offset.x, offset.y) > v.max_correction_m) return false;  // the check decides
  ++verify_.adjust_tries;
  // Within the position tolerance only the heading is corrected (a turn in place): the readings
  // on the way in were the check, and a turn of a few milliradians on odometry needs no other.
  verify_.lift_after_adjust =
      xy_ok && v.check_on_the_way_in && static_cast<int>(guide_.tags.size()) >= v.frames;
  if (verify_.lift_after_adjust) {
    ++verify_.code_checks;
    verify_.code_offset = offset;
  }
  adjust_.Start(obs.T_odom_base,
                xy_ok ? obs.T_odom_base * Pose2(0.0, 0.0, -offset.yaw) : T_odom_goal);
  phase_ = Phase::kAdjust;
  cmd->events.push_back("adjust: try " + std::to_string(verify_.adjust_tries) +
                        " from the code seen on the way in, offset " + Fmt(offset.x, 4) + "," +
                        Fmt(offset.y, 4) + "," + Fmt(offset.yaw, 4));
  return true;
}

void Docker::StepVerify(const Observations& obs, Command* cmd) {
  cmd->velocity = {};
  cmd->camera_on = true;
  if (!obs.camera_frame) return;
  if (!obs.marker) {
    if (++verify_.missing_frames > config_.verify.max_missing_frames) {
      Fail(OutcomeCode::kCodeNotFound,
           "no code seen under the shelf in " + std::to_string(verify_.missing_frames) + " frames",
           cmd);
    }
    return;
  }
  if (obs.marker->id != task_.shelf_id) {
    Fail(OutcomeCode::kWrongShelf,
         "the code under the shelf reads " + std::to_string(obs.marker->id) + ", expected " +
             std::to_string(task_.shelf_id),
         cmd);
    return;
  }
  verify_.readings.push_back(obs.marker->T_camera_tag);  // camera at the base origin
  if (static_cast<int>(verify_.readings.size()) < config_.verify.frames) return;

  const Pose2 T_tag_base = MeanPose(verify_.readings).inverse();
  ++verify_.code_checks;
  verify_.readings.clear();
  const Pose2 T_tag_goal = TagGoal(T_tag_base);
  const Pose2 offset = T_tag_goal.inverse() * T_tag_base;
  verify_.code_offset = offset;
  cmd->events.push_back("code_check: offset " + Fmt(offset.x, 4) + "," + Fmt(offset.y, 4) + "," +
                        Fmt(offset.yaw, 4));
  const double xy = std::hypot(offset.x, offset.y);
  const bool within = std::abs(offset.x) <= config_.verify.tolerance_xy_m &&
                      std::abs(offset.y) <= config_.verify.tolerance_xy_m &&
                      std::abs(offset.yaw) <= config_.verify.tolerance_yaw_rad;
  if (within || verify_.adjust_tries >= config_.verify.max_adjust_tries) {
    if (!within) cmd->events.push_back("adjust_exhausted: lifting with the offset above");
    phase_ = Phase::kLift;
    phase_start_t_ = obs.t_s;
    cmd->start_lift = true;
    cmd->events.push_back("lift_started");
    return;
  }
  if (xy > config_.verify.max_correction_m) {
    Fail(OutcomeCode::kWouldCollide,
         "the code shows the robot " + Fmt(xy) + " m off the centre: too far to correct blind",
         cmd);
    return;
  }
  ++verify_.adjust_tries;
  adjust_.Start(obs.T_odom_base, obs.T_odom_base * offset.inverse());
  phase_ = Phase::kAdjust;
  cmd->camera_on = false;
  cmd->events.push_back("adjust: try " + std::to_string(verify_.adjust_tries));
}

}  // namespace shelfdock::docking
