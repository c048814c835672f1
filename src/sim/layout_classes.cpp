#include "sim/layout_classes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/layout_obstacles.hpp"
#include "sim/layout_placement.hpp"
#include "sim/layout_rows.hpp"

namespace shelfdock::sim::layout {

namespace {
using Models = std::vector<geometry::ShelfModel>;

constexpr double kPi = std::numbers::pi;
constexpr int kFirstRowA = 1;    // shelf ids of the (first) row
constexpr int kFirstRowB = 101;  // shelf ids of the aisle's opposite row
constexpr double kUnbounded_m = 1e9;
constexpr double kMinClutterPresetRange_m = 1.0;  // an empty slot the robot was sent to

const geometry::ShelfModel& AnyModel(Context& c) { return c.models[c.rng.Index(c.models.size())]; }

const geometry::ShelfModel& RoundModel(const Models& models) {
  const auto it = std::find_if(models.begin(), models.end(), [](const geometry::ShelfModel& m) {
    return m.leg.shape == geometry::LegShape::kCircle;
  });
  return it != models.end() ? *it : models.front();
}

const geometry::ShelfModel& LargestModel(const Models& models) {
  return *std::max_element(models.begin(), models.end(), [](const auto& a, const auto& b) {
    return a.Diagonal() < b.Diagonal();
  });
}

ShelfInstance Shelf(const SceneBuilder& builder, int id) { return *builder.world().Shelf(id); }

/// A shelf on its own at the origin, any heading, drawn leg paint.
ShelfInstance AddLoneShelf(Context& c, const geometry::ShelfModel& model) {
  ShelfInstance shelf;
  shelf.id = kFirstRowA;
  shelf.model = model;
  shelf.T_world_shelf = geometry::Pose2(0.0, 0.0, c.rng.Angle());
  shelf.leg_material = DrawLegMaterial(c.rng, c.config);
  c.builder.AddShelf(shelf);
  return shelf;
}

/// One shelf, any heading, the sensor anywhere around it.
std::optional<Draft> BuildSingle(Context& c, const geometry::ShelfModel& model) {
  const ShelfInstance shelf = AddLoneShelf(c, model);
  const auto T_world_lidar =
      PlaceSensorFacing(c.builder, c.rng, shelf, -kPi, kPi, std::nullopt, c.config);
  if (!T_world_lidar) return std::nullopt;
  return Draft{*T_world_lidar, shelf.id, std::nullopt, -1, {}};
}

/// A row of `slots` with a wall or rack behind it half of the time (always with
/// `against_wall`, then a few centimetres behind the back legs), a target drawn from it and the
/// sensor in front of the row.
std::optional<Draft> BuildRow(Context& c, const std::vector<RowSlot>& slots,
                              bool against_wall = false) {
  const LayoutRow row = AddRow(c.builder, c.rng, {}, slots, kFirstRowA, c.config);
  if (against_wall) {
    AddRackBehind(c.builder, c.rng, row, c.config.wall_min_setback_m, c.config.wall_max_setback_m);
  } else if (c.rng.Chance(0.5)) {
    AddRackBehind(c.builder, c.rng, row, c.config.rack_min_setback_m, c.config.rack_max_setback_m);
  }
  const int target_id = row.shelf_ids[c.rng.Index(row.shelf_ids.size())];
  // In front: from the target's centre toward +y of the row, off the normal by up to a limit.
  const SensorBand band{row.T_world_row, c.config.sensor_clearance_m, kUnbounded_m};
  const double off = c.config.max_off_normal_rad;
  const auto T_world_lidar = PlaceSensorFacing(c.builder, c.rng, Shelf(c.builder, target_id),
                                               0.5 * kPi - off, 0.5 * kPi + off, band, c.config);
  if (!T_world_lidar) return std::nullopt;
  return Draft{*T_world_lidar, target_id, std::nullopt, -1, {row}};
}

std::vector<RowSlot> UniformRow(const geometry::ShelfModel& model, int count, bool along) {
  return std::vector<RowSlot>(static_cast<std::size_t>(count), RowSlot{&model, along});
}

int RowCount(Context& c) { return c.rng.Int(c.config.row_min_shelves, c.config.row_max_shelves); }

std::optional<Draft> BuildOneModelRow(Context& c, const geometry::ShelfModel& model) {
  const int count = RowCount(c);
  return BuildRow(c, UniformRow(model, count, c.rng.Chance(0.5)));
}

/// Neighbours differ in model (when there are two models to choose from); each shelf's
/// orientation is drawn on its own.
std::optional<Draft> BuildMixedRow(Context& c) {
  std::vector<RowSlot> slots;
  const int count = RowCount(c);
  for (int i = 0; i < count; ++i) {
    const geometry::ShelfModel* model = &AnyModel(c);
    while (c.models.size() > 1 && !slots.empty() && model->name == slots.back().model->name) {
      model = &AnyModel(c);
    }
    slots.push_back({model, c.rng.Chance(0.5)});
  }
  return BuildRow(c, slots);
}

/// Shelves pushed back against a wall or a rack: one shelf or a row of 3-6 (one model or
/// mixed), each turned either way, the sensor in front.
std::optional<Draft> BuildAgainstWall(Context& c) {
  const int count = c.rng.Chance(0.3) ? 1 : RowCount(c);
  std::vector<RowSlot> slots;
  const geometry::ShelfModel* model = &AnyModel(c);
  const bool mixed = c.rng.Chance(0.5);
  for (int i = 0; i < count; ++i) {
    if (mixed && i > 0) model = &AnyModel(c);
    slots.push_back({model, c.rng.Chance(0.5)});
  }
  return BuildRow(c, slots, true);
}

/// Two rows facing each other across the aisle (row A's frame: x along the aisle, y across
/// it), racks or walls behind both, people in the aisle, the sensor in the aisle.
std::optional<Draft> BuildAisle(Context& c) {
  const double width = c.rng.Uniform(c.config.aisle_min_width_m, c.config.aisle_max_width_m);
  auto count = [&c] { return c.rng.Int(c.config.aisle_min_shelves, c.config.aisle_max_shelves); };
  const geometry::ShelfModel& model_a = AnyModel(c);
  const int count_a = count();
  const auto slots_a = UniformRow(model_a, count_a, c.rng.Chance(0.5));
  const LayoutRow row_a = AddRow(c.builder, c.rng, {}, slots_a, kFirstRowA, c.config);
  // Row B runs back along -x from about row A's far end, so the rows overlap but not exactly.
  const double length_a = Shelf(c.builder, row_a.shelf_ids.back()).T_world_shelf.x;
  const geometry::Pose2 T_world_row_b(length_a + c.rng.Uniform(-1.0, 1.0), width, kPi);
  const geometry::ShelfModel& model_b = AnyModel(c);
  const int count_b = count();
  const auto slots_b = UniformRow(model_b, count_b, c.rng.Chance(0.5));
  const LayoutRow row_b = AddRow(c.builder, c.rng, T_world_row_b, slots_b, kFirstRowB, c.config);
  AddRackBehind(c.builder, c.rng, row_a, c.config.rack_min_setback_m, c.config.rack_max_setback_m);
  AddRackBehind(c.builder, c.rng, row_b, c.config.rack_min_setback_m, c.config.rack_max_setback_m);

  const LayoutRow& row = c.rng.Chance(0.5) ? row_a : row_b;
  const int target_id = row.shelf_ids[c.rng.Index(row.shelf_ids.size())];
  const double clearance = c.config.sensor_clearance_m;
  const SensorBand band{row.T_world_row, clearance, width - clearance};
  const double normal = row.T_world_row.yaw + 0.5 * kPi;
  const double off = c.config.max_off_normal_rad;
  const auto T_world_lidar = PlaceSensorFacing(c.builder, c.rng, Shelf(c.builder, target_id),
                                               normal - off, normal + off, band, c.config);
  if (!T_world_lidar) return std::nullopt;
  c.builder.KeepFree(T_world_lidar->translation(), c.config.person_clearance_m);
  AddAislePeople(c.builder, c.rng, {}, -1.0, T_world_row_b.x + 1.0, width, c.config);
  return Draft{*T_world_lidar, target_id, std::nullopt, -1, {row_a, row_b}};
}

/// A single shelf or a row of one model, half of the time each.
std::optional<Draft> BuildSingleOrRow(Context& c, const geometry::ShelfModel& model) {
  return c.rng.Chance(0.5) ? BuildSingle(c, model) : BuildOneModelRow(c, model);
}

std::optional<Draft> BuildOccludedLeg(Context& c) {
  auto draft = BuildSingleOrRow(c, AnyModel(c));
  if (!draft) return std::nullopt;
  c.builder.KeepFree(draft->T_world_lidar.translation(), c.config.sensor_clearance_m);
  const auto leg = AddOccluder(c.builder, c.rng, Shelf(c.builder, draft->target_id),
                               draft->T_world_lidar, c.config);
  if (!leg) return std::nullopt;
  draft->occluded_leg = *leg;
  return draft;
}

std::optional<Draft> BuildPersonBesideLeg(Context& c) {
  auto draft = BuildSingleOrRow(c, AnyModel(c));
  if (!draft) return std::nullopt;
  c.builder.KeepFree(draft->T_world_lidar.translation(), c.config.sensor_clearance_m);
  if (!AddPersonBesideLeg(c.builder, c.rng, Shelf(c.builder, draft->target_id),
                          draft->T_world_lidar, c.lidar, c.config)) {
    return std::nullopt;
  }
  return draft;
}

/// The largest model alone or in a row; the sensor near its centre, possibly under it.
std::optional<Draft> BuildLargeClose(Context& c) {
  const geometry::ShelfModel& model = LargestModel(c.models);
  Draft draft;
  draft.target_id = kFirstRowA;
  if (c.rng.Chance(0.5)) {
    AddLoneShelf(c, model);
  } else {
    const LayoutRow row =
        AddRow(c.builder, c.rng, {}, UniformRow(model, RowCount(c), true), kFirstRowA, c.config);
    draft.target_id = row.shelf_ids[c.rng.Index(row.shelf_ids.size())];
    draft.rows.push_back(row);
  }
  const auto T_world_lidar =
      PlaceSensorNear(c.builder, c.rng, Shelf(c.builder, draft.target_id),
                      c.config.large_close_radius_m, c.config.large_close_clearance_m);
  if (!T_world_lidar) return std::nullopt;
  draft.T_world_lidar = *T_world_lidar;
  return draft;
}

/// No shelf: the map still names one at the preset (most scenes) or the robot searches
/// without one; clutter all around.
std::optional<Draft> BuildClutter(Context& c) {
  Draft draft;
  draft.T_world_lidar = geometry::Pose2(0.0, 0.0, c.rng.Angle());
  c.builder.KeepFree(draft.T_world_lidar.translation(), c.config.sensor_clearance_m);
  if (c.rng.Chance(c.config.clutter_preset_share)) {
    const double range = c.rng.Uniform(kMinClutterPresetRange_m, c.config.max_standoff_m);
    const double bearing = c.rng.Uniform(-c.config.max_bearing_rad, c.config.max_bearing_rad);
    const Eigen::Vector2d p =
        draft.T_world_lidar * Eigen::Vector2d(range * std::cos(bearing), range * std::sin(bearing));
    draft.T_world_preset = geometry::Pose2(p.x(), p.y(), c.rng.Angle());
  }
  AddClutter(c.builder, c.rng, draft.T_world_lidar, draft.T_world_preset, c.config);
  return draft;
}
}  // namespace

std::optional<Draft> BuildClass(LayoutClass layout_class, Context& c) {
  switch (layout_class) {
    case LayoutClass::kOpen:
      return BuildSingle(c, AnyModel(c));
    case LayoutClass::kRow:
      return BuildOneModelRow(c, AnyModel(c));
    case LayoutClass::kAisle:
      return BuildAisle(c);
    case LayoutClass::kOccludedLeg:
      return BuildOccludedLeg(c);
    case LayoutClass::kPersonBesideLeg:
      return BuildPersonBesideLeg(c);
    case LayoutClass::kLargeClose:
      return BuildLargeClose(c);
    case LayoutClass::kMixedNeighbours:
      return BuildMixedRow(c);
    case LayoutClass::kRoundNoisy:
      return BuildSingleOrRow(c, RoundModel(c.models));
    case LayoutClass::kClutter:
      return BuildClutter(c);
    case LayoutClass::kAgainstWall:
      return BuildAgainstWall(c);
  }
  return std::nullopt;
}

}  // namespace shelfdock::sim::layout
