#pragma once

#include <string>
#include <vector>

#include "geometry/shelf_model.hpp"

namespace shelfdock::io {

/// Reads shelf models from YAML (`models: [{name, length, width, leg: {shape, length, width}}]`).
/// Checks the models' rules (geometry::FindConfigViolation: positive sizes, length >= width,
/// unique names) and the leg shape's name, and throws InputError naming the file and
/// `models[i].field` otherwise.
std::vector<geometry::ShelfModel> ReadShelfModels(const std::string& path);

}  // namespace shelfdock::io
