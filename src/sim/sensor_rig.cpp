#include "sim/sensor_rig.hpp"

#include <cmath>

namespace shelfdock::sim {

using geometry::Pose2;

std::optional<ShelfInstance> ShelfAbove(const World& world, const Pose2& T_world_base) {
  for (const ShelfInstance& s : world.shelves()) {
    const Pose2 local = s.T_world_shelf.inverse() * T_world_base;
    if (std::abs(local.x) < 0.5 * s.model.length_m && std::abs(local.y) < 0.5 * s.model.width_m) {
      return s;
    }
  }
  return std::nullopt;
}

SensorRig::SensorRig(const LidarConfig& lidar, const CameraConfig& camera,
                     const SensorRigConfig& config, const Pose2& T_base_lidar, std::uint64_t seed,
                     double t0_s)
    : lidar_config_(lidar),
      camera_(camera),
      config_(config),
      T_base_lidar_(T_base_lidar),
      seed_(seed),
      lidar_(lidar, seed * 7919 + 1),
      next_scan_t0_s_(t0_s),
      next_camera_t_s_(t0_s) {}

SensorReadings SensorRig::Sense(const World& world, const DiffDriveRobot& robot, double t_s,
                                double since_entry_s, bool camera_on) {
  SensorReadings out;
  const double scan_period = lidar_config_.ScanPeriod();
  if (t_s + 1e-9 >= next_scan_t0_s_ + scan_period) {
    const double t0 = next_scan_t0_s_;
    next_scan_t0_s_ += scan_period;
    const bool blackout = config_.blackout_start_s >= 0.0 && std::isfinite(since_entry_s) &&
                          since_entry_s >= config_.blackout_start_s &&
                          since_entry_s < config_.blackout_start_s + config_.blackout_duration_s;
    if (!blackout) {
      scan_ = lidar_.Scan(
          world, [&](double ti) { return robot.T_world_base_at(ti) * T_base_lidar_; }, t0);
      out.scan = &scan_;
    }
  }
  if (camera_on && t_s + 1e-9 >= next_camera_t_s_) {
    next_camera_t_s_ = t_s + 1.0 / config_.camera_rate_hz;
    out.camera_frame = true;
    const auto above =
        config_.camera_blind ? std::nullopt : ShelfAbove(world, robot.T_world_base());
    if (above) {
      out.image =
          RenderMarker(camera_, above->id, TagInCamera(robot.T_world_base(), above->T_world_shelf),
                       seed_ * 1000003 + static_cast<std::uint64_t>(++camera_frames_));
    }
  }
  return out;
}

}  // namespace shelfdock::sim
