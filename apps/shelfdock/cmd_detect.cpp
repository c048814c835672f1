// `shelfdock detect`: runs the shelf detector on every scan of a file and prints one JSON line
// per scan: {"detections": [...], "stats": {...}}, detections best first, in the scan's frame,
// plus "base"/"map" poses when --extrinsic / --robot-pose are given.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/explain_json.hpp"
#include "io/html_page.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"
#include "io/scan_json.hpp"
#include "perception/detector.hpp"
#include "perception/frames.hpp"
#include "web_pages.hpp"

namespace shelfdock::app {
namespace {

struct DetectOptions {
  std::string models;
  std::string scan;
  std::string params;
  std::string preset;
  std::string extrinsic;
  std::string robot_pose;
  bool explain = false;
  std::string html;
};

// The explain page holds every point of every scan: past this many scans it gets too heavy for a
// browser to open comfortably; cut the file first (one scan per line in JSON Lines).
constexpr std::size_t kMaxHtmlScans = 200;

// Parses "X,Y,YAW" (metres, metres, radians); `flag` names the option in errors.
std::optional<geometry::Pose2> ParsePose(const std::string& text, const std::string& flag) {
  if (text.empty()) return std::nullopt;
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double d = 0.0;
    try {
      d = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(d)) {
      throw io::InputError("(command line)", flag, "expected X,Y,YAW as three finite numbers");
    }
    v.push_back(d);
  }
  if (v.size() != 3) {
    throw io::InputError("(command line)", flag, "expected X,Y,YAW as three finite numbers");
  }
  return geometry::Pose2(v[0], v[1], v[2]);
}

nlohmann::json PoseJson(const geometry::Pose2& T) {
  return {{"x", T.x}, {"y", T.y}, {"yaw", T.yaw}};
}

nlohmann::json DetectionJson(const perception::Detection& d,
                             const std::optional<geometry::Pose2>& T_base_lidar,
                             const std::optional<geometry::Pose2>& T_map_base) {
  nlohmann::json legs = nlohmann::json::array();
  for (const auto& l : d.legs) legs.push_back({l.x(), l.y()});
  nlohmann::json cov = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    cov.push_back({d.covariance(r, 0), d.covariance(r, 1), d.covariance(r, 2)});
  nlohmann::json j = {{"model", d.model},
                      {"x", d.T_lidar_shelf.x},
                      {"y", d.T_lidar_shelf.y},
                      {"yaw", d.T_lidar_shelf.yaw},
                      {"length", d.length_m},
                      {"width", d.width_m},
                      {"legs", legs},
                      {"legs_used", d.legs_used},
                      {"err_sum", d.err_sum},
                      {"cost", d.cost},
                      {"covariance", cov},
                      {"confidence", d.confidence},
                      {"legs_visible", d.legs_visible},
                      {"legs_occluded", d.legs_occluded},
                      {"interior_points", d.interior_points},
                      {"leg_width_error", d.leg_width_error_m},
                      {"leg_width_bias", d.leg_width_bias_m}};
  if (T_base_lidar) j["base"] = PoseJson(perception::ShelfInBase(d, *T_base_lidar));
  if (T_map_base) {
    j["map"] =
        PoseJson(perception::ShelfInMap(d, T_base_lidar.value_or(geometry::Pose2()), *T_map_base));
  }
  return j;
}

nlohmann::json StatsJson(const perception::DetectionStats& s) {
  return {{"valid_points", s.valid_points},
          {"roi_points", s.roi_points},
          {"clusters", s.clusters},
          {"trailing_removed", s.trailing_removed},
          {"leg_candidates", s.leg_candidates},
          {"leg_sets", s.leg_sets},
          {"model_pairs", s.model_pairs},
          {"hypotheses", s.hypotheses},
          {"rejected",
           {{"fit", s.rejected.fit},
            {"model", s.rejected.model},
            {"three_leg_error", s.rejected.three_leg_error},
            {"leg_seen_through", s.rejected.leg_seen_through},
            {"low_confidence", s.rejected.low_confidence},
            {"lost_legs", s.rejected.lost_legs}}}};
}

nlohmann::json HypothesisJson(const perception::HypothesisRecord& h) {
  nlohmann::json legs = nlohmann::json::array();
  for (const auto& l : h.legs) legs.push_back({l.x(), l.y()});
  return {{"model", h.model},
          {"verdict", perception::VerdictName(h.verdict)},
          {"x", h.T_lidar_shelf.x},
          {"y", h.T_lidar_shelf.y},
          {"yaw", h.T_lidar_shelf.yaw},
          {"legs", legs},
          {"err_sum", h.err_sum},
          {"confidence", h.confidence},
          {"legs_visible", h.legs_visible},
          {"legs_occluded", h.legs_occluded},
          {"legs_seen_through", h.legs_seen_through},
          {"interior_points", h.interior_points},
          {"foreign_legs_inside", h.foreign_legs_inside},
          {"leg_width_error", h.leg_width_error_m},
          {"leg_width_bias", h.leg_width_bias_m}};
}

int RunDetect(const DetectOptions& opt) {
  // Parse everything before detecting anything: bad input never yields partial output.
  const auto preset = ParsePose(opt.preset, "--preset");
  const auto T_base_lidar = ParsePose(opt.extrinsic, "--extrinsic");
  const auto T_map_base = ParsePose(opt.robot_pose, "--robot-pose");
  auto models = io::ReadShelfModels(opt.models);
  const perception::DetectorConfig config =
      opt.params.empty() ? perception::DetectorConfig{} : io::ReadDetectorConfig(opt.params);
  const auto scans = io::ReadScans(opt.scan);
  if (!opt.html.empty() && scans.size() > kMaxHtmlScans) {
    throw io::InputError(opt.scan, "--html",
                         std::to_string(scans.size()) + " scans; the explain page holds at most " +
                             std::to_string(kMaxHtmlScans) + " (cut the file first)");
  }
  const perception::Detector detector(std::move(models), config);
  nlohmann::json page_scans = nlohmann::json::array();

  for (const auto& scan : scans) {
    const perception::DetectionResult result =
        detector.Detect(scan, preset, opt.explain || !opt.html.empty());
    nlohmann::json dets = nlohmann::json::array();
    for (const auto& d : result.detections)
      dets.push_back(DetectionJson(d, T_base_lidar, T_map_base));
    nlohmann::json out{{"detections", dets}, {"stats", StatsJson(result.stats)}};
    nlohmann::json hyps = nlohmann::json::array();
    for (const auto& h : result.hypotheses) hyps.push_back(HypothesisJson(h));
    if (opt.explain) out["hypotheses"] = hyps;
    std::cout << out.dump() << "\n";
    if (!opt.html.empty()) {
      nlohmann::json page_scan = io::ExplainGeometryJson(scan, detector, preset);
      page_scan["detections"] = out["detections"];
      page_scan["stats"] = out["stats"];
      page_scan["hypotheses"] = hyps;
      page_scan["stamp"] = scan.stamp;
      page_scans.push_back(std::move(page_scan));
    }
  }
  if (!opt.html.empty()) {
    const nlohmann::json page{
        {"source", opt.scan},
        {"preset", preset ? nlohmann::json{{"x", preset->x}, {"y", preset->y}, {"yaw", preset->yaw}}
                          : nlohmann::json(nullptr)},
        {"models", io::ModelsJson(detector.models())},
        {"min_confidence", detector.config().evidence.min_confidence},
        {"scans", page_scans}};
    io::WritePage(opt.html, kExplainPage, page);
  }
  return kExitOk;
}

}  // namespace

void AddDetectCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<DetectOptions>();
  CLI::App* cmd =
      app.add_subcommand("detect", "detect shelves in LiDAR scans (one JSON line per scan)");
  cmd->add_option("--models", opt->models, "shelf models YAML (e.g. config/models.yaml)")
      ->required();
  cmd->add_option("--scan", opt->scan, "scans: JSON object, array or JSON Lines")->required();
  cmd->add_option("--preset", opt->preset,
                  "expected shelf pose X,Y,YAW in the lidar frame [m,m,rad]");
  cmd->add_option("--params", opt->params, "detector parameters YAML (e.g. config/detector.yaml)");
  cmd->add_option("--extrinsic", opt->extrinsic, "T_base_lidar as X,Y,YAW: also report base poses");
  cmd->add_option("--robot-pose", opt->robot_pose, "T_map_base as X,Y,YAW: also report map poses");
  cmd->add_flag("--explain", opt->explain,
                "also print every hypothesis (leg set and model) with its evidence and verdict");
  cmd->add_option("--html", opt->html,
                  "also write the explain page here: points, clusters, ROI, legs, hypotheses with "
                  "their verdicts, detections (one self-contained HTML file)");
  cmd->callback([opt, exit_code] { *exit_code = RunDetect(*opt); });
}

}  // namespace shelfdock::app
