// `shelfdock eval paper`: re-runs the paper's section 4 experiments (Table 1 fitted size, Fig. 7
// fluctuation, Fig. 8 docking error, continuous against stop-and-recognise time) in the
// simulator, under the nominal and a harsh sensor, and prints them beside the paper's figures.
// A measurement: exit 0 whatever the figures, 2 on bad input.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "eval/paper_evaluation.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/paper_html.hpp"
#include "io/paper_report.hpp"
#include "io/scenario_yaml.hpp"
#include "progress.hpp"

namespace shelfdock::app {
namespace {

struct EvalPaperOptions {
  std::string scenario = "config/scenarios/paper_docking.yaml";
  std::string models = "config/models.yaml";
  std::string params;
  std::string lidar;
  bool quick = false;
  int runs = -1;
  int recognitions = -1;
  std::string json;
  std::string html;
};

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw io::InputError(path, "", "cannot write file");
  out << text;
}

int RunEvalPaper(const EvalPaperOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  eval::RunConfig run_config;
  if (!opt.params.empty()) run_config.detector = io::ReadDetectorConfig(opt.params);
  if (!opt.lidar.empty()) run_config.lidar = io::ReadLidarConfig(opt.lidar);
  eval::PaperEvaluationConfig config =
      opt.quick ? eval::PaperEvaluationConfig::Quick() : eval::PaperEvaluationConfig{};
  if (opt.runs != -1) {
    if (opt.runs < 2) throw io::InputError("(command line)", "--runs", "must be >= 2");
    config.docking.runs = opt.runs;
  }
  if (opt.recognitions != -1) {
    if (opt.recognitions < 1)
      throw io::InputError("(command line)", "--recognitions", "must be >= 1");
    config.size.recognitions_per_model = opt.recognitions;
  }
  // Fail on unwritable outputs before the long run.
  if (!opt.json.empty()) WriteText(opt.json, "");
  if (!opt.html.empty()) WriteText(opt.html, "");

  eval::PaperEvaluation evaluation;
  {
    Progress progress("eval paper", 0);
    evaluation = eval::RunPaperEvaluation(
        scenario, models, run_config, config,
        [&progress](const std::string& sensor, const std::string& stage, int done, int total) {
          progress.Update(done, sensor + ", " + stage + " " + std::to_string(done) + "/" +
                                    std::to_string(total));
        });
  }
  for (const std::string& line : io::PaperTableLines(evaluation)) std::cout << line << "\n";
  if (!opt.json.empty()) WriteText(opt.json, io::PaperJson(evaluation).dump(2) + "\n");
  if (!opt.html.empty()) WriteText(opt.html, io::PaperHtml(evaluation));
  return kExitOk;
}

}  // namespace

void AddEvalPaperCommand(CLI::App& eval, int* exit_code) {
  auto opt = std::make_shared<EvalPaperOptions>();
  CLI::App* cmd = eval.add_subcommand(
      "paper",
      "the paper's section 4 in the simulator (Table 1 size, Fig. 7 fluctuation, Fig. 8 docking "
      "error, time) under the nominal and a harsh sensor, beside the paper's figures");
  cmd->add_option("--scenario", opt->scenario, "docking scenario YAML")->capture_default_str();
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--params", opt->params, "detector parameters YAML");
  cmd->add_option("--lidar", opt->lidar, "nominal LiDAR YAML (default: the WLR-716's defaults)");
  cmd->add_flag("--quick", opt->quick,
                "a short run (under a minute): 6 scans per model, 3 dockings");
  cmd->add_option("--runs", opt->runs, "dockings per method and sensor (default 100, quick 3)");
  cmd->add_option("--recognitions", opt->recognitions,
                  "Table 1 scans per model and sensor (default 30, quick 6)");
  cmd->add_option("--json", opt->json, "write every figure as JSON");
  cmd->add_option("--html", opt->html, "write one self-contained HTML page with SVG plots");
  cmd->callback([opt, exit_code] { *exit_code = RunEvalPaper(*opt); });
}

}  // namespace shelfdock::app
