#pragma once
// A one-line progress display on stderr, shown only when stderr is a terminal.
#include <string>

namespace shelfdock::app {

class Progress {
 public:
  Progress();
  ~Progress();
  /// Rewrites the line: "[what] done/total".
  void Show(const std::string& what, int done, int total);

 private:
  bool enabled_ = false;
  bool shown_ = false;
};

}  // namespace shelfdock::app
