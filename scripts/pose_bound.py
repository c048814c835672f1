#!/usr/bin/env python3
"""The centre and heading error no estimator could beat on the same returns (Cramer-Rao bound).

Reads the scenes `shelfdock eval-layouts --dump-failures DIR --dump-all` wrote (each scan with its
truth), or those `scripts/independent_scenes.py --dump DIR --dump-all` wrote (the standoff there
the target centre's distance, no count of the legs a detection used). For every scene whose first
detection is the target (its model, centre within 50 mm), at the range noise and standoff asked
for, it finds the returns that hit the target's legs as they
truly stand (the beam's first hit on a leg section, ray cast from the sensor, within
`--hit-sigmas` range-noise sigmas of the measured range; beams hidden by something nearer or
blended are left out) and builds the Fisher information of the shelf's pose (x, y, yaw) from:
  - each such return's range, noise sigma the scene's (the derivative of the hit range by the pose,
    by central differences);
  - optimistically, each leg's two outline edges as bearings, one beam's spacing / sqrt(12) each
    (the scan brackets an edge between two beams), whether or not the scan shows the edge.
The inverse is the smallest covariance an unbiased estimator of the pose can reach from those
measurements. The script draws centre and heading errors from each scene's bound and reports the
pooled p50 / p95, beside the detector's own errors on the same scenes (the `first` detection of
each truth file). Leg positions are taken as exact (a real shelf's legs are off by millimetres,
which only adds), so the bound is a floor for any leg-based detector on these scans.

usage: pose_bound.py DIR [--models config/models.yaml] [--noise 0.01] [--max-standoff 3.5]
                         [--hit-sigmas 3] [--draws 400] [--seed 1] [--ranges-only]
"""
import argparse
import glob
import json
import math
import os
import sys
from collections import defaultdict

import numpy as np
import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from leg_errors import corners  # noqa: E402  (the shelf's leg centres, one definition)


def leg_centres(model, pose):
    """The four leg centres (lidar frame) of a shelf of `model` at pose (x, y, yaw)."""
    return corners(model, {"x": pose[0], "y": pose[1], "yaw": pose[2]})


def hit_range(ux, uy, centre, yaw, leg):
    """Range at which the beam (ux, uy) from the origin first hits a leg section, or None."""
    cx, cy = centre
    if leg["shape"] == "circle":
        r = 0.5 * leg["width"]
        b = ux * cx + uy * cy
        e = ux * cy - uy * cx
        if abs(e) >= r:
            return None
        t = b - math.sqrt(r * r - e * e)
        return t if t > 0 else None
    # Box: slab test in the leg's axes (square to the shelf's frame).
    c, s = math.cos(yaw), math.sin(yaw)
    o = (-(c * cx + s * cy), -(-s * cx + c * cy))
    d = (c * ux + s * uy, -s * ux + c * uy)
    h = (0.5 * leg["length"], 0.5 * leg["width"])
    t_in, t_out = -1e9, 1e9
    for k in range(2):
        if abs(d[k]) < 1e-12:
            if abs(o[k]) > h[k]:
                return None
            continue
        ta, tb = (-h[k] - o[k]) / d[k], (h[k] - o[k]) / d[k]
        t_in, t_out = max(t_in, min(ta, tb)), min(t_out, max(ta, tb))
    return t_in if t_in <= t_out and t_in > 0 else None


def first_hit(ux, uy, model, pose):
    """The nearest hit of the beam on any of the shelf's legs: (range, leg index) or None."""
    best = None
    for k, centre in enumerate(leg_centres(model, pose)):
        t = hit_range(ux, uy, centre, pose[2], model["leg"])
        if t is not None and (best is None or t < best[0]):
            best = (t, k)
    return best


