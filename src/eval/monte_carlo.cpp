#include "eval/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shelfdock::eval {
namespace {

AbsErrorStats Stats(const std::vector<double>& values) {
  AbsErrorStats s;
  std::vector<double> abs_values;
  abs_values.reserve(values.size());
  for (double v : values) abs_values.push_back(std::abs(v));
  s.p95 = Quantile(abs_values, 0.95);
  s.p99 = Quantile(abs_values, 0.99);
  s.max = Quantile(abs_values, 1.0);
  return s;
}

void AddPhases(const PhaseTimes& t, PhaseTimes* sum) {
  sum->approach_s += t.approach_s;
  sum->dock_s += t.dock_s;
  sum->final_slow_s += t.final_slow_s;
  sum->stand_s += t.stand_s;
  sum->verify_s += t.verify_s;
  sum->adjust_s += t.adjust_s;
  sum->lift_s += t.lift_s;
  sum->abort_s += t.abort_s;
}

/// The errors of one kind (before or after the code check) over the runs that reached it.
struct ErrorSamples {
  std::vector<double> x, y, yaw;
  int within = 0;  ///< runs inside the band on all three axes

  void Add(const PoseError& e, double band_xy_m, double band_yaw_rad) {
    if (!e.valid) return;
    x.push_back(e.x);
    y.push_back(e.y);
    yaw.push_back(e.yaw);
    within +=
        std::abs(e.x) <= band_xy_m && std::abs(e.y) <= band_xy_m && std::abs(e.yaw) <= band_yaw_rad;
  }
  double WithinShare() const { return x.empty() ? 0.0 : static_cast<double>(within) / x.size(); }
};

}  // namespace

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

MethodSummary Summarise(const std::vector<DockingRun>& runs, const AccuracyBands& bands) {
  MethodSummary s;
  s.runs = static_cast<int>(runs.size());
  ErrorSamples before, after;
  double time_sum = 0.0;
  for (const DockingRun& r : runs) {
    s.min_leg_clearance_m = std::min(s.min_leg_clearance_m, r.min_leg_clearance_m);
    if (r.outcome.ok()) {
      ++s.successes;
      time_sum += r.time_s;
      AddPhases(r.phases, &s.mean_phases);
      s.mean_code_checks += r.phases.code_checks;
      s.mean_adjustments += r.phases.adjustments;
    }
    before.Add(r.error_before_check, bands.before_xy_m, bands.before_yaw_rad);
    after.Add(r.error_after_check, bands.after_xy_m, bands.after_yaw_rad);
  }
  s.mean_time_s = s.successes > 0 ? time_sum / s.successes : 0.0;
  if (s.successes > 0) {
    const double n = s.successes;
    PhaseTimes& m = s.mean_phases;
    for (double* v : {&m.approach_s, &m.dock_s, &m.final_slow_s, &m.stand_s, &m.verify_s,
                      &m.adjust_s, &m.lift_s, &m.abort_s}) {
      *v /= n;
    }
    s.mean_code_checks /= n;
    s.mean_adjustments /= n;
  }
  s.before_x = Stats(before.x);
  s.before_y = Stats(before.y);
  s.before_yaw = Stats(before.yaw);
  s.after_x = Stats(after.x);
  s.after_y = Stats(after.y);
  s.after_yaw = Stats(after.yaw);
  s.within_before = before.WithinShare();
  s.within_after = after.WithinShare();
  return s;
}

}  // namespace shelfdock::eval
