#include "cli_args.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/input_error.hpp"

namespace shelfdock::app {

std::vector<double> ParseNumbers(const std::string& text, std::size_t n, const std::string& flag,
                                 const std::string& form) {
  const io::InputError error(kCommandLine, flag, "expected " + form + ", got '" + text + "'");
  std::vector<double> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::logic_error&) {  // invalid_argument, out_of_range
      throw error;
    }
    if (used != item.size() || !std::isfinite(value)) throw error;
    values.push_back(value);
  }
  // getline drops a trailing empty item ("1,2,3,"): count the commas too.
  const auto commas = static_cast<std::size_t>(std::count(text.begin(), text.end(), ','));
  if (values.size() != n || commas + 1 != n) throw error;
  return values;
}

CLI::Validator NonNegativeInteger() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
          return c >= '0' && c <= '9';
        });
        return digits ? "" : "must be a whole number >= 0, got '" + text + "'";
      },
      "INT>=0");
}

geometry::Pose2 ParsePose(const std::string& text, const std::string& flag) {
  const auto v = ParseNumbers(text, 3, flag, "X,Y,YAW (m, m, rad)");
  return geometry::Pose2(v[0], v[1], v[2]);
}

}  // namespace shelfdock::app
