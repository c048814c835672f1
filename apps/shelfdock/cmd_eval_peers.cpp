// `shelfdock eval peers`: shelfdock's detector beside what people would use instead, on the
// same seeded scans (the paper's set-up, the Table 1 sweep to 3.5 m, rows of shelves, clutter of
// leg-like posts): success, position and heading errors, time per scan and each peer's ratio to
// shelfdock; the ICP peer against its speed target; then the pruned leg search against an
// exhaustive one (checks and time as clutter grows). The ICP peer (PCL) is in only when the
// build has SHELFDOCK_WITH_PCL. A measurement: exit 0 whatever the figures, 2 on bad input.
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "eval/peer_comparison.hpp"
#include "io/detector_config_yaml.hpp"
#include "io/input_error.hpp"
#include "io/lidar_config_yaml.hpp"
#include "io/models_yaml.hpp"
#include "io/peers_report.hpp"
#include "progress.hpp"

#ifdef SHELFDOCK_WITH_PCL
#include "eval/peers/icp_peer.hpp"
#endif

namespace shelfdock::app {
namespace {

struct EvalPeersOptions {
  std::string models = "config/models.yaml";
  std::string params;
  std::string lidar;
  bool quick = false;
  std::uint64_t seed0 = eval::PeerScenesConfig{}.seed0;
  std::string json;
};

double NowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int RunEvalPeers(const EvalPeersOptions& opt) {
  const auto models = io::ReadShelfModels(opt.models);
  perception::DetectorConfig detector;
  if (!opt.params.empty()) detector = io::ReadDetectorConfig(opt.params);
  sim::LidarConfig lidar;
  if (!opt.lidar.empty()) lidar = io::ReadLidarConfig(opt.lidar);
  eval::PeerScenesConfig scenes;
  scenes.seed0 = opt.seed0;
  if (opt.quick) {
    scenes.paper_per_model = 5;
    scenes.sweep_scenes = 20;
    scenes.row_scenes = 20;
    scenes.clutter_scenes = 10;
  }
  if (!opt.json.empty()) {
    std::ofstream probe(opt.json);
    if (!probe) throw io::InputError(opt.json, "", "cannot write file");
  }

#ifdef SHELFDOCK_WITH_PCL
  const eval::peers::IcpPeer icp_peer(models, detector);
  const eval::PeerDetectFn icp = [&icp_peer](const geometry::LaserScan& scan,
                                             const std::optional<geometry::Pose2>& preset) {
    return icp_peer.Detect(scan, preset);
  };
#else
  const eval::PeerDetectFn icp;  // not built: no ICP row
#endif

  std::vector<eval::PeerRow> rows;
  std::vector<eval::SearchRow> search;
  {
    const std::vector<eval::PeerSceneSet> sets = eval::AllPeerSceneSets(models, lidar, scenes);
    Progress progress("eval peers", static_cast<long>(sets.size()));
    for (std::size_t i = 0; i < sets.size(); ++i) {
      progress.Update(static_cast<long>(i), sets[i].name);
      for (const eval::PeerRow& r :
           eval::ComparePeers(sets[i], models, detector, NowSeconds, icp)) {
        rows.push_back(r);
      }
      search.push_back(eval::CompareSearch(sets[i], models, detector, NowSeconds));
    }
  }
  std::cout << "**Accuracy and time per scan** (success: the first answer is the target's model "
               "within 5 cm; errors over successes; heading modulo the model's symmetry)\n\n";
  for (const std::string& line : io::PeerTableLines(rows)) std::cout << line << "\n";
  std::cout << "\n**ICP peer against the speed target** (shelfdock >= " << io::kIcpSpeedTarget
            << "x faster, median time per scan)\n\n";
  for (const std::string& line : io::IcpTargetLines(rows)) std::cout << line << "\n";
  std::cout << "\n**Leg search work** (all leg candidates of each scan, no region of interest; "
               "both searches uncapped)\n\n";
  for (const std::string& line : io::SearchTableLines(search)) std::cout << line << "\n";
  if (!opt.json.empty()) {
    std::ofstream out(opt.json);
    out << io::PeersJson(rows, search).dump(2) << "\n";
  }
  return kExitOk;
}

}  // namespace

void AddEvalPeersCommand(CLI::App& eval, int* exit_code) {
  auto opt = std::make_shared<EvalPeersOptions>();
#ifdef SHELFDOCK_WITH_PCL
  const std::string icp_note =
      ", ICP template matching with PCL (built with SHELFDOCK_WITH_PCL; shelfdock's speed "
      "target against it: >= " +
      std::to_string(static_cast<int>(io::kIcpSpeedTarget)) + "x)";
#else
  const std::string icp_note = ". " + std::string(io::kIcpNotBuilt);
#endif
  CLI::App* cmd = eval.add_subcommand(
      "peers",
      "shelfdock against other methods on the same seeded scans: centroid-only (no leg or "
      "shelf fit), corner finding, exhaustive search (checks and time)" +
          icp_note);
  cmd->add_option("--models", opt->models, "shelf models YAML")->capture_default_str();
  cmd->add_option("--params", opt->params, "detector parameters YAML");
  cmd->add_option("--lidar", opt->lidar, "LiDAR YAML (default: the WLR-716's defaults)");
  cmd->add_flag("--quick", opt->quick, "a short run: a tenth of the scenes");
  cmd->add_option("--seed0", opt->seed0, "first seed of every scene set")->capture_default_str();
  cmd->add_option("--json", opt->json, "write every figure as JSON");
  cmd->callback([opt, exit_code] { *exit_code = RunEvalPeers(*opt); });
}

}  // namespace shelfdock::app
