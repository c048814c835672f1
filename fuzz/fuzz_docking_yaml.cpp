// Docking config (config/docking.yaml, io::ReadDockingConfig).
#include "fuzz_input_file.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/input_error.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadDockingConfig(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("docking.yaml", Run)
