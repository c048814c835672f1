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
#include "config_paths.hpp"
#include "io/detection_json.hpp"
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
  std::string models = DefaultConfig("models.yaml");
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
    nlohmann::json out = io::DetectionResultToJson(result, true, T_base_lidar, T_map_base);
    const nlohmann::json hyps = out["hypotheses"];
    if (!opt.explain) out.erase("hypotheses");
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
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
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
