// LiDAR configs (config/lidar_*.yaml, io::ReadLidarConfig).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadLidarConfig(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("lidar.yaml", Run)
