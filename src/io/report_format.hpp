#pragma once
// Number formatting shared by the experiment reports (tables and JSON).

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace shelfdock::io {

/// `value * scale` with `decimals` decimals for a table cell, "n/a" when not finite.
inline std::string FormatNumber(double value, double scale = 1.0, int decimals = 1) {
  if (!std::isfinite(value)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, value * scale);
  return buf;
}

/// A number for JSON, null when not finite (JSON has no NaN).
inline nlohmann::json JsonNumber(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

}  // namespace shelfdock::io
