#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/laser_scan.hpp"

namespace shelfdock::io {

/// Reads scans from a file holding one scan object, a JSON array of them, or JSON Lines (one
/// object per line). Field names follow ROS sensor_msgs/LaserScan; `null` ranges become NaN.
/// Throws InputError naming the file, the scan index and the field on any malformed input.
std::vector<geometry::LaserScan> ReadScans(const std::string& path);

/// Parses one scan object; `where` prefixes field names in errors (e.g. "scan[3]").
geometry::LaserScan ScanFromJson(const nlohmann::json& j, const std::string& file,
                                 const std::string& where);

/// Serialises a scan; NaN and infinite ranges are written as null.
nlohmann::json ScanToJson(const geometry::LaserScan& scan);

}  // namespace shelfdock::io
