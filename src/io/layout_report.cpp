#include "io/layout_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/detection_json.hpp"
#include "io/input_error.hpp"
#include "io/scan_json.hpp"

namespace shelfdock::io {

namespace {

template <typename... Args>
std::string Format(const char* format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);
  std::string out(static_cast<std::size_t>(std::max(n, 0)) + 1, '\0');
  std::snprintf(out.data(), out.size(), format, args...);
  out.resize(static_cast<std::size_t>(std::max(n, 0)));
  return out;
}

/// "p50/p95" of an error, scaled (1e3: mm or mrad); "-" without samples.
std::string Pair(const eval::ErrorQuantiles& q, double scale) {
  if (q.count == 0) return "-";
  return Format("%.1f/%.1f", scale * q.p50, scale * q.p95);
}

std::string NoiseColumns(const eval::LayoutSummary& row, double noise_sigma_m) {
  const eval::NoiseLevelErrors* e = row.AtNoise(noise_sigma_m);
  if (e == nullptr) return Format(" %5s %11s %11s", "0", "-", "-");
  return Format(" %5d %11s %11s", e->centre_m.count, Pair(e->centre_m, 1e3).c_str(),
                Pair(e->heading_rad, 1e3).c_str());
}

std::string RowLine(const eval::LayoutSummary& r, double low, double high) {
  const double rate = r.RightFirstRate();
  const std::string pct = std::isnan(rate) ? "-" : Format("%.2f%%", 100.0 * rate);
  const std::string size =
      std::isnan(r.mean_abs_length_error_m)
          ? "-"
          : Format("%.1f/%.1f", 1e3 * r.mean_abs_length_error_m, 1e3 * r.mean_abs_width_error_m);
  return Format("%-17s %6d %6d %6d %8s %6d %6d %6d %6d %6d %6d", r.name.c_str(), r.scenes,
                r.findable, r.right_first, pct.c_str(), r.missed, r.wrong_first, r.not_findable(),
                r.not_findable_wrong, r.phantoms, r.clutter_detections) +
         NoiseColumns(r, low) + NoiseColumns(r, high) + Format(" %9s", size.c_str());
}

nlohmann::json PoseJson(const geometry::Pose2& T) {
  return {{"x", T.x}, {"y", T.y}, {"yaw", T.yaw}};
}

nlohmann::json QuantilesJson(const eval::ErrorQuantiles& q) {
  if (q.count == 0) return {{"count", 0}, {"p50", nullptr}, {"p95", nullptr}};
  return {{"count", q.count}, {"p50", q.p50}, {"p95", q.p95}};
}

nlohmann::json SummaryJson(const eval::LayoutSummary& r) {
  nlohmann::json noise = nlohmann::json::array();
  for (const auto& e : r.by_noise) {
    noise.push_back({{"noise_sigma_m", e.noise_sigma_m},
                     {"centre_m", QuantilesJson(e.centre_m)},
                     {"heading_rad", QuantilesJson(e.heading_rad)}});
  }
  const double rate = r.RightFirstRate();
  auto number_or_null = [](double v) {
    return std::isnan(v) ? nlohmann::json() : nlohmann::json(v);
  };
  return {{"class", r.name},
          {"scenes", r.scenes},
          {"findable", r.findable},
          {"right_first", r.right_first},
          {"right_first_rate", number_or_null(rate)},
          {"missed", r.missed},
          {"wrong_first", r.wrong_first},
          {"not_findable", r.not_findable()},
          {"not_findable_wrong_first", r.not_findable_wrong},
          {"phantoms", r.phantoms},
          {"phantom_scenes", r.phantom_scenes},
          {"clutter_scenes", r.clutter_scenes},
          {"clutter_detections", r.clutter_detections},
          {"errors_by_noise", noise},
          {"mean_abs_length_error_m", number_or_null(r.mean_abs_length_error_m)},
          {"mean_abs_width_error_m", number_or_null(r.mean_abs_width_error_m)}};
}

nlohmann::json FirstJson(const std::optional<eval::FirstDetection>& first,
                         const geometry::Pose2& T_frame_world) {
  if (!first) return nullptr;
  nlohmann::json j = PoseJson(T_frame_world * first->T_world_shelf);
  j["model"] = first->model;
  j["legs_used"] = first->legs_used;
  j["err_sum"] = first->err_sum;
  j["confidence"] = first->confidence;
  j["legs_occluded"] = first->legs_occluded;
  j["interior_points"] = first->interior_points;
  j["leg_width_bias"] = first->leg_width_bias_m;
  if (first->runner_up) j["runner_up"] = RunnerUpToJson(*first->runner_up);
  j["nearest_shelf_id"] = first->nearest_shelf_id;
  j["nearest_shelf_m"] = std::isfinite(first->nearest_shelf_m)
                             ? nlohmann::json(first->nearest_shelf_m)
                             : nlohmann::json();
  return j;
}

nlohmann::json SceneJson(const eval::LayoutSceneResult& r) {
  return {{"class", std::string(sim::LayoutClassName(r.layout_class))},
          {"seed", r.seed},
          {"lidar", r.lidar_name},
          {"noise_sigma_m", r.noise_sigma_m},
          {"outcome", std::string(eval::SceneOutcomeName(r.outcome))},
          {"legs_in_sight", r.legs_in_sight},
          {"standoff_m", r.standoff_m},
          {"target_model", r.target_model},
          {"target", r.target_model.empty() ? nlohmann::json() : PoseJson(r.T_world_target)},
          {"detections", r.detections},
          {"phantoms", r.phantoms},
          {"first", FirstJson(r.first, geometry::Pose2())},
          {"line", LayoutFailureLine(r)}};
}

void WriteJsonFile(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path);
  if (!out) throw InputError(path, "", "cannot write file");
  out << j.dump(1) << "\n";
}

