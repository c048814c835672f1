#!/usr/bin/env python3
"""Fitted leg centres against the simulated truth, by returns per leg.

Reads the scenes `shelfdock eval-layouts --dump-failures DIR --dump-all` wrote (each scan with its
truth and the `detect` command that reproduces it), runs each scan through the Python module with
`explain=True` and, for every hypothesis of the target's own model whose legs all lie within
`--match` of distinct true corners, compares each fitted leg with its corner: the error along the
leg's beam and across it, grouped by the leg's returns (scan points within 35 mm of the fitted
centre) and the scene's range noise, beside the bound sigma / sqrt(returns) that no fit of those
returns can beat (README, "The close models"). Also the fitted distance between legs along the
model's width and length against the true one. Then, for the two close models (1075x883 and
1080x856), how often any decision could tell them apart: for each scene whose first detection
stands at the target's place, the legs it used, each with the error std measured above for its
count of returns, are d apart (Mahalanobis, the other model's pose fitted to the true legs) from
the other model; an ideal decision confuses them with probability Phi(-d / 2). The sum over the
scenes, beside the confusions the detector made.

usage: leg_errors.py DIR [--models config/models.yaml] [--params FILE] [--module-dir build/python]
                         [--match 0.06] [--json OUT]
"""
import argparse
import glob
import json
import math
import os
import re
import sys
from collections import defaultdict

import numpy as np
import yaml


def corners(model, shelf):
    """The four leg centres of `shelf` (x, y, yaw) in its frame's order: +L/2+W/2, +L/2-W/2, ..."""
    half_l, half_w = 0.5 * model["length"], 0.5 * model["width"]
    c, s = math.cos(shelf["yaw"]), math.sin(shelf["yaw"])
    return [np.array([shelf["x"] + c * u - s * v, shelf["y"] + s * u + c * v])
            for u, v in [(half_l, half_w), (half_l, -half_w), (-half_l, -half_w), (-half_l, half_w)]]


def read_model_sizes(models_file):
    """Each shelf model of a models YAML (config/models.yaml) by name: its length and width."""
    with open(models_file) as f:
        return {m["name"]: m for m in yaml.safe_load(f)["models"]}


def scan_points(scan):
    ranges = np.array([math.nan if r is None else r for r in scan["ranges"]], dtype=float)
    angles = scan["angle_min"] + np.arange(len(ranges)) * scan["angle_increment"]
    return ranges, np.stack([ranges * np.cos(angles), ranges * np.sin(angles)], axis=1)


def measure(dump_dir, detector, model_sizes, match_m):
    """Per leg: (noise sigma, returns, along error, across error, range); per edge: (kind, error)."""
    legs, edges = [], []
    for truth_file in sorted(glob.glob(os.path.join(dump_dir, "*.truth.json"))):
        truth = json.load(open(truth_file))
        target = truth.get("target")
        if not target or not truth.get("findable"):
            continue
        points, out = detect_scene(truth_file, truth, detector, True)
        true_corners = corners(model_sizes[target["model"]], target)
        for h in out["hypotheses"]:
            if h["model"] != target["model"] or h["verdict"] not in ("returned", "model"):
                continue
            fitted = [np.array(leg) for leg in h["legs"]]
            which = match_corners(fitted, true_corners, match_m)
            if which is None:
                continue
            for leg, k in zip(fitted, which):
                err = leg - true_corners[k]
                view = true_corners[k] / np.linalg.norm(true_corners[k])
                returns = returns_near(points, leg)
                legs.append((truth["noise_sigma_m"], returns, float(err @ view),
                             float(view[0] * err[1] - view[1] * err[0]),
                             float(np.linalg.norm(true_corners[k]))))
            for a in range(len(which)):
                for b in range(a + 1, len(which)):
                    ka, kb = which[a], which[b]
                    if (ka - kb) % 2 == 0:
                        continue  # a diagonal
                    kind = "width" if {ka, kb} in ({0, 1}, {2, 3}) else "length"
                    edges.append((kind, float(np.linalg.norm(fitted[a] - fitted[b]) -
                                              np.linalg.norm(true_corners[ka] - true_corners[kb]))))
            break  # one hypothesis per scene: the first of the target's model that matches
    return legs, edges


