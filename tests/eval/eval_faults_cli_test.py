#!/usr/bin/env python3
"""`shelfdock eval faults --runs RUNS` through the CLI (seeds 1-RUNS; 30 by default: every
fault kind twice; the sanitizer build runs 15, every kind once): no leg contact (true clearance
> 0 in every run), no hang, every run ends in success or a typed failure with a reason, and every
run obeys the rule of which faults leave docking possible (src/eval/fault.hpp). Bad input exits 2.
Usage: eval_faults_cli_test.py SHELFDOCK SOURCE [RUNS]
"""
import json
import subprocess
import sys

KNOWN_RESULTS = {"success", "shelf_not_found", "detection_lost", "would_collide", "no_path",
                 "tracking_failed", "wrong_shelf", "code_not_found", "timeout",
                 "too_many_replans"}


def main():
    shelfdock, source = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 30
    kinds = 15
    assert runs % kinds == 0, f"RUNS must be a multiple of the {kinds} fault kinds"
    r = subprocess.run([shelfdock, "eval", "faults", "--runs", str(runs), "--json"], cwd=source,
                       capture_output=True, text=True)
    assert r.returncode in (0, 1), f"exit {r.returncode}\n{r.stderr}"
    s = json.loads(r.stdout)
    problems = json.dumps(s["problem_runs"], indent=1)
    assert s["runs"] == runs
    assert s["leg_contacts"] == 0, problems
    assert s["min_leg_clearance_m"] > 0.0, s["min_leg_clearance_m"]
    assert s["hangs"] == 0, problems
    assert s["untyped"] == 0, problems
    assert s["rule_violations"] == 0, problems
    assert r.returncode == 0, "every invariant held but the exit code says otherwise"
    assert len(s["faults"]) == kinds, [f["fault"] for f in s["faults"]]
    for row in s["faults"]:
        assert row["runs"] == runs // kinds, row
        assert set(row["failures"]) <= KNOWN_RESULTS, row
        share = row["success"] + sum(row["failures"].values())
        assert abs(share - 1.0) < 1e-9, row
        assert row["min_leg_clearance_m"] > 0.0, row
        if row["docking_possible"]:
            assert row["success"] == 1.0, row
        else:
            assert row["success"] == 0.0, row
    # The table form names the invariants; bad input is exit 2.
    t = subprocess.run([shelfdock, "eval", "faults", "--runs", "1"], cwd=source,
                       capture_output=True, text=True)
    assert t.returncode == 0 and "leg contacts 0" in t.stdout, t.stdout + t.stderr
    b = subprocess.run([shelfdock, "eval", "faults", "--runs", "0"], cwd=source,
                       capture_output=True, text=True)
    assert b.returncode == 2 and "--runs" in b.stderr, b.stderr
    print(f"eval faults: {runs} runs, invariants hold")


if __name__ == "__main__":
    main()
