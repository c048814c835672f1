#pragma once
// Internal to the layout generator: things that stand between, beside or instead of shelves.

#include <optional>

#include "geometry/pose2.hpp"
#include "sim/layout_builder.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::sim::layout {

/// Hides one leg of `target` (any of the four, drawn) behind a box, a round or square post or
/// a person's two legs, its near face occluder_min/max_gap_m in front of the leg centre along
/// the sensor's ray (under the shelf for a back leg). Returns the leg's index, or nullopt when
/// no occluder fitted in a bounded number of draws.
std::optional<int> AddOccluder(SceneBuilder& builder, SceneRng& rng, const ShelfInstance& target,
                               const geometry::Pose2& T_world_lidar, const LayoutConfig& config);

/// A person standing with the nearer leg centre person_min/max_distance_m from a target leg
/// that the sensor sees (at any angle around it). False when no leg is in sight or no spot fits.
bool AddPersonBesideLeg(SceneBuilder& builder, SceneRng& rng, const ShelfInstance& target,
                        const geometry::Pose2& T_world_lidar, const LidarConfig& lidar,
                        const LayoutConfig& config);

/// 0-2 people standing in the strip 0.3 m inside [0, width_m] of the frame T_world_aisle (y
/// across the aisle), within [x0, x1] along it.
void AddAislePeople(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_aisle,
                    double x0, double x1, double width_m, const LayoutConfig& config);

/// Leg-like posts (round and square), boxes and people around the sensor, half of the posts
/// around the preset when there is one.
void AddClutter(SceneBuilder& builder, SceneRng& rng, const geometry::Pose2& T_world_lidar,
                const std::optional<geometry::Pose2>& T_world_preset, const LayoutConfig& config);

}  // namespace shelfdock::sim::layout
