#include "docking/docker.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "docking/collision_check.hpp"
#include "docking/path_planner.hpp"
#include "geometry/angle.hpp"

namespace shelfdock::docking {
namespace {

using geometry::Pose2;

std::string Fmt(double v, int decimals = 3) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

/// Mean of poses around the first one (yaw averaged as differences, no wrap issues).
Pose2 MeanPose(const std::vector<Pose2>& poses) {
  double x = 0.0, y = 0.0, dyaw = 0.0;
  for (const Pose2& p : poses) {
    x += p.x;
    y += p.y;
    dyaw += geometry::AngleDiff(p.yaw, poses.front().yaw);
  }
  const double n = static_cast<double>(poses.size());
  return {x / n, y / n, poses.front().yaw + dyaw / n};
}

}  // namespace

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

void Docker::StartDocking(const Observations& obs, Command* cmd) {
  docking_start_t_ = obs.t_s;
  phase_ = Phase::kDock;
  cmd->events.push_back("docking_area_entered: " + std::string(ToString(method_)));
  T_odom_map_ = obs.T_odom_base * obs.T_map_base_estimate.inverse();
  tracker_.SetPrior(T_odom_map_ * task_.T_map_shelf_preset);
  lidar_in_use_ = method_ == Method::kContinuous;
  last_detection_t_ = obs.t_s;
  last_scan_t_ = obs.t_s;
  Pose2 target = GoalFromShelf(tracker_.estimate());
  if (method_ == Method::kStopAndRecognise) {
    goal_is_parking_ = true;
    target = target * Pose2(-config_.baseline.parking_distance_m, 0.0, 0.0);
  }
  if (Replan(obs.T_odom_base, target, cmd) != PlanStatus::kOk) {
    Fail(OutcomeCode::kWouldCollide, "no safe path into the docking area: " + replan_failure_, cmd);
  }
}

bool Docker::LidarStillUseful(const Pose2& T_odom_base) const {
  const Pose2 T_lidar_shelf = (T_odom_base * config_.T_base_lidar).inverse() * tracker_.estimate();
  int visible = 0;
  for (const Eigen::Vector2d& c : task_.model.LegCentres()) {
    const Eigen::Vector2d p = T_lidar_shelf * c;
    const double bearing = std::atan2(p.y(), p.x());
    if (p.norm() >= config_.leg_min_range_m && std::abs(bearing) <= config_.leg_max_bearing_rad) {
      ++visible;
    }
  }
  return visible >= 3;
}

void Docker::ProcessScan(const Observations& obs, bool recognise, Command* cmd) {
  last_scan_t_ = obs.t_s;
  const geometry::LaserScan& scan = *obs.scan;
  const std::vector<perception::ScanPoint> points =
      CompensatedPoints(scan, odometry_, config_.T_base_lidar, obs.t_s);
  const Pose2 T_odom_lidar = obs.T_odom_base * config_.T_base_lidar;

  // Safety first: unknown points (not the shelf's legs) on the path ahead stop the robot.
  if (follower_.has_path() && phase_ == Phase::kDock) {
    std::vector<Eigen::Vector2d> p_odom;
    p_odom.reserve(points.size());
    for (const auto& sp : points) p_odom.push_back(T_odom_lidar * sp.p);
    const double s_now = follower_.path().Project(obs.T_odom_base).s;
    const double s_blocked =
        FirstBlockedArcLength(follower_.path(), s_now, p_odom,
                              LegDiscs(task_.model, tracker_.estimate()), config_.safety);
    if (s_blocked >= 0.0 && blocked_since_t_ < 0.0) {
      blocked_since_t_ = obs.t_s;
      cmd->events.push_back("path_blocked: obstacle " + Fmt(s_blocked - s_now, 2) + " m ahead");
    } else if (s_blocked < 0.0 && blocked_since_t_ >= 0.0) {
      blocked_since_t_ = -1.0;
      follower_.SetPath(follower_.path(), config_.controller.max_speed_mps, 0.0, last_v_cmd_);
      cmd->events.push_back("path_clear");
    }
  }
  if (!recognise || points.empty()) return;

  const Pose2 T_lidar_preset = T_odom_lidar.inverse() * tracker_.estimate();
  const perception::DetectionResult result =
      detect_(points, scan.angle_increment, std::optional<Pose2>(T_lidar_preset));
  if (result.detections.empty()) return;
  const perception::Detection& det = result.detections.front();
  if (!task_.model.name.empty() && det.model != task_.model.name) {
    cmd->events.push_back("detection_ignored: model " + det.model);
    return;
  }
  const Pose2 T_odom_shelf = T_odom_lidar * det.T_lidar_shelf;
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  J.topLeftCorner<2, 2>() = T_odom_lidar.rotation();
  const TrackUpdate update = tracker_.Add(T_odom_shelf, J * det.covariance * J.transpose());
  if (update == TrackUpdate::kRejected) {
    cmd->events.push_back("detection_rejected: jump from the fused estimate");
    return;
  }
  last_detection_ = T_odom_shelf;
  last_detection_t_ = obs.t_s;
  cmd->events.push_back("detection: " + det.model + " legs " + std::to_string(det.legs_used) +
                        (update == TrackUpdate::kReinitialised ? " (track restarted)" : ""));
  if (goal_is_parking_) return;

  // Paper 3.5: compare each recognition with the current path's end; re-plan beyond a threshold.
  const Pose2 goal = GoalFromShelf(tracker_.estimate());
  const Pose2 diff = T_odom_goal_.inverse() * goal;
  if (std::hypot(diff.x, diff.y) <= config_.replan_xy_m &&
      std::abs(diff.yaw) <= config_.replan_yaw_rad) {
    return;
  }
  if (replans_ >= config_.max_replans) {
    Fail(OutcomeCode::kTooManyReplans,
         "the goal kept moving: " + std::to_string(replans_) + " re-plans", cmd);
    return;
  }
  ++replans_;
  const PlanStatus status = Replan(obs.T_odom_base, goal, cmd);
  if (status == PlanStatus::kCollides) {
    Fail(OutcomeCode::kWouldCollide, replan_failure_, cmd);
  } else if (status == PlanStatus::kInfeasible) {
    // Keep the current path unless it would now touch a leg.
    const ClearanceResult c = CheckPathAgainstLegs(
        follower_.path(), LegDiscs(task_.model, tracker_.estimate()), config_.safety);
    if (!c.ok) {
      Fail(OutcomeCode::kWouldCollide,
           "cannot re-plan (" + replan_failure_ + ") and the current path passes " +
               Fmt(c.min_clearance_m) + " m from a leg",
           cmd);
    }
  }
}

Pose2 Docker::TagGoal(const Pose2& T_tag_base) const {
  // The code is at the shelf centre along its long side; the goal is T_shelf_goal_ up to the
  // code's own pi (which end the robot came from).
  Pose2 T_tag_goal = T_shelf_goal_;
  if (std::abs(geometry::AngleDiff(T_tag_base.yaw, T_tag_goal.yaw)) > 0.5 * std::numbers::pi) {
    T_tag_goal = T_tag_goal * Pose2(0.0, 0.0, std::numbers::pi);
  }
  return T_tag_goal;
}

void Docker::GuideByCode(const Observations& obs, Command* cmd) {
  const CameraGuideConfig& g = config_.camera_guide;
  if (!obs.marker || obs.marker->id != task_.shelf_id) return;  // the check at the goal reports
  // The camera sits at the base origin: the code's pose in odom from this frame's odometry.
  // Averaging over frames taken along the last decimetres (odometry drift there is sub-mm).
  guide_tags_.push_back(obs.T_odom_base * obs.marker->T_camera_tag);
  if (static_cast<int>(guide_tags_.size()) < g.frames) return;
  const Pose2 T_odom_tag = MeanPose(guide_tags_);
  const Pose2 goal = T_odom_tag * TagGoal(T_odom_tag.inverse() * obs.T_odom_base);
  const double remaining_m = -(T_odom_goal_.inverse() * obs.T_odom_base).x;
  if (remaining_m < g.min_remaining_m) return;
  const Pose2 diff = T_odom_goal_.inverse() * goal;
  if (std::hypot(diff.x, diff.y) <= g.replan_xy_m && std::abs(diff.yaw) <= g.replan_yaw_rad) return;
  // A short Bezier straight onto the corrected goal: no final straight is left at this point,
  // and the curvature bound is the tracker's (slow speed), not the approach's.
  PlannerConfig planner = config_.planner;
  planner.min_final_straight_m = 0.0;
  planner.final_straight_m = std::min(planner.final_straight_m, 0.5 * remaining_m);
  planner.max_curvature_1pm = g.max_curvature_1pm;
  const Pose2 lidar_goal = T_odom_goal_;
  if (Replan(obs.T_odom_base, goal, cmd, &planner) != PlanStatus::kOk) return;
  if (!lidar_goal_before_camera_) lidar_goal_before_camera_ = lidar_goal;
  ++camera_corrections_;
  cmd->events.push_back("camera_guide: goal moved " + Fmt(diff.x, 4) + "," + Fmt(diff.y, 4) + "," +
                        Fmt(diff.yaw, 4) + " from " + std::to_string(guide_tags_.size()) +
                        " code readings, " + Fmt(remaining_m, 3) + " m to go");
}

bool Docker::StartAdjustFromGuide(const Observations& obs, Command* cmd) {
  if (guide_tags_.empty() || adjust_tries_ >= config_.verify.max_adjust_tries) return false;
  // The code seen on the way in (paper 3.5: the camera "in advance") already tells where the goal
  // is; odometry over the last centimetres carries it to the stop. Beyond the tolerance, adjust
  // at once instead of first standing for a check; the check after the adjustment verifies.
  const Pose2 T_odom_tag = MeanPose(guide_tags_);
  const Pose2 T_odom_goal = T_odom_tag * TagGoal(T_odom_tag.inverse() * obs.T_odom_base);
  const Pose2 offset = T_odom_goal.inverse() * obs.T_odom_base;
  const VerifyConfig& v = config_.verify;
  const bool xy_ok =
      std::abs(offset.x) <= v.tolerance_xy_m && std::abs(offset.y) <= v.tolerance_xy_m;
  if (xy_ok && std::abs(offset.yaw) <= v.tolerance_yaw_rad) return false;
  if (std::hypot(offset.x, offset.y) > v.max_correction_m) return false;  // the check decides
  ++adjust_tries_;
  // Within the position tolerance only the heading is corrected (a turn in place).
  adjust_.Start(obs.T_odom_base,
                xy_ok ? obs.T_odom_base * Pose2(0.0, 0.0, -offset.yaw) : T_odom_goal);
  phase_ = Phase::kAdjust;
  cmd->events.push_back("adjust: try " + std::to_string(adjust_tries_) +
                        " from the code seen on the way in, offset " + Fmt(offset.x, 4) + "," +
                        Fmt(offset.y, 4) + "," + Fmt(offset.yaw, 4));
  return true;
}

void Docker::StepDock(const Observations& obs, Command* cmd) {
  const double dt = std::max(obs.t_s - last_t_, 1e-4);
  if (obs.scan != nullptr) {
    ProcessScan(obs, lidar_in_use_, cmd);
    if (phase_ != Phase::kDock) return;
  }
  if (lidar_in_use_ && obs.t_s - last_scan_t_ > config_.scan_timeout_s) {
    Fail(OutcomeCode::kDetectionLost,
         "no LiDAR scan for " + Fmt(obs.t_s - last_scan_t_, 2) + " s while docking", cmd);
    return;
  }
  if (lidar_in_use_ && tracker_.has_detection() &&
      obs.t_s - last_detection_t_ > config_.detection_lost_s) {
    Fail(OutcomeCode::kDetectionLost,
         "the shelf was not recognised for " + Fmt(obs.t_s - last_detection_t_, 2) +
             " s while it was still needed",
         cmd);
    return;
  }
  if (blocked_since_t_ >= 0.0) {
    if (obs.t_s - blocked_since_t_ > config_.safety.obstacle_wait_s) {
      Fail(OutcomeCode::kWouldCollide,
           "an obstacle blocked the path for " + Fmt(obs.t_s - blocked_since_t_, 1) + " s", cmd);
      return;
    }
    const double v = std::max(0.0, last_v_cmd_ - 1.5 * config_.controller.max_decel_mps2 * dt);
    cmd->velocity = {v, 0.0};
    return;
  }
  if (obs.camera_frame && !goal_is_parking_ && !lidar_in_use_ && config_.camera_guide.enabled) {
    GuideByCode(obs, cmd);
    if (phase_ != Phase::kDock) return;
  }
  const TrackingStatus status = follower_.Update(obs.T_odom_base, dt);
  if (lidar_in_use_ && !tracker_.has_detection() && status.remaining_m < config_.must_detect_by_m &&
      !goal_is_parking_) {
    Fail(OutcomeCode::kShelfNotFound,
         "no shelf recognised within " + Fmt(obs.t_s - docking_start_t_, 1) +
             " s of entering the docking area",
         cmd);
    return;
  }
  if (status.lost) {
    Fail(OutcomeCode::kWouldCollide,
         "the robot left the planned path by " + Fmt(status.cross_track_m) + " m", cmd);
    return;
  }
  if (lidar_in_use_ && tracker_.has_detection() &&
      (status.remaining_m < config_.lidar_cutoff_m || !LidarStillUseful(obs.T_odom_base))) {
    lidar_in_use_ = false;
    cmd->events.push_back("lidar_off: legs too close to recognise, " + Fmt(status.remaining_m, 2) +
                          " m to go on odometry");
  }
  if (status.reached) {
    cmd->velocity = {};
    phase_start_t_ = obs.t_s;
    if (goal_is_parking_) {
      phase_ = Phase::kStand;
      standing_scans_ = 0;
      last_scan_t_ = obs.t_s;
      cmd->events.push_back("parked: recognising while standing");
    } else if (!StartAdjustFromGuide(obs, cmd)) {
      phase_ = Phase::kVerify;
      code_readings_.clear();
      missing_frames_ = 0;
      cmd->camera_on = true;
      cmd->events.push_back("goal_reached: checking the code");
    }
    return;
  }
  cmd->velocity = status.command;
  cmd->camera_on = !goal_is_parking_ && config_.camera_guide.enabled &&
                   status.remaining_m < config_.camera_guide.camera_on_m;
}

void Docker::StepStand(const Observations& obs, Command* cmd) {
  cmd->velocity = {};
  const bool settled = obs.t_s - phase_start_t_ >= config_.baseline.settle_s;
  if (obs.scan != nullptr) {
    if (!settled) {
      last_scan_t_ = obs.t_s;
      return;
    }
    ProcessScan(obs, true, cmd);
    ++standing_scans_;
  } else if (obs.t_s - last_scan_t_ > config_.scan_timeout_s) {
    Fail(OutcomeCode::kDetectionLost,
         "no LiDAR scan for " + Fmt(obs.t_s - last_scan_t_, 2) + " s while parked", cmd);
    return;
  }
  if (standing_scans_ < config_.baseline.standing_scans) return;
  if (!tracker_.has_detection()) {
    Fail(OutcomeCode::kShelfNotFound,
         "no shelf recognised in " + std::to_string(standing_scans_) + " scans at the parking spot",
         cmd);
    return;
  }
  goal_is_parking_ = false;
  lidar_in_use_ = false;
  phase_ = Phase::kDock;
  if (Replan(obs.T_odom_base, GoalFromShelf(tracker_.estimate()), cmd) != PlanStatus::kOk) {
    Fail(OutcomeCode::kWouldCollide, "no safe path from the parking spot: " + replan_failure_, cmd);
  }
}

void Docker::StepVerify(const Observations& obs, Command* cmd) {
  cmd->velocity = {};
  cmd->camera_on = true;
  if (!obs.camera_frame) return;
  if (!obs.marker) {
    if (++missing_frames_ > config_.verify.max_missing_frames) {
      Fail(OutcomeCode::kCodeNotFound,
           "no code seen under the shelf in " + std::to_string(missing_frames_) + " frames", cmd);
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
  code_readings_.push_back(obs.marker->T_camera_tag);  // camera at the base origin
  if (static_cast<int>(code_readings_.size()) < config_.verify.frames) return;

  const Pose2 T_tag_base = MeanPose(code_readings_).inverse();
  code_readings_.clear();
  const Pose2 T_tag_goal = TagGoal(T_tag_base);
  const Pose2 offset = T_tag_goal.inverse() * T_tag_base;
  code_offset_ = offset;
  cmd->events.push_back("code_check: offset " + Fmt(offset.x, 4) + "," + Fmt(offset.y, 4) + "," +
                        Fmt(offset.yaw, 4));
  const double xy = std::hypot(offset.x, offset.y);
  const bool within = std::abs(offset.x) <= config_.verify.tolerance_xy_m &&
                      std::abs(offset.y) <= config_.verify.tolerance_xy_m &&
                      std::abs(offset.yaw) <= config_.verify.tolerance_yaw_rad;
  if (within || adjust_tries_ >= config_.verify.max_adjust_tries) {
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
  ++adjust_tries_;
  adjust_.Start(obs.T_odom_base, obs.T_odom_base * offset.inverse());
  phase_ = Phase::kAdjust;
  cmd->camera_on = false;
  cmd->events.push_back("adjust: try " + std::to_string(adjust_tries_));
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
      const PlanResult plan =
          PlanDockingPath(obs.T_map_base_estimate, T_map_entry, config_.planner);
      if (!plan.ok) {
        Fail(OutcomeCode::kWouldCollide, "no approach path to the docking area: " + plan.reason,
             &cmd);
      } else {
        follower_.SetPath(plan.path, config_.controller.approach_speed_mps,
                          config_.controller.max_speed_mps, 0.0);
        ++path_version_;
        cmd.events.push_back("approach: planned to the docking area's entry");
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
    case Phase::kApproach: {
      const TrackingStatus s = follower_.Update(obs.T_map_base_estimate, dt);
      if (s.reached) {
        StartDocking(obs, &cmd);
        if (phase_ == Phase::kDock) StepDock(obs, &cmd);
      } else if (s.lost) {
        Fail(OutcomeCode::kWouldCollide, "the robot left the approach path", &cmd);
      } else {
        cmd.velocity = s.command;
      }
      break;
    }
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

}  // namespace shelfdock::docking