std::string PresetArgument(const geometry::Pose2& T) {
  return Format("%.6f,%.6f,%.6f", T.x, T.y, T.yaw);
}

}  // namespace

std::vector<std::string> LayoutTableLines(const std::vector<eval::LayoutSummary>& rows,
                                          double low_noise_sigma_m, double high_noise_sigma_m,
                                          const std::string& prefix,
                                          const std::string& first_column) {
  const double low_mm = 1e3 * low_noise_sigma_m, high_mm = 1e3 * high_noise_sigma_m;
  std::vector<std::string> lines;
  lines.push_back(prefix +
                  Format("%-17s %6s %6s %6s %8s %6s %6s %6s %6s %6s %6s | %3.0fmm: %5s %11s "
                         "%11s | %3.0fmm: %5s %11s %11s | %9s",
                         first_column.c_str(), "scenes", "find", "right", "right%", "missed",
                         "wrong", "nofind", "nf-wr", "phant", "clutd", low_mm, "n", "ctr mm",
                         "hdg mrad", high_mm, "n", "ctr mm", "hdg mrad", "|dL|/|dW|"));
  for (const auto& r : rows) {
    lines.push_back(prefix + RowLine(r, low_noise_sigma_m, high_noise_sigma_m));
  }
  return lines;
}

std::vector<std::string> LayoutLegendLines(const eval::LayoutSweepConfig& config,
                                           const std::string& prefix) {
  std::vector<std::string> lines;
  const std::string beams =
      config.min_beams_in_sight > 0 ? Format(" (%d+ beams)", config.min_beams_in_sight) : "";
  lines.push_back(prefix + Format("find: target scenes with >= %d legs in line of sight%s; right: "
                                  "the target first (its model, centre within %.0f mm); missed / "
                                  "wrong: findable, nothing / something else first;",
                                  config.min_legs_in_sight, beams.c_str(),
                                  1e3 * config.right_radius_m));
  lines.push_back(prefix + Format("nofind: not findable; nf-wr: not findable, another shelf or a "
                                  "phantom first; phant: detections > %.0f mm from every true "
                                  "shelf; clutd: detections on clutter;",
                                  1e3 * config.phantom_radius_m));
  lines.push_back(prefix + Format("n, ctr, hdg: right-first scenes with standoff <= %.1f m at that "
                                  "noise, centre and heading error p50/p95; |dL|/|dW|: mean size "
                                  "error [mm]",
                                  config.accuracy_max_standoff_m));
  if (config.map_knows_model) {
    lines.push_back(prefix +
                    "the map names the target's model: scenes with a target were "
                    "detected with that model alone");
  }
  return lines;
}

std::string LayoutFailureLine(const eval::LayoutSceneResult& r) {
  std::string line =
      Format("%s seed %llu [%s %.0fmm] %s: legs in sight %d, standoff %.2f m",
             std::string(sim::LayoutClassName(r.layout_class)).c_str(),
             static_cast<unsigned long long>(r.seed), r.lidar_name.c_str(), 1e3 * r.noise_sigma_m,
             std::string(eval::SceneOutcomeName(r.outcome)).c_str(), r.legs_in_sight, r.standoff_m);
  if (!r.target_model.empty()) {
    line += Format("; truth %s (%.3f, %.3f, %.3f)", r.target_model.c_str(), r.T_world_target.x,
                   r.T_world_target.y, r.T_world_target.yaw);
  }
  if (r.first) {
    const auto& f = *r.first;
    line += Format("; first %s (%.3f, %.3f, %.3f) %d legs err_sum %.3f, %.3f m from shelf %d",
                   f.model.c_str(), f.T_world_shelf.x, f.T_world_shelf.y, f.T_world_shelf.yaw,
                   f.legs_used, f.err_sum, f.nearest_shelf_m, f.nearest_shelf_id);
  } else {
    line += "; no detection";
  }
  const auto& s = r.stats;
  line += Format(
      "; detections %d phantoms %d; points %d roi %d clusters %d candidates %d sets %d "
      "pairs %d",
      r.detections, r.phantoms, s.valid_points, s.roi_points, s.clusters, s.leg_candidates,
      s.leg_sets, s.model_pairs);
  return line;
}

