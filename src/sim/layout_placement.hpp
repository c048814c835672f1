#pragma once
// Internal to the layout generator: where the sensor stands and what preset the robot is told.

#include <optional>

#include <Eigen/Core>

#include "geometry/pose2.hpp"
#include "sim/layout_builder.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::sim::layout {

/// A strip the sensor must stand in: min_y_m <= y <= max_y_m in the frame T_world_band (a row's
/// frame: in front of the row, or within an aisle).
struct SensorBand {
  geometry::Pose2 T_world_band;
  double min_y_m = 0.0;  ///< [m]
  double max_y_m = 1e9;  ///< [m]
};

/// Distance from `p_world` to the nearest leg centre of `shelf` (the standoff).
double Standoff(const ShelfInstance& shelf, const Eigen::Vector2d& p_world);

/// A sensor pose facing the target: its nearest leg centre a drawn standoff away, on a ray from
/// the target's centre at a world direction in [min_dir_rad, max_dir_rad], inside `band`,
/// clear of everything placed; turned so the target centre's bearing is drawn within
/// +-max_bearing_rad. nullopt when no such spot was found in a bounded number of draws.
std::optional<geometry::Pose2> PlaceSensorFacing(const SceneBuilder& builder, SceneRng& rng,
                                                 const ShelfInstance& target, double min_dir_rad,
                                                 double max_dir_rad,
                                                 const std::optional<SensorBand>& band,
                                                 const LayoutConfig& config);

/// A sensor anywhere within `radius_m` of the target's centre (possibly under it), any heading,
/// at least `clearance_m` from everything placed.
std::optional<geometry::Pose2> PlaceSensorNear(const SceneBuilder& builder, SceneRng& rng,
                                               const ShelfInstance& target, double radius_m,
                                               double clearance_m);

/// The preset: the true pose off by up to preset_error_xy_m (uniform over the disc) and
/// +-preset_error_yaw_rad, written with any of the model's symmetric headings.
geometry::Pose2 DrawPreset(SceneRng& rng, const ShelfInstance& target, const LayoutConfig& config);

}  // namespace shelfdock::sim::layout
