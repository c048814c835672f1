#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace shelfdock::app {

Progress::Progress(std::string label, long total)
    : label_(std::move(label)),
      total_(total),
      shown_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  // Leave the terminal as it was: clear the counter line.
  if (drawn_) std::fprintf(stderr, "\r\033[K");
}

void Progress::Update(long done, const std::string& note) {
  if (!shown_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last = total_ > 0 && done >= total_;
  if (drawn_ && !last && now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  drawn_ = true;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  if (total_ > 0) {
    const double eta_s = done > 0 ? elapsed_s * static_cast<double>(total_ - done) / done : 0.0;
    std::fprintf(stderr, "\r\033[K%s %ld/%ld (%.0f%%) %.0f s, ~%.0f s left %s", label_.c_str(),
                 done, total_, 100.0 * static_cast<double>(done) / static_cast<double>(total_),
                 elapsed_s, eta_s, note.c_str());
  } else {
    std::fprintf(stderr, "\r\033[K%s %ld %.0f s %s", label_.c_str(), done, elapsed_s, note.c_str());
  }
  std::fflush(stderr);
}

}  // namespace shelfdock::app
