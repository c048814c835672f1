#include "io/paper_report.hpp"

#include <cmath>

#include "eval/paper_figures.hpp"
#include "io/report_format.hpp"

namespace shelfdock::io {
namespace {

nlohmann::json Json(double v) { return JsonNumber(v); }

std::string MedianWorst(const eval::RunQuantiles& q, double scale, int decimals = 1) {
  return FormatNumber(q.median, scale, decimals) + " (" + FormatNumber(q.worst, scale, decimals) +
         ")";
}

nlohmann::json Json(const eval::RunQuantiles& q) {
  return {{"median", Json(q.median)}, {"worst", Json(q.worst)}};
}

nlohmann::json Json(const eval::AbsErrorStats& s) {
  return {{"p95", Json(s.p95)}, {"p99", Json(s.p99)}, {"max", Json(s.max)}};
}

nlohmann::json Json(const eval::FluctuationSummary& f) {
  return {
      {"runs", f.runs},
      {"recognitions_per_run", Json(f.recognitions)},
      {"range", {{"x", Json(f.x_range)}, {"y", Json(f.y_range)}, {"yaw", Json(f.yaw_range)}}},
      {"stddev", {{"x", Json(f.x_stddev)}, {"y", Json(f.y_stddev)}, {"yaw", Json(f.yaw_stddev)}}}};
}

nlohmann::json Json(const geometry::Pose2& p) { return {{"x", p.x}, {"y", p.y}, {"yaw", p.yaw}}; }

const eval::PaperTable1Row* PaperRow(const std::string& model) {
  for (const auto& row : eval::kPaperTable1) {
    if (row.model == model) return &row;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string> PaperTableLines(const eval::PaperEvaluation& ev) {
  std::vector<std::string> out;
  const auto& s = ev.sensors;
  auto header = [&](const std::string& first, const std::string& paper, bool two_per_sensor) {
    std::string h = "| " + first + " | " + paper + " |";
    std::string rule = "|---|---|";
    for (const auto& r : s) {
      if (two_per_sensor) {
        h += " " + r.sensor + ": detections | " + r.sensor + ": 10 detections | " + r.sensor +
             ": fused | " + r.sensor + ": detections in the map |";
        rule += "---|---|---|---|";
      } else {
        h += " " + r.sensor + " |";
        rule += "---|";
      }
    }
    out.push_back(h);
    out.push_back(rule);
  };

  // Table 1.
  out.push_back("**Table 1, fitted size** (sensor " +
                FormatNumber(ev.config.size.standoff_m, 1.0, 1) + " m before the front legs, " +
                std::to_string(ev.config.size.recognitions_per_model) +
                " recognitions per model; fitted length x width [m], error of the mean in %, "
                "single-scan p95 error in brackets)");
  out.push_back("");
  header("model", "paper", false);
  for (std::size_t m = 0; m < (s.empty() ? 0 : s[0].sizes.size()); ++m) {
    const std::string& name = s[0].sizes[m].model;
    std::string line = "| " + name + " | ";
    if (const eval::PaperTable1Row* p = PaperRow(name)) {
      line += FormatNumber(p->fitted_length_m, 1.0, 4) + " x " +
              FormatNumber(p->fitted_width_m, 1.0, 4) + ": " +
              FormatNumber(p->length_error, 100.0, 2) + " % / " +
              FormatNumber(p->width_error, 100.0, 2) + " %";
    } else {
      line += "-";
    }
    line += " |";
    for (const auto& r : s) {
      const eval::ModelSize& z = r.sizes[m];
      line += " " + FormatNumber(z.mean_length_m, 1.0, 4) + " x " +
              FormatNumber(z.mean_width_m, 1.0, 4) + ": " + FormatNumber(z.length_error, 100.0, 2) +
              " % / " + FormatNumber(z.width_error, 100.0, 2) + " % (" +
              FormatNumber(z.single_scan_p95_error, 100.0, 2) + " %), " +
              std::to_string(z.recognitions) + "/" + std::to_string(z.attempts) + " |";
    }
    out.push_back(line);
  }
  out.push_back("");

  // Fig. 7.
  out.push_back(
      "**Fig. 7, fluctuation** of the shelf pose over the recognitions of one docking "
      "(continuous method, from the docking area's entry; " +
      std::to_string(ev.config.docking.runs) +
      " runs per sensor: median run (worst run); mm, mrad). Detections (all, and 10 evenly "
      "spaced as in the paper) and the fused estimate placed with the true robot pose (the "
      "recognition's own spread); detections in the map through the simulated localisation "
      "estimate (10 mm / 5 mrad white noise per update)");
  out.push_back("");
  header("measure", "paper (10 recognitions)", true);
  using Getter = const eval::RunQuantiles& (*)(const eval::FluctuationSummary&);
  struct FRow {
    const char* name;
    std::string paper;
    Getter get;
    double scale;
  };
  const FRow frows[] = {
      {"x max-min", FormatNumber(eval::kPaperFluctuationX, 1e3),
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.x_range; },
       1e3},
      {"y max-min", FormatNumber(eval::kPaperFluctuationY, 1e3),
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.y_range; },
       1e3},
      {"yaw max-min", FormatNumber(eval::kPaperFluctuationYaw, 1e3),
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.yaw_range; },
       1e3},
      {"x std", "-",
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.x_stddev; },
       1e3},
      {"y std", "-",
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.y_stddev; },
       1e3},
      {"yaw std", "-",
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& { return f.yaw_stddev; },
       1e3},
      {"recognitions per run", "10",
       [](const eval::FluctuationSummary& f) -> const eval::RunQuantiles& {
         return f.recognitions;
       },
       1.0},
  };
  for (const FRow& f : frows) {
    std::string line = std::string("| ") + f.name + " | " + f.paper + " |";
    const int decimals = f.scale == 1.0 ? 0 : 1;
    for (const auto& r : s) {
      line += " " + MedianWorst(f.get(r.docking.detected), f.scale, decimals) + " | " +
              MedianWorst(f.get(r.docking.detected_10), f.scale, decimals) + " | " +
              MedianWorst(f.get(r.docking.fused), f.scale, decimals) + " | " +
              MedianWorst(f.get(r.docking.detected_map), f.scale, decimals) + " |";
    }
    out.push_back(line);
  }
  out.push_back("");

  // Fig. 8.
  out.push_back(
      "**Fig. 8, docking error** (LiDAR-guided final pose against the true shelf, "
      "before the code check; " +
      std::to_string(ev.config.docking.runs) + " dockings per sensor; mm, mrad)");
  out.push_back("");
  header("measure", "paper", false);
  auto add_row = [&](const std::string& name, const std::string& paper, auto value) {
    std::string line = "| " + name + " | " + paper + " |";
    for (const auto& r : s) line += " " + value(r) + " |";
    out.push_back(line);
  };
  add_row("success (continuous)", "-", [](const eval::PaperSensorResult& r) {
    return std::to_string(r.docking.continuous_successes) + "/" + std::to_string(r.docking.runs);
  });
  add_row("\\|x\\| p95 / max", "<= 10", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.final_error.x.p95, 1e3) + " / " +
           FormatNumber(r.docking.final_error.x.max, 1e3);
  });
  add_row("\\|y\\| p95 / max", "<= 10", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.final_error.y.p95, 1e3) + " / " +
           FormatNumber(r.docking.final_error.y.max, 1e3);
  });
  add_row("\\|yaw\\| p95 / max", "<= 14", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.final_error.yaw.p95, 1e3) + " / " +
           FormatNumber(r.docking.final_error.yaw.max, 1e3);
  });
  add_row("within 10 mm and 14 mrad", "all", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.final_error.within_paper_band, 100.0) + " %";
  });
  add_row("after the code check, max x / y / yaw", "-", [](const eval::PaperSensorResult& r) {
    const auto& f = r.docking.final_error;
    return FormatNumber(f.after_x.max, 1e3) + " / " + FormatNumber(f.after_y.max, 1e3) + " / " +
           FormatNumber(f.after_yaw.max, 1e3);
  });
  out.push_back("");

  // Time.
  out.push_back(
      "**Time**, docking area entry (4.5 m before the goal, 0.4 m/s) to the end of the "
      "lift, mean over successful runs [s]");
  out.push_back("");
  header("measure", "paper", false);
  add_row("continuous", FormatNumber(eval::kPaperContinuousTime, 1.0, 2),
          [](const eval::PaperSensorResult& r) {
            return FormatNumber(r.docking.continuous_time_s, 1.0, 2);
          });
  add_row("stop-and-recognise", FormatNumber(eval::kPaperStopTime, 1.0, 3),
          [](const eval::PaperSensorResult& r) {
            return FormatNumber(r.docking.stop_time_s, 1.0, 2) + " (" +
                   std::to_string(r.docking.stop_successes) + "/" + std::to_string(r.docking.runs) +
                   " ok)";
          });
  add_row("saving", FormatNumber(eval::kPaperTimeSaving, 100.0, 1) + " %",
          [](const eval::PaperSensorResult& r) {
            return FormatNumber(r.docking.time_saving, 100.0, 1) + " %";
          });
  add_row("perfect knowledge", "-", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.perfect_time_s, 1.0, 2);
  });
  add_row("continuous / perfect knowledge", "-", [](const eval::PaperSensorResult& r) {
    return FormatNumber(r.docking.continuous_time_s / r.docking.perfect_time_s, 1.0, 3) + "x";
  });
  return out;
}

