#pragma once

// Reports of `shelfdock eval paper`: the tables (Markdown, the paper's figure beside ours) and
// every number as JSON. Units in JSON: m, rad, s, shares in [0, 1]; tables print mm, mrad, %.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/paper_evaluation.hpp"

namespace shelfdock::io {

/// The four tables (Table 1, Fig. 7, Fig. 8, time), as Markdown lines.
std::vector<std::string> PaperTableLines(const eval::PaperEvaluation& evaluation);

/// Every figure: {"config": {...}, "sensors": [{"sensor", "lidar": {...}, "table1": [...],
/// "fluctuation": {"detected", "fused", "detected_map", "fused_map"}, "docking_error": {...},
/// "time": {...}, "trace": [{"t", "detected", "fused" (placed with the true pose), "detected_map"}]
/// (the run with the median x range), "final_errors": [...] (null: the run never reached the
/// check)}], "paper": {...}}.
nlohmann::json PaperJson(const eval::PaperEvaluation& evaluation);

}  // namespace shelfdock::io
