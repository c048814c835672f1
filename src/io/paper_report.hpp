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
/// "fluctuation": {"detected", "fused"}, "docking_error": {...}, "time": {...},
/// "trace": [...], "final_errors": [...]}], "paper": {...}}.
nlohmann::json PaperJson(const eval::PaperEvaluation& evaluation);

}  // namespace shelfdock::io
