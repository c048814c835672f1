#include "io/scan_json.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

#include "io/input_error.hpp"
#include "io/input_limits.hpp"
#include "io/scan_checks.hpp"
#include "io/scan_line_reader.hpp"

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

nlohmann::json ParseScanJson(std::string_view text, const std::string& file,
                             const std::string& where) {
  // Containers open around the element being parsed: element counts of arrays (-1: an object).
  std::vector<long> open;
  const auto count_element = [&]() {
    if (open.empty() || open.back() < 0) return;
    if (static_cast<std::size_t>(++open.back()) > kMaxJsonArrayElements) {
      throw InputError(file, where,
                       "an array holds more than " + std::to_string(kMaxJsonArrayElements) +
                           " elements, the limit (" + std::to_string(kMaxBeamsPerScan) +
                           " beams per scan)");
    }
  };
  const nlohmann::json::parser_callback_t limits = [&](int depth, nlohmann::json::parse_event_t ev,
                                                       nlohmann::json&) {
    using Event = nlohmann::json::parse_event_t;
    switch (ev) {
      case Event::object_start:
      case Event::array_start:
        if (depth >= kMaxScanJsonDepth) {
          throw InputError(file, where,
                           "nested deeper than " + std::to_string(kMaxScanJsonDepth) + " levels");
        }
        open.push_back(ev == Event::array_start ? 0 : -1);
        break;
      case Event::object_end:
      case Event::array_end:
        if (!open.empty()) open.pop_back();
        count_element();
        break;
      case Event::value:
        count_element();
        break;
      case Event::key:
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text.begin(), text.end(), limits);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, where, "malformed JSON at byte " + std::to_string(e.byte));
  } catch (const nlohmann::json::exception& e) {
    // out_of_range 406: a number beyond double (1e999999) is malformed input, not a crash.
    throw InputError(file, where, std::string("malformed JSON: ") + e.what());
  }
}

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
  }
  s.time_increment = OptionalNumber(j, "time_increment", 0.0, file, where);
  s.scan_time = OptionalNumber(j, "scan_time", 0.0, file, where);
  s.stamp = OptionalNumber(j, "stamp", 0.0, file, where);
  if (j.contains("frame_id") && j.at("frame_id").is_string()) {
    s.frame_id = j.at("frame_id").get<std::string>();
  }
  CheckScan(s, file, where);
  MakeBeamsAscending(s);
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

std::size_t ForEachScan(const std::string& path,
                        const std::function<void(const geometry::LaserScan&)>& on_scan) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file");
  // Regular files have a size to check up front; pipes and devices can only be read on.
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(path, ec);
  const std::uintmax_t bytes = regular ? std::filesystem::file_size(path, ec) : 0;

  in >> std::ws;
  const int first = in.peek();
  if (first == EOF) throw InputError(path, "", "file is empty");
  if (first != '[' && first != '{') {
    throw InputError(path, "line 1", "expected a scan object, an array of scans or JSON Lines");
  }
  // The whole file as one JSON document (an array, or one pretty-printed object).
  const auto read_document = [&]() {
    if (regular && bytes > kMaxScanDocumentBytes) {
      throw InputError(path, "",
                       "a JSON document over " + std::to_string(kMaxScanDocumentBytes) +
                           " bytes (the limit); write long recordings as JSON Lines");
    }
    if (regular) {
      in.clear();
      in.seekg(0);
    }
    // One byte over the limit tells a pipe that is too long from one that just fits.
    std::string text(regular ? static_cast<std::size_t>(bytes) : kMaxScanDocumentBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxScanDocumentBytes) {
      throw InputError(path, "",
                       "a JSON document over " + std::to_string(kMaxScanDocumentBytes) +
                           " bytes (the limit); write long recordings as JSON Lines");
    }
    return ParseScanJson(text, path, "");
  };

  if (first == '[') {
    const nlohmann::json doc = read_document();
    if (!doc.is_array()) throw InputError(path, "", "expected an array of scans");
    if (doc.empty()) throw InputError(path, "", "array holds no scans");
    for (std::size_t i = 0; i < doc.size(); ++i) {
      on_scan(ScanFromJson(doc[i], path, "scan[" + std::to_string(i) + "]"));
    }
    return doc.size();
  }

  // An object: JSON Lines when its first line is a whole JSON text, else one pretty-printed scan.
  ScanLineReader lines(in, path);
  std::optional<ScanLine> line = lines.Next();
  if (line && line->malformed_json && regular && bytes <= kMaxScanDocumentBytes) {
    on_scan(ScanFromJson(read_document(), path, "scan[0]"));
    return 1;
  }
  std::size_t count = 0;
  for (; line; line = lines.Next()) {
    if (line->error) throw *line->error;
    on_scan(*line->scan);
    ++count;
  }
  if (count == 0) throw InputError(path, "", "file is empty");
  return count;
}

std::vector<geometry::LaserScan> ReadScans(const std::string& path) {
  std::vector<geometry::LaserScan> scans;
  ForEachScan(path, [&scans](const geometry::LaserScan& s) { scans.push_back(s); });
  return scans;
}

}  // namespace shelfdock::io
