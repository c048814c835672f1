#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "geometry/shelf_model.hpp"
#include "perception/detector_config.hpp"
#include "sim/lidar_config.hpp"

namespace shelfdock::eval {

/// The paper's Table 1 experiment: the sensor about 0.5 m in front of the front legs, many
/// recognitions per model, the fitted size against the model's.
struct SizeExperimentConfig {
  int recognitions_per_model = 30;  ///< [-] scans per model (half end-on, half broadside)
  double standoff_m = 0.5;          ///< [m] sensor to the front leg line
  double jitter_rad = 0.1;          ///< [rad] heading and bearing drawn within +- this
  std::uint64_t seed0 = 5000;       ///< scan i of model m has seed seed0 + 100 m + i
};

/// One row of Table 1.
struct ModelSize {
  std::string model;
  double model_length_m = 0.0;  ///< [m]
  double model_width_m = 0.0;   ///< [m]
  int attempts = 0;
  int recognitions = 0;                                             ///< the right model found first
  double mean_length_m = std::numeric_limits<double>::quiet_NaN();  ///< [m] fitted, mean
  double mean_width_m = std::numeric_limits<double>::quiet_NaN();   ///< [m]
  /// |mean fitted / model - 1|, the paper's "error of shelf length/width" [-]
  double length_error = std::numeric_limits<double>::quiet_NaN();
  double width_error = std::numeric_limits<double>::quiet_NaN();
  /// 95th percentile over single scans of max(|l/L - 1|, |w/W - 1|) [-]
  double single_scan_p95_error = std::numeric_limits<double>::quiet_NaN();
};

/// Runs the Table 1 set-up for every model (a room around, the preset at the truth) with the
/// given sensor and detector settings; one row per model, in the models' order.
std::vector<ModelSize> RunSizeExperiment(const std::vector<geometry::ShelfModel>& models,
                                         const perception::DetectorConfig& detector,
                                         const sim::LidarConfig& lidar,
                                         const SizeExperimentConfig& config = {});

}  // namespace shelfdock::eval