def outline(centre, yaw, leg):
    """The bearings of a leg section's two outline edges seen from the origin."""
    cx, cy = centre
    mid = math.atan2(cy, cx)
    if leg["shape"] == "circle":
        half = math.asin(min(1.0, 0.5 * leg["width"] / math.hypot(cx, cy)))
        return mid - half, mid + half
    c, s = math.cos(yaw), math.sin(yaw)
    rel = []
    for sx in (-0.5 * leg["length"], 0.5 * leg["length"]):
        for sy in (-0.5 * leg["width"], 0.5 * leg["width"]):
            px, py = cx + c * sx - s * sy, cy + s * sx + c * sy
            rel.append(math.remainder(math.atan2(py, px) - mid, 2 * math.pi))
    return mid + min(rel), mid + max(rel)


def target_hits(scan, truth, model, hit_sigmas):
    """The scan's returns on the target's legs as they truly stand: (beam index, ux, uy, leg) for
    each beam whose range lies within `hit_sigmas` range-noise sigmas of its first hit on a leg
    (beams hidden by something nearer or blended are left out), in beam order."""
    t = truth["target"]
    pose = np.array([t["x"], t["y"], t["yaw"]])
    sigma = truth["noise_sigma_m"]
    a0, da = scan["angle_min"], scan["angle_increment"]
    hits = []
    for i, r in enumerate(scan["ranges"]):
        if r is None or not math.isfinite(r):
            continue
        a = a0 + i * da
        ux, uy = math.cos(a), math.sin(a)
        hit = first_hit(ux, uy, model, pose)
        if hit is not None and abs(r - hit[0]) <= hit_sigmas * sigma:
            hits.append((i, ux, uy, hit[1]))
    return hits


def scene_bound(scan, truth, model, hit_sigmas, outline_edges=True):
    """Fisher information of the target's pose from its scan; None when no return hits its legs."""
    t = truth["target"]
    pose = np.array([t["x"], t["y"], t["yaw"]])
    sigma = truth["noise_sigma_m"]
    da = scan["angle_increment"]
    info = np.zeros((3, 3))
    eps = np.array([1e-6, 1e-6, 1e-6])
    legs_hit = set()
    for _, ux, uy, leg in target_hits(scan, truth, model, hit_sigmas):
        grad = np.zeros(3)
        for k in range(3):
            step = np.zeros(3)
            step[k] = eps[k]
            up, down = first_hit(ux, uy, model, pose + step), first_hit(ux, uy, model, pose - step)
            if up is None or down is None or up[1] != leg or down[1] != leg:
                grad = None
                break
            grad[k] = (up[0] - down[0]) / (2 * eps[k])
        if grad is None:
            continue
        info += np.outer(grad, grad) / sigma**2
        legs_hit.add(leg)
    if not legs_hit:
        return None
    if not outline_edges:
        return info
    # Each leg with a return: its two outline edges as bearings, one beam's spacing / sqrt(12).
    sigma_b = abs(da) / math.sqrt(12.0)
    for k in legs_hit:
        for side in (0, 1):
            grad = np.zeros(3)
            for j in range(3):
                step = np.zeros(3)
                step[j] = eps[j]
                up = outline(leg_centres(model, pose + step)[k], pose[2] + step[2], model["leg"])
                down = outline(leg_centres(model, pose - step)[k], pose[2] - step[2], model["leg"])
                grad[j] = math.remainder(up[side] - down[side], 2 * math.pi) / (2 * eps[j])
            info += np.outer(grad, grad) / sigma_b**2
    return info


