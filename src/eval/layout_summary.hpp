#pragma once

#include <limits>
#include <string>
#include <vector>

#include "eval/layout_sweep.hpp"

namespace shelfdock::eval {

/// Median and 95th percentile of a set of errors.
struct ErrorQuantiles {
  int count = 0;
  double p50 = std::numeric_limits<double>::quiet_NaN();
  double p95 = std::numeric_limits<double>::quiet_NaN();
};

/// Accuracy of the right-first findable scenes at one range-noise level, within the sweep's
/// accuracy_max_standoff_m.
struct NoiseLevelErrors {
  double noise_sigma_m = 0.0;  ///< [m]
  ErrorQuantiles centre_m;     ///< [m]
  ErrorQuantiles heading_rad;  ///< [rad] modulo the model's symmetry
};

/// One row of the layout table: a class, or all classes together.
struct LayoutSummary {
  std::string name;
  int scenes = 0;
  int findable = 0;                        ///< target scenes with enough legs in sight
  int right_first = 0;                     ///< findable, target first
  int missed = 0;                          ///< findable, nothing detected
  int wrong_first = 0;                     ///< findable, something else first
  int not_findable_wrong = 0;              ///< not findable, another shelf or a phantom first
  int phantoms = 0;                        ///< phantom detections, any scene
  int phantom_scenes = 0;                  ///< scenes with at least one phantom
  int clutter_scenes = 0;                  ///< scenes without a shelf
  int clutter_detections = 0;              ///< detections in them
  std::vector<NoiseLevelErrors> by_noise;  ///< ascending noise
  double mean_abs_length_error_m = std::numeric_limits<double>::quiet_NaN();  ///< right-first
  double mean_abs_width_error_m = std::numeric_limits<double>::quiet_NaN();   ///< right-first

  int not_findable() const { return scenes - clutter_scenes - findable; }
  /// right_first / findable (NaN without findable scenes).
  double RightFirstRate() const;
  /// The errors at `noise_sigma_m` (within 0.1 mm), or nullptr when no scene had that noise.
  const NoiseLevelErrors* AtNoise(double noise_sigma_m) const;
};

/// Aggregates scene results into one table row named `name`.
LayoutSummary SummariseLayouts(const std::vector<LayoutSceneResult>& scenes,
                               const std::string& name, const LayoutSweepConfig& config);

/// One row per class of config.classes (in that order) that has scenes, then "overall".
std::vector<LayoutSummary> SummariseLayoutsByClass(const std::vector<LayoutSceneResult>& scenes,
                                                   const LayoutSweepConfig& config);

/// One row per LiDAR (named as in LayoutSceneResult::lidar_name, in order of first appearance),
/// every class together: which sensor the misses come from.
std::vector<LayoutSummary> SummariseLayoutsByLidar(const std::vector<LayoutSceneResult>& scenes,
                                                   const LayoutSweepConfig& config);

/// How close models were told apart: scenes whose first detection stands on the target (centre
/// within right_radius_m) under another model, and how many of them and of the right-first scenes
/// carried a runner-up model with a chi-square margin under `margin` (Detection::runner_up).
struct ModelConfusionSummary {
  int confusions = 0;           ///< wrong first: the target's place, another model
  int confusions_flagged = 0;   ///< of those, the target's model runner-up within `margin`
  int right_first = 0;          ///< right-first scenes
  int right_first_flagged = 0;  ///< of those, some runner-up within `margin`
};
/// Counts ModelConfusionSummary over `scenes` (right_radius_m from `config`).
ModelConfusionSummary SummariseModelConfusions(const std::vector<LayoutSceneResult>& scenes,
                                               const LayoutSweepConfig& config, double margin);

}  // namespace shelfdock::eval
