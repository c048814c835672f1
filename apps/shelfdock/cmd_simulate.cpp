// `shelfdock simulate`: ray casts a scenario's world with the simulated LiDAR and writes the
// scans (JSON Lines, the format `detect` reads) and the ground truth (true shelf poses in the
// LiDAR frame at each scan's first beam).
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_args.hpp"
#include "commands.hpp"
#include "config_paths.hpp"
#include "geometry/angle.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/scan_json.hpp"
#include "io/scenario_yaml.hpp"
#include "sim/lidar.hpp"

namespace shelfdock::app {
namespace {

struct SimulateOptions {
  std::string scenario;
  std::string pose;
  std::string velocity = "0,0";
  std::uint64_t seed = 1;
  int count = 1;
  std::string models = DefaultConfig("models.yaml");
  std::string lidar;
  std::string out;
  std::string truth;
};

nlohmann::json PoseJson(const geometry::Pose2& T) {
  return {{"x", T.x}, {"y", T.y}, {"yaw", T.yaw}};
}

int RunSimulate(const SimulateOptions& opt) {
  const auto p = ParseNumbers(opt.pose, 3, "--pose", "X,Y,YAW (m, m, rad)");
  const auto v = ParseNumbers(opt.velocity, 2, "--velocity", "V,W (m/s, rad/s)");
  if (opt.count < 1) throw io::InputError(kCommandLine, "--count", "must be >= 1");
  const auto models = io::ReadShelfModels(opt.models);
  const sim::Scenario scenario = io::ReadScenario(opt.scenario, models);
  const sim::LidarConfig config =
      opt.lidar.empty() ? sim::LidarConfig{} : io::ReadLidarConfig(opt.lidar);

  std::ofstream out(opt.out);
  if (!out) throw io::InputError(opt.out, "", "cannot write file");
  const std::string truth_path = opt.truth.empty() ? opt.out + ".truth.json" : opt.truth;
  std::ofstream truth_out(truth_path);
  if (!truth_out) throw io::InputError(truth_path, "", "cannot write file");

  // The LiDAR drives a unicycle path at (v, w) from --pose: zero velocity is a static sensor.
  const geometry::Pose2 T_map_lidar0(p[0], p[1], p[2]);
  const double speed = v[0], turn = v[1];
  const auto T_map_lidar_at = [&](double t) {
    if (std::abs(turn) < 1e-9) {
      return T_map_lidar0 * geometry::Pose2(speed * t, 0.0, 0.0);
    }
    const double r = speed / turn, a = turn * t;
    return T_map_lidar0 * geometry::Pose2(r * std::sin(a), r * (1.0 - std::cos(a)), a);
  };

  sim::Lidar lidar(config, opt.seed);
  nlohmann::json scans_truth = nlohmann::json::array();
  for (int k = 0; k < opt.count; ++k) {
    const double t0 = k * config.ScanPeriod();
    const auto scan = lidar.Scan(scenario.world, T_map_lidar_at, t0);
    out << io::ScanToJson(scan).dump() << "\n";

    const geometry::Pose2 T_lidar_map = T_map_lidar_at(t0).inverse();
    nlohmann::json shelves = nlohmann::json::array();
    for (const sim::ScenarioShelf& s : scenario.shelves) {
      nlohmann::json j = PoseJson(T_lidar_map * s.T_map_shelf);
      j["id"] = s.id;
      j["model"] = s.model_name;
      j["preset"] = PoseJson(T_lidar_map * *scenario.PresetPose(s.id, opt.seed));
      shelves.push_back(j);
    }
    scans_truth.push_back({{"index", k},
                           {"stamp", t0},
                           {"T_map_lidar", PoseJson(T_map_lidar_at(t0))},
                           {"shelves", shelves}});
  }
  truth_out << nlohmann::json{{"scenario", scenario.name},
                              {"seed", opt.seed},
                              {"frame", "lidar at each scan's first beam"},
                              {"target_shelf", scenario.target_shelf_id},
                              {"scans", scans_truth}}
                   .dump(1)
            << "\n";
  std::cout << nlohmann::json{{"scenario", opt.scenario},
                              {"scans", opt.count},
                              {"out", opt.out},
                              {"truth", truth_path}}
                   .dump()
            << "\n";
  return kExitOk;
}

}  // namespace

void AddSimulateCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "ray cast a scenario with the simulated LiDAR; write scans and ground truth");
  cmd->add_option("--scenario", opt->scenario, "scenario YAML (config/scenarios/)")->required();
  cmd->add_option("--pose", opt->pose, "LiDAR pose in the map: X,Y,YAW (m, rad)")->required();
  cmd->add_option("--velocity", opt->velocity, "LiDAR motion V,W (m/s, rad/s); default 0,0");
  cmd->add_option("--seed", opt->seed, "random seed (noise, dropouts, presets)")
      ->check(NonNegativeInteger());
  cmd->add_option("--count", opt->count, "number of scans (one per scan period)");
  cmd->add_option("--models", opt->models, "shelf models YAML (default config/models.yaml)");
  cmd->add_option("--lidar", opt->lidar, "LiDAR config YAML (default: VANJEE WLR-716)");
  cmd->add_option("--out", opt->out, "scans as JSON Lines")->required();
  cmd->add_option("--truth", opt->truth, "ground truth JSON (default <out>.truth.json)");
  cmd->callback([opt, exit_code] { *exit_code = RunSimulate(*opt); });
}

}  // namespace shelfdock::app