def as_layout_truth(truth):
    """A scene's truth in `shelfdock eval-layouts --dump-failures` terms: that file as it is, or
    one scripts/independent_scenes.py --dump --dump-all wrote (its target an index into its
    shelves, its outcome "right" / "wrong_model", no count of the legs a detection used; the
    standoff is the target centre's distance from the sensor, as that script's own table has it).
    {} for a scene without a findable target or a detection."""
    if "cls" not in truth or "shelves" not in truth:
        return truth
    target = truth.get("target")
    if target is None or not truth.get("findable") or not truth.get("detections"):
        return {}
    shelf, first = truth["shelves"][target], truth["detections"][0]
    outcome = {"right": "right-first", "wrong_model": "wrong-first"}.get(truth["outcome"])
    return dict(target=dict(model=shelf["model"], x=shelf["x"], y=shelf["y"], yaw=shelf["yaw"]),
                first=dict(model=first["model"], x=first["x"], y=first["y"], yaw=first["yaw"],
                           legs_used=None),
                outcome=outcome, noise_sigma_m=truth["noise"], lidar=truth["sensor"]["name"],
                standoff_m=math.hypot(shelf["x"], shelf["y"]))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--models", default=os.path.join(here, "..", "config", "models.yaml"))
    ap.add_argument("--noise", type=float, default=0.01, help="scenes of this range noise [m]")
    ap.add_argument("--max-standoff", type=float, default=3.5, help="[m]")
    ap.add_argument("--hit-sigmas", type=float, default=3.0)
    ap.add_argument("--draws", type=int, default=400, help="error draws per scene")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--ranges-only", action="store_true",
                    help="the returns' ranges alone, without the outline edges' bearings")
    args = ap.parse_args()
    models = {m["name"]: m for m in yaml.safe_load(open(args.models))["models"]}
    rng = np.random.default_rng(args.seed)
    measured = defaultdict(list)  # key -> [(centre error, heading error)]
    drawn = defaultdict(list)
    skipped = 0
    for path in sorted(glob.glob(os.path.join(args.dir, "*.truth.json"))):
        truth = as_layout_truth(json.load(open(path)))
        if truth.get("outcome") != "right-first":
            continue
        if abs(truth["noise_sigma_m"] - args.noise) > 1e-9 or truth["standoff_m"] > args.max_standoff:
            continue
        scan = json.load(open(path.replace(".truth.json", ".scan.json")))
        target, first = truth["target"], truth["first"]
        model = models[target["model"]]
        info = scene_bound(scan, truth, model, args.hit_sigmas, not args.ranges_only)
        if info is None:
            skipped += 1
            continue
        try:
            cov = np.linalg.inv(info)
        except np.linalg.LinAlgError:
            skipped += 1
            continue
        cov = 0.5 * (cov + cov.T)
        w, v = np.linalg.eigh(cov)
        draws = rng.standard_normal((args.draws, 3)) * np.sqrt(np.maximum(w, 0.0)) @ v.T
        # The model's symmetry: a half turn, a quarter turn for a square one.
        period = math.pi / 2 if abs(model["length"] - model["width"]) < 1e-9 else math.pi
        dyaw = math.remainder(first["yaw"] - target["yaw"], period)
        err = (math.hypot(first["x"] - target["x"], first["y"] - target["y"]), abs(dyaw))
        band = f"{int(truth['standoff_m'])}-{int(truth['standoff_m']) + 1} m"
        legs = [f"{first['legs_used']} legs"] if first.get("legs_used") else []
        for key in ["all", truth["lidar"], band] + legs:
            measured[key].append(err)
            drawn[key].append(np.column_stack([np.hypot(draws[:, 0], draws[:, 1]),
                                               np.abs(draws[:, 2])]))
    print(f"scenes: right first, noise {args.noise * 1000:.0f} mm, standoff <= "
          f"{args.max_standoff} m ({skipped} skipped: no return on the target's legs)")
    print(f"{'':10s} {'n':>5s} | {'centre p50/p95 [mm]':>22s} {'bound':>12s} | "
          f"{'heading p50/p95 [mrad]':>24s} {'bound':>12s}")
    for key in sorted(measured, key=lambda k: (k != "all", k)):
        m = np.array(measured[key]) * 1000.0
        d = np.vstack(drawn[key]) * 1000.0
        print(f"{key:10s} {len(m):5d} | {np.percentile(m[:, 0], 50):10.1f} / "
              f"{np.percentile(m[:, 0], 95):4.1f}      {np.percentile(d[:, 0], 50):4.1f} / "
              f"{np.percentile(d[:, 0], 95):4.1f} | {np.percentile(m[:, 1], 50):12.1f} / "
              f"{np.percentile(m[:, 1], 95):4.1f}      {np.percentile(d[:, 1], 50):4.1f} / "
              f"{np.percentile(d[:, 1], 95):4.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
