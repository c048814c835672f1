#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "eval/docking_runner.hpp"
#include "eval/fault.hpp"

namespace shelfdock::eval {

/// One faulted docking and how it is judged.
struct FaultRun {
  FaultSpec fault;
  DockingRun run;               ///< without its record
  bool possible = true;         ///< DockingPossible(fault)
  bool leg_contact = false;     ///< the true footprint met a true leg (clearance <= 0)
  bool typed = true;            ///< ended by the Docker with an outcome code and a reason
  bool rule_violation = false;  ///< possible but failed, or impossible but not an expected failure
};

/// Draws the fault of `seed` (DrawFault), puts it into a copy of the scenario and into the
/// run's sensors, runs one docking and judges it.
FaultRun RunFaulted(const sim::Scenario& scenario, const std::vector<geometry::ShelfModel>& models,
                    docking::Method method, std::uint64_t seed, RunConfig config,
                    const FaultDrawConfig& draw = {});

/// The outcomes of one fault kind.
struct FaultKindSummary {
  FaultKind kind = FaultKind::kNone;
  bool possible = true;
  int runs = 0;
  int successes = 0;
  std::map<docking::OutcomeCode, int> failures;  ///< per typed failure
  int rule_violations = 0;
  double min_leg_clearance_m = 1e9;  ///< [m] worst over its runs
};

/// The whole sweep: the invariants as counts (each must be 0) and a row per kind.
struct FaultSweepSummary {
  int runs = 0;
  int leg_contacts = 0;     ///< runs whose true clearance to a leg was <= 0
  int hangs = 0;            ///< runs the Docker had not ended by the simulation's time limit
  int untyped = 0;          ///< runs that ended without an outcome code and reason
  int rule_violations = 0;  ///< runs against DockingPossible / ExpectedFailures
  double min_leg_clearance_m = 1e9;     ///< [m] worst over all runs
  std::vector<FaultKindSummary> kinds;  ///< in AllFaultKinds() order, kinds with runs only
};

/// Counts per fault kind and over all runs: successes, typed failures, contacts, hangs, rule
/// violations.
FaultSweepSummary SummariseFaults(const std::vector<FaultRun>& runs);

}  // namespace shelfdock::eval
