// `shelfdock eval faults`: N seeded dockings, each with one fault drawn at random (eval/fault.hpp),
// reported per fault as the share of successes and of each typed failure, with the issue's
// invariants counted: leg contacts, hangs, untyped ends, and runs against the rule of which
// faults leave docking possible. Exit 0 when every count is zero, 1 otherwise, 2 on bad input.
#include <atomic>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "eval/fault_sweep.hpp"
#include "io/docking_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/robot_yaml.hpp"
#include "io/scenario_yaml.hpp"
#include "progress.hpp"

namespace shelfdock::app {
namespace {

struct EvalFaultsOptions {
  int runs = 1000;
  std::uint64_t seed0 = 1;
  std::string scenario = DefaultConfig("scenarios/paper_docking.yaml");
  std::string models = DefaultConfig("models.yaml");
  std::string config;
  std::string lidar;
  std::string robot;
  bool json = false;
  int jobs = 1;
};

std::string Percent(int n, int of) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << (of > 0 ? 100.0 * n / of : 0.0) << " %";
  return s.str();
}

/// A clearance in metres; "no legs" when no run had a shelf (the 1e9 start value).
std::string Clearance(double m) {
  if (m >= 1e8) return "no legs";
  std::ostringstream s;
  s << std::fixed << std::setprecision(3) << m << " m";
  return s.str();
}

std::string FailuresText(const eval::FaultKindSummary& k) {
  std::string text;
  for (const auto& [code, n] : k.failures) {
    if (!text.empty()) text += ", ";
    text += std::string(docking::ToString(code)) + " " + Percent(n, k.runs);
  }
  return text.empty() ? "-" : text;
}

/// One line per run that broke an invariant, to reproduce it with the same seed.
nlohmann::json ProblemRuns(const std::vector<eval::FaultRun>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const eval::FaultRun& r : runs) {
    if (!r.leg_contact && r.typed && !r.rule_violation) continue;
    out.push_back({{"seed", r.run.seed},
                   {"fault", eval::ToString(r.fault.kind)},
                   {"result", docking::ToString(r.run.outcome.code)},
                   {"reason", r.run.outcome.reason},
                   {"leg_contact", r.leg_contact},
                   {"hung", r.run.hung},
                   {"rule_violation", r.rule_violation},
                   {"min_leg_clearance_m", r.run.min_leg_clearance_m}});
  }
  return out;
}

nlohmann::json SummaryJson(const eval::FaultSweepSummary& s,
                           const std::vector<eval::FaultRun>& runs) {
  nlohmann::json kinds = nlohmann::json::array();
  for (const eval::FaultKindSummary& k : s.kinds) {
    nlohmann::json failures = nlohmann::json::object();
    for (const auto& [code, n] : k.failures) {
      failures[std::string(docking::ToString(code))] = static_cast<double>(n) / k.runs;
    }
    kinds.push_back({{"fault", eval::ToString(k.kind)},
                     {"docking_possible", k.possible},
                     {"runs", k.runs},
                     {"success", static_cast<double>(k.successes) / k.runs},
                     {"failures", failures},
                     {"rule_violations", k.rule_violations},
                     {"min_leg_clearance_m", k.min_leg_clearance_m}});
  }
  return {{"runs", s.runs},
          {"leg_contacts", s.leg_contacts},
          {"hangs", s.hangs},
          {"untyped", s.untyped},
          {"rule_violations", s.rule_violations},
          {"min_leg_clearance_m", s.min_leg_clearance_m},
          {"faults", kinds},
          {"problem_runs", ProblemRuns(runs)}};
}

void PrintTable(const eval::FaultSweepSummary& s, const std::vector<eval::FaultRun>& runs) {
  std::cout << "| fault | docking possible | runs | success | typed failures | rule violations "
               "| min leg clearance |\n|---|---|---|---|---|---|---|\n";
  for (const eval::FaultKindSummary& k : s.kinds) {
    std::cout << "| " << eval::ToString(k.kind) << " | " << (k.possible ? "yes" : "no") << " | "
              << k.runs << " | " << Percent(k.successes, k.runs) << " | " << FailuresText(k)
              << " | " << k.rule_violations << " | " << Clearance(k.min_leg_clearance_m) << " |\n";
  }
  std::cout << "\nruns " << s.runs << ": leg contacts " << s.leg_contacts << ", hangs " << s.hangs
            << ", untyped ends " << s.untyped << ", rule violations " << s.rule_violations
            << ", min leg clearance " << Clearance(s.min_leg_clearance_m) << "\n";
  for (const auto& p : ProblemRuns(runs)) std::cout << "problem: " << p.dump() << "\n";
}

