#include "io/scan_json.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/input_error.hpp"

namespace shelfdock::io {
namespace {

double RequireNumber(const nlohmann::json& j, const char* key, const std::string& file,
                     const std::string& where) {
  const std::string field = where + "." + key;
  if (!j.contains(key)) throw InputError(file, field, "missing required field");
  const auto& v = j.at(key);
  if (!v.is_number()) throw InputError(file, field, "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(file, field, "expected a finite number");
  return d;
}

double OptionalNumber(const nlohmann::json& j, const char* key, double fallback,
                      const std::string& file, const std::string& where) {
  if (!j.contains(key) || j.at(key).is_null()) return fallback;
  return RequireNumber(j, key, file, where);
}

std::vector<double> ReadRanges(const nlohmann::json& j, const char* key, const std::string& file,
                               const std::string& where) {
  const std::string field = where + "." + key;
  const auto& arr = j.at(key);
  if (!arr.is_array()) throw InputError(file, field, "expected an array");
  std::vector<double> out;
  out.reserve(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const auto& v = arr[i];
    if (v.is_null()) {
      out.push_back(std::numeric_limits<double>::quiet_NaN());
    } else if (v.is_number()) {
      out.push_back(v.get<double>());
    } else {
      throw InputError(file, field + "[" + std::to_string(i) + "]", "expected a number or null");
    }
  }
  return out;
}

}  // namespace

geometry::LaserScan ScanFromJson(const nlohmann::json& j, const std::string& file,
                                 const std::string& where) {
  if (!j.is_object()) throw InputError(file, where, "expected a scan object");
  geometry::LaserScan s;
  s.angle_min = RequireNumber(j, "angle_min", file, where);
  s.angle_max = RequireNumber(j, "angle_max", file, where);
  s.angle_increment = RequireNumber(j, "angle_increment", file, where);
  s.range_min = RequireNumber(j, "range_min", file, where);
  s.range_max = RequireNumber(j, "range_max", file, where);
  if (!j.contains("ranges")) throw InputError(file, where + ".ranges", "missing required field");
  s.ranges = ReadRanges(j, "ranges", file, where);
  if (j.contains("intensities") && !j.at("intensities").is_null()) {
    s.intensities = ReadRanges(j, "intensities", file, where);
    if (s.intensities.size() != s.ranges.size() && !s.intensities.empty()) {
      throw InputError(file, where + ".intensities", "length differs from ranges");
    }
  }
  s.time_increment = OptionalNumber(j, "time_increment", 0.0, file, where);
  s.scan_time = OptionalNumber(j, "scan_time", 0.0, file, where);
  s.stamp = OptionalNumber(j, "stamp", 0.0, file, where);
  if (j.contains("frame_id") && j.at("frame_id").is_string()) {
    s.frame_id = j.at("frame_id").get<std::string>();
  }

  if (s.angle_increment == 0.0) {
    throw InputError(file, where + ".angle_increment", "must be non-zero");
  }
  if (s.range_min < 0.0 || s.range_max <= s.range_min) {
    throw InputError(file, where + ".range_max", "must exceed range_min >= 0");
  }
  if (s.ranges.empty()) throw InputError(file, where + ".ranges", "empty scan");
  const double expected = (s.angle_max - s.angle_min) / s.angle_increment + 1.0;
  if (std::abs(expected - static_cast<double>(s.ranges.size())) > 1.5) {
    std::ostringstream msg;
    msg << "holds " << s.ranges.size() << " beams but angle_min/angle_max/angle_increment imply "
        << std::lround(expected);
    throw InputError(file, where + ".ranges", msg.str());
  }
  return s;
}

nlohmann::json ScanToJson(const geometry::LaserScan& scan) {
  nlohmann::json ranges = nlohmann::json::array();
  for (double r : scan.ranges) {
    if (std::isfinite(r)) {
      ranges.push_back(r);
    } else {
      ranges.push_back(nullptr);
    }
  }
  nlohmann::json j = {{"angle_min", scan.angle_min},
                      {"angle_max", scan.angle_max},
                      {"angle_increment", scan.angle_increment},
                      {"range_min", scan.range_min},
                      {"range_max", scan.range_max},
                      {"ranges", ranges},
                      {"time_increment", scan.time_increment},
                      {"scan_time", scan.scan_time},
                      {"stamp", scan.stamp},
                      {"frame_id", scan.frame_id}};
  if (!scan.intensities.empty()) j["intensities"] = scan.intensities;
  return j;
}

std::vector<geometry::LaserScan> ReadScans(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(path, "", "file is empty");
  }

  std::vector<geometry::LaserScan> scans;
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!doc.is_discarded()) {
    if (doc.is_array()) {
      if (doc.empty()) throw InputError(path, "", "array holds no scans");
      for (std::size_t i = 0; i < doc.size(); ++i) {
        scans.push_back(ScanFromJson(doc[i], path, "scan[" + std::to_string(i) + "]"));
      }
    } else {
      scans.push_back(ScanFromJson(doc, path, "scan[0]"));
    }
    return scans;
  }

  // Not one JSON document: read as JSON Lines.
  std::istringstream lines(text);
  std::string line;
  int line_no = 0;
  while (std::getline(lines, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) {
      throw InputError(path, "line " + std::to_string(line_no), "malformed JSON");
    }
    scans.push_back(ScanFromJson(j, path, "line " + std::to_string(line_no)));
  }
  return scans;
}

}  // namespace shelfdock::io
