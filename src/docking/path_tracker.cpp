#include "docking/path_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace shelfdock::docking {

void PathTracker::SetPath(Path path, double cruise_mps, double end_speed_mps, double v_now_mps,
                          double lateral_settle_m) {
  path_ = std::move(path);
  lateral_settle_m_ = lateral_settle_m > 0.0 ? lateral_settle_m : config_.lateral_settle_m;
  hint_ = 0;
  cruise_mps_ = cruise_mps;
  end_speed_mps_ = end_speed_mps;
  v_cmd_ = std::max(0.0, v_now_mps);
}

double PathTracker::MaxCurvatureAhead(double s_from, double distance_m) const {
  double k = 0.0;
  for (std::size_t i = hint_; i < path_.points.size(); ++i) {
    if (path_.points[i].s > s_from + distance_m) break;
    k = std::max(k, std::abs(path_.points[i].curvature));
  }
  return k;
}

TrackingStatus PathTracker::Update(const geometry::Pose2& T_frame_base, double dt_s) {
  TrackingStatus status;
  if (path_.empty()) return status;
  const PathProjection proj = path_.Project(T_frame_base, hint_);
  hint_ = proj.index;
  status.remaining_m = path_.Length() - proj.s;
  status.cross_track_m = proj.cross_track_m;
  status.heading_error_rad = proj.heading_error_rad;
  if (std::abs(proj.cross_track_m) > config_.max_cross_track_m) {
    status.lost = true;
    v_cmd_ = 0.0;
    return status;
  }

  // Stop once the goal's arc length is reached, or would be within half a step.
  const bool stopping = end_speed_mps_ <= 0.0;
  if (stopping && status.remaining_m <= std::max(config_.goal_tolerance_m, 0.5 * v_cmd_ * dt_s)) {
    status.reached = true;
    v_cmd_ = 0.0;
    return status;
  }
  if (!stopping && status.remaining_m <= 0.0) {
    status.reached = true;
    status.command = {v_cmd_, 0.0};
    return status;
  }

  // Speed profile: cruise, braking distance, curvature ahead within the braking distance.
  const double r = std::max(0.0, status.remaining_m - config_.goal_tolerance_m);
  double v_target = std::min(
      cruise_mps_, std::sqrt(end_speed_mps_ * end_speed_mps_ + 2.0 * config_.max_decel_mps2 * r));
  const double look = v_cmd_ * v_cmd_ / (2.0 * config_.max_decel_mps2) + 0.1;
  const double k_ahead = MaxCurvatureAhead(proj.s, look);
  if (k_ahead > 1e-6) {
    v_target = std::min(v_target, std::sqrt(config_.max_lateral_accel_mps2 / k_ahead));
    // A sharp short path (a camera correction close in) must also fit the yaw-rate limit.
    v_target = std::min(v_target, 0.8 * config_.max_yaw_rate_radps / k_ahead);
  }
  if (stopping) v_target = std::max(v_target, std::min(config_.creep_speed_mps, cruise_mps_));
  // Rate limits; braking may use a little more than the profile's deceleration.
  const double dv_up = config_.max_accel_mps2 * dt_s;
  const double dv_down = 1.5 * config_.max_decel_mps2 * dt_s;
  v_cmd_ = std::clamp(v_target, v_cmd_ - dv_down, v_cmd_ + dv_up);
  v_cmd_ = std::max(v_cmd_, 0.0);

  // Frenet feedback law (see header), then yaw-rate and lateral-acceleration limits.
  const double omega = 1.0 / lateral_settle_m_;
  double curvature = proj.curvature - 2.0 * omega * std::sin(proj.heading_error_rad) -
                     omega * omega * proj.cross_track_m;
  // The last centimetres before a stop: what lateral error is left can no longer be removed
  // without turning away from the goal heading (1 mm over 1 cm is 0.1 rad), so the heading alone
  // is steered onto the path's, and the robot stops aligned instead of needing a turn after.
  if (stopping && status.remaining_m < config_.heading_priority_m) {
    curvature = proj.curvature - std::sin(proj.heading_error_rad) / config_.heading_settle_m;
  }
  double w = v_cmd_ * curvature;
  double w_max = config_.max_yaw_rate_radps;
  if (v_cmd_ > 1e-6) w_max = std::min(w_max, config_.max_lateral_accel_mps2 / v_cmd_);
  w = std::clamp(w, -w_max, w_max);
  status.command = {v_cmd_, w};
  return status;
}

}  // namespace shelfdock::docking
