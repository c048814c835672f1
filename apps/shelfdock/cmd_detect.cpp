// Temporary: replaced by the detector's implementation.
#include "commands.hpp"

namespace shelfdock::app {
void AddDetectCommand(CLI::App& app, int* exit_code) {
  app.add_subcommand("detect", "detect shelves in scans")->callback([exit_code] {
    *exit_code = kExitFailure;
  });
}
}  // namespace shelfdock::app
