#pragma once
// Internal to the layout generator: rows of shelves, the racks behind them, the room around.

#include <vector>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/layout_builder.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::sim::layout {

/// One shelf of a row to build: its model and whether its long side runs along the row.
struct RowSlot {
  const geometry::ShelfModel* model = nullptr;
  bool long_side_along_row = true;
};

/// Extents of a shelf's footprint (every leg's outer edge) around its centre, for a shelf
/// turned by `yaw_rad` in the frame the extents are taken in: (min, max).
void FootprintExtents(const geometry::ShelfModel& model, double yaw_rad, Eigen::Vector2d* min,
                      Eigen::Vector2d* max);

/// A painted (dark) or galvanised (shiny) leg, drawn per shelf.
Material DrawLegMaterial(SceneRng& rng, const LayoutConfig& config);

/// Shelves side by side in the row frame T_world_row: along x from x = 0, neighbouring
/// footprints a drawn gap apart (projected on x), front faces near y = 0 and the shelves on
/// the -y side; each turned and shifted by a little jitter. Ids count up from `first_id`.
LayoutRow AddRow(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_row,
                 const std::vector<RowSlot>& slots, int first_id, const LayoutConfig& config);

/// A wall, or a pallet rack (square uprights, pallets, a back wall), behind a row's back legs,
/// its front a drawn min_setback_m..max_setback_m behind them.
void AddRackBehind(SceneBuilder& builder, SceneRng& rng, const LayoutRow& row, double min_setback_m,
                   double max_setback_m);

/// Four walls around everything placed so far (and the discs kept free), axis-aligned in the
/// world frame, each 0.3-4 m beyond it.
void AddRoom(SceneBuilder& builder, SceneRng& rng);

}  // namespace shelfdock::sim::layout
