// Detector parameters (config/detector.yaml, io::ReadDetectorConfig).
#include "fuzz_input_file.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadDetectorConfig(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("detector.yaml", Run)