nlohmann::json LayoutSweepJson(const std::vector<eval::LayoutSummary>& rows,
                               const std::vector<eval::LayoutSceneResult>& scenes,
                               const eval::LayoutSweepConfig& config,
                               const std::vector<eval::LayoutSummary>& lidar_rows) {
  nlohmann::json table = nlohmann::json::array();
  for (const auto& r : rows) table.push_back(SummaryJson(r));
  nlohmann::json failures = nlohmann::json::array();
  nlohmann::json all = nlohmann::json::array();
  for (const auto& s : scenes) {
    all.push_back(SceneJson(s));
    if (s.Failed()) failures.push_back(all.back());
  }
  nlohmann::json out = {{"scenes_per_class", config.scenes_per_class},
                        {"seed0", config.seed0},
                        {"right_radius_m", config.right_radius_m},
                        {"phantom_radius_m", config.phantom_radius_m},
                        {"min_legs_in_sight", config.min_legs_in_sight},
                        {"min_beams_in_sight", config.min_beams_in_sight},
                        {"map_knows_model", config.map_knows_model},
                        {"accuracy_max_standoff_m", config.accuracy_max_standoff_m},
                        {"rows", table},
                        {"failures", failures},
                        {"scenes", all}};
  if (!lidar_rows.empty()) {
    nlohmann::json by_lidar = nlohmann::json::array();
    for (const auto& r : lidar_rows) by_lidar.push_back(SummaryJson(r));
    out["rows_by_lidar"] = by_lidar;
  }
  return out;
}

std::string WriteLayoutFailure(const std::string& dir, const sim::LayoutScene& scene,
                               const eval::LayoutSceneResult& result,
                               const std::string& detect_args) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir, "", "cannot create directory: " + ec.message());
  const std::string stem =
      (std::filesystem::path(dir) /
       Format("%s_%llu", std::string(sim::LayoutClassName(scene.layout_class)).c_str(),
              static_cast<unsigned long long>(scene.seed)))
          .string();
  const std::string scan_path = stem + ".scan.json";
  WriteJsonFile(scan_path, ScanToJson(sim::SimulateLayoutScan(scene)));

  const geometry::Pose2 T_lidar_world = scene.T_world_lidar.inverse();
  nlohmann::json shelves = nlohmann::json::array();
  for (const auto& s : scene.shelves()) {
    nlohmann::json j = PoseJson(T_lidar_world * s.T_world_shelf);
    j["id"] = s.id;
    j["model"] = s.model.name;
    if (!s.legs_as_built.empty()) {
      // Each leg's offset and twist off its design place, shelf frame (eval-layouts --as-built).
      nlohmann::json legs = nlohmann::json::array();
      for (const auto& leg : s.legs_as_built) legs.push_back(PoseJson(leg));
      j["legs_as_built"] = legs;
    }
    shelves.push_back(j);
  }
  nlohmann::json target;
  if (const auto t = scene.Target()) {
    target = PoseJson(T_lidar_world * t->T_world_shelf);
    target["id"] = t->id;
    target["model"] = t->model.name;
  }
  const auto preset = scene.PresetInLidar();
  std::string detect = "shelfdock detect " + detect_args + " --scan " + scan_path;
  if (preset) detect += " --preset " + PresetArgument(*preset);
  WriteJsonFile(stem + ".truth.json",
                {{"class", std::string(sim::LayoutClassName(scene.layout_class))},
                 {"seed", scene.seed},
                 {"lidar", scene.lidar_name},
                 {"noise_sigma_m", scene.lidar.range_noise_sigma_m},
                 {"outcome", std::string(eval::SceneOutcomeName(result.outcome))},
                 {"legs_in_sight", result.legs_in_sight},
                 {"findable", result.findable},
                 {"standoff_m", scene.target_standoff_m},
                 {"frame", "lidar (the scan's own)"},
                 {"T_world_lidar", PoseJson(scene.T_world_lidar)},
                 {"preset", preset ? PoseJson(*preset) : nlohmann::json()},
                 {"target", target},
                 {"shelves", shelves},
                 {"first", FirstJson(result.first, T_lidar_world)},
                 {"detect", detect}});
  return scan_path;
}

}  // namespace shelfdock::io
