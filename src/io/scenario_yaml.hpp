#pragma once

#include <string>
#include <vector>

#include "geometry/shelf_model.hpp"
#include "sim/scenario.hpp"

namespace shelfdock::io {

/// Reads a simulator scenario (schema at the top of config/scenarios/*.yaml). Shelf models are
/// looked up by name in `models`. Throws InputError naming the file and the key path (e.g.
/// `shelves[1].pose.yaw`) on a missing file, malformed YAML, unknown key, wrong type or
/// impossible value.
sim::Scenario ReadScenario(const std::string& path,
                           const std::vector<geometry::ShelfModel>& models);

}  // namespace shelfdock::io
