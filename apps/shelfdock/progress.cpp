#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace shelfdock::app {

Progress::Progress() : enabled_(isatty(fileno(stderr)) != 0) {}

Progress::~Progress() {
  if (shown_) std::fputs("\r\033[K", stderr);
}

void Progress::Show(const std::string& what, int done, int total) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r\033[K[%s] %d/%d", what.c_str(), done, total);
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace shelfdock::app
