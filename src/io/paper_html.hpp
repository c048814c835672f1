#pragma once

#include <string>

#include "eval/paper_evaluation.hpp"

namespace shelfdock::io {

/// `eval paper --html`: one self-contained page (no network) with SVG plots of the size error
/// per model, the fluctuation trace, the docking-error scatter and the time bars. The page is
/// web/paper_report.html, embedded at build time, with the run's PaperJson in it.
std::string PaperHtml(const eval::PaperEvaluation& evaluation);

}  // namespace shelfdock::io
