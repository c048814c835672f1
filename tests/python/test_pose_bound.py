"""scripts/pose_bound.py on the independent generator's scenes: the Cramer-Rao floor of the
shelf's centre and heading error.

The case (README, docs/detector_history.md) that the issue's centre p95 <= 5 mm at 10 mm noise
cannot be met rests on this script. It reads `eval-layouts` dumps and, through
`as_layout_truth`, those scripts/independent_scenes.py --dump --dump-all writes. Asserted: the
independent truth is read as the layout truth it stands for (target, first detection, outcome,
noise, sensor, standoff), and on 40 open scenes (seed 7) the floor holds for the detector: no
right-first scene's information is singular, and the detector's median centre and heading errors
are not below half the floor's (an estimator beating the bound would mean the script misreads the
scenes, e.g. the noise in the wrong unit).
"""
import glob
import json
import math
import os

import numpy as np
import pytest
import yaml


def test_independent_truth_reads_as_layout_truth(load_script):
    pb = load_script("pose_bound")
    truth = dict(cls="open", seed=1, index=3, findable=True, target=1, noise=0.02,
                 sensor=dict(name="tim571"), outcome="right",
                 shelves=[dict(model="a", x=9.0, y=9.0, yaw=0.0),
                          dict(model="t1-rect-1075x883", x=3.0, y=4.0, yaw=0.5)],
                 detections=[dict(model="t1-rect-1075x883", x=3.01, y=4.0, yaw=0.51,
                                  confidence=0.9)])
    got = pb.as_layout_truth(truth)
    assert got["target"] == dict(model="t1-rect-1075x883", x=3.0, y=4.0, yaw=0.5)
    assert got["first"]["x"] == 3.01 and got["first"]["yaw"] == 0.51
    assert got["first"]["legs_used"] is None
    assert got["outcome"] == "right-first" and got["noise_sigma_m"] == 0.02
    assert got["lidar"] == "tim571" and got["standoff_m"] == pytest.approx(5.0)
    assert pb.as_layout_truth(dict(truth, outcome="wrong_model"))["outcome"] == "wrong-first"
    assert pb.as_layout_truth(dict(truth, target=None)) == {}
    assert pb.as_layout_truth(dict(truth, detections=[])) == {}
    layout = dict(target=dict(model="m", x=1.0, y=0.0, yaw=0.0), outcome="right-first")
    assert pb.as_layout_truth(layout) is layout


def test_the_detector_does_not_beat_the_floor_on_independent_scenes(load_script, models, tmp_path):
    pytest.importorskip("shelfdock")
    gen, pb = load_script("independent_scenes"), load_script("pose_bound")
    gen.run(str(models), 7, 40, classes=["open"], jobs=1, dump=str(tmp_path), dump_all=True)
    sizes = {m["name"]: m for m in yaml.safe_load(open(models))["models"]}
    errors, floors = [], []
    for path in sorted(glob.glob(os.path.join(tmp_path, "*.truth.json"))):
        truth = pb.as_layout_truth(json.load(open(path)))
        if truth.get("outcome") != "right-first":
            continue
        scan = json.load(open(path.replace(".truth.json", ".scan.json")))
        model = sizes[truth["target"]["model"]]
        info = pb.scene_bound(scan, truth, model, 3.0)
        assert info is not None and np.linalg.matrix_rank(info) == 3, path
        cov = np.linalg.inv(info)
        floors.append((math.sqrt(cov[0, 0] + cov[1, 1]), math.sqrt(cov[2, 2])))
        t, f = truth["target"], truth["first"]
        period = math.pi / 2 if abs(model["length"] - model["width"]) < 1e-9 else math.pi
        errors.append((math.hypot(f["x"] - t["x"], f["y"] - t["y"]),
                       abs(math.remainder(f["yaw"] - t["yaw"], period))))
    assert len(errors) >= 25, len(errors)
    # sqrt(trace) of the centre block is the RMS of the bound's centre error; its median over
    # scenes, like the detector's median error, is of the order of a millimetre or two.
    errors, floors = np.array(errors), np.array(floors)
    print(np.median(errors, axis=0), np.median(floors, axis=0))
    assert np.median(errors[:, 0]) >= 0.5 * np.median(floors[:, 0])
    assert np.median(errors[:, 1]) >= 0.5 * np.median(floors[:, 1])
