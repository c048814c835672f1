#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shelfdock::app {

/// Where the CLI looks for its default configs (models.yaml, camera.yaml, scenarios/...), first
/// match wins, so that it runs from any working directory, from the build tree or an install:
///   1. $SHELFDOCK_CONFIG_DIR, when set;
///   2. <directory of the executable>/../share/shelfdock/config (an install: bin/shelfdock);
///   3. the source tree's config/ (compiled in: a build tree's build/bin/shelfdock).
/// A path given on the command line is used as given (relative to the working directory).
std::vector<std::filesystem::path> ConfigSearchPath();

/// The default config `name` (e.g. "models.yaml", "scenarios/paper_docking.yaml"): its path in
/// the first directory of ConfigSearchPath() that holds it; "config/<name>" when none does (the
/// old working-directory-relative default, so the error names a path the user recognises).
std::string DefaultConfig(const std::string& name);

/// One paragraph for --help: the search order with the directories of this executable.
std::string ConfigSearchHelp();

}  // namespace shelfdock::app
