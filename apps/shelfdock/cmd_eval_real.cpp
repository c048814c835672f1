// `shelfdock eval-real`: runs the detector over every LaserScan of a recorded ROS 1 bag that holds
// no shelf of our models (real clutter) and reports false positives and detection time. The
// clock lives here, in the app layer, never in the core.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "config_paths.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/rosbag_scans.hpp"
#include "perception/detector.hpp"
#include "progress.hpp"

namespace shelfdock::app {
namespace {

struct EvalRealOptions {
  std::vector<std::string> bags;
  std::string topic;
  std::string models = DefaultConfig("models.yaml");
  std::string params;
};

double Percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto idx = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(idx, values.size() - 1)];
}

nlohmann::json EvaluateTopic(const perception::Detector& detector,
                             const std::vector<geometry::LaserScan>& scans, Progress& progress) {
  std::vector<double> times_us;
  times_us.reserve(scans.size());
  int scans_with_detection = 0;
  int detections = 0;
  long leg_candidates = 0;
  long leg_sets = 0;
  for (const auto& scan : scans) {
    const auto start = std::chrono::steady_clock::now();
    const perception::DetectionResult result = detector.Detect(scan);
    const auto stop = std::chrono::steady_clock::now();
    times_us.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
    detections += static_cast<int>(result.detections.size());
    scans_with_detection += result.detections.empty() ? 0 : 1;
    leg_candidates += result.stats.leg_candidates;
    leg_sets += result.stats.leg_sets;
    progress.Update(static_cast<long>(times_us.size()));
  }
  const double n = static_cast<double>(scans.size());
  return {{"scans", scans.size()},
          {"beams", scans.front().ranges.size()},
          {"scans_with_detection", scans_with_detection},
          {"detections", detections},
          {"false_positive_rate", scans_with_detection / n},
          {"mean_leg_candidates", static_cast<double>(leg_candidates) / n},
          {"mean_leg_sets", static_cast<double>(leg_sets) / n},
          {"detect_us",
           {{"median", Percentile(times_us, 0.5)},
            {"p95", Percentile(times_us, 0.95)},
            {"max", Percentile(times_us, 1.0)}}}};
}

int RunEvalReal(const EvalRealOptions& opt) {
  perception::DetectorConfig config;
  if (!opt.params.empty()) config = io::ReadDetectorConfig(opt.params);
  const perception::Detector detector(io::ReadShelfModels(opt.models), config);

  nlohmann::json report = nlohmann::json::array();
  for (const auto& bag : opt.bags) {
    std::vector<std::string> topics;
    if (opt.topic.empty()) {
      for (const auto& t : io::ListBagScanTopics(bag)) topics.push_back(t.topic);
    } else {
      topics.push_back(opt.topic);
    }
    for (const auto& topic : topics) {
      Progress progress("eval-real " + bag + " " + topic, 0);
      progress.Update(0, "reading");
      const std::vector<geometry::LaserScan> scans = io::ReadBagScans(bag, topic);
      Progress detecting("eval-real " + topic, static_cast<long>(scans.size()));
      nlohmann::json row = EvaluateTopic(detector, scans, detecting);
      row["bag"] = bag;
      row["topic"] = topic;
      report.push_back(row);
    }
  }
  std::cout << nlohmann::json{{"real_clutter", report}}.dump(2) << "\n";
  return kExitOk;
}

}  // namespace

void AddEvalRealCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<EvalRealOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval-real", "false positives and detection time on recorded real scans (ROS 1 bags)");
  cmd->add_option("--bag", opt->bags, "ROS 1 bag file(s) holding no shelf of the models")
      ->required();
  cmd->add_option("--topic", opt->topic, "LaserScan topic (default: every LaserScan topic)");
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--params", opt->params, "detector parameters YAML");
  cmd->callback([opt, exit_code] { *exit_code = RunEvalReal(*opt); });
}

}  // namespace shelfdock::app
