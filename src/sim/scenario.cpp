#include "sim/scenario.hpp"

#include <random>

namespace shelfdock::sim {

const ScenarioShelf* Scenario::FindShelf(int id) const {
  for (const ScenarioShelf& s : shelves) {
    if (s.id == id) return &s;
  }
  return nullptr;
}

std::optional<geometry::Pose2> Scenario::PresetPose(int shelf_id, std::uint64_t seed) const {
  const ScenarioShelf* shelf = FindShelf(shelf_id);
  if (shelf == nullptr) return std::nullopt;
  if (shelf->T_map_shelf_preset) return *shelf->T_map_shelf_preset;
  if (shelf->preset_offset_xy_m <= 0.0 && shelf->preset_offset_yaw_rad <= 0.0) {
    return shelf->T_map_shelf;
  }
  // One stream per (seed, shelf): adding a shelf does not change the others' presets.
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(shelf_id)};
  std::mt19937_64 rng(seq);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double dx = shelf->preset_offset_xy_m * unit(rng);
  const double dy = shelf->preset_offset_xy_m * unit(rng);
  const double dyaw = shelf->preset_offset_yaw_rad * unit(rng);
  const geometry::Pose2& T = shelf->T_map_shelf;
  return geometry::Pose2(T.x + dx, T.y + dy, T.yaw + dyaw);
}

}  // namespace shelfdock::sim
