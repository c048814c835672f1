#include "eval/layout_summary.hpp"

#include <algorithm>

#include <cmath>
#include <map>

#include "eval/monte_carlo.hpp"

namespace shelfdock::eval {

namespace {

ErrorQuantiles Quantiles(const std::vector<double>& values) {
  ErrorQuantiles q;
  q.count = static_cast<int>(values.size());
  if (values.empty()) return q;
  q.p50 = Quantile(values, 0.5);
  q.p95 = Quantile(values, 0.95);
  return q;
}

double MeanAbs(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double v : values) sum += std::abs(v);
  return sum / static_cast<double>(values.size());
}

void Count(const LayoutSceneResult& r, LayoutSummary* s) {
  ++s->scenes;
  s->findable += r.findable ? 1 : 0;
  s->phantoms += r.phantoms;
  s->phantom_scenes += r.phantoms > 0 ? 1 : 0;
  switch (r.outcome) {
    case SceneOutcome::kRightFirst:
      ++s->right_first;
      break;
    case SceneOutcome::kMissed:
      ++s->missed;
      break;
    case SceneOutcome::kWrongFirst:
      ++s->wrong_first;
      break;
    case SceneOutcome::kNotFindableWrong:
      ++s->not_findable_wrong;
      break;
    case SceneOutcome::kClutterClean:
    case SceneOutcome::kClutterDetections:
      ++s->clutter_scenes;
      s->clutter_detections += r.detections;
      break;
    case SceneOutcome::kNotFindableClean:
      break;
  }
}

}  // namespace

double LayoutSummary::RightFirstRate() const {
  return findable > 0 ? static_cast<double>(right_first) / findable
                      : std::numeric_limits<double>::quiet_NaN();
}

const NoiseLevelErrors* LayoutSummary::AtNoise(double noise_sigma_m) const {
  for (const NoiseLevelErrors& e : by_noise) {
    if (std::abs(e.noise_sigma_m - noise_sigma_m) < 1e-4) return &e;
  }
  return nullptr;
}

LayoutSummary SummariseLayouts(const std::vector<LayoutSceneResult>& scenes,
                               const std::string& name, const LayoutSweepConfig& config) {
  LayoutSummary s;
  s.name = name;
  // Errors per noise level, keyed to 0.1 mm so that equal configured noises meet.
  std::map<long, std::pair<std::vector<double>, std::vector<double>>> errors;
  std::vector<double> length_errors, width_errors;
  for (const LayoutSceneResult& r : scenes) {
    Count(r, &s);
    if (r.outcome != SceneOutcome::kRightFirst) continue;
    length_errors.push_back(r.length_error_m);
    width_errors.push_back(r.width_error_m);
    if (r.standoff_m > config.accuracy_max_standoff_m) continue;
    auto& [centre, heading] = errors[std::lround(r.noise_sigma_m * 1e4)];
    centre.push_back(r.centre_error_m);
    heading.push_back(r.heading_error_rad);
  }
  for (const auto& [key, values] : errors) {
    s.by_noise.push_back(
        {static_cast<double>(key) * 1e-4, Quantiles(values.first), Quantiles(values.second)});
  }
  s.mean_abs_length_error_m = MeanAbs(length_errors);
  s.mean_abs_width_error_m = MeanAbs(width_errors);
  return s;
}

std::vector<LayoutSummary> SummariseLayoutsByClass(const std::vector<LayoutSceneResult>& scenes,
                                                   const LayoutSweepConfig& config) {
  std::vector<LayoutSummary> rows;
  for (const sim::LayoutClass c : config.classes) {
    std::vector<LayoutSceneResult> of_class;
    for (const LayoutSceneResult& r : scenes) {
      if (r.layout_class == c) of_class.push_back(r);
    }
    if (!of_class.empty()) {
      rows.push_back(SummariseLayouts(of_class, std::string(sim::LayoutClassName(c)), config));
    }
  }
  rows.push_back(SummariseLayouts(scenes, "overall", config));
  return rows;
}

std::vector<LayoutSummary> SummariseLayoutsByLidar(const std::vector<LayoutSceneResult>& scenes,
                                                   const LayoutSweepConfig& config) {
  std::vector<std::string> names;
  for (const LayoutSceneResult& r : scenes) {
    if (std::find(names.begin(), names.end(), r.lidar_name) == names.end()) {
      names.push_back(r.lidar_name);
    }
  }
  std::vector<LayoutSummary> rows;
  for (const std::string& name : names) {
    std::vector<LayoutSceneResult> of_lidar;
    for (const LayoutSceneResult& r : scenes) {
      if (r.lidar_name == name) of_lidar.push_back(r);
    }
    rows.push_back(SummariseLayouts(of_lidar, name, config));
  }
  return rows;
}

ModelConfusionSummary SummariseModelConfusions(const std::vector<LayoutSceneResult>& scenes,
                                               const LayoutSweepConfig& config, double margin) {
  ModelConfusionSummary out;
  for (const LayoutSceneResult& r : scenes) {
    if (!r.first) continue;
    const FirstDetection& f = *r.first;
    const bool unsure = f.runner_up && f.runner_up->chi2_margin < margin;
    if (r.outcome == SceneOutcome::kRightFirst) {
      ++out.right_first;
      if (unsure) ++out.right_first_flagged;
    } else if (r.outcome == SceneOutcome::kWrongFirst && f.model != r.target_model &&
               geometry::Distance(f.T_world_shelf, r.T_world_target) <= config.right_radius_m) {
      ++out.confusions;
      if (unsure && f.runner_up->model == r.target_model) ++out.confusions_flagged;
    }
  }
  return out;
}

}  // namespace shelfdock::eval
