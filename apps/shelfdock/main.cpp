// shelfdock: one executable, one subcommand per job. main only wires subcommands and maps
// errors to exit codes; each subcommand lives in its own cmd_*.cpp.
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "io/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"shelfdock: find a shelf with a 2D LiDAR and dock under it"};
  app.set_version_flag("--version", std::string("shelfdock ") + SHELFDOCK_VERSION);
  // `--version` alone is a complete command line; everything else names one subcommand.
  app.require_subcommand(0, 1);
  app.footer(shelfdock::app::ConfigSearchHelp());  // subcommands added below inherit it
  int exit_code = shelfdock::app::kExitOk;
  shelfdock::app::AddDetectCommand(app, &exit_code);
  shelfdock::app::AddBagCommand(app, &exit_code);
  shelfdock::app::AddEvalRealCommand(app, &exit_code);
  shelfdock::app::AddEvalLayoutsCommand(app, &exit_code);
  shelfdock::app::AddSimulateCommand(app, &exit_code);
  shelfdock::app::AddMarkerCommand(app, &exit_code);
  shelfdock::app::AddDockCommands(app, &exit_code);
  shelfdock::app::AddViewCommand(app, &exit_code);
  shelfdock::app::AddEvalCommands(app, &exit_code);
  shelfdock::app::AddEvalFaultsCommand(app, &exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with exit 0; a bad argument gets the one error style.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "error: " << shelfdock::app::kCommandLine << ": " << e.what() << "\n";
    return shelfdock::app::kExitBadInput;
  } catch (const shelfdock::io::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return shelfdock::app::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return shelfdock::app::kExitFailure;
  }
  if (app.get_subcommands().empty()) {
    std::cerr << "error: " << shelfdock::app::kCommandLine
              << ": a subcommand is required (shelfdock --help lists them)\n";
    return shelfdock::app::kExitBadInput;
  }
  return exit_code;
}
