#pragma once

#include <string>

#include "sim/lidar_config.hpp"

namespace shelfdock::io {

/// Reads a LiDAR config (config/lidar_*.yaml): every key optional, named as the LidarConfig
/// field exactly (`angle_min_rad`, `range_noise_sigma_m`, ...), SI units (m, rad, Hz).
/// Absent keys keep the struct's defaults (the WLR-716). Throws InputError naming the key.
sim::LidarConfig ReadLidarConfig(const std::string& path);

}  // namespace shelfdock::io
