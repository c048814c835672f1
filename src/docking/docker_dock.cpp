// Autonomous docking stage (paper 3.5): the entry, recognition at the scan rate while moving,
// re-planning when the goal moves, and the hand-over to odometry when the legs get too close.
#include "docking/docker.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "docking/collision_check.hpp"
#include "docking/path_planner.hpp"
#include "perception/known_legs.hpp"

#include "docking/docker_detail.hpp"

namespace shelfdock::docking {

using detail::Fmt;
using detail::MeanPose;
using geometry::Pose2;

void Docker::StartDocking(const Observations& obs, Command* cmd) {
  docking_start_t_ = obs.t_s;
  phase_ = Phase::kDock;
  cmd->events.push_back("docking_area_entered: " + std::string(ToString(method_)));
  T_odom_map_ = obs.T_odom_base * obs.T_map_base_estimate.inverse();
  tracker_.SetPrior(T_odom_map_ * task_.T_map_shelf_preset);
  dock_.T_odom_shelf_preset = T_odom_map_ * task_.T_map_shelf_preset;
  dock_.lidar_in_use = method_ == Method::kContinuous;
  dock_.last_detection_t = obs.t_s;
  dock_.last_scan_t = obs.t_s;
  Pose2 target = GoalFromShelf(tracker_.estimate());
  if (method_ == Method::kStopAndRecognise) {
    dock_.goal_is_parking = true;
    target = target * Pose2(-config_.baseline.parking_distance_m, 0.0, 0.0);
  }
  const PlanStatus status = Replan(obs.T_odom_base, target, cmd);
  if (status != PlanStatus::kOk) {
    Fail(status == PlanStatus::kCollides ? OutcomeCode::kWouldCollide : OutcomeCode::kNoPath,
         "no path into the docking area: " + dock_.replan_failure, cmd);
    return;
  }
  dock_.first_goal = T_odom_goal_;
}

bool Docker::ReplanJustified() const {
  if (!dock_.first_goal) return true;
  const Pose2 moved = dock_.first_goal->inverse() * T_odom_goal_;
  const double explained = std::hypot(moved.x, moved.y) / config_.replan_xy_m +
                           std::abs(moved.yaw) / config_.replan_yaw_rad;
  return dock_.replans < config_.max_replans + static_cast<int>(explained);
}

std::array<bool, 4> Docker::TrustedLegs(const Pose2& T_odom_base) const {
  const Pose2 T_lidar_shelf = (T_odom_base * config_.T_base_lidar).inverse() * tracker_.estimate();
  std::array<bool, 4> trusted{};
  const auto corners = task_.model.LegCentres();
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector2d p = T_lidar_shelf * corners[k];
    const double bearing = std::atan2(p.y(), p.x());
    trusted[k] =
        p.norm() >= config_.leg_min_range_m && std::abs(bearing) <= config_.leg_max_bearing_rad;
  }
  return trusted;
}

