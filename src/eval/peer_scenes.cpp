#include "eval/peer_scenes.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "eval/size_experiment.hpp"
#include "sim/layout_generator.hpp"
#include "sim/lidar.hpp"
#include "sim/world.hpp"

namespace shelfdock::eval {
namespace {

using geometry::Pose2;

/// Layout scenes whose target shows fewer legs are left out: no method can find it.
constexpr int kMinLegsInSight = 3;

void AddRoom(sim::World& world) {
  world.AddWall({{-5.0, -5.0}, {7.0, -5.0}, {7.0, 5.0}, {-5.0, 5.0}}, true);
}

PeerScene Scan(const sim::World& world, const sim::LidarConfig& lidar, std::uint64_t seed,
               const geometry::ShelfModel& model, const Pose2& truth,
               const std::optional<Pose2>& preset) {
  sim::Lidar sensor(lidar, seed);
  return {seed, sensor.Scan(world, Pose2()), model.name, model.HeadingPeriod(), truth, preset};
}

/// A layout scene as a peer scene (the scene's own sensor with `lidar`'s flaws and its noise).
PeerScene FromLayout(const sim::LayoutScene& scene, std::uint64_t seed) {
  const sim::ShelfInstance target = *scene.Target();
  const Pose2 truth = scene.T_world_lidar.inverse() * target.T_world_shelf;
  return {seed,  sim::SimulateLayoutScan(scene), target.model.name, target.model.HeadingPeriod(),
          truth, scene.PresetInLidar()};
}

sim::LayoutConfig LayoutFor(const sim::LidarConfig& lidar) {
  sim::LayoutConfig layout;
  layout.lidars = {sim::NamedLidar{"peers", lidar}};
  layout.noise_sigma_m = lidar.range_noise_sigma_m;
  layout.high_noise_share = 0.0;
  return layout;
}

}  // namespace

PeerSceneSet PaperSetupScenes(const std::vector<geometry::ShelfModel>& models,
                              const sim::LidarConfig& lidar, const PeerScenesConfig& config) {
  // The same placement rule as RunSizeExperiment (Table 1).
  PeerSceneSet set{"paper set-up (0.5 m)", {}};
  const SizeExperimentConfig size;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const geometry::ShelfModel& model = models[m];
    std::mt19937_64 rng(config.seed0 + 100 * m);
    std::uniform_real_distribution<double> jitter(-size.jitter_rad, size.jitter_rad);
    for (int i = 0; i < config.paper_per_model; ++i) {
      const bool broadside = i % 2 == 1;
      const double yaw = (broadside ? 0.5 * std::numbers::pi : 0.0) + jitter(rng);
      const double bearing = jitter(rng);
      const double d = size.standoff_m + 0.5 * (broadside ? model.width_m : model.length_m);
      const Pose2 truth(d * std::cos(bearing), d * std::sin(bearing), bearing + yaw);
      sim::World world;
      AddRoom(world);
      world.AddShelf(1, model, truth);
      set.scenes.push_back(Scan(world, lidar,
                                config.seed0 + 100 * m + static_cast<std::uint64_t>(i), model,
                                truth, truth));
    }
  }
  return set;
}

PeerSceneSet SweepScenes(const std::vector<geometry::ShelfModel>& models,
                         const sim::LidarConfig& lidar, const PeerScenesConfig& config) {
  PeerSceneSet set{"Table 1 sweep 0.5-3.5 m", {}};
  std::mt19937_64 rng(config.seed0);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < config.sweep_scenes; ++i) {
    const geometry::ShelfModel& model = models[i % models.size()];
    const double standoff = 0.5 + 3.0 * u01(rng);
    const double yaw = -std::numbers::pi + 2.0 * std::numbers::pi * u01(rng);
    const double bearing = -0.8 + 1.6 * u01(rng);
    // The nearest leg `standoff` from the sensor: the centre is half a diagonal behind it at most;
    // place the centre at standoff + half the width (the leg line faces the sensor).
    const double d = standoff + 0.5 * model.width_m;
    const Pose2 truth(d * std::cos(bearing), d * std::sin(bearing), yaw);
    const double r = config.preset_error_xy_m * std::sqrt(u01(rng));
    const double phi = 2.0 * std::numbers::pi * u01(rng);
    const Pose2 preset(truth.x + r * std::cos(phi), truth.y + r * std::sin(phi),
                       truth.yaw + config.preset_error_yaw_rad * (2.0 * u01(rng) - 1.0));
    sim::World world;
    AddRoom(world);
    world.AddShelf(1, model, truth);
    set.scenes.push_back(Scan(world, lidar, config.seed0 + 1000 + static_cast<std::uint64_t>(i),
                              model, truth, preset));
  }
  return set;
}

PeerSceneSet RowScenes(const std::vector<geometry::ShelfModel>& models,
                       const sim::LidarConfig& lidar, const PeerScenesConfig& config) {
  PeerSceneSet set{"rows of shelves", {}};
  const sim::LayoutConfig layout = LayoutFor(lidar);
  for (std::uint64_t seed = config.seed0; static_cast<int>(set.scenes.size()) < config.row_scenes;
       ++seed) {
    const sim::LayoutScene scene =
        sim::GenerateLayoutScene(sim::LayoutClass::kRow, seed, models, layout);
    if (scene.target_legs_in_sight >= kMinLegsInSight)
      set.scenes.push_back(FromLayout(scene, seed));
  }
  return set;
}

PeerSceneSet ClutterScenes(const std::vector<geometry::ShelfModel>& models,
                           const sim::LidarConfig& lidar, int posts,
                           const PeerScenesConfig& config) {
  PeerSceneSet set{"clutter " + std::to_string(posts) + " posts", {}};
  const sim::LayoutConfig layout = LayoutFor(lidar);
  for (std::uint64_t seed = config.seed0;
       static_cast<int>(set.scenes.size()) < config.clutter_scenes; ++seed) {
    sim::LayoutScene scene =
        sim::GenerateLayoutScene(sim::LayoutClass::kOpen, seed, models, layout);
    if (scene.target_legs_in_sight < kMinLegsInSight) continue;
    const sim::ShelfInstance target = *scene.Target();
    std::mt19937_64 rng(seed * 7919 + static_cast<std::uint64_t>(posts));
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double keep_out = 0.5 * target.model.Diagonal() + 0.15;
    int placed = 0;
    for (int draw = 0; placed < posts && draw < 100 * posts; ++draw) {
      const double r = config.clutter_radius_m * std::sqrt(u01(rng));
      const double a = 2.0 * std::numbers::pi * u01(rng);
      const Eigen::Vector2d c =
          scene.T_world_lidar * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
      if (r < layout.sensor_clearance_m) continue;
      if ((c - target.T_world_shelf.translation()).norm() < keep_out) continue;
      const double diameter = config.post_min_diameter_m +
                              (config.post_max_diameter_m - config.post_min_diameter_m) * u01(rng);
      scene.world.AddRoundPost(c, 0.5 * diameter);
      ++placed;
    }
    set.scenes.push_back(FromLayout(scene, seed));
  }
  return set;
}

std::vector<PeerSceneSet> AllPeerSceneSets(const std::vector<geometry::ShelfModel>& models,
                                           const sim::LidarConfig& lidar,
                                           const PeerScenesConfig& config) {
  std::vector<PeerSceneSet> sets = {PaperSetupScenes(models, lidar, config),
                                    SweepScenes(models, lidar, config),
                                    RowScenes(models, lidar, config)};
  for (int posts : config.clutter_posts)
    sets.push_back(ClutterScenes(models, lidar, posts, config));
  return sets;
}

}  // namespace shelfdock::eval
