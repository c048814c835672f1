#include "io/run_record.hpp"

#include <cmath>
#include <fstream>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

using nlohmann::json;

json PoseJson(const geometry::Pose2& p) { return {{"x", p.x}, {"y", p.y}, {"yaw", p.yaw}}; }

json ErrorJson(const eval::PoseError& e) {
  if (!e.valid) return {{"x", nullptr}, {"y", nullptr}, {"yaw", nullptr}};
  return {{"x", e.x}, {"y", e.y}, {"yaw", e.yaw}};
}

}  // namespace

json PhaseTimesJson(const eval::PhaseTimes& t) {
  return {{"approach_s", t.approach_s},  {"dock_s", t.dock_s},     {"final_slow_s", t.final_slow_s},
          {"stand_s", t.stand_s},        {"verify_s", t.verify_s}, {"adjust_s", t.adjust_s},
          {"lift_s", t.lift_s},          {"abort_s", t.abort_s},   {"code_checks", t.code_checks},
          {"adjustments", t.adjustments}};
}

json DockingRunToJson(const eval::DockingRun& run) {
  json j;
  j["result"] = std::string(docking::ToString(run.outcome.code));
  j["reason"] = run.outcome.reason;
  j["time_s"] = run.time_s;
  j["error_before_check"] = ErrorJson(run.error_before_check);
  j["error_after_check"] = ErrorJson(run.error_after_check);
  j["replans"] = run.replans;
  j["detections"] = run.detections;
  j["min_leg_clearance_m"] =
      run.min_leg_clearance_m < 1e8 ? json(run.min_leg_clearance_m) : json(nullptr);
  j["method"] = std::string(docking::ToString(run.method));
  j["seed"] = run.seed;
  j["phases"] = PhaseTimesJson(run.phases);
  return j;
}

std::vector<json> RunRecordLines(const sim::Scenario& scenario,
                                 const geometry::Pose2& T_map_shelf_preset,
                                 const eval::DockingRun& run, double robot_length_m,
                                 double robot_width_m) {
  std::vector<json> lines;
  json header{{"type", "header"},
              {"scenario", scenario.name},
              {"method", std::string(docking::ToString(run.method))},
              {"seed", run.seed},
              {"target_shelf", scenario.target_shelf_id},
              {"preset", PoseJson(T_map_shelf_preset)},
              {"robot", {{"length", robot_length_m}, {"width", robot_width_m}}}};
  json shelves = json::array();
  for (const auto& s : scenario.world.shelves()) {
    json legs = json::array();
    for (const auto& c : s.model.LegCentres()) {
      const Eigen::Vector2d p = s.T_world_shelf * c;
      legs.push_back({p.x(), p.y()});
    }
    json sj = PoseJson(s.T_world_shelf);
    sj["id"] = s.id;
    sj["model"] = s.model.name;
    sj["length"] = s.model.length_m;
    sj["width"] = s.model.width_m;
    sj["legs"] = legs;
    shelves.push_back(sj);
  }
  header["shelves"] = shelves;
  lines.push_back(std::move(header));
  for (const eval::RecordFrame& f : run.record) {
    json j{{"type", "step"},
           {"t", f.t_s},
           {"phase", f.phase},
           {"true", PoseJson(f.T_world_base_true)},
           {"odom", PoseJson(f.T_odom_base)},
           {"estimate", PoseJson(f.T_map_base_estimate)},
           {"cmd", {{"v", f.v_cmd}, {"w", f.w_cmd}}}};
    if (!f.scan_world.empty()) {
      json scan = json::array();
      for (const auto& p : f.scan_world) {
        scan.push_back({std::round(p.x() * 1000.0) / 1000.0, std::round(p.y() * 1000.0) / 1000.0});
      }
      j["scan"] = scan;
    }
    if (f.detection_world) j["detection"] = PoseJson(*f.detection_world);
    if (f.shelf_estimate_world) j["shelf"] = PoseJson(*f.shelf_estimate_world);
    if (!f.path_world.empty()) {
      json p = json::array();
      for (const auto& q : f.path_world) p.push_back({q.x, q.y, q.yaw});
      j["path"] = p;
    }
    if (!f.events.empty()) j["events"] = f.events;
    lines.push_back(std::move(j));
  }
  json summary = DockingRunToJson(run);
  summary["type"] = "summary";
  lines.push_back(std::move(summary));
  return lines;
}

void WriteRunRecord(const std::string& path, const sim::Scenario& scenario,
                    const geometry::Pose2& T_map_shelf_preset, const eval::DockingRun& run,
                    double robot_length_m, double robot_width_m) {
  std::ofstream out(path);
  if (!out) throw InputError(path, "", "cannot open the record file for writing");
  for (const json& line :
       RunRecordLines(scenario, T_map_shelf_preset, run, robot_length_m, robot_width_m)) {
    out << line.dump() << "\n";
  }
  if (!out) throw InputError(path, "", "write failed");
}

}  // namespace shelfdock::io
