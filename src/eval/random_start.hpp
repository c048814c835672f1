#pragma once

#include <cstdint>
#include <optional>

#include "geometry/pose2.hpp"
#include "sim/scenario.hpp"

namespace shelfdock::eval {

/// Where random starts are drawn: anywhere in free space around the target shelf.
struct RandomStartConfig {
  double min_distance_m = 0.3;  ///< [m] robot centre to the target shelf's centre, at least
  double max_distance_m = 8.0;  ///< [m] and at most
  double clearance_m = 0.03;    ///< [m] the footprint keeps this from every true obstacle
  int max_draws = 10000;        ///< draws before giving up (a scene without free space)
};

/// A start pose drawn for `seed`: uniform in the annulus around the target shelf's true centre
/// (inside the bounding box of the scenario's walls when it has any), any heading, with the
/// footprint (`length_m` x `width_m`, centred on the base) clear of walls, boxes, posts and
/// every shelf's legs. nullopt when no draw was clear.
std::optional<geometry::Pose2> RandomStart(const sim::Scenario& scenario, std::uint64_t seed,
                                           double length_m, double width_m,
                                           const RandomStartConfig& config = {});

}  // namespace shelfdock::eval
