"""The Python module against the CLI (same scan, same result) and against simulated truth."""
import json
import math
import re
import subprocess

import numpy as np
import pytest

import shelfdock

# Single-scan accuracy at 2.5 m with margin for any one scan (README: p95 6.7 mm / 7.7 mrad over
# 0.5-3.5 m), as in tests/apps/cli_simulate_detect_test.py.
TOL_M = 0.020
TOL_RAD = 0.020


def cli_detect(cli, models, scan_file, *extra):
    out = subprocess.run([cli, "detect", "--models", str(models), "--scan", str(scan_file), *extra],
                         check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.strip()]


def module_detect(detector, scan, **kw):
    return detector.detect(np.array([math.nan if r is None else r for r in scan["ranges"]]),
                           scan["angle_min"], scan["angle_increment"],
                           range_min=scan["range_min"], range_max=scan["range_max"], **kw)


@pytest.fixture(scope="module")
def simulated(cli, source_dir, tmp_path_factory):
    """Three scans of the paper's scenario from 2.5 m, with the true shelf pose per scan."""
    work = tmp_path_factory.mktemp("sim")
    scans, truth = work / "paper.jsonl", work / "truth.json"
    subprocess.run([cli, "simulate", "--scenario",
                    str(source_dir / "config/scenarios/paper_docking.yaml"), "--pose",
                    "2.5,2.0,0.0", "--seed", "5", "--count", "3", "--out", str(scans), "--truth",
                    str(truth)], check=True, capture_output=True)
    doc = json.loads(truth.read_text())
    per_scan = doc["scans"] if isinstance(doc, dict) else doc
    lines = [json.loads(line) for line in scans.read_text().splitlines() if line.strip()]
    return scans, lines, [s["shelves"][0] for s in per_scan]


def test_same_result_as_cli(cli, models, simulated):
    scan_file, scans, truth = simulated
    preset = truth[0]["preset"]
    preset_arg = f"{preset['x']},{preset['y']},{preset['yaw']}"
    detector = shelfdock.Detector(models=str(models))
    for extra, kw in [((), {}),
                      (("--preset", preset_arg),
                       {"preset": (preset["x"], preset["y"], preset["yaw"])}),
                      (("--explain",), {"explain": True})]:
        expected = cli_detect(cli, models, scan_file, *extra)
        got = [module_detect(detector, s, **kw) for s in scans]
        assert got == expected, f"module and CLI differ with {extra}"
        assert all(r["detections"] for r in got)


def test_finds_the_true_shelf(models, simulated):
    _, scans, truth = simulated
    detector = shelfdock.Detector(models=models, params=None)  # a pathlib.Path works too
    for scan, t in zip(scans, truth):
        p = t["preset"]
        result = module_detect(detector, scan, preset=(p["x"], p["y"], p["yaw"]))
        d = result["detections"][0]
        assert d["model"] == t["model"]
        assert math.hypot(d["x"] - t["x"], d["y"] - t["y"]) <= TOL_M
        assert abs(math.remainder(d["yaw"] - t["yaw"], math.pi)) <= TOL_RAD
        assert len(d["covariance"]) == 3 and d["legs_used"] >= 3


def test_only_the_models_the_map_names(models, simulated):
    """only=[name]: the detector looks for that model alone (the map names the shelf's model):
    the paper scenario's shelf is found as its own model and, named as another, not at all."""
    _, scans, truth = simulated
    own = shelfdock.Detector(models=models, only=[truth[0]["model"]])
    assert own.models == [truth[0]["model"]]
    other = next(m for m in shelfdock.Detector(models=models).models if m != truth[0]["model"])
    elsewhere = shelfdock.Detector(models=models, only=[other])
    for scan, t in zip(scans, truth):
        p = t["preset"]
        d = module_detect(own, scan, preset=(p["x"], p["y"], p["yaw"]))["detections"][0]
        assert d["model"] == t["model"]
        assert math.hypot(d["x"] - t["x"], d["y"] - t["y"]) <= TOL_M
        forced = module_detect(elsewhere, scan, preset=(p["x"], p["y"], p["yaw"]))["detections"]
        assert not any(math.hypot(x["x"] - t["x"], x["y"] - t["y"]) <= 0.05 for x in forced), forced
    with pytest.raises(shelfdock.InputError, match="only: no model 'no-such-model'"):
        shelfdock.Detector(models=models, only=["no-such-model"])


def test_params_file_and_array_types(models, source_dir, simulated):
    _, scans, _ = simulated
    a = shelfdock.Detector(models=str(models), params=str(source_dir / "config/detector.yaml"))
    b = shelfdock.Detector(models=str(models))
    assert b.models == re.findall(r"name:\s*(\S+)", models.read_text())
    scan = scans[0]
    ranges64 = np.array([math.nan if r is None else r for r in scan["ranges"]])
    # float32 and plain lists are converted; the float32 result is a detection all the same.
    r32 = a.detect(ranges64.astype(np.float32), scan["angle_min"], scan["angle_increment"])
    rlist = b.detect(list(ranges64), scan["angle_min"], scan["angle_increment"])
    r64 = b.detect(ranges64, scan["angle_min"], scan["angle_increment"])
    assert rlist == r64
    assert r32["detections"] and r64["detections"]


def test_empty_and_invalid_scans(models):
    detector = shelfdock.Detector(models=str(models))
    for ranges in [np.array([]), np.full(811, np.nan), np.array([1.0])]:
        result = detector.detect(ranges, -2.356, 0.0058)
        assert result["detections"] == []
        assert result["stats"]["hypotheses"] == 0


def test_bad_input_names_the_argument(models, tmp_path):
    with pytest.raises(shelfdock.InputError, match="missing.yaml"):
        shelfdock.Detector(models=str(tmp_path / "missing.yaml"))
    bad = tmp_path / "bad_params.yaml"
    bad.write_text("preprocess:\n  cluster_gap_m: banana\n")
    with pytest.raises(ValueError, match="cluster_gap_m"):
        shelfdock.Detector(models=str(models), params=str(bad))
    detector = shelfdock.Detector(models=str(models))
    with pytest.raises(ValueError, match="ranges"):
        detector.detect(np.zeros((2, 3)), 0.0, 0.01)
    with pytest.raises(ValueError, match="angle_increment"):
        detector.detect(np.ones(10), 0.0, 0.0)
    with pytest.raises(ValueError, match="preset"):
        detector.detect(np.ones(10), 0.0, 0.01, preset=(0.0, math.nan, 0.0))
