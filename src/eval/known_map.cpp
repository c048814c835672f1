#include "eval/known_map.hpp"

#include <cmath>

#include "docking/collision_check.hpp"

namespace shelfdock::eval {
namespace {

constexpr double kSpacing_m = 0.05;  ///< outline sampling
/// Discs this large centred on samples kSpacing_m apart cover the whole segment between them.
constexpr double kCover_m = 0.5 * kSpacing_m * 1.2;

void AddSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, docking::FreeSpace* out) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / kSpacing_m)));
  for (int i = 0; i <= n; ++i) {
    out->obstacles.push_back({a + (b - a) * (static_cast<double>(i) / n), kCover_m});
  }
}

void AddOutline(const std::vector<Eigen::Vector2d>& points, bool closed, docking::FreeSpace* out) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) AddSegment(points[i], points[i + 1], out);
  if (closed && points.size() > 2) AddSegment(points.back(), points.front(), out);
}

}  // namespace

docking::FreeSpace KnownObstacles(const sim::Scenario& scenario,
                                  const std::vector<geometry::ShelfModel>& models,
                                  std::uint64_t seed, bool shelf_outlines) {
  docking::FreeSpace map;
  const sim::World& world = scenario.world;
  for (const sim::Wall& wall : world.walls()) AddOutline(wall.points, wall.closed, &map);
  for (const sim::Box& box : world.boxes()) {
    std::vector<Eigen::Vector2d> corners;
    for (const auto& [sx, sy] : {std::pair{0.5, 0.5}, {-0.5, 0.5}, {-0.5, -0.5}, {0.5, -0.5}}) {
      corners.push_back(box.T_world_box * Eigen::Vector2d(sx * box.length_m, sy * box.width_m));
    }
    AddOutline(corners, true, &map);
  }
  for (const sim::RoundPost& post : world.round_posts()) {
    map.obstacles.push_back({post.centre, post.radius_m});
  }
  const auto target_preset = scenario.PresetPose(scenario.target_shelf_id, seed);
  for (const sim::ScenarioShelf& shelf : scenario.shelves) {
    if (shelf.id == scenario.target_shelf_id) continue;
    const auto preset = scenario.PresetPose(shelf.id, seed);
    // A map holds one shelf per place: one standing where the target is said to be is not in it
    // (the robot learns it is another shelf only from its code).
    constexpr double kSamePlace_m = 0.5;
    if (preset && target_preset &&
        (preset->translation() - target_preset->translation()).norm() < kSamePlace_m) {
      continue;
    }
    for (const geometry::ShelfModel& m : models) {
      if (m.name != shelf.model_name || !preset) continue;
      for (const docking::LegDisc& leg : docking::LegDiscs(m, *preset)) {
        map.obstacles.push_back(leg);
      }
      if (shelf_outlines) {
        std::vector<Eigen::Vector2d> corners;
        for (const Eigen::Vector2d& c : m.LegCentres()) corners.push_back(*preset * c);
        AddOutline(corners, true, &map);
      }
    }
  }
  return map;
}

}  // namespace shelfdock::eval
