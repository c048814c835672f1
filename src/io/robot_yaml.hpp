#pragma once

#include <string>

#include "sim/diff_drive_robot.hpp"

namespace shelfdock::io {

/// Reads a robot file (config/robot.yaml): the DiffDriveConfig fields without their unit
/// suffixes (max_v, max_w, max_accel, max_alpha, wheel_base, footprint_length,
/// footprint_width, control_rate, lift_duration, history) and two maps, `odometry`
/// (wheel_scale_std, wheel_base_scale_std, slip_std) and `localisation` (noise_std_xy,
/// noise_std_yaw, bias_std_xy, bias_std_yaw, bias_time_constant, update_rate). Every key is
/// optional; SI units (m, rad, s). Throws InputError naming the file and the key.
sim::DiffDriveConfig ReadRobotConfig(const std::string& path);

}  // namespace shelfdock::io
