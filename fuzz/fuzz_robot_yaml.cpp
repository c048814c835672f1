// Robot config (config/robot.yaml, io::ReadRobotConfig).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/robot_yaml.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadRobotConfig(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("robot.yaml", Run)
