#include "io/scan_line_reader.hpp"

#include <array>

#include "io/input_error.hpp"
#include "io/input_limits.hpp"
#include "io/scan_json.hpp"

namespace shelfdock::io {

bool ScanLineReader::ReadLine(bool& too_long) {
  text_.clear();
  too_long = false;
  std::array<char, 65536> chunk;
  bool any = false;
  while (true) {
    in_.getline(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto n = static_cast<std::size_t>(in_.gcount());
    any = any || n > 0;
    // getline fails without reaching the end when the chunk filled up before the newline.
    const bool chunk_full = in_.fail() && !in_.eof() && n == chunk.size() - 1;
    const bool newline = !in_.fail() && !in_.eof();
    const std::size_t stored = newline ? n - 1 : n;
    if (!skipping_) {
      if (text_.size() + stored > kMaxScanLineBytes) {
        // Report now; the rest of the line is skipped on the next call.
        too_long = true;
        skipping_ = chunk_full;
        in_.clear(in_.rdstate() & ~std::ios::failbit);
        return true;
      }
      text_.append(chunk.data(), stored);
    }
    if (chunk_full) {
      in_.clear();
      continue;
    }
    if (skipping_) {
      skipping_ = false;
      if (!newline) return false;
      text_.clear();
      any = false;
      continue;  // the skipped line was reported already: read the next one
    }
    return newline || any;
  }
}

std::optional<ScanLine> ScanLineReader::Next() {
  while (true) {
    bool too_long = false;
    if (!ReadLine(too_long)) return std::nullopt;
    ++line_;
    const std::string where = "line " + std::to_string(line_);
    ScanLine out;
    out.line = line_;
    if (too_long) {
      out.error = InputError(name_, where,
                             "longer than " + std::to_string(kMaxScanLineBytes) +
                                 " bytes, the limit of one JSON Lines scan");
      return out;
    }
    if (text_.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json j;
    try {
      j = ParseScanJson(text_, name_, where);
    } catch (const InputError& e) {
      out.error = e;
      out.malformed_json = true;
      return out;
    }
    try {
      out.scan = ScanFromJson(j, name_, where);
    } catch (const InputError& e) {
      out.error = e;
    }
    return out;
  }
}

}  // namespace shelfdock::io
