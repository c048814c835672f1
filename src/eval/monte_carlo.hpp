#pragma once

#include <vector>

#include "eval/docking_runner.hpp"

namespace shelfdock::eval {

/// Linearly interpolated quantile q in [0, 1] of `values` (NaN when empty).
double Quantile(std::vector<double> values, double q);

/// Percentiles of an absolute error over runs.
struct AbsErrorStats {
  double p95 = 0.0;  ///< of |error|
  double p99 = 0.0;
  double max = 0.0;
};

/// The paper's accuracy bands: 10 mm / 14 mrad before the code check (section 4), and the
/// issue's 3 mm / 5 mrad after it.
struct AccuracyBands {
  double before_xy_m = 0.010;
  double before_yaw_rad = 0.014;
  double after_xy_m = 0.003;
  double after_yaw_rad = 0.005;
};

/// One docking method's figures over many seeded runs.
struct MethodSummary {
  int runs = 0;
  int successes = 0;
  double mean_time_s = 0.0;                      ///< over successful runs
  AbsErrorStats before_x, before_y, before_yaw;  ///< over runs that reached the code check
  AbsErrorStats after_x, after_y, after_yaw;     ///< over runs that lifted
  double within_before = 0.0;  ///< share of checked runs inside the before band (x, y and yaw)
  double within_after = 0.0;   ///< share of lifted runs inside the after band
  double min_leg_clearance_m = 1e9;  ///< [m] worst over all runs
  PhaseTimes mean_phases;            ///< mean over successful runs (counts as means too)
  double mean_code_checks = 0.0;     ///< per successful run
  double mean_adjustments = 0.0;     ///< per successful run
};

/// The figures of a method's runs.
MethodSummary Summarise(const std::vector<DockingRun>& runs, const AccuracyBands& bands = {});

}  // namespace shelfdock::eval
