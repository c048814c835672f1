#pragma once

#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/lidar_config.hpp"

namespace shelfdock::eval {

/// One seeded scan every method is run on, with its ground truth in the scan's frame.
struct PeerScene {
  std::uint64_t seed = 0;
  geometry::LaserScan scan;
  std::string model;                              ///< the target's model
  double heading_period_rad = std::numbers::pi;   ///< the target model's ShelfModel::HeadingPeriod
  geometry::Pose2 T_lidar_shelf;                  ///< true target pose
  std::optional<geometry::Pose2> T_lidar_preset;  ///< what the robot is told
};

/// A named set of scenes (one table block).
struct PeerSceneSet {
  std::string name;
  std::vector<PeerScene> scenes;
};

/// The scene sets of `eval peers` and how many scenes each has.
struct PeerScenesConfig {
  int paper_per_model = 25;  ///< Table 1 set-up (0.5 m), per model
  int sweep_scenes = 200;    ///< Table 1 models at 0.5-3.5 m, any heading
  int row_scenes = 200;      ///< rows of 3-6 shelves (sim layout class `row`)
  int clutter_scenes = 100;  ///< per post count
  std::vector<int> clutter_posts = {10, 30, 50, 100};  ///< one set per count
  double post_min_diameter_m = 0.02;                   ///< [m] leg-like posts
  double post_max_diameter_m = 0.06;                   ///< [m]
  double clutter_radius_m = 5.0;                       ///< [m] posts within this of the sensor
  double preset_error_xy_m = 0.2;                      ///< [m] sweep: radius of the preset's error
  double preset_error_yaw_rad = 0.1;                   ///< [rad]
  std::uint64_t seed0 = 1;
};

/// The paper's set-up: the Table 1 experiment's scans (sensor 0.5 m before the front legs).
PeerSceneSet PaperSetupScenes(const std::vector<geometry::ShelfModel>& models,
                              const sim::LidarConfig& lidar, const PeerScenesConfig& config);
/// The Table 1 sweep to 3.5 m: a random model, standoff 0.5-3.5 m, any heading, the preset off.
PeerSceneSet SweepScenes(const std::vector<geometry::ShelfModel>& models,
                         const sim::LidarConfig& lidar, const PeerScenesConfig& config);
/// Rows of shelves (sim::LayoutClass::kRow at the nominal noise).
PeerSceneSet RowScenes(const std::vector<geometry::ShelfModel>& models,
                       const sim::LidarConfig& lidar, const PeerScenesConfig& config);
/// One shelf on an open floor (sim::LayoutClass::kOpen) with `posts` leg-like round posts
/// around the sensor, none under the shelf.
PeerSceneSet ClutterScenes(const std::vector<geometry::ShelfModel>& models,
                           const sim::LidarConfig& lidar, int posts,
                           const PeerScenesConfig& config);

/// Every set above, in that order.
std::vector<PeerSceneSet> AllPeerSceneSets(const std::vector<geometry::ShelfModel>& models,
                                           const sim::LidarConfig& lidar,
                                           const PeerScenesConfig& config);

}  // namespace shelfdock::eval
