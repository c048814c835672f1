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

}  // namespace shelfdock::docking
