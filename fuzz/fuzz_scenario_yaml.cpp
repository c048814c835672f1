// Simulator scenarios (config/scenarios/*.yaml, io::ReadScenario) against the paper's models.
#include "common/paper_models.hpp"
#include "fuzz_input_file.hpp"
#include "io/input_error.hpp"
#include "io/scenario_yaml.hpp"

namespace {
void Run(const std::string& path) {
  static const std::vector<shelfdock::geometry::ShelfModel> models =
      shelfdock::testing::PaperModels();
  (void)shelfdock::io::ReadScenario(path, models);
}
}  // namespace

SHELFDOCK_FUZZ_FILE_TARGET("scenario.yaml", Run)
