#include "eval/fault_sweep.hpp"

#include <algorithm>

#include "eval/fault_injector.hpp"

namespace shelfdock::eval {

FaultRun RunFaulted(const sim::Scenario& scenario, const std::vector<geometry::ShelfModel>& models,
                    docking::Method method, std::uint64_t seed, RunConfig config,
                    const FaultDrawConfig& draw) {
  FaultRun out;
  out.fault = DrawFault(seed, draw);
  sim::Scenario faulted = scenario;
  ApplyFaultToScenario(out.fault, config.docking.entry_distance_m, &faulted);
  config.fault = out.fault;
  config.record = false;
  out.run = RunDocking(faulted, models, method, seed, config);
  out.possible = DockingPossible(out.fault);
  out.leg_contact = out.run.min_leg_clearance_m <= 0.0;
  const docking::OutcomeCode code = out.run.outcome.code;
  out.typed =
      !out.run.hung && code != docking::OutcomeCode::kPending && !out.run.outcome.reason.empty();
  if (out.possible) {
    out.rule_violation = !out.run.outcome.ok();
  } else if (out.run.outcome.ok()) {
    out.rule_violation = !SuccessAcceptable(out.fault.kind);
  } else {
    const auto expected = ExpectedFailures(out.fault.kind);
    out.rule_violation = std::find(expected.begin(), expected.end(), code) == expected.end();
  }
  return out;
}

FaultSweepSummary SummariseFaults(const std::vector<FaultRun>& runs) {
  FaultSweepSummary s;
  std::map<FaultKind, FaultKindSummary> by_kind;
  for (const FaultRun& r : runs) {
    ++s.runs;
    s.leg_contacts += r.leg_contact;
    s.hangs += r.run.hung;
    s.untyped += !r.typed;
    s.rule_violations += r.rule_violation;
    s.min_leg_clearance_m = std::min(s.min_leg_clearance_m, r.run.min_leg_clearance_m);
    FaultKindSummary& k = by_kind[r.fault.kind];
    k.kind = r.fault.kind;
    k.possible = r.possible;
    ++k.runs;
    if (r.run.outcome.ok()) {
      ++k.successes;
    } else {
      ++k.failures[r.run.outcome.code];
    }
    k.rule_violations += r.rule_violation;
    k.min_leg_clearance_m = std::min(k.min_leg_clearance_m, r.run.min_leg_clearance_m);
  }
  for (FaultKind kind : AllFaultKinds()) {
    if (const auto it = by_kind.find(kind); it != by_kind.end()) s.kinds.push_back(it->second);
  }
  return s;
}

}  // namespace shelfdock::eval
