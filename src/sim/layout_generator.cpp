#include "sim/layout_generator.hpp"

#include <cassert>
#include <utility>
#include <vector>

#include "sim/layout_builder.hpp"
#include "sim/layout_classes.hpp"
#include "sim/layout_placement.hpp"
#include "sim/layout_rows.hpp"
#include "sim/lidar.hpp"

namespace shelfdock::sim {

namespace {
using layout::SceneRng;

constexpr int kMaxAttempts = 1000;
/// The as-built legs' stream: after every class's (the class's value) and apart from them.
constexpr std::uint64_t kAsBuiltStream = 1000;

/// Moves every shelf's legs off their design places (LayoutConfig::leg_build_error_m, _twist_rad)
/// with draws of their own, so that the scene is otherwise its as-designed twin.
void BuildLegsWithErrors(World& world, std::uint64_t seed, std::uint64_t stream,
                         std::uint64_t attempt, const LayoutConfig& config) {
  if (config.leg_build_error_m <= 0.0 && config.leg_build_twist_rad <= 0.0) return;
  SceneRng rng(seed, kAsBuiltStream + stream, attempt);
  const double e = config.leg_build_error_m;
  const double t = config.leg_build_twist_rad;
  std::vector<std::pair<int, std::vector<geometry::Pose2>>> built;
  for (const ShelfInstance& shelf : world.shelves()) {
    std::vector<geometry::Pose2> legs;
    for (std::size_t i = 0; i < shelf.model.LegCentres().size(); ++i) {
      const double dx = rng.Uniform(-e, e);
      const double dy = rng.Uniform(-e, e);
      const double twist = rng.Uniform(-t, t);
      legs.emplace_back(dx, dy, twist);
    }
    built.emplace_back(shelf.id, std::move(legs));
  }
  world.SetLegsAsBuilt(std::move(built));
}

/// The scene's sensor: a drawn LiDAR with the scene's range noise.
NamedLidar DrawLidar(LayoutClass layout_class, SceneRng& rng, const LayoutConfig& config) {
  assert(!config.lidars.empty());
  NamedLidar lidar = config.lidars[rng.Index(config.lidars.size())];
  const bool high = layout_class == LayoutClass::kRoundNoisy || rng.Chance(config.high_noise_share);
  lidar.config.range_noise_sigma_m = high ? config.high_noise_sigma_m : config.noise_sigma_m;
  return lidar;
}
}  // namespace

std::string_view LayoutClassName(LayoutClass layout_class) {
  switch (layout_class) {
    case LayoutClass::kOpen:
      return "open";
    case LayoutClass::kRow:
      return "row";
    case LayoutClass::kAisle:
      return "aisle";
    case LayoutClass::kOccludedLeg:
      return "occluded_leg";
    case LayoutClass::kPersonBesideLeg:
      return "person_beside_leg";
    case LayoutClass::kLargeClose:
      return "large_close";
    case LayoutClass::kMixedNeighbours:
      return "mixed_neighbours";
    case LayoutClass::kRoundNoisy:
      return "round_noisy";
    case LayoutClass::kClutter:
      return "clutter";
    case LayoutClass::kAgainstWall:
      return "against_wall";
  }
  return "unknown";
}

std::optional<LayoutClass> ParseLayoutClass(std::string_view name) {
  for (LayoutClass c : kAllLayoutClasses) {
    if (LayoutClassName(c) == name) return c;
  }
  return std::nullopt;
}

std::optional<geometry::Pose2> LayoutScene::PresetInLidar() const {
  if (!T_world_preset) return std::nullopt;
  return T_world_lidar.inverse() * *T_world_preset;
}

LayoutScene GenerateLayoutScene(LayoutClass layout_class, std::uint64_t seed,
                                const std::vector<geometry::ShelfModel>& models,
                                const LayoutConfig& config) {
  assert(!models.empty());
  const auto stream = static_cast<std::uint64_t>(layout_class);
  // A draw that finds no room for the sensor or an occluder starts the scene over on the next
  // attempt's stream: still a function of (class, seed) alone.
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    SceneRng rng(seed, stream, static_cast<std::uint64_t>(attempt));
    const NamedLidar lidar = DrawLidar(layout_class, rng, config);
    layout::SceneBuilder builder;
    layout::Context context{models, config, lidar.config, rng, builder};
    const std::optional<layout::Draft> draft = layout::BuildClass(layout_class, context);
    if (!draft) continue;
    builder.KeepFree(draft->T_world_lidar.translation(), config.sensor_clearance_m);
    layout::AddRoom(builder, rng);

    LayoutScene scene;
    scene.layout_class = layout_class;
    scene.seed = seed;
    scene.T_world_lidar = draft->T_world_lidar;
    scene.target_shelf_id = draft->target_id;
    scene.occluded_leg = draft->occluded_leg;
    scene.rows = draft->rows;
    scene.lidar_name = lidar.name;
    scene.lidar = lidar.config;
    scene.scan_seed = rng.Bits();
    scene.world = builder.world();
    BuildLegsWithErrors(scene.world, seed, stream, static_cast<std::uint64_t>(attempt), config);
    scene.T_world_preset = draft->T_world_preset;
    if (const auto target = scene.Target()) {
      scene.T_world_preset = layout::DrawPreset(rng, *target, config);
      scene.target_sight =
          ComputeLegSight(scene.world, scene.T_world_lidar, scene.lidar, target->id);
      scene.target_legs_in_sight = scene.target_sight.LegsInSight(config.min_beams_in_sight);
      scene.target_standoff_m = layout::Standoff(*target, scene.T_world_lidar.translation());
    }
    return scene;
  }
  assert(false && "no layout scene could be built: the config's ranges leave no room");
  return {};
}

geometry::LaserScan SimulateLayoutScan(const LayoutScene& scene) {
  Lidar lidar(scene.lidar, scene.scan_seed);
  return lidar.Scan(scene.world, scene.T_world_lidar);
}

}  // namespace shelfdock::sim
