#include "eval/paper_evaluation.hpp"

namespace shelfdock::eval {

PaperEvaluationConfig PaperEvaluationConfig::Quick() {
  PaperEvaluationConfig c;
  c.size.recognitions_per_model = 6;
  c.docking.runs = 3;
  return c;
}

PaperEvaluation RunPaperEvaluation(const sim::Scenario& scenario,
                                   const std::vector<geometry::ShelfModel>& models,
                                   const RunConfig& run_config, const PaperEvaluationConfig& config,
                                   const PaperProgressFn& progress) {
  PaperEvaluation out;
  out.config = config;
  const std::vector<std::pair<std::string, sim::LidarConfig>> sensors = {
      {"nominal", run_config.lidar}, {"harsh", HarshLidar(run_config.lidar, config.harsh)}};
  for (const auto& [name, lidar] : sensors) {
    PaperSensorResult r;
    r.sensor = name;
    r.lidar = lidar;
    if (progress) progress(name, "Table 1 sizes", 0, 1);
    r.sizes = RunSizeExperiment(models, run_config.detector, lidar, config.size);
    RunConfig rc = run_config;
    rc.lidar = lidar;
    const std::string sensor = name;
    r.docking = RunDockingExperiment(scenario, models, rc, config.docking,
                                     [&progress, &sensor](int done, int total) {
                                       if (progress) progress(sensor, "dockings", done, total);
                                     });
    out.sensors.push_back(std::move(r));
  }
  return out;
}

}  // namespace shelfdock::eval
