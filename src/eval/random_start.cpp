#include "eval/random_start.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "docking/free_space.hpp"
#include "eval/known_map.hpp"

namespace shelfdock::eval {

std::optional<geometry::Pose2> RandomStart(const sim::Scenario& scenario, std::uint64_t seed,
                                           double length_m, double width_m,
                                           const RandomStartConfig& config) {
  const std::optional<sim::ShelfInstance> target = scenario.world.Shelf(scenario.target_shelf_id);
  if (!target) return std::nullopt;
  // The true world as obstacles: the known map's walls, boxes and posts, and every shelf's true
  // legs (the target's too).
  sim::Scenario truth = scenario;
  for (sim::ScenarioShelf& s : truth.shelves) {
    s.T_map_shelf_preset = s.T_map_shelf;
  }
  std::vector<geometry::ShelfModel> models;
  for (const sim::ShelfInstance& s : scenario.world.shelves()) models.push_back(s.model);
  truth.target_shelf_id = -1;
  const docking::FreeSpace space = KnownObstacles(truth, models, seed, /*shelf_outlines=*/false);
  docking::SafetyConfig footprint;
  footprint.robot_length_m = length_m;
  footprint.robot_width_m = width_m;
  footprint.robot_offset_x_m = 0.0;

  Eigen::Vector2d lo = Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  if (!scenario.world.walls().empty()) {
    lo = -lo;
    hi = -hi;
    for (const sim::Wall& w : scenario.world.walls()) {
      for (const Eigen::Vector2d& p : w.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r0 = config.min_distance_m, r1 = config.max_distance_m;
  for (int i = 0; i < config.max_draws; ++i) {
    // Uniform in the annulus's area.
    const double r = std::sqrt(r0 * r0 + (r1 * r1 - r0 * r0) * unit(rng));
    const double bearing = 2.0 * std::numbers::pi * unit(rng);
    const double yaw = 2.0 * std::numbers::pi * unit(rng) - std::numbers::pi;
    const Eigen::Vector2d p = target->T_world_shelf.translation() +
                              r * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    const geometry::Pose2 pose(p.x(), p.y(), yaw);
    if (space.Clearance(pose, footprint) >= config.clearance_m) return pose;
  }
  return std::nullopt;
}

}  // namespace shelfdock::eval
