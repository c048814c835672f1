// `shelfdock eval-layouts`: runs the detector over generated warehouse scenes (rows, aisles,
// occluders, people, clutter; sim::GenerateLayoutScene) and prints a table per class and
// overall, then one line per failing scene. A measurement: exit 0 whatever the figures, 2 on
// bad input. --dump-failures writes each failing scene's (with --dump-all every scene's) scan and
// truth so that the printed `shelfdock detect` line reproduces it.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "eval/layout_summary.hpp"
#include "eval/layout_sweep.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/layout_report.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "perception/detector.hpp"
#include "sim/world_objects.hpp"

namespace shelfdock::app {
namespace {

const std::vector<std::string> kDefaultLidarFiles = {DefaultConfig("lidar_tim571.yaml"),
                                                     DefaultConfig("lidar_ust10lx.yaml")};

struct EvalLayoutsOptions {
  int scenes_per_class = eval::LayoutSweepConfig{}.scenes_per_class;
  std::uint64_t seed0 = eval::LayoutSweepConfig{}.seed0;
  std::vector<std::string> classes;
  std::string models = DefaultConfig("models.yaml");
  std::string params;
  std::vector<std::string> lidars;
  std::string json;
  std::string dump_failures;
  bool dump_all = false;  // --dump-failures writes every scene, not only the failing ones
  bool no_preset = false;
  bool map_knows_model = false;
  int beams_in_sight = 0;        // 0: the generator's count
  std::vector<double> row_gaps;  // [m] min, max between footprints in rows; empty: the generator's
  std::vector<double> as_built;  // [m], [rad] legs' build error and twist; empty: as designed
};

/// "lidar_tim571.yaml" -> "tim571".
std::string LidarName(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  const std::string prefix = "lidar_";
  return stem.rfind(prefix, 0) == 0 ? stem.substr(prefix.size()) : stem;
}

/// The sensors to draw from: the files given, else the WLR-716 defaults and the two presets.
std::vector<sim::NamedLidar> ReadLidars(const std::vector<std::string>& files) {
  std::vector<sim::NamedLidar> lidars;
  if (files.empty()) lidars.push_back(sim::NamedLidar{});
  for (const auto& file : files.empty() ? kDefaultLidarFiles : files) {
    lidars.push_back({LidarName(file), io::ReadLidarConfig(file)});
  }
  return lidars;
}

eval::LayoutSweepConfig SweepConfig(const EvalLayoutsOptions& opt) {
  if (opt.scenes_per_class < 1) {
    throw io::InputError(kCommandLine, "--scenes-per-class", "must be >= 1");
  }
  eval::LayoutSweepConfig config;
  config.scenes_per_class = opt.scenes_per_class;
  config.seed0 = opt.seed0;
  config.use_preset = !opt.no_preset;
  config.map_knows_model = opt.map_knows_model;
  config.min_beams_in_sight = opt.beams_in_sight;
  if (opt.classes.empty()) return config;
  config.classes.clear();
  for (const auto& name : opt.classes) {
    const auto c = sim::ParseLayoutClass(name);
    if (!c) {
      // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on "literal" + string.
      std::string message = "unknown class '";
      message.append(name).append("'; one of");
      for (auto k : sim::kAllLayoutClasses) message.append(" ").append(sim::LayoutClassName(k));
      throw io::InputError(kCommandLine, "--class", message);
    }
    config.classes.push_back(*c);
  }
  return config;
}

void DumpFailures(const EvalLayoutsOptions& opt, const std::vector<geometry::ShelfModel>& models,
                  const sim::LayoutConfig& layout,
                  const std::vector<eval::LayoutSceneResult>& results) {
  std::string detect_args = "--models " + opt.models;
  if (!opt.params.empty()) detect_args += " --params " + opt.params;
  int written = 0;
  for (const auto& r : results) {
    if (!r.Failed() && !opt.dump_all) continue;
    sim::LayoutScene scene = sim::GenerateLayoutScene(r.layout_class, r.seed, models, layout);
    if (opt.no_preset) scene.T_world_preset.reset();  // the detect line then has no --preset
    const bool one_model = opt.map_knows_model && !r.target_model.empty();
    io::WriteLayoutFailure(opt.dump_failures, scene, r,
                           one_model ? detect_args + " --model " + r.target_model : detect_args);
    ++written;
  }
  std::cout << (opt.dump_all ? "scenes" : "failing scenes") << " written to " << opt.dump_failures
            << ": " << written << "\n";
}

int RunEvalLayouts(const EvalLayoutsOptions& opt) {
  // Parse and load everything before the sweep: bad input never costs a run.
  const eval::LayoutSweepConfig config = SweepConfig(opt);
  const auto models = io::ReadShelfModels(opt.models);
  const perception::DetectorConfig detector_config =
      opt.params.empty() ? perception::DetectorConfig{} : io::ReadDetectorConfig(opt.params);
  sim::LayoutConfig layout;
  layout.lidars = ReadLidars(opt.lidars);
  if (!opt.row_gaps.empty()) {
    // Rows are drawn with their gaps uniform in [min, max]; more than a few metres is no row.
    const double lo = opt.row_gaps[0], hi = opt.row_gaps[1];
    if (!(lo >= 0.0 && hi >= lo && hi <= 5.0)) {
      throw io::InputError(kCommandLine, "--row-gaps", "needs 0 <= MIN <= MAX <= 5 [m]");
    }
    layout.row_min_gap_m = lo;
    layout.row_max_gap_m = hi;
  }
  if (!opt.as_built.empty()) {
    // The bounds a shelf's legs as built may have (sim::ShelfInstance::legs_as_built).
    const double error = opt.as_built[0], twist = opt.as_built[1];
    if (!(error >= 0.0 && error <= sim::kMaxLegBuildError_m && twist >= 0.0 &&
          twist <= sim::kMaxLegTwist_rad)) {
      throw io::InputError(kCommandLine, "--as-built",
                           "needs 0 <= ERROR <= 0.05 [m] and 0 <= TWIST <= 0.785 [rad]");
    }
    layout.leg_build_error_m = error;
    layout.leg_build_twist_rad = twist;
  }
  const perception::Detector detector(models, detector_config);

  const auto start = std::chrono::steady_clock::now();
  const auto results = eval::RunLayoutSweep(detector, models, layout, config);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto rows = eval::SummariseLayoutsByClass(results, config);

  for (const auto& line :
       io::LayoutTableLines(rows, layout.noise_sigma_m, layout.high_noise_sigma_m, "")) {
    std::cout << line << "\n";
  }
  for (const auto& line : io::LayoutLegendLines(config, "")) std::cout << line << "\n";
  // With more than one sensor, the same by sensor (every class together): which one the misses
  // come from.
  const auto lidar_rows = eval::SummariseLayoutsByLidar(results, config);
  if (lidar_rows.size() > 1) {
    for (const auto& line : io::LayoutTableLines(lidar_rows, layout.noise_sigma_m,
                                                 layout.high_noise_sigma_m, "", "lidar")) {
      std::cout << line << "\n";
    }
  }
  // Close models (1075x883 against 1080x856) told apart by a few millimetres of leg positions:
  // how many confusions the runner-up margin flags, and at what cost in right shelves flagged.
  constexpr double kUnsureMargin = 4.0;
  const auto confusions = eval::SummariseModelConfusions(results, config, kUnsureMargin);
  std::cout << "model confusions (the target's place, another model first): "
            << confusions.confusions << "; runner-up the target's model within chi2 margin "
            << kUnsureMargin << ": " << confusions.confusions_flagged
            << "; right-first scenes with a runner-up that close: "
            << confusions.right_first_flagged << " of " << confusions.right_first << "\n";
  std::cout << results.size() << " scenes in " << std::fixed << std::setprecision(1) << seconds
            << " s\n";
  int failures = 0;
  for (const auto& r : results) {
    if (!r.Failed()) continue;
    std::cout << "FAIL " << io::LayoutFailureLine(r) << "\n";
    ++failures;
  }
  std::cout << "failing scenes: " << failures << "\n";
  if (!opt.json.empty()) {
    std::ofstream out(opt.json);
    if (!out) throw io::InputError(opt.json, "", "cannot write file");
    out << io::LayoutSweepJson(rows, results, config, lidar_rows).dump(1) << "\n";
  }
  if (!opt.dump_failures.empty()) DumpFailures(opt, models, layout, results);
  return kExitOk;
}

}  // namespace

void AddEvalLayoutsCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<EvalLayoutsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval-layouts",
      "detector figures per class on generated warehouse scenes (rows, aisles, occluders, "
      "people, clutter)");
  cmd->add_option("--scenes-per-class", opt->scenes_per_class, "scenes of each class")
      ->capture_default_str();
  cmd->add_option("--seed0", opt->seed0, "seed of each class's first scene (then +1 per scene)")
      ->capture_default_str()
      ->check(NonNegativeInteger());
  cmd->add_option("--class", opt->classes,
                  "only these classes: open row aisle occluded_leg person_beside_leg large_close "
                  "mixed_neighbours round_noisy against_wall clutter");
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--params", opt->params, "detector parameters YAML");
  cmd->add_option("--lidar", opt->lidars,
                  "LiDAR config YAML, repeatable; scenes draw among them (default: the WLR-716, "
                  "config/lidar_tim571.yaml and config/lidar_ust10lx.yaml)");
  cmd->add_flag("--no-preset", opt->no_preset,
                "detect without the map's preset (a robot that searches, e.g. after a restart): "
                "with neighbours about, the first detection is then often another shelf");
  cmd->add_flag("--map-knows-model", opt->map_knows_model,
                "the map names the target's model too: detect with that model alone, as "
                "`shelfdock detect --model NAME` (the 1075x883 and 1080x856 are then never "
                "confused)");
  cmd->add_option("--beams-in-sight", opt->beams_in_sight,
                  "ideal beams on a target leg for it to count as in line of sight when scenes "
                  "are sorted into findable or not (default: the generator's 2; 1 counts a leg "
                  "that peeks past an occluder by one beam)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--row-gaps", opt->row_gaps,
                  "MIN MAX [m]: gaps between neighbouring footprints in rows and aisles, drawn "
                  "uniformly (default: the generator's 0.2 0.5); e.g. 0.05 1.2 puts some gaps as "
                  "wide as a shelf, where a phantom on two neighbours' legs fits a model")
      ->expected(2);
  cmd->add_option("--as-built", opt->as_built,
                  "ERROR [m] TWIST [rad]: shelves as built, each leg's centre off its design "
                  "place by up to ERROR along each shelf axis and turned by up to TWIST, the "
                  "scene otherwise unchanged (default: as designed); e.g. 0.005 0.05")
      ->expected(2);
  cmd->add_option("--json", opt->json, "write the table and the failures as JSON");
  auto* dump =
      cmd->add_option("--dump-failures", opt->dump_failures,
                      "write each failing scene's scan and truth (with a detect command) here");
  cmd->add_flag("--dump-all", opt->dump_all,
                "with --dump-failures, write every scene, right ones too (e.g. to compare fitted "
                "legs with the truth through detect --explain)")
      ->needs(dump);
  cmd->callback([opt, exit_code] { *exit_code = RunEvalLayouts(*opt); });
}

}  // namespace shelfdock::app