nlohmann::json PaperJson(const eval::PaperEvaluation& ev) {
  nlohmann::json sensors = nlohmann::json::array();
  for (const auto& r : ev.sensors) {
    nlohmann::json table1 = nlohmann::json::array();
    for (const auto& z : r.sizes) {
      table1.push_back({{"model", z.model},
                        {"model_length_m", z.model_length_m},
                        {"model_width_m", z.model_width_m},
                        {"attempts", z.attempts},
                        {"recognitions", z.recognitions},
                        {"mean_length_m", Json(z.mean_length_m)},
                        {"mean_width_m", Json(z.mean_width_m)},
                        {"length_error", Json(z.length_error)},
                        {"width_error", Json(z.width_error)},
                        {"single_scan_p95_error", Json(z.single_scan_p95_error)}});
    }
    const eval::DockingExperimentResult& d = r.docking;
    nlohmann::json trace = nlohmann::json::array();
    for (const auto& t : d.trace) {
      trace.push_back({{"t", t.t_s},
                       {"detected", Json(t.T_world_shelf_detected)},
                       {"fused", Json(t.T_world_shelf_fused)},
                       {"detected_map", Json(t.T_map_shelf_detected)}});
    }
    nlohmann::json finals = nlohmann::json::array();
    for (const auto& e : d.final_errors) {
      finals.push_back(e.valid ? nlohmann::json{{"x", e.x}, {"y", e.y}, {"yaw", e.yaw}}
                               : nlohmann::json());
    }
    sensors.push_back({{"sensor", r.sensor},
                       {"lidar",
                        {{"range_noise_sigma_m", r.lidar.range_noise_sigma_m},
                         {"beam_divergence_rad", r.lidar.beam_divergence_rad},
                         {"echo_separation_m", r.lidar.echo_separation_m},
                         {"dropout_probability", r.lidar.dropout_probability},
                         {"dark_dropout_gain", r.lidar.dark_dropout_gain},
                         {"tilt_pitch_rad", r.lidar.tilt_pitch_rad}}},
                       {"table1", table1},
                       {"fluctuation",
                        {{"detected", Json(d.detected)},
                         {"detected_10", Json(d.detected_10)},
                         {"fused", Json(d.fused)},
                         {"detected_map", Json(d.detected_map)},
                         {"fused_map", Json(d.fused_map)}}},
                       {"docking_error",
                        {{"runs", d.final_error.runs},
                         {"x", Json(d.final_error.x)},
                         {"y", Json(d.final_error.y)},
                         {"yaw", Json(d.final_error.yaw)},
                         {"within_10mm_14mrad", d.final_error.within_paper_band},
                         {"after_check",
                          {{"x", Json(d.final_error.after_x)},
                           {"y", Json(d.final_error.after_y)},
                           {"yaw", Json(d.final_error.after_yaw)}}}}},
                       {"time",
                        {{"runs", d.runs},
                         {"continuous_successes", d.continuous_successes},
                         {"stop_successes", d.stop_successes},
                         {"continuous_s", Json(d.continuous_time_s)},
                         {"stop_and_recognise_s", Json(d.stop_time_s)},
                         {"saving", Json(d.time_saving)},
                         {"perfect_knowledge_s", Json(d.perfect_time_s)}}},
                       {"trace_seed", d.trace_seed},
                       {"trace", trace},
                       {"final_errors", finals}});
  }
  nlohmann::json paper_t1 = nlohmann::json::array();
  for (const auto& p : eval::kPaperTable1) {
    paper_t1.push_back({{"model", std::string(p.model)},
                        {"fitted_length_m", p.fitted_length_m},
                        {"fitted_width_m", p.fitted_width_m},
                        {"length_error", p.length_error},
                        {"width_error", p.width_error}});
  }
  return {{"config",
           {{"recognitions_per_model", ev.config.size.recognitions_per_model},
            {"standoff_m", ev.config.size.standoff_m},
            {"size_seed0", ev.config.size.seed0},
            {"docking_runs", ev.config.docking.runs},
            {"docking_seed0", ev.config.docking.seed0}}},
          {"sensors", sensors},
          {"paper",
           {{"table1", paper_t1},
            {"fluctuation",
             {{"x", eval::kPaperFluctuationX},
              {"y", eval::kPaperFluctuationY},
              {"yaw", eval::kPaperFluctuationYaw}}},
            {"docking_error",
             {{"xy", eval::kPaperDockingErrorXY}, {"yaw", eval::kPaperDockingErrorYaw}}},
            {"time",
             {{"continuous_s", eval::kPaperContinuousTime},
              {"stop_and_recognise_s", eval::kPaperStopTime},
              {"saving", eval::kPaperTimeSaving}}}}}};
}

}  // namespace shelfdock::io
