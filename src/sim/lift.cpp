#include "sim/lift.hpp"

#include <algorithm>

namespace shelfdock::sim {

void Lift::Start(double time_s) {
  if (started_) return;
  started_ = true;
  start_time_s_ = time_s;
}

double Lift::Progress(double time_s) const {
  if (!started_) return 0.0;
  if (Done(time_s)) return 1.0;
  return std::clamp((time_s - start_time_s_) / duration_s_, 0.0, 1.0);
}

bool Lift::Done(double time_s) const {
  constexpr double kTimeTolerance_s = 1e-9;
  return started_ && time_s - start_time_s_ >= duration_s_ - kTimeTolerance_s;
}

}  // namespace shelfdock::sim
