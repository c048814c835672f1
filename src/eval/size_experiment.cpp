#include "eval/size_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "eval/monte_carlo.hpp"
#include "perception/detector.hpp"
#include "sim/lidar.hpp"
#include "sim/world.hpp"

namespace shelfdock::eval {

std::vector<ModelSize> RunSizeExperiment(const std::vector<geometry::ShelfModel>& models,
                                         const perception::DetectorConfig& detector_config,
                                         const sim::LidarConfig& lidar,
                                         const SizeExperimentConfig& config) {
  const perception::Detector detector(models, detector_config);
  std::vector<ModelSize> rows;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const geometry::ShelfModel& model = models[m];
    std::mt19937_64 rng(config.seed0 + 100 * m);
    std::uniform_real_distribution<double> jitter(-config.jitter_rad, config.jitter_rad);
    ModelSize row;
    row.model = model.name;
    row.model_length_m = model.length_m;
    row.model_width_m = model.width_m;
    double sum_length = 0.0, sum_width = 0.0;
    std::vector<double> single;
    for (int i = 0; i < config.recognitions_per_model; ++i) {
      // Half end-on (long side along the view), half broadside; the centre lies behind the
      // front leg line by half the shelf's depth.
      const bool broadside = i % 2 == 1;
      const double yaw = (broadside ? 0.5 * std::numbers::pi : 0.0) + jitter(rng);
      const double bearing = jitter(rng);
      const double depth = broadside ? model.width_m : model.length_m;
      const double d = config.standoff_m + 0.5 * depth;
      const geometry::Pose2 T_lidar_shelf(d * std::cos(bearing), d * std::sin(bearing),
                                          bearing + yaw);
      sim::World world;
      world.AddWall({{-5.0, -5.0}, {7.0, -5.0}, {7.0, 5.0}, {-5.0, 5.0}}, true);
      world.AddShelf(1, model, T_lidar_shelf);
      sim::Lidar sensor(lidar, config.seed0 + 100 * m + static_cast<std::uint64_t>(i));
      const perception::DetectionResult result =
          detector.Detect(sensor.Scan(world, geometry::Pose2()), T_lidar_shelf);
      ++row.attempts;
      if (result.detections.empty() || result.detections[0].model != model.name) continue;
      const perception::Detection& det = result.detections[0];
      ++row.recognitions;
      sum_length += det.length_m;
      sum_width += det.width_m;
      single.push_back(std::max(std::abs(det.length_m / model.length_m - 1.0),
                                std::abs(det.width_m / model.width_m - 1.0)));
    }
    if (row.recognitions > 0) {
      row.mean_length_m = sum_length / row.recognitions;
      row.mean_width_m = sum_width / row.recognitions;
      row.length_error = std::abs(row.mean_length_m / model.length_m - 1.0);
      row.width_error = std::abs(row.mean_width_m / model.width_m - 1.0);
      row.single_scan_p95_error = Quantile(single, 0.95);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace shelfdock::eval
