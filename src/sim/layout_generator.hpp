#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "sim/lidar_config.hpp"
#include "sim/line_of_sight.hpp"
#include "sim/world.hpp"

namespace shelfdock::sim {

/// The kinds of warehouse scene the layout generator builds (issue 7): one target shelf among
/// what a warehouse puts around it, or no shelf at all (clutter).
enum class LayoutClass {
  kOpen,             ///< one shelf on an open floor in a room (baseline)
  kRow,              ///< a row of 3-6 shelves of one model, the sensor in front of it
  kAisle,            ///< rows on both sides of an aisle, racks or walls behind them
  kOccludedLeg,      ///< one target leg hidden behind a box, a post or a person
  kPersonBesideLeg,  ///< a person standing next to a visible target leg
  kLargeClose,       ///< the largest square model with the sensor within reach of its centre
  kMixedNeighbours,  ///< a row whose neighbours are of different models
  kRoundNoisy,       ///< the round-leg model at the high range noise
  kClutter,          ///< no shelf: leg-like posts, boxes and people
  /// shelves pushed back against a wall or a rack, a few centimetres behind their back legs
  /// (after kClutter: a class's value seeds its scenes, so the others keep theirs)
  kAgainstWall,
};

/// Every class, in table order.
inline constexpr std::array<LayoutClass, 10> kAllLayoutClasses = {LayoutClass::kOpen,
                                                                  LayoutClass::kRow,
                                                                  LayoutClass::kAisle,
                                                                  LayoutClass::kOccludedLeg,
                                                                  LayoutClass::kPersonBesideLeg,
                                                                  LayoutClass::kLargeClose,
                                                                  LayoutClass::kMixedNeighbours,
                                                                  LayoutClass::kRoundNoisy,
                                                                  LayoutClass::kAgainstWall,
                                                                  LayoutClass::kClutter};

/// The class's name as written in tables and on the command line (`open`, `row`, ...).
std::string_view LayoutClassName(LayoutClass layout_class);
/// The class named `name`, or nullopt.
std::optional<LayoutClass> ParseLayoutClass(std::string_view name);

/// A LiDAR the generator may put in a scene, with a label for tables.
struct NamedLidar {
  std::string name = "wlr-716";
  LidarConfig config;  ///< its range noise is replaced by the scene's (see LayoutConfig)
};

/// Ranges the generator draws from. Distances are between footprints (the legs' outer
/// edges) unless said otherwise; "standoff" is from the sensor to the target's nearest leg
/// centre.
struct LayoutConfig {
  std::vector<NamedLidar> lidars = {NamedLidar{}};  ///< one drawn per scene, uniformly

  // Range noise: shelf and clutter classes at the low noise, a share of them at the high one;
  // round_noisy always at the high one.
  double noise_sigma_m = 0.010;       ///< [m] range noise of most scenes
  double high_noise_sigma_m = 0.020;  ///< [m]
  double high_noise_share = 0.25;     ///< [-] of the scenes (except round_noisy) at high noise

  // Sensor placement.
  double min_standoff_m = 0.5;           ///< [m] sensor to the target's nearest leg centre
  double max_standoff_m = 3.5;           ///< [m]
  double max_bearing_rad = 1.2;          ///< [rad] target centre bearing in the lidar frame
  double max_off_normal_rad = 1.4;       ///< [rad] rows, aisles: the sensor's direction from the
                                         ///< target, off the row's normal (80 deg)
  double sensor_clearance_m = 0.25;      ///< [m] free radius around the sensor (robot body)
  double large_close_radius_m = 1.1;     ///< [m] large_close: sensor to the target centre
  double large_close_clearance_m = 0.1;  ///< [m] large_close: sensor to any leg (may be under)

  // Presets: the pose the robot is told, off the truth by up to these.
  double preset_error_xy_m = 0.2;     ///< [m] radius of the preset's centre error
  double preset_error_yaw_rad = 0.1;  ///< [rad]

  // Rows and aisles.
  int row_min_shelves = 3;           ///< [-]
  int row_max_shelves = 6;           ///< [-]
  double row_min_gap_m = 0.2;        ///< [m] between neighbouring footprints along the row
  double row_max_gap_m = 0.5;        ///< [m]
  double row_jitter_m = 0.03;        ///< [m] front-line misalignment of each shelf
  double row_jitter_yaw_rad = 0.03;  ///< [rad] heading misalignment of each shelf
  double aisle_min_width_m = 2.5;    ///< [m] between the two rows' front lines
  double aisle_max_width_m = 3.5;    ///< [m]
  int aisle_min_shelves = 4;         ///< [-] per row
  int aisle_max_shelves = 7;         ///< [-]
  double person_clearance_m = 0.5;   ///< [m] people standing in an aisle to the sensor
  double rack_min_setback_m = 0.1;   ///< [m] rack or wall behind a row's back legs
  double rack_max_setback_m = 0.8;   ///< [m]
  double wall_min_setback_m = 0.02;  ///< [m] against_wall: wall or rack behind the back legs
  double wall_max_setback_m = 0.12;  ///< [m]

