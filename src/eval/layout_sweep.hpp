#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/laser_scan.hpp"
#include "geometry/pose2.hpp"
#include "geometry/shelf_model.hpp"
#include "perception/detection.hpp"
#include "perception/detector.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::eval {

/// Which scenes a layout sweep runs and how it scores them (issue 7).
struct LayoutSweepConfig {
  int scenes_per_class = 400;  ///< [-] 9 classes x 400 = 3600 scenes
  std::uint64_t seed0 = 1;     ///< scene i of every class has seed seed0 + i
  std::vector<sim::LayoutClass> classes = {sim::kAllLayoutClasses.begin(),
                                           sim::kAllLayoutClasses.end()};
  double right_radius_m = 0.05;    ///< [m] first detection this close to the target (and of its
                                   ///< model): the right shelf
  double phantom_radius_m = 0.05;  ///< [m] a detection farther than this from every true shelf
                                   ///< is a phantom
  int min_legs_in_sight = 3;       ///< [-] target legs in sight for a scene to be findable
  int min_beams_in_sight = 0;      ///< [-] ideal beams on a leg for it to count as in sight;
                                   ///< 0: the generator's (LayoutConfig::min_beams_in_sight)
  bool use_preset = true;          ///< hand the detector the scene's preset (false: search
                                   ///< without one)
  bool map_knows_model = false;    ///< the map also names the target's model: scenes with a
                                   ///< target are detected with that model alone
  double accuracy_max_standoff_m = 3.5;  ///< [m] centre and heading errors are gathered up to
                                         ///< this standoff (sensor to the nearest target leg)
};

/// How a scene went.
enum class SceneOutcome {
  kRightFirst,         ///< findable; the first detection is the target
  kMissed,             ///< findable; nothing detected
  kWrongFirst,         ///< findable; the first detection is not the target
  kNotFindableClean,   ///< not findable; nothing, or the target, first
  kNotFindableWrong,   ///< not findable; another shelf or a phantom first
  kClutterClean,       ///< no shelf; nothing detected
  kClutterDetections,  ///< no shelf; something detected
};

/// The outcome's snake_case name (reports).
std::string_view SceneOutcomeName(SceneOutcome outcome);

/// The detector's first answer, against the truth.
struct FirstDetection {
  std::string model;
  geometry::Pose2 T_lidar_shelf;  ///< as the detector returned it
  geometry::Pose2 T_world_shelf;
  int legs_used = 0;
  double err_sum = 0.0;     ///< [m] Eq. 2
  double confidence = 0.0;  ///< [0, 1] the detector's
  int legs_occluded = 0;    ///< model legs hidden
  int interior_points = 0;
  double leg_width_bias_m = 0.0;                                     ///< points in the footprint
  std::optional<perception::RunnerUp> runner_up;                     ///< Detection::runner_up
  int nearest_shelf_id = -1;                                         ///< -1: no shelf at all
  double nearest_shelf_m = std::numeric_limits<double>::infinity();  ///< [m] centre to centre
};

/// One scene's score, kept for every scene so that failures can be listed and reproduced
/// (GenerateLayoutScene(layout_class, seed, ...) rebuilds the scene and its scan).
struct LayoutSceneResult {
  sim::LayoutClass layout_class = sim::LayoutClass::kOpen;
  std::uint64_t seed = 0;
  std::string lidar_name;
  double noise_sigma_m = 0.0;  ///< [m] the scene's range noise
  int legs_in_sight = 0;       ///< target legs in the sensor's line of sight
  bool findable = false;
  double standoff_m = 0.0;   ///< [m] sensor to the nearest target leg centre
  std::string target_model;  ///< empty on clutter
  geometry::Pose2 T_world_target;
  std::optional<geometry::Pose2> T_world_preset;
  SceneOutcome outcome = SceneOutcome::kRightFirst;
  int detections = 0;
  int phantoms = 0;  ///< detections farther than phantom_radius_m from every true shelf
  std::optional<FirstDetection> first;
  // Right-first scenes only (NaN otherwise).
  double centre_error_m = std::numeric_limits<double>::quiet_NaN();     ///< [m]
  double heading_error_rad = std::numeric_limits<double>::quiet_NaN();  ///< [rad] mod symmetry
  double length_error_m = std::numeric_limits<double>::quiet_NaN();     ///< [m] fitted - model
  double width_error_m = std::numeric_limits<double>::quiet_NaN();      ///< [m] fitted - model
  perception::DetectionStats stats;

  /// Anything the targets forbid: not the right shelf first where it is findable, a
  /// wrong shelf first where it is not, a phantom, a detection in clutter.
  bool Failed() const;
};

/// Scores one scene's detections (the scan from sim::SimulateLayoutScan, the preset the scene
/// gives, in the lidar frame).
LayoutSceneResult ScoreLayoutScene(const sim::LayoutScene& scene,
                                   const perception::DetectionResult& result,
                                   const LayoutSweepConfig& config);

/// Generates, scans, detects and scores `scenes_per_class` scenes of each class in
/// config.classes, class by class, seeds counting up from seed0.
std::vector<LayoutSceneResult> RunLayoutSweep(const perception::Detector& detector,
                                              const std::vector<geometry::ShelfModel>& models,
                                              const sim::LayoutConfig& layout_config,
                                              const LayoutSweepConfig& config);

}  // namespace shelfdock::eval
