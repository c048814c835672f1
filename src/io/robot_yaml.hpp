#pragma once

#include <string>

#include "sim/diff_drive_robot.hpp"

namespace shelfdock::io {

/// Reads a robot file (config/robot.yaml): the DiffDriveConfig fields, named exactly as the
/// struct's (max_v_mps, wheel_base_m, ...), and two maps named as its members, `odometry`
/// (OdometryNoiseConfig) and `localisation` (LocalisationNoiseConfig). Every key is optional;
/// SI units (m, rad, s). Throws InputError naming the file and the key.
sim::DiffDriveConfig ReadRobotConfig(const std::string& path);

}  // namespace shelfdock::io
