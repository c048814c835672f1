#pragma once

#include "docking/docking_config.hpp"
#include "docking/path.hpp"

namespace shelfdock::docking {

/// A (v, w) command to the base.
struct VelocityCommand {
  double v_mps = 0.0;    ///< [m/s] forward speed
  double w_radps = 0.0;  ///< [rad/s] yaw rate
};

/// The tracker's command and where the robot stands against the path.
struct TrackingStatus {
  VelocityCommand command;
  bool reached = false;        ///< stopped at the goal (arc length reached)
  bool lost = false;           ///< farther off the path than max_cross_track_m
  double remaining_m = 0.0;    ///< [m] arc length to the goal (negative past it)
  double cross_track_m = 0.0;  ///< [m]
  double heading_error_rad = 0.0;
};

/// Follows a sampled path with a Frenet-frame feedback law and a speed profile that respects the
/// acceleration, deceleration, lateral-acceleration and yaw-rate limits and stops exactly where the
/// path's arc length ends. Lateral dynamics (distance domain, e_y'' + 2 w e_y' + w^2 e_y = 0):
///   w = v * (kappa_ref - 2 omega sin(e_theta) - omega^2 e_y),  omega = 1 / lateral_settle_m.
/// Speed: v = min(cruise, sqrt(v_end^2 + 2 a_dec r), sqrt(a_lat / |kappa_ahead|)), rate-limited.
class PathTracker {
 public:
  explicit PathTracker(const ControllerConfig& config = {}) : config_(config) {}

  /// Starts following `path` at `cruise_mps`, arriving with `end_speed_mps` (0: stop at the goal).
  /// `v_now_mps` is the current speed so a re-plan while moving keeps the speed continuous.
  /// `lateral_settle_m` > 0 replaces the config's lateral_settle_m for this path.
  void SetPath(Path path, double cruise_mps, double end_speed_mps, double v_now_mps,
               double lateral_settle_m = 0.0);

  /// One control step at pose `T_frame_base` (the path's frame), period dt.
  TrackingStatus Update(const geometry::Pose2& T_frame_base, double dt_s);

  const Path& path() const { return path_; }
  bool has_path() const { return !path_.empty(); }
  double last_speed_command() const { return v_cmd_; }
  void Clear() { path_.points.clear(); }

 private:
  double MaxCurvatureAhead(double s_from, double distance_m) const;

  ControllerConfig config_;
  Path path_;
  std::size_t hint_ = 0;
  double cruise_mps_ = 0.0;
  double end_speed_mps_ = 0.0;
  double v_cmd_ = 0.0;
  double lateral_settle_m_ = 0.0;  ///< [m] of the current path
};

}  // namespace shelfdock::docking