  // Legs.
  double leg_min_reflectivity = 0.08;  ///< [0..1] painted steel is dark
  double leg_max_reflectivity = 0.6;   ///< [0..1]
  double shiny_leg_share = 0.1;        ///< [-] galvanised (specular) legs
  /// Shelves as built: each leg's centre off its design place by up to this along each of the
  /// shelf's axes (uniform), and turned by up to leg_build_twist_rad. Drawn from a stream of
  /// their own after the scene is placed, so a scene differs from its as-designed twin only in
  /// its legs; 0 and 0: as designed, nothing drawn.
  double leg_build_error_m = 0.0;    ///< [m]
  double leg_build_twist_rad = 0.0;  ///< [rad]

  // Occluders (occluded_leg) and people.
  double occluder_min_gap_m = 0.2;        ///< [m] leg centre to the occluder's near face
  double occluder_max_gap_m = 0.4;        ///< [m]
  double box_min_side_m = 0.2;            ///< [m]
  double box_max_side_m = 0.5;            ///< [m]
  double post_min_size_m = 0.08;          ///< [m] diameter or side of an occluding post
  double post_max_size_m = 0.25;          ///< [m]
  double person_min_leg_radius_m = 0.05;  ///< [m]
  double person_max_leg_radius_m = 0.07;  ///< [m]
  double person_leg_spacing_m = 0.2;      ///< [m] between the two leg centres
  double person_min_distance_m = 0.1;     ///< [m] person_beside_leg: shelf leg centre to the
                                          ///< nearer person leg centre
  double person_max_distance_m = 0.35;    ///< [m]

  // Clutter.
  int clutter_min_posts = 10;         ///< [-] leg-like posts, round and square
  int clutter_max_posts = 100;        ///< [-]
  double clutter_min_post_m = 0.02;   ///< [m] diameter or side
  double clutter_max_post_m = 0.06;   ///< [m]
  int clutter_max_boxes = 6;          ///< [-] crates, bins, pallets (0.2-1.2 m)
  int clutter_max_people = 4;         ///< [-] standing
  double clutter_max_range_m = 5.0;   ///< [m] from the sensor
  double clutter_preset_share = 0.7;  ///< [-] scenes where the map still names a shelf there
  double min_object_gap_m = 0.03;     ///< [m] between any two objects placed by the generator

  int min_beams_in_sight = 2;  ///< [-] ideal beams on a leg for it to count as in sight
};

/// A straight row of shelves: its frame has x along the row and y toward its front (the side
/// the sensor or the aisle is on); the front legs' outer faces lie near y = 0.
struct LayoutRow {
  geometry::Pose2 T_world_row;
  std::vector<int> shelf_ids;  ///< in order along x
};

/// One generated scene: the true world, where the sensor stands, what the robot is told.
struct LayoutScene {
  LayoutClass layout_class = LayoutClass::kOpen;
  std::uint64_t seed = 0;
  World world;  ///< ground truth; its shelves are the true shelves
  geometry::Pose2 T_world_lidar;
  int target_shelf_id = -1;                       ///< -1: no target (clutter)
  std::optional<geometry::Pose2> T_world_preset;  ///< the target's preset, nullopt: none given
  std::string lidar_name;
  LidarConfig lidar;               ///< the sensor with this scene's range noise
  std::uint64_t scan_seed = 0;     ///< for sim::Lidar
  LegSight target_sight;           ///< ideal beams on each target leg
  int target_legs_in_sight = 0;    ///< legs with at least min_beams_in_sight beams
  double target_standoff_m = 0.0;  ///< [m] sensor to the nearest target leg centre
  int occluded_leg = -1;           ///< occluded_leg: the hidden leg's index, else -1
  std::vector<LayoutRow> rows;

  const std::vector<ShelfInstance>& shelves() const { return world.shelves(); }
  /// The target shelf, nullopt for clutter.
  std::optional<ShelfInstance> Target() const { return world.Shelf(target_shelf_id); }
  /// The preset in the lidar frame, as a robot hands it to the detector.
  std::optional<geometry::Pose2> PresetInLidar() const;
};

/// Builds the scene of `layout_class` for `seed` with shelves of `models` (the paper's Table 1
/// in config/models.yaml; must not be empty). The same arguments give the same scene.
/// round_noisy uses a round-leg model (the first model if there is none); large_close the model
/// with the longest diagonal.
LayoutScene GenerateLayoutScene(LayoutClass layout_class, std::uint64_t seed,
                                const std::vector<geometry::ShelfModel>& models,
                                const LayoutConfig& config = {});

/// The scene's scan: sim::Lidar with the scene's sensor and scan seed, standing still at t = 0.
geometry::LaserScan SimulateLayoutScan(const LayoutScene& scene);

}  // namespace shelfdock::sim
