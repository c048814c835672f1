#pragma once

#include <cstdint>
#include <vector>

#include "docking/free_space.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/scenario.hpp"

namespace shelfdock::eval {

/// What a robot's map holds of a scenario, for the Docker's free-space reasoning: walls, boxes
/// and posts where they are, every other shelf's legs where its preset puts them (the map is
/// only as good as the presets), as discs in the map frame. With `shelf_outlines` the other
/// shelves are solid (their outline between the legs): no docking area or approach runs under
/// a shelf that is not the target. People and other robots are not in a map; the target shelf
/// is left out (the Docker places it itself).
docking::FreeSpace KnownObstacles(const sim::Scenario& scenario,
                                  const std::vector<geometry::ShelfModel>& models,
                                  std::uint64_t seed, bool shelf_outlines = true);

}  // namespace shelfdock::eval
