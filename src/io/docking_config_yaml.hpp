#pragma once

#include <string>

#include "docking/docking_config.hpp"

namespace shelfdock::io {

/// Reads a docking config (config/docking.yaml): every key optional, falling back to the
/// struct's default; unknown keys and impossible values throw InputError naming the key.
docking::DockingConfig ReadDockingConfig(const std::string& path);

}  // namespace shelfdock::io
