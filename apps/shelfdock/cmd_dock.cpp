// `shelfdock dock`: one simulated docking, printed as one JSON object; `shelfdock eval-docking`:
// N seeded dockings with both methods on the same seeds, printed as one JSON summary.
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "eval/docking_runner.hpp"
#include "eval/monte_carlo.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/models_yaml.hpp"
#include "io/run_record.hpp"
#include "io/scenario_yaml.hpp"

namespace shelfdock::app {
namespace {

struct DockOptions {
  std::string scenario = "config/scenarios/paper_docking.yaml";
  std::string models = "config/models.yaml";
  std::string config;
  std::string method = "continuous";
  std::string record;
  std::uint64_t seed = 1;
  int runs = 100;
  double blackout_s = -1.0;
  bool camera_blind = false;
};

docking::Method ParseMethod(const std::string& text) {
  if (text == "continuous") return docking::Method::kContinuous;
  if (text == "stop-and-recognise") return docking::Method::kStopAndRecognise;
  throw io::InputError("(command line)", "--method", "expected continuous or stop-and-recognise");
}

eval::RunConfig MakeRunConfig(const DockOptions& opt) {
  eval::RunConfig config;
  if (!opt.config.empty()) config.docking = io::ReadDockingConfig(opt.config);
  config.blackout_start_s = opt.blackout_s;
  config.camera_blind = opt.camera_blind;
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

int RunDock(const DockOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  const docking::Method method = ParseMethod(opt.method);
  eval::RunConfig config = MakeRunConfig(opt);
  config.record = !opt.record.empty();
  const eval::DockingRun run = eval::RunDocking(scenario, models, method, opt.seed, config);
  if (!opt.record.empty()) {
    io::WriteRunRecord(
        opt.record, scenario,
        scenario.PresetPose(scenario.target_shelf_id, opt.seed).value_or(geometry::Pose2()), run,
        config.robot.footprint_length_m, config.robot.footprint_width_m);
  }
  std::cout << io::DockingRunToJson(run).dump() << "\n";
  return run.outcome.ok() ? kExitOk : kExitFailure;
}

int RunEvalDocking(const DockOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  if (opt.runs < 1) throw io::InputError("(command line)", "--runs", "must be >= 1");
  const eval::RunConfig config = MakeRunConfig(opt);
  nlohmann::json out{{"scenario", scenario.name}, {"runs", opt.runs}, {"seed0", opt.seed}};
  double mean_time[2] = {0.0, 0.0};
  int k = 0;
  for (docking::Method method :
       {docking::Method::kContinuous, docking::Method::kStopAndRecognise}) {
    std::vector<eval::DockingRun> runs;
    for (int i = 0; i < opt.runs; ++i) {
      runs.push_back(eval::RunDocking(scenario, models, method, opt.seed + i, config));
    }
    const eval::MethodSummary s = eval::Summarise(runs);
    mean_time[k++] = s.mean_time_s;
    out[std::string(docking::ToString(method))] = SummaryJson(s);
  }
  out["continuous_time_saving"] = mean_time[1] > 0.0 ? 1.0 - mean_time[0] / mean_time[1] : 0.0;
  out["perfect_knowledge_time_s"] = eval::PerfectKnowledgeTime(scenario, config);
  std::cout << out.dump(2) << "\n";
  return kExitOk;
}

void AddCommonOptions(CLI::App* cmd, DockOptions* opt) {
  cmd->add_option("--scenario", opt->scenario, "scenario YAML")->capture_default_str();
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--config", opt->config, "docking config YAML (e.g. config/docking.yaml)");
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
  dock->add_option("--seed", opt->seed, "random seed")->capture_default_str();
  dock->add_option("--record", opt->record, "write the run as JSON Lines for replay");
  dock->callback([opt, exit_code] { *exit_code = RunDock(*opt); });

  auto eopt = std::make_shared<DockOptions>();
  CLI::App* ev = app.add_subcommand(
      "eval-docking", "N seeded dockings, both methods on the same seeds: percentiles and times");
  AddCommonOptions(ev, eopt.get());
  ev->add_option("--runs", eopt->runs, "dockings per method")->capture_default_str();
  ev->add_option("--seed0", eopt->seed, "first seed")->capture_default_str();
  ev->callback([eopt, exit_code] { *exit_code = RunEvalDocking(*eopt); });
}

}  // namespace shelfdock::app
