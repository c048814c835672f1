#include "eval/docking_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shelfdock::eval {
namespace {

double YawSymmetry(const sim::Scenario& scenario, const std::vector<geometry::ShelfModel>& models) {
  const sim::ScenarioShelf* target = scenario.FindShelf(scenario.target_shelf_id);
  for (const auto& m : models) {
    if (target != nullptr && m.name == target->model_name && m.IsSquare()) {
      return 0.5 * std::numbers::pi;
    }
  }
  return std::numbers::pi;
}

FluctuationSummary Summarise(const std::vector<PoseSpread>& spreads) {
  FluctuationSummary s;
  std::vector<double> n, xr, yr, ar, xs, ys, as;
  for (const PoseSpread& p : spreads) {
    if (p.samples < 2) continue;
    ++s.runs;
    n.push_back(p.samples);
    xr.push_back(p.x.range);
    yr.push_back(p.y.range);
    ar.push_back(p.yaw.range);
    xs.push_back(p.x.stddev);
    ys.push_back(p.y.stddev);
    as.push_back(p.yaw.stddev);
  }
  s.recognitions = MedianAndWorst(n);
  s.x_range = MedianAndWorst(xr);
  s.y_range = MedianAndWorst(yr);
  s.yaw_range = MedianAndWorst(ar);
  s.x_stddev = MedianAndWorst(xs);
  s.y_stddev = MedianAndWorst(ys);
  s.yaw_stddev = MedianAndWorst(as);
  return s;
}

/// `count` of the poses, evenly spaced from the first to the last (all when there are fewer).
std::vector<geometry::Pose2> EvenlySpaced(const std::vector<geometry::Pose2>& poses, int count) {
  if (static_cast<int>(poses.size()) <= count || count < 2) return poses;
  std::vector<geometry::Pose2> out;
  for (int k = 0; k < count; ++k) {
    out.push_back(poses[static_cast<std::size_t>(
        std::lround(static_cast<double>(k) * (poses.size() - 1) / (count - 1)))]);
  }
  return out;
}

double MeanTime(const std::vector<DockingRun>& runs, int* successes) {
  double sum = 0.0;
  *successes = 0;
  for (const DockingRun& r : runs) {
    if (!r.outcome.ok()) continue;
    sum += r.time_s;
    ++*successes;
  }
  return *successes > 0 ? sum / *successes : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

RunQuantiles MedianAndWorst(const std::vector<double>& values) {
  std::vector<double> v;
  for (double x : values) {
    if (std::isfinite(x)) v.push_back(x);
  }
  RunQuantiles q;
  if (v.empty()) return q;
  q.median = Quantile(v, 0.5);
  q.worst = *std::max_element(v.begin(), v.end());
  return q;
}

DockingExperimentResult RunDockingExperiment(const sim::Scenario& scenario,
                                             const std::vector<geometry::ShelfModel>& models,
                                             RunConfig run_config,
                                             const DockingExperimentConfig& config,
                                             const ProgressFn& progress) {
  DockingExperimentResult out;
  out.runs = config.runs;
  run_config.keep_recognitions = true;
  run_config.record = false;
  const double symmetry = YawSymmetry(scenario, models);
  const int total = 2 * config.runs;

  std::vector<DockingRun> continuous, stop;
  std::vector<PoseSpread> detected, detected_10, fused, detected_map, fused_map;
  for (int i = 0; i < config.runs; ++i) {
    const std::uint64_t seed = config.seed0 + static_cast<std::uint64_t>(i);
    DockingRun run = RunDocking(scenario, models, docking::Method::kContinuous, seed, run_config);
    // Fig. 7: the recognitions of the docking stage (RunDocking keeps those after the entry).
    std::vector<geometry::Pose2> det, fus, det_map, fus_map;
    for (const Recognition& r : run.recognitions) {
      det.push_back(r.T_world_shelf_detected);
      fus.push_back(r.T_world_shelf_fused);
      det_map.push_back(r.T_map_shelf_detected);
      fus_map.push_back(r.T_map_shelf_fused);
    }
    detected.push_back(SpreadOf(det, symmetry));
    detected_10.push_back(SpreadOf(EvenlySpaced(det, config.paper_recognitions), symmetry));
    fused.push_back(SpreadOf(fus, symmetry));
    detected_map.push_back(SpreadOf(det_map, symmetry));
    fused_map.push_back(SpreadOf(fus_map, symmetry));
    out.final_errors.push_back(run.error_before_check);
    run.recognitions.shrink_to_fit();
    continuous.push_back(std::move(run));
    if (progress) progress(i + 1, total);
  }
  run_config.keep_recognitions = false;
  for (int i = 0; i < config.runs; ++i) {
    const std::uint64_t seed = config.seed0 + static_cast<std::uint64_t>(i);
    stop.push_back(
        RunDocking(scenario, models, docking::Method::kStopAndRecognise, seed, run_config));
    if (progress) progress(config.runs + i + 1, total);
  }

  out.detected = Summarise(detected);
  out.detected_10 = Summarise(detected_10);
  out.fused = Summarise(fused);
  out.detected_map = Summarise(detected_map);
  out.fused_map = Summarise(fused_map);

  // The trace: the run whose x range is the median one.
  std::vector<std::pair<double, int>> by_range;
  for (int i = 0; i < static_cast<int>(detected.size()); ++i) {
    if (detected[i].samples >= 2) by_range.emplace_back(detected[i].x.range, i);
  }
  if (!by_range.empty()) {
    std::sort(by_range.begin(), by_range.end());
    const int k = by_range[by_range.size() / 2].second;
    out.trace = continuous[k].recognitions;
    out.trace_seed = continuous[k].seed;
  }

  const MethodSummary cs = eval::Summarise(continuous);
  FinalErrorSummary& fe = out.final_error;
  fe.x = cs.before_x;
  fe.y = cs.before_y;
  fe.yaw = cs.before_yaw;
  fe.after_x = cs.after_x;
  fe.after_y = cs.after_y;
  fe.after_yaw = cs.after_yaw;
  int within = 0;
  for (const PoseError& e : out.final_errors) {
    if (!e.valid) continue;
    ++fe.runs;
    within += std::abs(e.x) <= 0.01 && std::abs(e.y) <= 0.01 && std::abs(e.yaw) <= 0.014;
  }
  fe.within_paper_band = fe.runs > 0 ? static_cast<double>(within) / fe.runs : 0.0;

  out.continuous_time_s = MeanTime(continuous, &out.continuous_successes);
  out.stop_time_s = MeanTime(stop, &out.stop_successes);
  out.time_saving = 1.0 - out.continuous_time_s / out.stop_time_s;
  run_config.T_map_robot_start.reset();
  out.perfect_time_s = PerfectKnowledgeTime(scenario, run_config);
  return out;
}

}  // namespace shelfdock::eval
