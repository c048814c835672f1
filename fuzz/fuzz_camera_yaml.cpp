// Camera setup (config/camera.yaml, io::ReadCameraSetup).
#include "fuzz_input_file.hpp"
#include "io/camera_yaml.hpp"
#include "io/input_error.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadCameraSetup(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("camera.yaml", Run)
