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
  std::vector<double> bx, by, byaw, ax, ay, ayaw;
  double time_sum = 0.0;
  int in_before = 0, in_after = 0;
  for (const DockingRun& r : runs) {
    s.min_leg_clearance_m = std::min(s.min_leg_clearance_m, r.min_leg_clearance_m);
    if (r.outcome.ok()) {
      ++s.successes;
      time_sum += r.time_s;
      AddPhases(r.phases, &s.mean_phases);
      s.mean_code_checks += r.phases.code_checks;
      s.mean_adjustments += r.phases.adjustments;
    }
    if (r.error_before_check.valid) {
      const PoseError& e = r.error_before_check;
      bx.push_back(e.x);
      by.push_back(e.y);
      byaw.push_back(e.yaw);
      in_before += std::abs(e.x) <= bands.before_xy_m && std::abs(e.y) <= bands.before_xy_m &&
                   std::abs(e.yaw) <= bands.before_yaw_rad;
    }
    if (r.error_after_check.valid) {
      const PoseError& e = r.error_after_check;
      ax.push_back(e.x);
      ay.push_back(e.y);
      ayaw.push_back(e.yaw);
      in_after += std::abs(e.x) <= bands.after_xy_m && std::abs(e.y) <= bands.after_xy_m &&
                  std::abs(e.yaw) <= bands.after_yaw_rad;
    }
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
  s.before_x = Stats(bx);
  s.before_y = Stats(by);
  s.before_yaw = Stats(byaw);
  s.after_x = Stats(ax);
  s.after_y = Stats(ay);
  s.after_yaw = Stats(ayaw);
  s.within_before = bx.empty() ? 0.0 : static_cast<double>(in_before) / bx.size();
  s.within_after = ax.empty() ? 0.0 : static_cast<double>(in_after) / ax.size();
  return s;
}

}  // namespace shelfdock::eval
