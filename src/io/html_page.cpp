#include "io/html_page.hpp"

#include <fstream>
#include <stdexcept>

#include "io/input_error.hpp"

namespace shelfdock::io {

std::string FillPage(std::string_view page_template, const nlohmann::json& data) {
  const std::size_t at = page_template.find(kPageDataSlot);
  if (at == std::string_view::npos) throw std::logic_error("page template has no data slot");
  // JSON allows "\/" for "/", and "</" can only occur inside strings: escaping it keeps a
  // model name such as "</script>" from ending the element.
  std::string json = data.dump();
  std::string safe;
  safe.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    safe.push_back(json[i]);
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') safe.push_back('\\');
  }
  const std::string_view slot = kPageDataSlot;
  const std::size_t close = slot.find("</script>");
  std::string page;
  page.reserve(page_template.size() + safe.size());
  page.append(page_template.substr(0, at));
  page.append(slot.substr(0, close));
  page.append(safe);
  page.append(slot.substr(close));
  page.append(page_template.substr(at + slot.size()));
  return page;
}

void WritePage(const std::string& path, std::string_view page_template,
               const nlohmann::json& data) {
  const std::string page = FillPage(page_template, data);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path, "", "cannot open the page for writing");
  out << page;
  if (!out) throw InputError(path, "", "write failed");
}

}  // namespace shelfdock::io