int RunEvalFaults(const EvalFaultsOptions& opt) {
  if (opt.runs < 1) throw io::InputError(kCommandLine, "--runs", "must be >= 1");
  if (opt.jobs < 1 || opt.jobs > 64) {
    throw io::InputError(kCommandLine, "--jobs", "must be in 1..64");
  }
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  eval::RunConfig config;
  if (!opt.config.empty()) config.docking = io::ReadDockingConfig(opt.config);
  if (!opt.lidar.empty()) config.lidar = io::ReadLidarConfig(opt.lidar);
  if (!opt.robot.empty()) config.robot = io::ReadRobotConfig(opt.robot);
  // Every run must end by the Docker's own time budget; the simulation stops a little after it.
  config.max_sim_time_s = config.docking.timeout_s + 30.0;

  // Runs are independent (each builds its own world, robot, detector and Docker from its seed),
  // so --jobs threads take them in turn; run i always has seed seed0 + i, whatever the order.
  std::vector<eval::FaultRun> runs(static_cast<std::size_t>(opt.runs));
  std::atomic<int> next{0};
  int done = 0;
  {  // the progress line is cleared when it goes, before the table is printed
    std::mutex progress_mutex;
    Progress progress("eval faults", opt.runs);
    auto worker = [&] {
      for (int i = next++; i < opt.runs; i = next++) {
        const std::uint64_t seed = opt.seed0 + static_cast<std::uint64_t>(i);
        runs[static_cast<std::size_t>(i)] =
            eval::RunFaulted(scenario, models, docking::Method::kContinuous, seed, config);
        const std::lock_guard<std::mutex> lock(progress_mutex);
        progress.Update(++done);
      }
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < opt.jobs; ++j) threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();
  }
  const eval::FaultSweepSummary s = eval::SummariseFaults(runs);
  if (opt.json) {
    std::cout << SummaryJson(s, runs).dump(2) << "\n";
  } else {
    PrintTable(s, runs);
  }
  const bool held = s.leg_contacts == 0 && s.hangs == 0 && s.untyped == 0 && s.rule_violations == 0;
  return held ? kExitOk : kExitFailure;
}

/// The `eval` group: created by whichever eval subcommand registers first.
CLI::App* EvalGroup(CLI::App& app) {
  const auto found = app.get_subcommands([](const CLI::App* s) { return s->get_name() == "eval"; });
  if (!found.empty()) return app.get_subcommand(found.front());
  CLI::App* eval = app.add_subcommand("eval", "evaluations (see each subcommand)");
  eval->require_subcommand(1);
  return eval;
}

}  // namespace

void AddEvalFaultsCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<EvalFaultsOptions>();
  CLI::App* cmd = EvalGroup(app)->add_subcommand(
      "faults",
      "N seeded dockings, each with one random fault: success and typed failures per fault; "
      "exit 1 if a leg was touched, a run hung or ended against the rule");
  cmd->add_option("--runs", opt->runs, "dockings, one fault each")->capture_default_str();
  cmd->add_option("--seed0", opt->seed0, "first seed")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->add_option("--scenario", opt->scenario, "scenario YAML")->capture_default_str();
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--config", opt->config, "docking config YAML (e.g. config/docking.yaml)");
  cmd->add_option("--lidar", opt->lidar, "LiDAR config YAML (default: the WLR-716's defaults)");
  cmd->add_option("--robot", opt->robot, "robot config YAML (default: config/robot.yaml's values)");
  cmd->add_flag("--json", opt->json, "print one JSON summary instead of the table");
  cmd->add_option("--jobs", opt->jobs,
                  "runs in parallel (threads); the results do not depend on it")
      ->capture_default_str();
  cmd->callback([opt, exit_code] { *exit_code = RunEvalFaults(*opt); });
}

}  // namespace shelfdock::app
