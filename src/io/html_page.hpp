#pragma once

// Self-contained HTML pages: a page template (web/*.html, embedded in the CLI at build time) with
// its data written into the page, so one file opens anywhere, offline.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace shelfdock::io {

/// The element of a page template that receives the data; the page reads it with
/// JSON.parse(document.getElementById("shelfdock-data").textContent).
inline constexpr std::string_view kPageDataSlot =
    R"(<script type="application/json" id="shelfdock-data"></script>)";

/// `page_template` with `data` written into its kPageDataSlot ("</" escaped so the data cannot
/// close the script element). Throws std::logic_error when the template has no slot.
std::string FillPage(std::string_view page_template, const nlohmann::json& data);

/// FillPage, written to `path`; throws InputError (naming `path`) when it cannot be written.
void WritePage(const std::string& path, std::string_view page_template, const nlohmann::json& data);

}  // namespace shelfdock::io
