// `shelfdock dock`: one simulated docking, printed as one JSON object; `shelfdock eval-docking`:
// N seeded dockings with both methods on the same seeds, printed as one JSON summary.
#include <algorithm>
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
#include "eval/docking_runner.hpp"
#include "eval/monte_carlo.hpp"
#include "eval/random_start.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/html_page.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/robot_yaml.hpp"
#include "io/run_record.hpp"
#include "io/scenario_yaml.hpp"
#include "progress.hpp"
#include "web_pages.hpp"

namespace shelfdock::app {
namespace {

// Runs listed per axis under "worst_before_check" in eval-docking's JSON.
constexpr std::size_t kWorstRunsListed = 5;

struct DockOptions {
  std::string scenario = DefaultConfig("scenarios/paper_docking.yaml");
  std::string models = DefaultConfig("models.yaml");
  std::string config;
  std::string params;
  std::string lidar;
  std::string robot;
  std::string method = "continuous";
  int target = -1;
  bool random_start = false;
  std::string record;
  std::string html;
  std::uint64_t seed = 1;
  int runs = 100;
  double blackout_s = -1.0;
  bool camera_blind = false;
};

docking::Method ParseMethod(const std::string& text) {
  if (text == "continuous") return docking::Method::kContinuous;
  if (text == "stop-and-recognise") return docking::Method::kStopAndRecognise;
  throw io::InputError(kCommandLine, "--method", "expected continuous or stop-and-recognise");
}

eval::RunConfig MakeRunConfig(const DockOptions& opt) {
  eval::RunConfig config;
  if (!opt.config.empty()) config.docking = io::ReadDockingConfig(opt.config);
  if (!opt.params.empty()) config.detector = io::ReadDetectorConfig(opt.params);
  if (!opt.lidar.empty()) config.lidar = io::ReadLidarConfig(opt.lidar);
  if (!opt.robot.empty()) config.robot = io::ReadRobotConfig(opt.robot);
  config.sensors.blackout_start_s = opt.blackout_s;
  config.sensors.camera_blind = opt.camera_blind;
  return config;
}

nlohmann::json StatsJson(const eval::AbsErrorStats& s) {
  return {{"p95", s.p95}, {"p99", s.p99}, {"max", s.max}};
}

nlohmann::json SummaryJson(const eval::MethodSummary& s) {
  nlohmann::json phases = io::PhaseTimesJson(s.mean_phases);
  phases.erase("code_checks");  // counts are averaged separately (fractional)
  phases.erase("adjustments");
  return {{"runs", s.runs},
          {"success_rate", s.runs > 0 ? static_cast<double>(s.successes) / s.runs : 0.0},
          {"mean_time_s", s.mean_time_s},
          {"before_check",
           {{"x", StatsJson(s.before_x)},
            {"y", StatsJson(s.before_y)},
            {"yaw", StatsJson(s.before_yaw)},
            {"within_10mm_14mrad", s.within_before}}},
          {"after_check",
           {{"x", StatsJson(s.after_x)},
            {"y", StatsJson(s.after_y)},
            {"yaw", StatsJson(s.after_yaw)},
            {"within_3mm_5mrad", s.within_after}}},
          {"min_leg_clearance_m", s.min_leg_clearance_m},
          {"mean_phases_s", phases},
          {"mean_code_checks", s.mean_code_checks},
          {"mean_adjustments", s.mean_adjustments}};
}

/// The scenario with --target applied (it must name one of its shelves).
sim::Scenario LoadScenario(const DockOptions& opt,
                           const std::vector<geometry::ShelfModel>& models) {
  sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  if (opt.target >= 0) {
    if (scenario.FindShelf(opt.target) == nullptr) {
      throw io::InputError(kCommandLine, "--target",
                           "no shelf " + std::to_string(opt.target) + " in " + opt.scenario);
    }
    scenario.target_shelf_id = opt.target;
  }
  return scenario;
}

/// A random start for `seed` (--random-start), else the scenario's.
std::optional<geometry::Pose2> StartFor(const DockOptions& opt, const sim::Scenario& scenario,
                                        const eval::RunConfig& config, std::uint64_t seed) {
  if (!opt.random_start) return std::nullopt;
  const auto start = eval::RandomStart(scenario, seed, config.robot.footprint_length_m,
                                       config.robot.footprint_width_m);
  if (!start) {
    throw io::InputError(opt.scenario, "shelves",
                         "no free start 0.3-8 m from the target shelf for --random-start");
  }
  return start;
}

int RunDock(const DockOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = LoadScenario(opt, models);
  const docking::Method method = ParseMethod(opt.method);
  eval::RunConfig config = MakeRunConfig(opt);
  config.T_map_robot_start = StartFor(opt, scenario, config, opt.seed);
  config.record = !opt.record.empty() || !opt.html.empty();
  const eval::DockingRun run = eval::RunDocking(scenario, models, method, opt.seed, config);
  const geometry::Pose2 T_map_shelf_preset =
      scenario.PresetPose(scenario.target_shelf_id, opt.seed).value_or(geometry::Pose2());
  if (!opt.record.empty()) {
    io::WriteRunRecord(opt.record, scenario, T_map_shelf_preset, run,
                       config.robot.footprint_length_m, config.robot.footprint_width_m);
  }
  if (!opt.html.empty()) {
    const std::string name = scenario.name + " seed " + std::to_string(opt.seed) + " " +
                             std::string(docking::ToString(method));
    const nlohmann::json record = {{"name", name},
                                   {"lines", io::RunRecordLines(scenario, T_map_shelf_preset, run,
                                                                config.robot.footprint_length_m,
                                                                config.robot.footprint_width_m)}};
    io::WritePage(opt.html, kReplayPage, {{"records", {record}}});
  }
  std::cout << io::DockingRunToJson(run).dump() << "\n";
  return run.outcome.ok() ? kExitOk : kExitFailure;
}

int RunEvalDocking(const DockOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = LoadScenario(opt, models);
  if (opt.runs < 1) throw io::InputError(kCommandLine, "--runs", "must be >= 1");
  std::vector<docking::Method> methods{docking::Method::kContinuous,
                                       docking::Method::kStopAndRecognise};
  if (opt.method != "both") methods = {ParseMethod(opt.method)};
  eval::RunConfig config = MakeRunConfig(opt);
  nlohmann::json out{{"scenario", scenario.name},
                     {"target_shelf", scenario.target_shelf_id},
                     {"runs", opt.runs},
                     {"seed0", opt.seed},
                     {"random_start", opt.random_start}};
  double mean_time[2] = {0.0, 0.0};
  Progress progress("eval-docking", static_cast<long>(methods.size()) * opt.runs);
  long done = 0;
  for (docking::Method method : methods) {
    std::vector<eval::DockingRun> runs;
    nlohmann::json failures = nlohmann::json::array();
    nlohmann::json touched = nlohmann::json::array();  // runs whose footprint met a true leg
    for (int i = 0; i < opt.runs; ++i) {
      const std::uint64_t seed = opt.seed + static_cast<std::uint64_t>(i);
      config.T_map_robot_start = StartFor(opt, scenario, config, seed);
      runs.push_back(eval::RunDocking(scenario, models, method, seed, config));
      const eval::DockingRun& run = runs.back();
      progress.Update(++done,
                      std::string(docking::ToString(method)) + " seed " + std::to_string(seed));
      if (run.min_leg_clearance_m <= 0.0) {
        touched.push_back({{"seed", seed}, {"min_leg_clearance_m", run.min_leg_clearance_m}});
      }
      if (!run.outcome.ok()) {
        nlohmann::json f{{"seed", seed},
                         {"result", docking::ToString(run.outcome.code)},
                         {"reason", run.outcome.reason}};
        if (config.T_map_robot_start) {
          const geometry::Pose2& p = *config.T_map_robot_start;
          f["start"] = {p.x, p.y, p.yaw};
        }
        failures.push_back(f);
      }
    }
    const eval::MethodSummary s = eval::Summarise(runs);
    // The runs behind the tail of the before-check figures, by seed, so each can be replayed
    // with `dock --seed` (its events say what the robot saw).
    std::vector<const eval::DockingRun*> valid;
    for (const auto& r : runs) {
      if (r.error_before_check.valid) valid.push_back(&r);
    }
    nlohmann::json worst = nlohmann::json::object();
    for (const bool yaw : {false, true}) {
      auto size = [yaw](const eval::DockingRun* r) {
        const eval::PoseError& e = r->error_before_check;
        return yaw ? std::abs(e.yaw) : std::hypot(e.x, e.y);
      };
      std::sort(
          valid.begin(), valid.end(),
          [&](const eval::DockingRun* a, const eval::DockingRun* b) { return size(a) > size(b); });
      nlohmann::json list = nlohmann::json::array();
      for (std::size_t k = 0; k < std::min<std::size_t>(kWorstRunsListed, valid.size()); ++k) {
        const eval::PoseError& e = valid[k]->error_before_check;
        list.push_back({{"seed", valid[k]->seed}, {"x_m", e.x}, {"y_m", e.y}, {"yaw_rad", e.yaw}});
      }
      worst[yaw ? "yaw" : "xy"] = list;
    }
    mean_time[method == docking::Method::kContinuous ? 0 : 1] = s.mean_time_s;
    nlohmann::json summary = SummaryJson(s);
    summary["failures"] = failures;
    summary["leg_contacts"] = touched;
    summary["worst_before_check"] = worst;
    out[std::string(docking::ToString(method))] = summary;
  }
  if (mean_time[0] > 0.0 && mean_time[1] > 0.0) {
    out["continuous_time_saving"] = 1.0 - mean_time[0] / mean_time[1];
  }
  if (!opt.random_start) {
    config.T_map_robot_start.reset();
    const double perfect_s = eval::PerfectKnowledgeTime(scenario, config);
    out["perfect_knowledge_time_s"] = perfect_s;
    if (mean_time[0] > 0.0 && perfect_s > 0.0) {
      out["continuous_time_vs_perfect_knowledge"] = mean_time[0] / perfect_s;
    }
  }
  std::cout << out.dump(2) << "\n";
  return kExitOk;
}

void AddCommonOptions(CLI::App* cmd, DockOptions* opt) {
  cmd->add_option("--scenario", opt->scenario, "scenario YAML")->capture_default_str();
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--config", opt->config, "docking config YAML (e.g. config/docking.yaml)");
  cmd->add_option("--params", opt->params,
                  "detector parameters YAML (e.g. config/detector.yaml; default: its values)");
  cmd->add_option("--lidar", opt->lidar, "LiDAR config YAML (default: the WLR-716's defaults)");
  cmd->add_option("--robot", opt->robot, "robot config YAML (default: config/robot.yaml's values)");
  cmd->add_option("--target", opt->target, "dock under this shelf id instead of the scenario's");
  cmd->add_flag("--random-start", opt->random_start,
                "start anywhere in free space 0.3-8 m from the shelf, any heading (per seed)");
  cmd->add_option("--lidar-blackout", opt->blackout_s,
                  "failure injection: no scans from this many seconds after the entry");
  cmd->add_flag("--camera-blind", opt->camera_blind,
                "failure injection: the upward camera never sees a code");
}

}  // namespace

void AddDockCommands(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<DockOptions>();
  CLI::App* dock = app.add_subcommand("dock", "simulate one docking and print its outcome (JSON)");
  AddCommonOptions(dock, opt.get());
  dock->add_option("--method", opt->method, "continuous | stop-and-recognise")
      ->capture_default_str();
  dock->add_option("--seed", opt->seed, "random seed")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  dock->add_option("--record", opt->record, "write the run as JSON Lines for replay");
  dock->add_option("--html", opt->html,
                   "write the replay page of the run here (one self-contained HTML file)");
  dock->callback([opt, exit_code] { *exit_code = RunDock(*opt); });

  auto eopt = std::make_shared<DockOptions>();
  CLI::App* ev = app.add_subcommand(
      "eval-docking", "N seeded dockings, both methods on the same seeds: percentiles and times");
  AddCommonOptions(ev, eopt.get());
  ev->add_option("--runs", eopt->runs, "dockings per method")->capture_default_str();
  eopt->method = "both";
  ev->add_option("--method", eopt->method, "both | continuous | stop-and-recognise")
      ->capture_default_str();
  ev->add_option("--seed0", eopt->seed, "first seed")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  ev->callback([eopt, exit_code] { *exit_code = RunEvalDocking(*eopt); });
}

}  // namespace shelfdock::app
