// The stop-and-recognise baseline's own stage: standing at the parking spot to recognise.
#include "docking/docker.hpp"

#include "docking/docker_detail.hpp"

namespace shelfdock::docking {

using detail::Fmt;
using detail::MeanPose;
using geometry::Pose2;

void Docker::StepStand(const Observations& obs, Command* cmd) {
  cmd->velocity = {};
  const bool settled = obs.t_s - phase_start_t_ >= config_.baseline.settle_s;
  if (obs.scan != nullptr) {
    if (!settled) {
      dock_.last_scan_t = obs.t_s;
      return;
    }
    ProcessScan(obs, true, cmd);
    ++stand_.scans;
  } else if (obs.t_s - dock_.last_scan_t > config_.scan_timeout_s) {
    Fail(OutcomeCode::kDetectionLost,
         "no LiDAR scan for " + Fmt(obs.t_s - dock_.last_scan_t, 2) + " s while parked", cmd);
    return;
  }
  if (stand_.scans < config_.baseline.standing_scans) return;
  if (!tracker_.has_detection()) {
    Fail(OutcomeCode::kShelfNotFound,
         "no shelf recognised in " + std::to_string(stand_.scans) + " scans at the parking spot",
         cmd);
    return;
  }
  dock_.goal_is_parking = false;
  dock_.lidar_in_use = false;
  phase_ = Phase::kDock;
  const PlanStatus status = Replan(obs.T_odom_base, GoalFromShelf(tracker_.estimate()), cmd);
  if (status != PlanStatus::kOk) {
    Fail(status == PlanStatus::kCollides ? OutcomeCode::kWouldCollide : OutcomeCode::kNoPath,
         "no path from the parking spot: " + dock_.replan_failure, cmd);
  }
}

}  // namespace shelfdock::docking
