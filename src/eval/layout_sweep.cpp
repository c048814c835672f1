#include "eval/layout_sweep.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "geometry/angle.hpp"

namespace shelfdock::eval {

namespace {

/// The true shelf nearest to a detected centre (id, distance); (-1, inf) without shelves.
std::pair<int, double> NearestShelf(const sim::World& world, const Eigen::Vector2d& p_world) {
  std::pair<int, double> best{-1, std::numeric_limits<double>::infinity()};
  for (const sim::ShelfInstance& s : world.shelves()) {
    const double d = (s.T_world_shelf.translation() - p_world).norm();
    if (d < best.second) best = {s.id, d};
  }
  return best;
}

FirstDetection MakeFirst(const sim::LayoutScene& scene, const perception::Detection& d) {
  FirstDetection f;
  f.model = d.model;
  f.T_lidar_shelf = d.T_lidar_shelf;
  f.T_world_shelf = scene.T_world_lidar * d.T_lidar_shelf;
  f.legs_used = d.legs_used;
  f.err_sum = d.err_sum;
  f.confidence = d.confidence;
  f.legs_occluded = d.legs_occluded;
  f.interior_points = d.interior_points;
  f.leg_width_bias_m = d.leg_width_bias_m;
  f.runner_up = d.runner_up;
  std::tie(f.nearest_shelf_id, f.nearest_shelf_m) =
      NearestShelf(scene.world, f.T_world_shelf.translation());
  return f;
}

bool IsTarget(const FirstDetection& first, const sim::ShelfInstance& target, double radius_m) {
  return first.model == target.model.name &&
         geometry::Distance(first.T_world_shelf, target.T_world_shelf) <= radius_m;
}

SceneOutcome Classify(const LayoutSceneResult& r, bool right) {
  if (r.target_model.empty()) {
    return r.detections == 0 ? SceneOutcome::kClutterClean : SceneOutcome::kClutterDetections;
  }
  if (!r.findable) {
    return !r.first || right ? SceneOutcome::kNotFindableClean : SceneOutcome::kNotFindableWrong;
  }
  if (!r.first) return SceneOutcome::kMissed;
  return right ? SceneOutcome::kRightFirst : SceneOutcome::kWrongFirst;
}

void RecordErrors(const sim::ShelfInstance& target, const perception::Detection& d,
                  const FirstDetection& first, LayoutSceneResult* r) {
  r->centre_error_m = geometry::Distance(first.T_world_shelf, target.T_world_shelf);
  // Modulo the model's symmetry: the detector cannot tell the ends of a shelf apart and is not
  // asked to.
  r->heading_error_rad = geometry::AngleDiffModulo(
      first.T_world_shelf.yaw, target.T_world_shelf.yaw, target.model.HeadingPeriod());
  r->length_error_m = d.length_m - target.model.length_m;
  r->width_error_m = d.width_m - target.model.width_m;
}

}  // namespace

std::string_view SceneOutcomeName(SceneOutcome outcome) {
  switch (outcome) {
    case SceneOutcome::kRightFirst:
      return "right-first";
    case SceneOutcome::kMissed:
      return "missed";
    case SceneOutcome::kWrongFirst:
      return "wrong-first";
    case SceneOutcome::kNotFindableClean:
      return "not-findable";
    case SceneOutcome::kNotFindableWrong:
      return "not-findable-wrong-first";
    case SceneOutcome::kClutterClean:
      return "clutter-clean";
    case SceneOutcome::kClutterDetections:
      return "clutter-detection";
  }
  return "unknown";
}

bool LayoutSceneResult::Failed() const {
  const bool outcome_ok = outcome == SceneOutcome::kRightFirst ||
                          outcome == SceneOutcome::kNotFindableClean ||
                          outcome == SceneOutcome::kClutterClean;
  return !outcome_ok || phantoms > 0;
}

LayoutSceneResult ScoreLayoutScene(const sim::LayoutScene& scene,
                                   const perception::DetectionResult& result,
                                   const LayoutSweepConfig& config) {
  LayoutSceneResult r;
  r.layout_class = scene.layout_class;
  r.seed = scene.seed;
  r.lidar_name = scene.lidar_name;
  r.noise_sigma_m = scene.lidar.range_noise_sigma_m;
  // Another evaluator may count a leg in sight from fewer (or more) beams than the generator
  // does when it places occluders: the findable scenes are counted as asked.
  r.legs_in_sight = config.min_beams_in_sight > 0
                        ? scene.target_sight.LegsInSight(config.min_beams_in_sight)
                        : scene.target_legs_in_sight;
  r.standoff_m = scene.target_standoff_m;
  r.T_world_preset = scene.T_world_preset;
  r.stats = result.stats;
  r.detections = static_cast<int>(result.detections.size());
  for (const perception::Detection& d : result.detections) {
    const geometry::Pose2 T_world_shelf = scene.T_world_lidar * d.T_lidar_shelf;
    if (NearestShelf(scene.world, T_world_shelf.translation()).second > config.phantom_radius_m) {
      ++r.phantoms;
    }
  }
  if (!result.detections.empty()) r.first = MakeFirst(scene, result.detections.front());

  const auto target = scene.Target();
  bool right = false;
  if (target) {
    r.target_model = target->model.name;
    r.T_world_target = target->T_world_shelf;
    r.findable = r.legs_in_sight >= config.min_legs_in_sight;
    right = r.first && IsTarget(*r.first, *target, config.right_radius_m);
  }
  r.outcome = Classify(r, right);
  if (r.outcome == SceneOutcome::kRightFirst) {
    RecordErrors(*target, result.detections.front(), *r.first, &r);
  }
  return r;
}

std::vector<LayoutSceneResult> RunLayoutSweep(const perception::Detector& detector,
                                              const std::vector<geometry::ShelfModel>& models,
                                              const sim::LayoutConfig& layout_config,
                                              const LayoutSweepConfig& config) {
  std::vector<LayoutSceneResult> results;
  results.reserve(config.classes.size() * static_cast<std::size_t>(config.scenes_per_class));
  // A robot sent to a shelf its map names by model as well as by place detects with that model
  // alone (as `shelfdock detect --model NAME`): one detector per model, with the same parameters.
  std::map<std::string, perception::Detector> by_model;
  auto detector_for = [&](const sim::LayoutScene& scene) -> const perception::Detector& {
    const std::optional<sim::ShelfInstance> target = scene.Target();
    if (!config.map_knows_model || !target) return detector;
    auto it = by_model.find(target->model.name);
    if (it == by_model.end()) {
      it =
          by_model
              .emplace(target->model.name, perception::Detector({target->model}, detector.config()))
              .first;
    }
    return it->second;
  };
  for (const sim::LayoutClass layout_class : config.classes) {
    for (int i = 0; i < config.scenes_per_class; ++i) {
      const std::uint64_t seed = config.seed0 + static_cast<std::uint64_t>(i);
      const sim::LayoutScene scene =
          sim::GenerateLayoutScene(layout_class, seed, models, layout_config);
      const perception::DetectionResult detected = detector_for(scene).Detect(
          sim::SimulateLayoutScan(scene), config.use_preset ? scene.PresetInLidar() : std::nullopt);
      results.push_back(ScoreLayoutScene(scene, detected, config));
    }
  }
  return results;
}

}  // namespace shelfdock::eval
