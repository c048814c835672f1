#pragma once

#include <CLI/CLI.hpp>

namespace shelfdock::app {

/// Exit codes shared by every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   ///< the job ran but did not succeed (e.g. docking failed)
inline constexpr int kExitBadInput = 2;  ///< bad input: file, field or parameter

/// Each subcommand registers itself on the app and sets `*exit_code` when it runs. The run
/// callbacks may throw io::InputError; main turns that into kExitBadInput.
void AddDetectCommand(CLI::App& app, int* exit_code);
void AddBagCommand(CLI::App& app, int* exit_code);
void AddEvalRealCommand(CLI::App& app, int* exit_code);
void AddEvalLayoutsCommand(CLI::App& app, int* exit_code);
void AddSimulateCommand(CLI::App& app, int* exit_code);
void AddMarkerCommand(CLI::App& app, int* exit_code);
void AddDockCommands(CLI::App& app, int* exit_code);  ///< dock and eval-docking
void AddViewCommand(CLI::App& app, int* exit_code);   ///< view: records -> replay page
/// `eval` with its sub-subcommands `paper` and `peers` (cmd_eval*.cpp).
void AddEvalCommands(CLI::App& app, int* exit_code);
void AddEvalPaperCommand(CLI::App& eval, int* exit_code);
void AddEvalPeersCommand(CLI::App& eval, int* exit_code);
void AddEvalFaultsCommand(CLI::App& app, int* exit_code);  ///< eval faults

}  // namespace shelfdock::app
