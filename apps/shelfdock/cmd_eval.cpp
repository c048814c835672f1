// `shelfdock eval <experiment>`: the experiments that answer "does it reproduce the paper" and
// "is it better than what I would use instead". The dashed commands (eval-docking, eval-layouts,
// eval-real) stay as they are.
#include "commands.hpp"

namespace shelfdock::app {

void AddEvalCommands(CLI::App& app, int* exit_code) {
  CLI::App* eval = app.add_subcommand(
      "eval", "experiments: `eval paper` (the paper's section 4), `eval peers` (other methods)");
  eval->require_subcommand(1);
  AddEvalPaperCommand(*eval, exit_code);
  AddEvalPeersCommand(*eval, exit_code);
}

}  // namespace shelfdock::app