void Docker::ProcessScan(const Observations& obs, bool recognise, Command* cmd) {
  dock_.last_scan_t = obs.t_s;
  const geometry::LaserScan& scan = *obs.scan;
  const std::vector<perception::ScanPoint> points =
      CompensatedPoints(scan, odometry_, config_.T_base_lidar, obs.t_s);
  const Pose2 T_odom_lidar = obs.T_odom_base * config_.T_base_lidar;

  // Safety first: unknown points (not the shelf's legs) on the path ahead stop the robot.
  if (follower_.has_path() && phase_ == Phase::kDock) {
    std::vector<Eigen::Vector2d> p_odom;
    p_odom.reserve(points.size());
    for (const auto& sp : points) {
      const auto beam = static_cast<std::size_t>(sp.beam);
      if (beam < obstacle_returns_.size() && obstacle_returns_[beam]) {
        p_odom.push_back(T_odom_lidar * sp.p);
      }
    }
    const double s_now = follower_.path().Project(obs.T_odom_base).s;
    const double s_blocked =
        FirstBlockedArcLength(follower_.path(), s_now, p_odom,
                              LegDiscs(task_.model, tracker_.estimate()), config_.safety);
    if (s_blocked >= 0.0 && dock_.blocked_since_t < 0.0) {
      dock_.blocked_since_t = obs.t_s;
      cmd->events.push_back("path_blocked: obstacle " + Fmt(s_blocked - s_now, 2) + " m ahead");
    } else if (s_blocked < 0.0 && dock_.blocked_since_t >= 0.0) {
      dock_.blocked_since_t = -1.0;
      follower_.SetPath(follower_.path(), config_.controller.max_speed_mps, 0.0, last_v_cmd_);
      cmd->events.push_back("path_clear");
    }
  }
  if (!recognise || points.empty()) return;

  const Pose2 T_lidar_preset = T_odom_lidar.inverse() * tracker_.estimate();
  if (dock_.two_leg_tracking) {
    // Two legs left in view: re-measure the tracked shelf from them (the detector would need
    // three to find it).
    const auto measured = perception::MeasureKnownLegs(points, T_lidar_preset, task_.model,
                                                       TrustedLegs(obs.T_odom_base));
    if (!measured) return;
    FuseShelf(obs, T_odom_lidar * measured->T_lidar_shelf, T_odom_lidar, measured->covariance,
              "two legs", cmd);
    return;
  }
  const perception::DetectionResult result =
      detect_(points, scan.angle_increment, std::optional<Pose2>(T_lidar_preset));
  if (result.detections.empty()) return;
  // The detection of this shelf: the right model, where the preset allows it to be (a neighbour
  // in an aisle is farther than that), nearest the fused estimate.
  const perception::Detection* chosen = nullptr;
  double chosen_m = 0.0;
  for (const perception::Detection& d : result.detections) {
    if (!task_.model.name.empty() && d.model != task_.model.name) continue;
    const Pose2 T_odom_d = T_odom_lidar * d.T_lidar_shelf;
    const double from_preset_m =
        (T_odom_d.translation() - dock_.T_odom_shelf_preset.translation()).norm();
    if (from_preset_m > config_.tracker.preset_gate_sigmas * config_.tracker.preset_sigma_xy_m) {
      continue;
    }
    const double from_estimate_m =
        (T_odom_d.translation() - tracker_.estimate().translation()).norm();
    if (chosen == nullptr || from_estimate_m < chosen_m) {
      chosen = &d;
      chosen_m = from_estimate_m;
    }
  }
  if (chosen == nullptr) {
    cmd->events.push_back("detection_ignored: model " + result.detections.front().model +
                          " or too far from the preset");
    return;
  }
  const perception::Detection& det = *chosen;
  // The fit's pose, which the covariance describes (the refined pose's heading tail was worse).
  FuseShelf(obs, T_odom_lidar * det.FusionPose(), T_odom_lidar, det.covariance,
            det.model + " legs " + std::to_string(det.legs_used), cmd);
}

void Docker::FuseShelf(const Observations& obs, const Pose2& T_odom_shelf,
                       const Pose2& T_odom_lidar, const Eigen::Matrix3d& covariance_lidar,
                       const std::string& what, Command* cmd) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  J.topLeftCorner<2, 2>() = T_odom_lidar.rotation();
  const TrackUpdate update = tracker_.Add(T_odom_shelf, J * covariance_lidar * J.transpose());
  if (update == TrackUpdate::kRejected) {
    cmd->events.push_back("detection_rejected: jump from the fused estimate");
    return;
  }
  dock_.last_detection = T_odom_shelf;
  dock_.last_detection_t = obs.t_s;
  cmd->events.push_back("detection: " + what +
                        (update == TrackUpdate::kReinitialised ? " (track restarted)" : ""));
  if (dock_.goal_is_parking) return;

  // Paper 3.5: compare each recognition with the current path's end; re-plan beyond a threshold.
  const Pose2 goal = GoalFromShelf(tracker_.estimate());
  const Pose2 diff = T_odom_goal_.inverse() * goal;
  if (std::hypot(diff.x, diff.y) <= config_.replan_xy_m &&
      std::abs(diff.yaw) <= config_.replan_yaw_rad) {
    return;
  }
  if (!ReplanJustified()) {
    Fail(OutcomeCode::kTooManyReplans,
         "the goal kept moving back and forth: " + std::to_string(dock_.replans) +
             " re-plans, more than its net movement explains",
         cmd);
    return;
  }
  ++dock_.replans;
  // The goal moved: bend the path the robot is on to it, or plan afresh when the bend would
  // need more than the planner's curvature bound.
  if (BendToGoal(obs.T_odom_base, goal, config_.planner.max_curvature_1pm, cmd)) return;
  const PlanStatus status = Replan(obs.T_odom_base, goal, cmd);
  if (status == PlanStatus::kCollides) {
    Fail(OutcomeCode::kWouldCollide, dock_.replan_failure, cmd);
  } else if (status == PlanStatus::kInfeasible) {
    // Keep the current path unless it would now touch a leg.
    const ClearanceResult c = CheckPathAgainstLegs(
        follower_.path(), LegDiscs(task_.model, tracker_.estimate()), config_.safety);
    if (!c.ok) {
      Fail(OutcomeCode::kWouldCollide,
           "cannot re-plan (" + dock_.replan_failure + ") and the current path passes " +
               Fmt(c.min_clearance_m) + " m from a leg",
           cmd);
    }
  }
}

