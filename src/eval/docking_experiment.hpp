#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "eval/docking_runner.hpp"
#include "eval/monte_carlo.hpp"
#include "eval/pose_spread.hpp"

namespace shelfdock::eval {

/// The paper's docking experiments (section 4, Fig. 7, Fig. 8 and the time comparison): many
/// seeded dockings to the same shelf with the continuous method, and the same seeds with
/// stop-and-recognise.
struct DockingExperimentConfig {
  int runs = 100;               ///< [-] dockings per method
  std::uint64_t seed0 = 1000;   ///< run i has seed seed0 + i (both methods)
  int paper_recognitions = 10;  ///< [-] the paper's Fig. 7 count, for the evenly spaced subset
};

/// Median and worst over runs of one per-run figure.
struct RunQuantiles {
  double median = std::numeric_limits<double>::quiet_NaN();
  double worst = std::numeric_limits<double>::quiet_NaN();
};

/// Fig. 7 over many runs: each run's spread of the shelf pose in the map over its recognitions.
struct FluctuationSummary {
  int runs = 0;  ///< runs with at least 2 recognitions
  RunQuantiles recognitions;
  RunQuantiles x_range, y_range, yaw_range;     ///< max - min [m, m, rad]
  RunQuantiles x_stddev, y_stddev, yaw_stddev;  ///< [m, m, rad]
};

/// Fig. 8: the LiDAR-guided final error of the continuous runs (the robot's pose against the true
/// shelf, before the code check corrects it: what the paper's camera measured after docking).
struct FinalErrorSummary {
  int runs = 0;  ///< runs that reached the check
  AbsErrorStats x, y, yaw;
  double within_paper_band = 0.0;  ///< share with |x|, |y| <= 1 cm and |yaw| <= 0.014 rad
  AbsErrorStats after_x, after_y, after_yaw;  ///< after the code check and adjustment
};

/// The docking experiment of one sensor: Fig. 7 spreads, Fig. 8 errors and the times.
struct DockingExperimentResult {
  int runs = 0;
  int continuous_successes = 0;
  int stop_successes = 0;
  // In the world, placed with the true robot pose: the recognitions' own spread.
  FluctuationSummary detected;     ///< single-scan detections
  FluctuationSummary detected_10;  ///< 10 of them, evenly spaced in the run (as many as the paper)
  FluctuationSummary fused;        ///< the tracker's estimate after each detection
  // In the map, through the robot's simulated localisation estimate (its white noise, 10 mm and
  // 5 mrad per update by default, and its wandering bias add to the spread).
  FluctuationSummary detected_map;
  FluctuationSummary fused_map;
  FinalErrorSummary final_error;
  std::vector<PoseError> final_errors;  ///< per continuous run (scatter plot)
  double continuous_time_s = std::numeric_limits<double>::quiet_NaN();  ///< [s] mean, successes
  double stop_time_s = std::numeric_limits<double>::quiet_NaN();        ///< [s]
  double perfect_time_s = std::numeric_limits<double>::quiet_NaN();     ///< [s]
  double time_saving = std::numeric_limits<double>::quiet_NaN();        ///< 1 - continuous / stop
  /// Recognitions of the run whose x range is the median one (the fluctuation trace).
  std::vector<Recognition> trace;
  std::uint64_t trace_seed = 0;
};

/// Called after each docking with (done, total).
using ProgressFn = std::function<void(int, int)>;

/// Runs config.runs dockings per method on `scenario` (its target shelf) and summarises them.
DockingExperimentResult RunDockingExperiment(const sim::Scenario& scenario,
                                             const std::vector<geometry::ShelfModel>& models,
                                             RunConfig run_config,
                                             const DockingExperimentConfig& config,
                                             const ProgressFn& progress = {});

/// Median and worst (largest) of per-run values; NaN values are skipped.
RunQuantiles MedianAndWorst(const std::vector<double>& values);

}  // namespace shelfdock::eval
