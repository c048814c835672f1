#!/usr/bin/env python3
"""`shelfdock eval paper --quick` and `shelfdock eval peers --quick` through the CLI: every figure
of the paper's experiments is present and finite in the JSON and the table, the HTML page is
self-contained, the simulated figures stand against the truth within stated tolerances, and bad
input exits 2. Usage: eval_paper_cli_test.py SHELFDOCK SOURCE WORK
"""
import json
import math
import sys
import tempfile
from pathlib import Path

from cli_test_util import expect_bad_input, run


def finite(value, where):
    assert isinstance(value, (int, float)) and math.isfinite(value), f"{where}: {value!r}"
    return value


def check_paper(doc, stdout):
    models = [p["model"] for p in doc["paper"]["table1"]]
    assert [s["sensor"] for s in doc["sensors"]] == ["nominal", "harsh"]
    for s in doc["sensors"]:
        name = s["sensor"]
        assert [r["model"] for r in s["table1"]] == models, name
        for r in s["table1"]:
            for key in ("mean_length_m", "mean_width_m", "length_error", "width_error",
                        "single_scan_p95_error"):
                finite(r[key], f"{name} {r['model']} {key}")
            assert r["recognitions"] >= 1, f"{name} {r['model']}: nothing recognised"
        for kind in ("detected", "detected_10", "fused", "detected_map", "fused_map"):
            f = s["fluctuation"][kind]
            assert f["runs"] >= 1, f"{name} {kind}: no run with 2 recognitions"
            for group in ("range", "stddev"):
                for axis in ("x", "y", "yaw"):
                    for q in ("median", "worst"):
                        finite(f[group][axis][q], f"{name} {kind} {group} {axis} {q}")
        e = s["docking_error"]
        for axis in ("x", "y", "yaw"):
            for q in ("p95", "max"):
                finite(e[axis][q], f"{name} docking error {axis} {q}")
        finite(e["within_10mm_14mrad"], f"{name} within")
        t = s["time"]
        for key in ("continuous_s", "stop_and_recognise_s", "saving", "perfect_knowledge_s"):
            finite(t[key], f"{name} time {key}")
        assert len(s["final_errors"]) == t["runs"], name
        assert len(s["trace"]) >= 2, f"{name}: no fluctuation trace"

    nominal = doc["sensors"][0]
    # Against the simulated truth, nominal sensor. Table 1: the fitted size within 1 % of the
    # model at 0.5 m (the perception tests assert the same on 30 scans per model).
    for r in nominal["table1"]:
        assert r["length_error"] <= 0.01 and r["width_error"] <= 0.01, r
    # Every quick docking succeeds, within the paper's 10 mm / 14 mrad before the code check.
    assert nominal["time"]["continuous_successes"] == nominal["time"]["runs"], nominal["time"]
    assert nominal["docking_error"]["within_10mm_14mrad"] == 1.0, nominal["docking_error"]
    # The continuous method is faster than stop-and-recognise and slower than perfect knowledge.
    t = nominal["time"]
    assert t["perfect_knowledge_s"] < t["continuous_s"] < t["stop_and_recognise_s"], t

    for heading in ("Table 1, fitted size", "Fig. 7, fluctuation", "Fig. 8, docking error",
                    "**Time**"):
        assert heading in stdout, f"no '{heading}' in the table"
    assert "n/a" not in stdout, stdout


def check_peers(doc, stdout):
    methods = {"shelfdock", "centroid-only", "corner-finding"}
    # The ICP peer is in only when the build has SHELFDOCK_WITH_PCL; otherwise the output says
    # how to build it.
    icp = doc["icp"]
    if icp["built"]:
        methods.add("icp-pcl")
        assert len(icp["sets"]) == 7, icp
        for row in icp["sets"]:
            finite(row["time_ratio"], f"{row['set']} ICP time ratio")
        assert "target >= 20x" in stdout, stdout
    else:
        assert icp["sets"] == [], icp
        assert "-DSHELFDOCK_WITH_PCL=ON" in stdout, stdout
    sets = {}
    for row in doc["accuracy"]:
        sets.setdefault(row["set"], set()).add(row["method"])
        assert row["scenes"] > 0, row
        finite(row["time_s"]["p50"], f"{row['set']} {row['method']} time")
    assert len(sets) == 7, sets  # paper set-up, sweep, rows, 4 clutter levels
    for name, got in sets.items():
        assert got == methods, f"{name}: {got}"
    for row in doc["search"]:
        # Past a few candidates the pruning pays: the issue asks >= 10x fewer checks at 50
        # clusters; with 10 or more candidates it is already past 10x (about 50x measured).
        if row["mean_candidates"] >= 10:
            assert row["mean_exhaustive_checks"] >= 10 * row["mean_pruned_checks"], row
    assert "Leg search work" in stdout, stdout


def main():
    shelfdock, source = sys.argv[1], Path(sys.argv[2])
    with tempfile.TemporaryDirectory(prefix="eval_paper_") as tmp:
        work = Path(tmp)
        report, page = work / "paper.json", work / "paper.html"
        r = run(shelfdock, ["eval", "paper", "--quick", "--json", str(report), "--html",
                            str(page)], source)
        assert r.returncode == 0, f"eval paper: exit {r.returncode}\n{r.stdout}{r.stderr}"
        check_paper(json.loads(report.read_text()), r.stdout)
        html = page.read_text()
        assert "__SHELFDOCK_DATA__" not in html and '"sensors"' in html, "data not embedded"
        for link in ("http://", "https://"):
            # The SVG namespace URI is an identifier, not a fetch.
            for line in html.splitlines():
                if link in line:
                    assert "http://www.w3.org/2000/svg" in line, f"network reference: {line}"
        print("eval paper --quick: every figure present and finite")

        peers = work / "peers.json"
        r = run(shelfdock, ["eval", "peers", "--quick", "--json", str(peers)], source)
        assert r.returncode == 0, f"eval peers: exit {r.returncode}\n{r.stdout}{r.stderr}"
        check_peers(json.loads(peers.read_text()), r.stdout)
        print("eval peers --quick: every method on every scene set")

    expect_bad_input(shelfdock, source, ["eval", "paper", "--runs", "1"], "--runs")
    expect_bad_input(shelfdock, source, ["eval", "paper", "--models", "tests/data/missing.yaml"],
                     "missing.yaml")
    expect_bad_input(shelfdock, source, ["eval", "peers", "--params",
                                         "tests/data/detector_unknown_key.yaml"],
                     "detector_unknown_key.yaml")
    expect_bad_input(shelfdock, source, ["eval"], "subcommand is required")


if __name__ == "__main__":
    main()
