// Autonomous docking stage (paper 3.5): the entry, recognition at the scan rate while moving,
// re-planning when the goal moves, and the hand-over to odometry when the legs get too close.
#include "docking/docker.hpp"

#include <cmath>

#include "docking/collision_check.hpp"
#include "docking/path_planner.hpp"

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

}  // namespace shelfdock::docking
