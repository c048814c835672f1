// The default configs' search path: the CLI is the only place that needs it (the libraries take
// paths or structs), so it lives with the CLI.
#include "config_paths.hpp"

#include <cstdlib>
#include <system_error>

#ifndef SHELFDOCK_SOURCE_CONFIG_DIR
#error "SHELFDOCK_SOURCE_CONFIG_DIR must be defined by the build (the source tree's config/)"
#endif

namespace shelfdock::app {
namespace {

// bin/shelfdock -> bin; empty when the platform does not say (then only 1 and 3 apply).
std::filesystem::path ExecutableDir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

std::vector<std::filesystem::path> ConfigSearchPath() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("SHELFDOCK_CONFIG_DIR"); env != nullptr && *env != '\0') {
    dirs.emplace_back(env);
  }
  if (const auto bin = ExecutableDir(); !bin.empty()) {
    dirs.push_back((bin.parent_path() / "share" / "shelfdock" / "config").lexically_normal());
  }
  dirs.emplace_back(SHELFDOCK_SOURCE_CONFIG_DIR);
  return dirs;
}

std::string DefaultConfig(const std::string& name) {
  for (const auto& dir : ConfigSearchPath()) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(dir / name, ec)) return (dir / name).string();
  }
  return (std::filesystem::path("config") / name).string();
}

std::string ConfigSearchHelp() {
  std::string text =
      "Default configs (models.yaml, camera.yaml, scenarios/, ...) are looked up in, first "
      "match wins:";
  for (const auto& dir : ConfigSearchPath()) text += "\n  " + dir.string();
  text +=
      "\n($SHELFDOCK_CONFIG_DIR first when set; then the install's share/shelfdock/config next "
      "to this executable; then the source tree.) Paths given as options are used as given.";
  return text;
}

}  // namespace shelfdock::app
