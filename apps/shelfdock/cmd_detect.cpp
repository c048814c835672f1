// `shelfdock detect`: runs the shelf detector on every scan of a file (or of standard input,
// `--scan -`, streamed) and prints one JSON line per scan: {"detections": [...], "stats": {...}},
// detections best first, in the scan's frame, plus "base"/"map" poses when --extrinsic /
// --robot-pose are given.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "io/detection_json.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/explain_json.hpp"
#include "io/html_page.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"
#include "io/scan_json.hpp"
#include "io/scan_line_reader.hpp"
#include "perception/detector.hpp"
#include "perception/frames.hpp"
#include "web_pages.hpp"

namespace shelfdock::app {
namespace {

struct DetectOptions {
  std::string models = DefaultConfig("models.yaml");
  std::vector<std::string> model_names;  // --model: keep only these of the models file
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

std::optional<geometry::Pose2> OptionalPose(const std::string& text, const std::string& flag) {
  if (text.empty()) return std::nullopt;
  return ParsePose(text, flag);
}

/// The detector and frames of one `detect` run, and the JSON line it prints per scan.
struct DetectJob {
  perception::Detector detector;
  std::optional<geometry::Pose2> preset;
  std::optional<geometry::Pose2> T_base_lidar;
  std::optional<geometry::Pose2> T_map_base;
  bool explain = false;

  /// The line for `scan`; when `page_scan` is given it also gets the explain page's entry.
  nlohmann::json Run(const geometry::LaserScan& scan, nlohmann::json* page_scan = nullptr) const {
    const perception::DetectionResult result =
        detector.Detect(scan, preset, explain || page_scan != nullptr);
    nlohmann::json out = io::DetectionResultToJson(result, true, T_base_lidar, T_map_base);
    if (page_scan != nullptr) {
      *page_scan = io::ExplainGeometryJson(scan, detector, preset);
      (*page_scan)["detections"] = out["detections"];
      (*page_scan)["stats"] = out["stats"];
      (*page_scan)["hypotheses"] = out["hypotheses"];
      (*page_scan)["candidates"] = out["candidates"];
      (*page_scan)["stamp"] = scan.stamp;
    }
    if (!explain) {
      out.erase("hypotheses");
      out.erase("candidates");
    }
    return out;
  }
};

/// `--scan -`: JSON Lines from standard input, one flushed line out per line in, as soon as it
/// is computed. A bad line gets {"error", "line"} and the stream goes on; the exit code says
/// whether any line was bad.
int StreamDetect(const DetectJob& job) {
  io::ScanLineReader reader(std::cin, "(stdin)");
  bool any_bad = false;
  while (const std::optional<io::ScanLine> line = reader.Next()) {
    nlohmann::json out;
    if (line->scan) {
      out = job.Run(*line->scan);
    } else {
      any_bad = true;
      out = {{"error", line->error->what()}, {"line", line->line}};
    }
    std::cout << out.dump() << std::endl;  // flushed: the consumer sees it now
  }
  return any_bad ? kExitBadInput : kExitOk;
}

int RunDetect(const DetectOptions& opt) {
  // Parse everything before detecting anything: bad input never yields partial output.
  DetectJob job{
      perception::Detector(
          io::SelectModels(io::ReadShelfModels(opt.models), opt.model_names, opt.models, "--model"),
          opt.params.empty() ? perception::DetectorConfig{} : io::ReadDetectorConfig(opt.params)),
      OptionalPose(opt.preset, "--preset"), OptionalPose(opt.extrinsic, "--extrinsic"),
      OptionalPose(opt.robot_pose, "--robot-pose"), opt.explain};
  if (opt.scan == "-") {
    if (!opt.html.empty()) {
      throw io::InputError(std::string(kCommandLine), "--html",
                           "the explain page is written from a file, not from --scan -");
    }
    return StreamDetect(job);
  }
  // A file is checked whole first (one scan in memory at a time), then detected.
  std::size_t count = 0;
  io::ForEachScan(opt.scan, [&count](const geometry::LaserScan&) { ++count; });
  if (!opt.html.empty() && count > kMaxHtmlScans) {
    throw io::InputError(opt.scan, "--html",
                         std::to_string(count) + " scans; the explain page holds at most " +
                             std::to_string(kMaxHtmlScans) + " (cut the file first)");
  }
  nlohmann::json page_scans = nlohmann::json::array();
  io::ForEachScan(opt.scan, [&](const geometry::LaserScan& scan) {
    nlohmann::json page_scan;
    std::cout << job.Run(scan, opt.html.empty() ? nullptr : &page_scan).dump() << "\n";
    if (!opt.html.empty()) page_scans.push_back(std::move(page_scan));
  });
  if (!opt.html.empty()) {
    const auto& preset = job.preset;
    const nlohmann::json page{
        {"source", opt.scan},
        {"preset", preset ? nlohmann::json{{"x", preset->x}, {"y", preset->y}, {"yaw", preset->yaw}}
                          : nlohmann::json(nullptr)},
        {"models", io::ModelsJson(job.detector.models())},
        {"min_confidence", job.detector.config().evidence.min_confidence},
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
  cmd->add_option("--model", opt->model_names,
                  "detect only this model of --models, repeatable (the map names the shelf's "
                  "model: close models such as 1075x883 and 1080x856 are then never confused)");
  cmd->add_option("--scan", opt->scan,
                  "scans: JSON object, array or JSON Lines; - streams JSON Lines from stdin")
      ->required();
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