CLOSE_MODELS = ("t1-rect-1075x883", "t1-rect-1080x856")


def detect_scene(truth_file, truth, detector, explain):
    """A dumped scene's points and the detector's output on them (`truth`: its truth file, read)."""
    scan = json.load(open(truth_file.replace(".truth.json", ".scan.json")))
    preset = re.search(r"--preset ([-0-9.e]+),([-0-9.e]+),([-0-9.e]+)", truth["detect"])
    ranges, points = scan_points(scan)
    out = detector.detect(ranges, scan["angle_min"], scan["angle_increment"],
                          tuple(float(v) for v in preset.groups()) if preset else None,
                          scan["range_min"], scan["range_max"], explain)
    return points, out


def match_corners(fitted, true_corners, match_m):
    """The true corner each fitted leg stands on (within match_m), or None when a leg stands on
    none or two legs on the same one."""
    which = []
    for leg in fitted:
        d = [np.linalg.norm(leg - c) for c in true_corners]
        which.append(int(np.argmin(d)) if min(d) <= match_m else -1)
    return None if -1 in which or len(set(which)) != len(which) else which


def returns_near(points, leg):
    """The scan points within 35 mm of a fitted leg centre: the returns it was fitted to."""
    return int(np.sum(np.linalg.norm(points - leg, axis=1) < 0.035))


def other_model_distance2(model, legs, sigmas, shelf):
    """Squared Mahalanobis distance from the true legs `legs` (corner index, position) to the
    corners of `model` at the pose that fits them best (Gauss-Newton from the true pose);
    `sigmas`: each leg's (along, across) std."""
    pose = np.array([shelf["x"], shelf["y"], shelf["yaw"]])

    def residuals(p):
        c = corners(model, {"x": p[0], "y": p[1], "yaw": p[2]})
        r = []
        for (k, q), (s_along, s_across) in zip(legs, sigmas):
            view = q / np.linalg.norm(q)
            e = c[k] - q
            r += [float(e @ view) / s_along, float(view[0] * e[1] - view[1] * e[0]) / s_across]
        return np.array(r)

    for _ in range(10):
        r0 = residuals(pose)
        jac = np.stack([(residuals(pose + 1e-6 * np.eye(3)[i]) - r0) / 1e-6 for i in range(3)],
                       axis=1)
        pose = pose + np.linalg.lstsq(jac, -r0, rcond=None)[0]
    return float(residuals(pose) @ residuals(pose))


def ideal_decision(dump_dir, detector, model_sizes, rows, match_m):
    """(scenes, expected confusions of an ideal decision, the detector's confusions) over the
    scenes with a close-model target whose first detection stands within 0.05 m of it."""
    def leg_sigma(noise, returns):
        """The measured (along, across) std of legs with this many returns at this noise, else of
        the nearest count measured at it, else sigma / sqrt(returns) both ways."""
        same = [r for r in rows if r["noise_sigma_m"] == noise]
        if not same:
            return noise / math.sqrt(returns), noise / math.sqrt(returns)
        r = min(same, key=lambda r: abs(r["returns"] - returns))
        return r["along_std_m"], r["across_std_m"]

    scenes, expected, observed = 0, 0.0, 0
    for truth_file in sorted(glob.glob(os.path.join(dump_dir, "*.truth.json"))):
        truth = json.load(open(truth_file))
        target = truth.get("target")
        if not target or not truth.get("findable") or target["model"] not in CLOSE_MODELS:
            continue
        points, out = detect_scene(truth_file, truth, detector, False)
        if not out["detections"]:
            continue
        first = out["detections"][0]
        if math.hypot(first["x"] - target["x"], first["y"] - target["y"]) > 0.05:
            continue
        true_corners = corners(model_sizes[target["model"]], target)
        fitted = [np.array(leg) for leg in first["legs"]]
        which = match_corners(fitted, true_corners, match_m)
        if which is None:
            continue
        legs = [(k, true_corners[k]) for k in which]
        sigmas = [leg_sigma(truth["noise_sigma_m"], max(1, returns_near(points, leg)))
                  for leg in fitted]
        other = CLOSE_MODELS[1] if target["model"] == CLOSE_MODELS[0] else CLOSE_MODELS[0]
        d2 = other_model_distance2(model_sizes[other], legs, sigmas, target)
        scenes += 1
        expected += 0.5 * math.erfc(math.sqrt(d2) / 2 / math.sqrt(2))
        observed += first["model"] != target["model"]
    return scenes, expected, observed


