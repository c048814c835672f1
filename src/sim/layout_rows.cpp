#include "sim/layout_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shelfdock::sim::layout {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Pallet racking as found behind shelf rows [m]: bay depth and width, upright section, pallet.
constexpr double kRackMinDepth_m = 0.8, kRackMaxDepth_m = 1.1;
constexpr double kRackMinBay_m = 1.8, kRackMaxBay_m = 2.8;
constexpr double kUprightMin_m = 0.08, kUprightMax_m = 0.12;
constexpr double kPalletLength_m = 1.2, kPalletWidth_m = 0.8;
// Walls of the room stand this far beyond everything placed [m]; a wall or rack behind a row
// reaches this far past its ends.
constexpr double kRoomMinMargin_m = 0.3, kRoomMaxMargin_m = 4.0;
constexpr double kRackMinOverhang_m = 0.3, kRackMaxOverhang_m = 1.5;

/// Footprint extents of the row's shelves in the row frame, over all of them (min, max).
void RowExtents(const World& world, const LayoutRow& row, Eigen::Vector2d* min,
                Eigen::Vector2d* max) {
  *min = Eigen::Vector2d::Constant(kInf);
  *max = Eigen::Vector2d::Constant(-kInf);
  const geometry::Pose2 T_row_world = row.T_world_row.inverse();
  for (int id : row.shelf_ids) {
    const auto shelf = world.Shelf(id);
    const geometry::Pose2 T_row_shelf = T_row_world * shelf->T_world_shelf;
    Eigen::Vector2d lo, hi;
    FootprintExtents(shelf->model, T_row_shelf.yaw, &lo, &hi);
    *min = min->cwiseMin(T_row_shelf.translation() + lo);
    *max = max->cwiseMax(T_row_shelf.translation() + hi);
  }
}

Material DrawWallMaterial(SceneRng& rng) { return Material{rng.Uniform(0.2, 0.9), false}; }

/// Pallet racking: square uprights at the front and back of each bay, a pallet on the floor
/// in some bays, a wall behind.
void AddRack(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_row, double x0,
             double x1, double front_y) {
  const double depth = rng.Uniform(kRackMinDepth_m, kRackMaxDepth_m);
  const double bay = rng.Uniform(kRackMinBay_m, kRackMaxBay_m);
  const double side = rng.Uniform(kUprightMin_m, kUprightMax_m);
  const Material material{rng.Uniform(0.2, 0.8), rng.Chance(0.3)};
  for (double x = x0; x <= x1; x += bay) {
    for (double y : {front_y - 0.5 * side, front_y - depth + 0.5 * side}) {
      Box upright;
      upright.T_world_box = T_world_row * geometry::Pose2(x, y, 0.0);
      upright.length_m = upright.width_m = side;
      upright.material = material;
      builder.AddBox(upright);
    }
    if (x + bay <= x1 && rng.Chance(0.6)) {
      Box pallet;
      pallet.length_m = std::min(kPalletLength_m, bay - side - 0.2);
      pallet.width_m = std::min(kPalletWidth_m, depth - 0.1);
      const double y = front_y - rng.Uniform(0.0, 0.1) - 0.5 * pallet.width_m;
      pallet.T_world_box = T_world_row * geometry::Pose2(x + 0.5 * bay, y, 0.0);
      pallet.material = DrawWallMaterial(rng);
      builder.AddBox(pallet);
    }
  }
  Wall back;
  back.points = {T_world_row * Eigen::Vector2d(x0, front_y - depth - 0.1),
                 T_world_row * Eigen::Vector2d(x1, front_y - depth - 0.1)};
  back.material = DrawWallMaterial(rng);
  builder.AddWall(back);
}
}  // namespace

