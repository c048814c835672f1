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
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"
#include "io/scan_json.hpp"
#include "io/scan_line_reader.hpp"
#include "perception/detector.hpp"
#include "perception/frames.hpp"

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
};

std::optional<geometry::Pose2> OptionalPose(const std::string& text, const std::string& flag) {
  if (text.empty()) return std::nullopt;
  return ParsePose(text, flag);
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
                      {"leg_width_error", d.leg_width_error_m}};
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
          {"leg_width_error", h.leg_width_error_m}};
}

/// The detector and frames of one `detect` run, and the JSON line it prints per scan.
struct DetectJob {
  perception::Detector detector;
  std::optional<geometry::Pose2> preset;
  std::optional<geometry::Pose2> T_base_lidar;
  std::optional<geometry::Pose2> T_map_base;
  bool explain = false;

  nlohmann::json Run(const geometry::LaserScan& scan) const {
    const perception::DetectionResult result = detector.Detect(scan, preset, explain);
    nlohmann::json dets = nlohmann::json::array();
    for (const auto& d : result.detections)
      dets.push_back(DetectionJson(d, T_base_lidar, T_map_base));
    nlohmann::json out{{"detections", dets}, {"stats", StatsJson(result.stats)}};
    if (explain) {
      nlohmann::json hyps = nlohmann::json::array();
      for (const auto& h : result.hypotheses) hyps.push_back(HypothesisJson(h));
      out["hypotheses"] = hyps;
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
  DetectJob job{perception::Detector(io::ReadShelfModels(opt.models),
                                     opt.params.empty() ? perception::DetectorConfig{}
                                                        : io::ReadDetectorConfig(opt.params)),
                OptionalPose(opt.preset, "--preset"), OptionalPose(opt.extrinsic, "--extrinsic"),
                OptionalPose(opt.robot_pose, "--robot-pose"), opt.explain};
  if (opt.scan == "-") return StreamDetect(job);
  // A file is checked whole first (one scan in memory at a time), then detected.
  io::ForEachScan(opt.scan, [](const geometry::LaserScan&) {});
  io::ForEachScan(opt.scan, [&job](const geometry::LaserScan& scan) {
    std::cout << job.Run(scan).dump() << "\n";
  });
  return kExitOk;
}

}  // namespace

void AddDetectCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<DetectOptions>();
  CLI::App* cmd =
      app.add_subcommand("detect", "detect shelves in LiDAR scans (one JSON line per scan)");
  cmd->add_option("--models", opt->models, "shelf models YAML (e.g. config/models.yaml)")
      ->required();
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
  cmd->callback([opt, exit_code] { *exit_code = RunDetect(*opt); });
}

}  // namespace shelfdock::app
