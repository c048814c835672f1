// The Docker's frame: construction, planning, failure, and the per-step dispatch over the
// stages (docker_approach.cpp, docker_dock.cpp, docker_baseline.cpp, docker_verify.cpp).
#include "docking/docker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "docking/collision_check.hpp"
#include "docking/path_bend.hpp"
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

namespace {
/// The approach's turns and straight moves use the docking limits, not the slow adjustment's.
VerifyConfig ManoeuvreLimits(const DockingConfig& c) {
  VerifyConfig m = c.verify;
  m.adjust_speed_mps = c.controller.max_speed_mps;
  m.adjust_accel_mps2 = c.controller.max_decel_mps2;
  m.adjust_yaw_rate_radps = c.controller.max_yaw_rate_radps;
  return m;
}
}  // namespace

Docker::Docker(DockingConfig config, DockingTask task, Method method, DetectFn detect)
    : config_(std::move(config)),
      task_(std::move(task)),
      method_(method),
      detect_(std::move(detect)),
      follower_(config_.controller),
      tracker_(config_.tracker),
      adjust_(config_.verify),
      manoeuvre_(ManoeuvreLimits(config_)),
      docking_start_t_(std::numeric_limits<double>::quiet_NaN()) {}

Pose2 Docker::GoalFromShelf(const Pose2& T_odom_shelf) const {
  return T_odom_shelf * T_shelf_goal_;
}

void Docker::Fail(OutcomeCode code, std::string reason, Command* cmd) {
  outcome_ = {code, std::move(reason)};
  cmd->events.push_back("failed: " + std::string(ToString(code)) + ": " + outcome_.reason);
  phase_ = Phase::kAbort;
}

VelocityCommand Docker::BrakeCommand(double dt) const {
  const double decel = config_.abort_decel_factor * config_.controller.max_decel_mps2;
  const double v = last_v_cmd_ >= 0.0 ? std::max(0.0, last_v_cmd_ - decel * dt)
                                      : std::min(0.0, last_v_cmd_ + decel * dt);
  return {v, 0.0};
}

Docker::PlanStatus Docker::Replan(const Pose2& T_odom_base, const Pose2& goal, Command* cmd,
                                  const PlannerConfig* planner) {
  const PlanResult plan =
      PlanDockingPath(T_odom_base, goal, planner != nullptr ? *planner : config_.planner);
  if (!plan.ok) {
    dock_.replan_failure = plan.reason;
    cmd->events.push_back("plan_failed: " + plan.reason);
    return PlanStatus::kInfeasible;
  }
  const ClearanceResult clearance =
      CheckPathAgainstLegs(plan.path, LegDiscs(task_.model, tracker_.estimate()), config_.safety);
  if (!clearance.ok) {
    dock_.replan_failure = "the planned path passes " + Fmt(clearance.min_clearance_m) +
                           " m from a leg (margin " + Fmt(config_.safety.leg_margin_m) + " m)";
    cmd->events.push_back("plan_refused: " + dock_.replan_failure);
    return PlanStatus::kCollides;
  }
  follower_.SetPath(plan.path, config_.controller.max_speed_mps, 0.0, last_v_cmd_);
  T_odom_goal_ = goal;
  ++path_version_;
  cmd->events.push_back("plan: goal " + Fmt(goal.x, 4) + "," + Fmt(goal.y, 4) + "," +
                        Fmt(goal.yaw, 4) + " straight " + Fmt(plan.straight_m, 2) + " m");
  return PlanStatus::kOk;
}

bool Docker::BendToGoal(const Pose2& T_odom_base, const Pose2& goal, double max_curvature_1pm,
                        Command* cmd) {
  if (!follower_.has_path()) return false;
  const double s_from = follower_.path().Project(T_odom_base).s;
  const std::optional<Path> bent = BendPathToGoal(follower_.path(), s_from, goal);
  if (!bent || bent->MaxAbsCurvature(s_from) > max_curvature_1pm) return false;
  if (!CheckPathAgainstLegs(*bent, LegDiscs(task_.model, tracker_.estimate()), config_.safety).ok) {
    return false;
  }
  follower_.SetPath(*bent, config_.controller.max_speed_mps, 0.0, last_v_cmd_);
  T_odom_goal_ = goal;
  ++path_version_;
  cmd->events.push_back("plan_bent: goal " + Fmt(goal.x, 4) + "," + Fmt(goal.y, 4) + "," +
                        Fmt(goal.yaw, 4) + ", " + Fmt(bent->Length() - s_from, 2) + " m ahead");
  return true;
}

Command Docker::Step(const Observations& obs) {
  Command cmd;
  odometry_.Add(obs.t_s, obs.T_odom_base);
  if (!started_) Start(obs, &cmd);
  const double dt = std::max(obs.t_s - last_t_, 1e-4);
  tracker_.AddOdometryMotion(last_T_odom_base_, obs.T_odom_base);
  if (obs.scan != nullptr) {
    ScanReturns returns = PlaceReturns(*obs.scan, obs.T_odom_base * config_.T_base_lidar);
    obstacle_returns_ =
        ObstacleReturns(returns, scan_returns_, config_.safety.obstacle_neighbour_gap_m);
    scan_returns_ = std::move(returns);
  }
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
        cmd.events.push_back("adjust_done");
        if (verify_.lift_after_adjust) {
          StartLift(obs.t_s, &cmd);
        } else {
          StartVerify(obs.t_s, &cmd);
        }
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
    case Phase::kAbort:
      cmd.velocity = BrakeCommand(dt);
      if (cmd.velocity.v_mps == 0.0) phase_ = Phase::kDone;
      break;
    case Phase::kDone:
      break;
  }
  last_v_cmd_ = cmd.velocity.v_mps;
  last_t_ = obs.t_s;
  last_T_odom_base_ = obs.T_odom_base;
  return cmd;
}

}  // namespace shelfdock::docking
