#!/usr/bin/env python3
"""`simulate` -> `detect` through the CLI, against the simulator's ground truth.

simulate writes scans of the paper's docking scenario from 2.5 m and the true shelf pose in the
LiDAR frame; detect, given the scenario's preset (also from the truth file), must find the target
model within 20 mm and 20 mrad of the truth in every scan: the detector's single-scan accuracy at
this range with margin for any one scan. Usage: cli_simulate_detect_test.py SHELFDOCK SOURCE WORK
"""
import json
import math
import subprocess
import sys
from pathlib import Path

TOL_M = 0.020
TOL_RAD = 0.020
COUNT = 5


def main():
    shelfdock, source, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    scans, truth = work / "paper.jsonl", work / "paper.truth.json"
    subprocess.run([shelfdock, "simulate", "--scenario",
                    str(source / "config/scenarios/paper_docking.yaml"), "--pose", "2.5,2.0,0.0",
                    "--seed", "11", "--count", str(COUNT), "--out", str(scans), "--truth",
                    str(truth)], check=True, cwd=source)
    truth_doc = json.loads(truth.read_text())
    per_scan = truth_doc["scans"] if isinstance(truth_doc, dict) else truth_doc
    shelf = per_scan[0]["shelves"][0]
    preset = shelf["preset"]
    out = subprocess.run([shelfdock, "detect", "--models", str(source / "config/models.yaml"),
                          "--scan", str(scans), "--preset",
                          f"{preset['x']},{preset['y']},{preset['yaw']}"],
                         check=True, capture_output=True, text=True).stdout
    lines = [json.loads(l) for l in out.splitlines() if l.strip()]
    assert len(lines) == COUNT, f"{len(lines)} result lines for {COUNT} scans"
    for i, result in enumerate(lines):
        t = per_scan[i]["shelves"][0]
        assert result["detections"], f"scan {i}: no detection"
        d = result["detections"][0]
        assert d["model"] == t["model"], f"scan {i}: model {d['model']} != {t['model']}"
        err_xy = math.hypot(d["x"] - t["x"], d["y"] - t["y"])
        err_yaw = abs(math.remainder(d["yaw"] - t["yaw"], math.pi))  # heading modulo pi
        assert err_xy <= TOL_M, f"scan {i}: centre error {err_xy:.4f} m > {TOL_M}"
        assert err_yaw <= TOL_RAD, f"scan {i}: heading error {err_yaw:.4f} rad > {TOL_RAD}"
        print(f"scan {i}: centre error {err_xy * 1000:.1f} mm, heading {err_yaw * 1000:.1f} mrad")
    print(f"{COUNT} scans within {TOL_M} m / {TOL_RAD} rad of the simulator's truth")


if __name__ == "__main__":
    main()