def summarise(legs, edges, min_legs=20):
    rows = []
    groups = defaultdict(list)
    for sigma, n, along, across, _ in legs:
        groups[(sigma, n)].append((along, across))
    for (sigma, n), errs in sorted(groups.items()):
        # No return near the fitted centre: a leg placed by its blend's bearing, not its returns.
        if len(errs) < min_legs or n == 0:
            continue
        e = np.array(errs)
        rows.append({"noise_sigma_m": sigma, "returns": n, "legs": len(e),
                     "along_mean_m": float(e[:, 0].mean()), "along_std_m": float(e[:, 0].std()),
                     "bound_m": sigma / math.sqrt(n), "across_std_m": float(e[:, 1].std())})
    edge_rows = []
    for kind in ("width", "length"):
        e = np.array([d for k, d in edges if k == kind])
        if len(e):
            edge_rows.append({"edge": kind, "count": len(e), "mean_m": float(e.mean()),
                              "std_m": float(e.std())})
    return rows, edge_rows


def fail(message):
    """Bad input: the message on stderr, exit 2 (as the CLI does)."""
    print(f"leg_errors.py: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dump_dir")
    parser.add_argument("--models", default="config/models.yaml")
    parser.add_argument("--params", default=None)
    parser.add_argument("--module-dir", default="build/python")
    parser.add_argument("--match", type=float, default=0.06,
                        help="a fitted leg within this of a true corner is that corner's [m]")
    parser.add_argument("--json", default=None, help="also write the tables here")
    args = parser.parse_args()
    if not glob.glob(os.path.join(args.dump_dir, "*.truth.json")):
        fail(f"{args.dump_dir}: no *.truth.json scenes (write them with eval-layouts "
             "--dump-failures DIR --dump-all)")
    if not os.path.isfile(args.models):
        fail(f"{args.models}: no such models file (--models)")
    sys.path.insert(0, args.module_dir)
    import shelfdock  # noqa: E402  (the built module, found through --module-dir)

    detector = shelfdock.Detector(args.models, args.params)
    model_sizes = read_model_sizes(args.models)
    legs, edges = measure(args.dump_dir, detector, model_sizes, args.match)
    rows, edge_rows = summarise(legs, edges)
    print("noise  returns  legs  along mean / std [mm]  sigma/sqrt(n) [mm]  ratio  across std [mm]")
    for r in rows:
        print("%4.0f mm %6d %6d %10.1f / %4.1f %14.1f %12.2f %10.1f" % (
            1e3 * r["noise_sigma_m"], r["returns"], r["legs"], 1e3 * r["along_mean_m"],
            1e3 * r["along_std_m"], 1e3 * r["bound_m"], r["along_std_m"] / r["bound_m"],
            1e3 * r["across_std_m"]))
    for e in edge_rows:
        print("%s edges: %d, fitted minus true: mean %+.1f mm, std %.1f mm" % (
            e["edge"], e["count"], 1e3 * e["mean_m"], 1e3 * e["std_m"]))
    scenes, expected, observed = ideal_decision(args.dump_dir, detector, model_sizes, rows,
                                                args.match)
    print("%s / %s at the target's place: %d scenes, an ideal decision on their legs confuses "
          "%.1f, the detector %d" % (*CLOSE_MODELS, scenes, expected, observed))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"legs": rows, "edges": edge_rows,
                       "close_models": {"scenes": scenes, "ideal_confusions": expected,
                                        "confusions": observed}}, f, indent=1)


if __name__ == "__main__":
    main()
