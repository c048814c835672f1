#pragma once

#include <istream>
#include <optional>
#include <string>

#include "geometry/laser_scan.hpp"
#include "io/input_error.hpp"

namespace shelfdock::io {

/// One non-blank line of a JSON Lines scan stream: a scan, or what was wrong with the line.
struct ScanLine {
  int line = 0;                             ///< 1-based line number in the stream
  std::optional<geometry::LaserScan> scan;  ///< empty when the line is bad
  std::optional<InputError> error;          ///< what was wrong, naming the stream and line
  bool malformed_json = false;              ///< the line is not one whole JSON text
};

/// Reads JSON Lines scans one line at a time from any stream (standard input, a pipe, a file of
/// any length): memory is one line, at most kMaxScanLineBytes, whatever the stream's length. A
/// bad line (malformed JSON, a bad field, a line over the limit) is returned as an error and
/// reading goes on with the next line.
class ScanLineReader {
 public:
  /// `name` stands for the stream in error messages (a file name, or "(stdin)").
  ScanLineReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}

  /// The next non-blank line, or nullopt at the end of the stream.
  std::optional<ScanLine> Next();

  const std::string& name() const { return name_; }

 private:
  /// Reads one line into `text_`; false at end of stream, `too_long` when it was cut short.
  bool ReadLine(bool& too_long);

  std::istream& in_;
  std::string name_;
  std::string text_;
  int line_ = 0;
  bool skipping_ = false;  ///< the rest of a too-long line is still to be skipped
};

}  // namespace shelfdock::io
