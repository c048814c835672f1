// Shelf models (config/models.yaml, io::ReadShelfModels).
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"

namespace {
void Run(const std::string& path) { (void)shelfdock::io::ReadShelfModels(path); }
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("models.yaml", Run)
