// shelfdock: one executable, one subcommand per job. main only wires subcommands and maps
// errors to exit codes; each subcommand lives in its own cmd_*.cpp.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "io/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shelfdock: find a shelf with a 2D LiDAR and dock under it"};
  app.require_subcommand(1);
  int exit_code = shelfdock::app::kExitOk;
  shelfdock::app::AddDetectCommand(app, &exit_code);
  shelfdock::app::AddBagCommand(app, &exit_code);
  shelfdock::app::AddEvalRealCommand(app, &exit_code);
  shelfdock::app::AddEvalLayoutsCommand(app, &exit_code);
  shelfdock::app::AddSimulateCommand(app, &exit_code);
  shelfdock::app::AddMarkerCommand(app, &exit_code);
  shelfdock::app::AddDockCommands(app, &exit_code);
  shelfdock::app::AddEvalFaultsCommand(app, &exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : shelfdock::app::kExitBadInput;
  } catch (const shelfdock::io::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return shelfdock::app::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return shelfdock::app::kExitFailure;
  }
  return exit_code;
}
