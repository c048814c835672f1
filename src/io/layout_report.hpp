#pragma once

// Reports of the warehouse layout sweep (`shelfdock eval-layouts`, tests/eval): the per-class
// table as text lines, one line per failing scene, the sweep as JSON, and a failing scene's
// files for `shelfdock detect`:
//
//   <dir>/<class>_<seed>.scan.json   the scan, as io::ScanToJson writes it
//   <dir>/<class>_<seed>.truth.json  {"class", "seed", "lidar", "noise_sigma_m", "outcome",
//     "legs_in_sight", "findable", "standoff_m", "T_world_lidar", "preset" (lidar frame, the
//     --preset argument; null without one), "target" ({"id", "model", "x", "y", "yaw"} in the
//     lidar frame; null on clutter), "shelves" (every true shelf, lidar frame), "first" (the
//     first detection, lidar frame; null when none), "detect" (the command line that
//     reproduces the detection)}
//
// Units: m, rad; the table prints mm and mrad.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/layout_summary.hpp"
#include "eval/layout_sweep.hpp"
#include "sim/layout_generator.hpp"

namespace shelfdock::io {

/// The table: a header and one line per summary row, each line starting with `prefix`. Accuracy
/// columns for the two noise levels given (p50/p95 of the right-first findable scenes within the
/// sweep's standoff limit). `first_column` heads the rows' names. LayoutLegendLines explains it.
std::vector<std::string> LayoutTableLines(const std::vector<eval::LayoutSummary>& rows,
                                          double low_noise_sigma_m, double high_noise_sigma_m,
                                          const std::string& prefix,
                                          const std::string& first_column = "class");
/// What the table's columns mean (thresholds from `config`), each line starting with `prefix`.
std::vector<std::string> LayoutLegendLines(const eval::LayoutSweepConfig& config,
                                           const std::string& prefix);

/// One line for a failing scene: class, seed, sensor, what happened, truth and first detection.
std::string LayoutFailureLine(const eval::LayoutSceneResult& result);

/// The sweep: {"scenes_per_class", "seed0", "rows": [per class ..., overall], "failures": [...]},
/// and "rows_by_lidar" when `lidar_rows` is not empty.
nlohmann::json LayoutSweepJson(const std::vector<eval::LayoutSummary>& rows,
                               const std::vector<eval::LayoutSceneResult>& scenes,
                               const eval::LayoutSweepConfig& config,
                               const std::vector<eval::LayoutSummary>& lidar_rows = {});

/// Writes `scene`'s scan and truth files into `dir` (created if missing) as described above;
/// `detect_args` is appended to the reproducing command (e.g. "--models config/models.yaml").
/// Returns the scan file's path; throws InputError when a file cannot be written.
std::string WriteLayoutFailure(const std::string& dir, const sim::LayoutScene& scene,
                               const eval::LayoutSceneResult& result,
                               const std::string& detect_args);

}  // namespace shelfdock::io
