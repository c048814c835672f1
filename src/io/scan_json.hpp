#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/laser_scan.hpp"

namespace shelfdock::io {

/// Reads scans from a file holding one scan object, a JSON array of them, or JSON Lines (one
/// object per line). Field names follow ROS sensor_msgs/LaserScan; `null` ranges become NaN.
/// Throws InputError naming the file, the scan index and the field on any malformed input.
/// Limits (input_limits.hpp) are checked before the work: a JSON document over
/// kMaxScanDocumentBytes, a line over kMaxScanLineBytes, an array over kMaxJsonArrayElements.
std::vector<geometry::LaserScan> ReadScans(const std::string& path);

/// As ReadScans, but hands each scan to `on_scan` as it is read: JSON Lines files of any length
/// take one line of memory. Returns the number of scans; throws InputError at the first bad one.
std::size_t ForEachScan(const std::string& path,
                        const std::function<void(const geometry::LaserScan&)>& on_scan);

/// Parses one JSON text of a scan file (a line, or a whole document): at most
/// kMaxJsonArrayElements elements in any array and 8 levels of nesting, checked while parsing.
/// Throws InputError naming `file` and `where` (e.g. "line 3").
nlohmann::json ParseScanJson(std::string_view text, const std::string& file,
                             const std::string& where);

/// Parses one scan object; `where` prefixes field names in errors (e.g. "scan[3]"). The scan
/// passes CheckScan (scan_checks.hpp) and comes back with its beams in ascending angle order.
geometry::LaserScan ScanFromJson(const nlohmann::json& j, const std::string& file,
                                 const std::string& where);

/// Serialises a scan; NaN and infinite ranges are written as null.
nlohmann::json ScanToJson(const geometry::LaserScan& scan);

}  // namespace shelfdock::io