void FootprintExtents(const geometry::ShelfModel& model, double yaw_rad, Eigen::Vector2d* min,
                      Eigen::Vector2d* max) {
  const geometry::Pose2 T(0.0, 0.0, yaw_rad);
  *min = Eigen::Vector2d::Constant(kInf);
  *max = Eigen::Vector2d::Constant(-kInf);
  const double hl = 0.5 * model.leg.length_m, hw = 0.5 * model.leg.width_m;
  for (const Eigen::Vector2d& c : model.LegCentres()) {
    if (model.leg.shape == geometry::LegShape::kCircle) {
      *min = min->cwiseMin(T * c - Eigen::Vector2d::Constant(hl));
      *max = max->cwiseMax(T * c + Eigen::Vector2d::Constant(hl));
      continue;
    }
    for (const Eigen::Vector2d& corner : {Eigen::Vector2d(-hl, -hw), Eigen::Vector2d(hl, -hw),
                                          Eigen::Vector2d(hl, hw), Eigen::Vector2d(-hl, hw)}) {
      *min = min->cwiseMin(T * Eigen::Vector2d(c + corner));
      *max = max->cwiseMax(T * Eigen::Vector2d(c + corner));
    }
  }
}

Material DrawLegMaterial(SceneRng& rng, const LayoutConfig& config) {
  return Material{rng.Uniform(config.leg_min_reflectivity, config.leg_max_reflectivity),
                  rng.Chance(config.shiny_leg_share)};
}

LayoutRow AddRow(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_row,
                 const std::vector<RowSlot>& slots, int first_id, const LayoutConfig& config) {
  LayoutRow row;
  row.T_world_row = T_world_row;
  double previous_max_x = 0.0;
  for (std::size_t i = 0; i < slots.size(); ++i) {
    const geometry::ShelfModel& model = *slots[i].model;
    // Heading is the long side's direction: along the row (0 or pi) or across it (+-pi/2).
    const double flip = rng.Chance(0.5) ? std::numbers::pi : 0.0;
    const double jitter = rng.Uniform(-config.row_jitter_yaw_rad, config.row_jitter_yaw_rad);
    const double yaw =
        (slots[i].long_side_along_row ? 0.0 : 0.5 * std::numbers::pi) + flip + jitter;
    Eigen::Vector2d lo, hi;
    FootprintExtents(model, yaw, &lo, &hi);
    const double gap = rng.Uniform(config.row_min_gap_m, config.row_max_gap_m);
    const double x = (i == 0 ? 0.0 : previous_max_x + gap) - lo.x();
    const double y = -hi.y() + rng.Uniform(-config.row_jitter_m, config.row_jitter_m);
    previous_max_x = x + hi.x();
    ShelfInstance shelf;
    shelf.id = first_id + static_cast<int>(i);
    shelf.model = model;
    shelf.T_world_shelf = T_world_row * geometry::Pose2(x, y, yaw);
    shelf.leg_material = DrawLegMaterial(rng, config);
    builder.AddShelf(shelf);
    row.shelf_ids.push_back(shelf.id);
  }
  return row;
}

void AddRackBehind(SceneBuilder& builder, SceneRng& rng, const LayoutRow& row, double min_setback_m,
                   double max_setback_m) {
  Eigen::Vector2d lo, hi;
  RowExtents(builder.world(), row, &lo, &hi);
  const double front_y = lo.y() - rng.Uniform(min_setback_m, max_setback_m);
  const double x0 = lo.x() - rng.Uniform(kRackMinOverhang_m, kRackMaxOverhang_m);
  const double x1 = hi.x() + rng.Uniform(kRackMinOverhang_m, kRackMaxOverhang_m);
  if (rng.Chance(0.5)) {
    AddRack(builder, rng, row.T_world_row, x0, x1, front_y);
    return;
  }
  Wall wall;
  wall.points = {row.T_world_row * Eigen::Vector2d(x0, front_y),
                 row.T_world_row * Eigen::Vector2d(x1, front_y)};
  wall.material = DrawWallMaterial(rng);
  builder.AddWall(wall);
}

void AddRoom(SceneBuilder& builder, SceneRng& rng) {
  Eigen::Vector2d lo, hi;
  builder.Bounds(&lo, &hi);
  auto margin = [&rng] { return rng.Uniform(kRoomMinMargin_m, kRoomMaxMargin_m); };
  lo.x() -= margin();
  lo.y() -= margin();
  hi.x() += margin();
  hi.y() += margin();
  Wall room;
  room.points = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  room.closed = true;
  room.material = DrawWallMaterial(rng);
  builder.AddWall(room);
}

}  // namespace shelfdock::sim::layout