void Docker::StepDock(const Observations& obs, Command* cmd) {
  const double dt = std::max(obs.t_s - last_t_, 1e-4);
  if (obs.scan != nullptr) {
    ProcessScan(obs, dock_.lidar_in_use, cmd);
    if (phase_ != Phase::kDock) return;
  }
  // A silent LiDAR stops the robot until its scans return (a blackout of a second leaves docking
  // possible); silent for detection_lost_s, it is dead and the shelf lost.
  const double silent_s = obs.t_s - dock_.last_scan_t;
  if (dock_.lidar_in_use && silent_s > config_.detection_lost_s) {
    Fail(OutcomeCode::kDetectionLost, "no LiDAR scan for " + Fmt(silent_s, 2) + " s while docking",
         cmd);
    return;
  }
  if (dock_.lidar_in_use && silent_s > config_.scan_timeout_s) {
    if (!dock_.lidar_silent) {
      dock_.lidar_silent = true;
      cmd->events.push_back("lidar_silent: no scan for " + Fmt(silent_s, 2) +
                            " s, stopping until scans return");
    }
    cmd->velocity = BrakeCommand(dt);
    return;
  }
  if (dock_.lidar_silent) {
    dock_.lidar_silent = false;
    follower_.SetPath(follower_.path(), config_.controller.max_speed_mps, 0.0, last_v_cmd_);
    cmd->events.push_back("lidar_back");
  }
  if (dock_.lidar_in_use && tracker_.has_detection() &&
      obs.t_s - dock_.last_detection_t > config_.detection_lost_s) {
    Fail(OutcomeCode::kDetectionLost,
         "the shelf was not recognised for " + Fmt(obs.t_s - dock_.last_detection_t, 2) +
             " s while it was still needed",
         cmd);
    return;
  }
  if (dock_.blocked_since_t >= 0.0) {
    if (obs.t_s - dock_.blocked_since_t > config_.safety.obstacle_wait_s) {
      Fail(OutcomeCode::kWouldCollide,
           "an obstacle blocked the path for " + Fmt(obs.t_s - dock_.blocked_since_t, 1) + " s",
           cmd);
      return;
    }
    cmd->velocity = BrakeCommand(dt);
    return;
  }
  if (obs.camera_frame && !dock_.goal_is_parking && config_.camera_guide.enabled) {
    // The code under the shelf is the better guide from the moment the camera reads it: the
    // LiDAR hands over then (or at lidar_cutoff_m, whichever comes first), so the camera has as
    // much of the straight as it can get to correct the goal.
    if (dock_.lidar_in_use && obs.marker && obs.marker->id == task_.shelf_id) {
      dock_.lidar_in_use = false;
      cmd->events.push_back("lidar_off: the camera reads the code");
    }
    if (!dock_.lidar_in_use) GuideByCode(obs, cmd);
    if (phase_ != Phase::kDock) return;
  }
  const TrackingStatus status = follower_.Update(obs.T_odom_base, dt);
  if (dock_.lidar_in_use && !tracker_.has_detection() &&
      status.remaining_m < config_.must_detect_by_m && !dock_.goal_is_parking) {
    Fail(OutcomeCode::kShelfNotFound,
         "no shelf recognised within " + Fmt(obs.t_s - docking_start_t_, 1) +
             " s of entering the docking area",
         cmd);
    return;
  }
  if (status.lost) {
    Fail(OutcomeCode::kTrackingFailed,
         "the robot left the planned path by " + Fmt(status.cross_track_m) + " m", cmd);
    return;
  }
  if (dock_.lidar_in_use && tracker_.has_detection()) {
    const std::array<bool, 4> trusted = TrustedLegs(obs.T_odom_base);
    const int legs = static_cast<int>(std::count(trusted.begin(), trusted.end(), true));
    if (status.remaining_m < config_.lidar_cutoff_m || legs < 2 ||
        (legs < 3 && !config_.two_leg_tracking)) {
      dock_.lidar_in_use = false;
      cmd->events.push_back("lidar_off: legs too close to recognise, " +
                            Fmt(status.remaining_m, 2) + " m to go on odometry");
    } else if (legs < 3 && !dock_.two_leg_tracking) {
      dock_.two_leg_tracking = true;
      cmd->events.push_back("two_leg_tracking: two legs left in view, " +
                            Fmt(status.remaining_m, 2) + " m to go");
    }
  }
  if (status.reached) {
    cmd->velocity = {};
    phase_start_t_ = obs.t_s;
    if (dock_.goal_is_parking) {
      phase_ = Phase::kStand;
      stand_.scans = 0;
      dock_.last_scan_t = obs.t_s;
      cmd->events.push_back("parked: recognising while standing");
    } else if (!StartAdjustFromGuide(obs, cmd)) {
      StartVerify(obs.t_s, cmd);
      cmd->events.push_back("goal_reached: checking the code");
    }
    return;
  }
  cmd->velocity = status.command;
  cmd->camera_on = !dock_.goal_is_parking && config_.camera_guide.enabled &&
                   status.remaining_m < config_.camera_guide.camera_on_m;
}

}  // namespace shelfdock::docking
