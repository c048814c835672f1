// `shelfdock view`: turns docking records (`shelfdock dock --record FILE`) into the replay page,
// one self-contained HTML file that opens offline; with several records the page switches
// between them.
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "io/html_page.hpp"
#include "io/input_error.hpp"
#include "web_pages.hpp"

namespace shelfdock::app {
namespace {

struct ViewOptions {
  std::vector<std::string> records;
  std::string html;
};

// One record as its JSON Lines objects; the file must hold a header and at least one step.
nlohmann::json ReadRecord(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path, "", "cannot open the record");
  nlohmann::json lines = nlohmann::json::array();
  std::string line;
  int number = 0;
  int headers = 0;
  int steps = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json obj = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    const std::string where = "line " + std::to_string(number);
    if (obj.is_discarded() || !obj.is_object()) {
      throw io::InputError(path, where, "not a JSON object (expected a `dock --record` file)");
    }
    if (!obj.contains("type") || !obj["type"].is_string()) {
      throw io::InputError(path, where + ": type", "missing (header, step or summary)");
    }
    const std::string type = obj["type"].get<std::string>();
    if (type == "header") ++headers;
    if (type == "step") {
      ++steps;
      for (const char* key : {"t", "true", "estimate"}) {
        if (!obj.contains(key)) throw io::InputError(path, where + ": " + key, "missing");
      }
    }
    lines.push_back(std::move(obj));
  }
  if (headers != 1) throw io::InputError(path, "header", "expected exactly one header line");
  if (steps == 0) throw io::InputError(path, "step", "no step lines");
  return {{"name", path}, {"lines", lines}};
}

int RunView(const ViewOptions& opt) {
  nlohmann::json records = nlohmann::json::array();
  for (const auto& path : opt.records) records.push_back(ReadRecord(path));
  io::WritePage(opt.html, kReplayPage, {{"records", records}});
  std::cout << nlohmann::json{{"html", opt.html}, {"records", opt.records.size()}}.dump() << "\n";
  return kExitOk;
}

}  // namespace

void AddViewCommand(CLI::App& app, int* exit_code) {
  auto opt = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "write the replay page of docking records (dock --record) as one HTML file");
  cmd->add_option("records", opt->records, "record file(s) written by `dock --record`")->required();
  cmd->add_option("--html", opt->html, "the page to write")->required();
  cmd->callback([opt, exit_code] { *exit_code = RunView(*opt); });
}

}  // namespace shelfdock::app
