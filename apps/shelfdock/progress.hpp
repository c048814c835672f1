#pragma once

#include <chrono>
#include <string>

namespace shelfdock::app {

/// "No silent minutes": a one-line counter on stderr for long commands (eval-docking, eval-real,
/// bag conversion), redrawn at most five times a second. Shown only when stderr is a terminal,
/// so piped or captured output (CI, tests, scripts) stays exactly as before.
class Progress {
 public:
  /// `total` <= 0: unknown (only the count is shown).
  Progress(std::string label, long total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` items of `total` finished; `note` is appended (e.g. the current file).
  void Update(long done, const std::string& note = "");

  /// True when progress is drawn (stderr is a terminal).
  bool shown() const { return shown_; }

 private:
  std::string label_;
  long total_;
  bool shown_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace shelfdock::app
