#include "io/paper_html.hpp"

#include <string_view>

#include "io/paper_report.hpp"

namespace shelfdock::io {

extern const char* const kPaperHtmlTemplate;

std::string PaperHtml(const eval::PaperEvaluation& evaluation) {
  std::string page = kPaperHtmlTemplate;
  // Inside <script>, "</" could close the element: JSON allows "<\/" for it.
  std::string data = PaperJson(evaluation).dump();
  for (std::size_t at = data.find("</"); at != std::string::npos; at = data.find("</", at + 3)) {
    data.replace(at, 2, "<\\/");
  }
  constexpr std::string_view kMarker = "__SHELFDOCK_DATA__";
  const std::size_t at = page.find(kMarker);
  if (at != std::string::npos) page.replace(at, kMarker.size(), data);
  return page;
}

}  // namespace shelfdock::io
