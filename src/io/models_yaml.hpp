#pragma once

#include <string>
#include <vector>

#include "geometry/shelf_model.hpp"

namespace shelfdock::io {

/// Reads shelf models from YAML (`models: [{name, length, width, leg: {shape, length, width}}]`).
/// Validates every field (positive sizes, length >= width, known shape, unique names) and throws
/// InputError naming the file and `models[i].field` otherwise.
std::vector<geometry::ShelfModel> ReadShelfModels(const std::string& path);

}  // namespace shelfdock::io
