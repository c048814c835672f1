// The Docker's frame: construction, planning, failure, and the per-step dispatch over the
// stages (docker_dock.cpp, docker_baseline.cpp, docker_verify.cpp).
#include "docking/docker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "docking/collision_check.hpp"
#include "docking/path_planner.hpp"
#include "geometry/angle.hpp"

#include "docking/docker_detail.hpp"

namespace shelfdock::docking {

using detail::Fmt;
using detail::MeanPose;
using geometry::Pose2;

std::string_view ToString(Method method) {
  return method == Method::kContinuous ? "continuous" : "stop-and-recognise";
}

std::string_view ToString(Phase phase) {
  switch (phase) {
    case Phase::kApproach:
      return "approach";
    case Phase::kDock:
      return "dock";
    case Phase::kStand:
      return "stand";
    case Phase::kVerify:
      return "verify";
    case Phase::kAdjust:
      return "adjust";
    case Phase::kLift:
      return "lift";
    case Phase::kAbort:
      return "abort";
    case Phase::kDone:
      return "done";
  }
  return "unknown";
}

Docker::Docker(DockingConfig config, DockingTask task, Method method, DetectFn detect)
    : config_(std::move(config)),
      task_(std::move(task)),
      method_(method),
      detect_(std::move(detect)),
      follower_(config_.controller),
      tracker_(config_.tracker),
      adjust_(config_.verify),
      docking_start_t_(std::numeric_limits<double>::quiet_NaN()) {}

Pose2 Docker::GoalFromShelf(const Pose2& T_odom_shelf) const {
  return T_odom_shelf * T_shelf_goal_;
}

void Docker::Fail(OutcomeCode code, std::string reason, Command* cmd) {
  outcome_ = {code, std::move(reason)};
  cmd->events.push_back("failed: " + std::string(ToString(code)) + ": " + outcome_.reason);
  phase_ = Phase::kAbort;
}

Docker::PlanStatus Docker::Replan(const Pose2& T_odom_base, const Pose2& goal, Command* cmd,
                                  const PlannerConfig* planner) {
  const PlanResult plan =
      PlanDockingPath(T_odom_base, goal, planner != nullptr ? *planner : config_.planner);
  if (!plan.ok) {
    replan_failure_ = plan.reason;
    cmd->events.push_back("plan_failed: " + plan.reason);
    return PlanStatus::kInfeasible;
  }
  const ClearanceResult clearance =
      CheckPathAgainstLegs(plan.path, LegDiscs(task_.model, tracker_.estimate()), config_.safety);
  if (!clearance.ok) {
    replan_failure_ = "the planned path passes " + Fmt(clearance.min_clearance_m) +
                      " m from a leg (margin " + Fmt(config_.safety.leg_margin_m) + " m)";
    cmd->events.push_back("plan_refused: " + replan_failure_);
    return PlanStatus::kCollides;
  }
  const double cruise = phase_ == Phase::kApproach ? config_.controller.approach_speed_mps
                                                   : config_.controller.max_speed_mps;
  follower_.SetPath(plan.path, cruise, 0.0, last_v_cmd_);
  T_odom_goal_ = goal;
  ++path_version_;
  cmd->events.push_back("plan: goal " + Fmt(goal.x, 4) + "," + Fmt(goal.y, 4) + "," +
                        Fmt(goal.yaw, 4) + " straight " + Fmt(plan.straight_m, 2) + " m");
  return PlanStatus::kOk;
}

Command Docker::Step(const Observations& obs) {
  Command cmd;
  odometry_.Add(obs.t_s, obs.T_odom_base);
  if (!started_) {
    started_ = true;
    t_start_ = obs.t_s;
    last_t_ = obs.t_s - config_.control_period_s;
    last_T_odom_base_ = obs.T_odom_base;
    // Enter under the shelf from the end that faces the robot.
    const Pose2 T_map_shelf = task_.T_map_shelf_preset;
    T_shelf_goal_ = Pose2(0.0, 0.0, config_.dock_yaw_offset_rad);
    const Pose2 flipped(0.0, 0.0, config_.dock_yaw_offset_rad + std::numbers::pi);
    const Pose2 local = (T_map_shelf * T_shelf_goal_).inverse() * obs.T_map_base_estimate;
    const Pose2 local_flipped = (T_map_shelf * flipped).inverse() * obs.T_map_base_estimate;
    if (local_flipped.x < local.x) T_shelf_goal_ = flipped;
    const Pose2 T_map_goal = T_map_shelf * T_shelf_goal_;
    const double along = (T_map_goal.inverse() * obs.T_map_base_estimate).x;
    if (along >= -(config_.entry_distance_m + 0.05)) {
      StartDocking(obs, &cmd);
    } else {
      const Pose2 T_map_entry = T_map_goal * Pose2(-config_.entry_distance_m, 0.0, 0.0);
      if (PlanApproach(obs.T_map_base_estimate, T_map_entry)) {
        cmd.events.push_back("approach: planned to the docking area's entry");
      } else {
        // A differential drive can always face its target first; the smooth curve from there
        // bends less.
        turn_toward_entry_ = T_map_entry;
        cmd.events.push_back("approach: no smooth path from here; turning toward the entry");
      }
    }
  }
  const double dt = std::max(obs.t_s - last_t_, 1e-4);
  tracker_.AddOdometryDrift(geometry::Distance(obs.T_odom_base, last_T_odom_base_));
  if (phase_ != Phase::kDone && phase_ != Phase::kAbort && obs.t_s - t_start_ > config_.timeout_s) {
    Fail(OutcomeCode::kTimeout, "docking took longer than " + Fmt(config_.timeout_s, 0) + " s",
         &cmd);
  }

  switch (phase_) {
    case Phase::kApproach:
      StepApproach(obs, dt, &cmd);
      break;
    case Phase::kDock:
      StepDock(obs, &cmd);
      break;
    case Phase::kStand:
      StepStand(obs, &cmd);
      break;
    case Phase::kVerify:
      if (obs.t_s - phase_start_t_ >= config_.verify.settle_s) StepVerify(obs, &cmd);
      cmd.camera_on = phase_ == Phase::kVerify || cmd.camera_on;
      break;
    case Phase::kAdjust: {
      bool finished = false;
      cmd.velocity = adjust_.Update(obs.T_odom_base, dt, &finished);
      if (finished) {
        phase_ = Phase::kVerify;
        phase_start_t_ = obs.t_s;
        code_readings_.clear();
        missing_frames_ = 0;
        cmd.camera_on = true;
        cmd.events.push_back("adjust_done");
      }
      break;
    }
    case Phase::kLift:
      if (obs.lift_done) {
        outcome_ = {OutcomeCode::kSuccess,
                    "docked under shelf " + std::to_string(task_.shelf_id) + " and lifted it"};
        phase_ = Phase::kDone;
        cmd.events.push_back("lift_done");
      } else if (obs.t_s - phase_start_t_ > config_.lift_timeout_s) {
        Fail(OutcomeCode::kTimeout, "the lift did not finish", &cmd);
      }
      break;
    case Phase::kAbort: {
      const double v = std::max(0.0, last_v_cmd_ - 1.5 * config_.controller.max_decel_mps2 * dt);
      cmd.velocity = {v, 0.0};
      if (v <= 0.0) phase_ = Phase::kDone;
      break;
    }
    case Phase::kDone:
      break;
  }
  last_v_cmd_ = cmd.velocity.v_mps;
  last_t_ = obs.t_s;
  last_T_odom_base_ = obs.T_odom_base;
  return cmd;
}

bool Docker::PlanApproach(const Pose2& T_map_base, const Pose2& T_map_entry) {
  const PlanResult plan = PlanDockingPath(T_map_base, T_map_entry, config_.planner);
  if (!plan.ok) return false;
  follower_.SetPath(plan.path, config_.controller.approach_speed_mps,
                    config_.controller.max_speed_mps, 0.0);
  ++path_version_;
  return true;
}

void Docker::StepApproach(const Observations& obs, double dt, Command* cmd) {
  if (turn_toward_entry_) {
    constexpr double kAligned_rad = 0.02;
    constexpr double kTurnGain_1ps = 2.0;
    const Eigen::Vector2d to_entry =
        turn_toward_entry_->translation() - obs.T_map_base_estimate.translation();
    const double error =
        geometry::AngleDiff(std::atan2(to_entry.y(), to_entry.x()), obs.T_map_base_estimate.yaw);
    if (std::abs(error) > kAligned_rad) {
      const double w_max = config_.controller.max_yaw_rate_radps;
      cmd->velocity = {0.0, std::clamp(kTurnGain_1ps * error, -w_max, w_max)};
      return;
    }
    const Pose2 T_map_entry = *turn_toward_entry_;
    turn_toward_entry_.reset();
    if (!PlanApproach(obs.T_map_base_estimate, T_map_entry)) {
      Fail(OutcomeCode::kWouldCollide, "no approach path to the docking area's entry", cmd);
      return;
    }
    cmd->events.push_back("approach: planned to the docking area's entry after turning");
  }
  const TrackingStatus s = follower_.Update(obs.T_map_base_estimate, dt);
  if (s.reached) {
    StartDocking(obs, cmd);
    if (phase_ == Phase::kDock) StepDock(obs, cmd);
  } else if (s.lost) {
    Fail(OutcomeCode::kWouldCollide, "the robot left the approach path", cmd);
  } else {
    cmd->velocity = s.command;
  }
}

}  // namespace shelfdock::docking
