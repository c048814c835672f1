// `shelfdock bag`: lists the LaserScan topics of a ROS 1 bag, or converts one topic to the JSON
// Lines scan format that `detect` reads.
#include <fstream>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "io/input_error.hpp"
#include "io/rosbag_scans.hpp"
#include "io/scan_json.hpp"
#include "progress.hpp"

namespace shelfdock::app {
namespace {

struct BagOptions {
  std::string bag;
  std::string topic;
  std::string out;
};

int RunBag(const BagOptions& opt) {
  if (opt.out.empty()) {
    nlohmann::json topics = nlohmann::json::array();
    for (const auto& t : io::ListBagScanTopics(opt.bag)) {
      topics.push_back({{"topic", t.topic}, {"messages", t.messages}});
    }
    std::cout << nlohmann::json{{"bag", opt.bag}, {"laser_scan_topics", topics}}.dump() << "\n";
    return kExitOk;
  }
  std::ofstream out(opt.out);
  if (!out) throw io::InputError(opt.out, "", "cannot write file");
  Progress writing("bag -> " + opt.out, 0);
  long written = 0;
  // One scan in memory at a time, whatever the bag's length.
  const std::size_t scans = io::ForEachBagScan(opt.bag, opt.topic, [&](const auto& scan) {
    out << io::ScanToJson(scan).dump() << "\n";
    writing.Update(++written);
  });
  if (scans == 0) {
    throw io::InputError(opt.bag, opt.topic.empty() ? "topics" : opt.topic,
                         "no sensor_msgs/LaserScan messages");
  }
  std::cout << nlohmann::json{{"bag", opt.bag},
                              {"topic", opt.topic},
                              {"scans", scans},
                              {"out", opt.out}}
                   .dump()
            << "\n";
  return kExitOk;
}

}  // namespace

void AddBagCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<BagOptions>();
  CLI::App* cmd = app.add_subcommand("bag", "list or convert the LaserScan topics of a ROS 1 bag");
  cmd->add_option("--bag", opt->bag, "ROS 1 bag file (format 2.0)")->required();
  cmd->add_option("--topic", opt->topic, "LaserScan topic to convert (default: all)");
  cmd->add_option("--out", opt->out, "write the scans as JSON Lines here (default: list topics)");
  cmd->callback([opt, exit_code] { *exit_code = RunBag(*opt); });
}

}  // namespace shelfdock::app
