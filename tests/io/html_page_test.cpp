#include "io/html_page.hpp"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace shelfdock::io {
namespace {

// The text of the data element of a filled page.
std::string DataOf(const std::string& page) {
  const std::string open = R"(<script type="application/json" id="shelfdock-data">)";
  const std::size_t begin = page.find(open) + open.size();
  return page.substr(begin, page.find("</script>", begin) - begin);
}

TEST(HtmlPage, DataGoesIntoTheSlotAndReadsBackUnchanged) {
  const std::string page_template =
      std::string("<html><body>") + std::string(kPageDataSlot) + "<script>x()</script></body>";
  const nlohmann::json data = {{"scans", {1, 2, 3}}, {"name", "a/b"}};
  const std::string page = FillPage(page_template, data);
  EXPECT_EQ(nlohmann::json::parse(DataOf(page)), data);
  EXPECT_EQ(page.rfind("<html><body>", 0), 0u);
  EXPECT_NE(page.find("<script>x()</script></body>"), std::string::npos);
}

TEST(HtmlPage, DataCannotCloseTheScriptElement) {
  const nlohmann::json data = {{"model", "</script><script>alert(1)</script>"}};
  const std::string page = FillPage(kPageDataSlot, data);
  // One closing tag: the slot's own.
  EXPECT_EQ(page.find("</script>"), page.rfind("</script>"));
  EXPECT_EQ(nlohmann::json::parse(DataOf(page)), data);
}

TEST(HtmlPage, ATemplateWithoutSlotIsAProgrammerError) {
  EXPECT_THROW(FillPage("<html></html>", nlohmann::json::object()), std::logic_error);
}

}  // namespace
}  // namespace shelfdock::io
