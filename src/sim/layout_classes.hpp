#pragma once
// Internal to the layout generator: one builder per scene class. Each places the class's
// shelves and objects into a SceneBuilder and decides where the sensor stands and which shelf
// is the target; GenerateLayoutScene adds the room, the preset and the sensor's line of sight.

#include <optional>
#include <vector>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/layout_builder.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::sim::layout {

/// What a class builder decides besides the world: where the sensor is, which shelf is meant.
struct Draft {
  geometry::Pose2 T_world_lidar;
  int target_id = -1;
  std::optional<geometry::Pose2> T_world_preset;  ///< clutter only; shelves get theirs drawn
  int occluded_leg = -1;
  std::vector<LayoutRow> rows;
};

/// What every class builder is handed.
struct Context {
  const std::vector<geometry::ShelfModel>& models;
  const LayoutConfig& config;
  const LidarConfig& lidar;
  SceneRng& rng;
  SceneBuilder& builder;
};

/// Builds a scene of `layout_class` into c.builder; nullopt when the draws left no room (the
/// caller starts over with a fresh stream).
std::optional<Draft> BuildClass(LayoutClass layout_class, Context& c);

}  // namespace shelfdock::sim::layout
