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

/// The models named in `names`, in that order, each once (all of `models` when `names` is empty):
/// when the map names the shelf's model, the detector looks for it alone. A name `models` (read
/// from `path`) lacks throws InputError naming `path`, `field` (the option that named it) and the
/// names it holds.
std::vector<geometry::ShelfModel> SelectModels(const std::vector<geometry::ShelfModel>& models,
                                               const std::vector<std::string>& names,
                                               const std::string& path, const std::string& field);

}  // namespace shelfdock::io
