#pragma once

#include <string>
#include <vector>

#include "eval/docking_experiment.hpp"
#include "eval/harsh_lidar.hpp"
#include "eval/size_experiment.hpp"

namespace shelfdock::eval {

/// `eval paper`: the paper's section 4 experiments, each under the nominal and the harsh sensor.
struct PaperEvaluationConfig {
  SizeExperimentConfig size;
  DockingExperimentConfig docking;
  HarshLidarConfig harsh;

  /// The `--quick` run (< 1 min): few recognitions, few dockings.
  static PaperEvaluationConfig Quick();
};

/// All experiments under one sensor.
struct PaperSensorResult {
  std::string sensor;  ///< "nominal" or "harsh"
  sim::LidarConfig lidar;
  std::vector<ModelSize> sizes;     ///< Table 1
  DockingExperimentResult docking;  ///< Fig. 7, Fig. 8, time
};

/// Every figure of `eval paper`: its configuration and one result per sensor (nominal, harsh).
struct PaperEvaluation {
  PaperEvaluationConfig config;
  std::vector<PaperSensorResult> sensors;  ///< nominal, then harsh
};

/// Called with (sensor, stage, done, total) as the work goes on.
using PaperProgressFn = std::function<void(const std::string&, const std::string&, int, int)>;

/// Runs Table 1 and the docking experiments on `scenario` (the paper's: shelf 2, 4.5 m docking
/// area at 0.4 m/s) with `run_config.lidar` as the nominal sensor and HarshLidar of it.
PaperEvaluation RunPaperEvaluation(const sim::Scenario& scenario,
                                   const std::vector<geometry::ShelfModel>& models,
                                   const RunConfig& run_config, const PaperEvaluationConfig& config,
                                   const PaperProgressFn& progress = {});

}  // namespace shelfdock::eval
