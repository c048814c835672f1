#!/usr/bin/env python3
"""How often no detector could tell two close shelf models apart on the same returns.

The 1075x883 and 1080x856 models of Table 1 differ by 5 mm in length and 27 mm in width, the
same legs on both. Which of the two a scan shows is a test between two hypotheses whose poses are
free (nuisance parameters). For Gaussian range noise and the measurements linear in the
parameters over those few millimetres, the best test (the likelihood ratio, which a detector
choosing the model of lower chi-square on the legs' returns is) picks the wrong model with
probability Phi(-d / 2), d the Mahalanobis distance between the two models' sizes once the pose is
fitted away: d^2 = delta^T S delta, delta the size difference (dL, dW) and S the Schur complement
of the size block in the Fisher information of (x, y, yaw, L, W).

Reads the scenes `shelfdock eval-layouts --dump-failures DIR --dump-all` wrote (each scan with its
truth), or those `scripts/independent_scenes.py --dump DIR --dump-all` wrote (grouped by noise and
sensor only: its truth does not say how many legs a detection used). On the independent
generator the detector confuses fewer scenes than this floor expects (seeds 1 / 1001 / 2001, 200
per class: 25 / 41 / 32 against 41.9 / 49.0 / 45.9): its scans carry more than the floor's
assumptions grant (the stated noise, an outline edge known to a beam spacing / sqrt(12)), so
there the floor says only that its confusions are near what its scans hold. Much of that excess
is the bloom (a wide spot returns the leg on a beam whose centre misses it): such returns hide
the edge from the test above, and with `--past-bloom` it counts past them. Then, on seed 1001 at
92da2e5 (200 per class): open 1.4 expected against the detector's 1, but row / aisle /
against_wall / mixed_neighbours 1.5 / 1.9 / 1.9 / 1.1 against 6 / 6 / 7 / 4: beside neighbours
and walls the detector read less of its scans (thirty-sixth session, docs/detector_history.md,
where a leg placed by one bloomed edge chose the model). For every scene
whose target has such a twin and whose first detection stands at the target (centre within 50
mm, either model), the information comes from the returns that hit the target's legs as they
truly stand and from each hit leg's two outline edges as bearings, one beam
spacing / sqrt(12) each, as scripts/pose_bound.py builds it (the same optimism: every outline
edge counted, leg positions exact). The expected number of wrong models, the sum of the scenes'
probabilities, is a floor for any detector on these scans; beside it, how many the detector got
wrong (its `first` detection's model).

usage: model_choice_bound.py DIR [--models config/models.yaml] [--twin-within 0.05]
                                 [--hit-sigmas 3] [--edge-sigma-beams 0.29] [--all-edges]
                                 [--past-bloom]
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
from pose_bound import (as_layout_truth, first_hit, leg_centres, outline,  # noqa: E402
                        target_hits)  # one ray cast, one reading of either generator's truth


def sized(model, length, width):
    """`model` with its leg centres `length` x `width` apart (the same legs)."""
    out = dict(model)
    out["length"], out["width"] = length, width
    return out


def measurements(theta, model, beams, hit_legs):
    """Predicted hit ranges on `beams` ((ux, uy, leg)) and outline bearings of `hit_legs` for the
    parameters theta = (x, y, yaw, L, W); None where a beam no longer hits its leg."""
    m = sized(model, theta[3], theta[4])
    pose = theta[:3]
    out = []
    for ux, uy, leg in beams:
        hit = first_hit(ux, uy, m, pose)
        if hit is None or hit[1] != leg:
            return None
        out.append(hit[0])
    centres = leg_centres(m, pose)
    for k in sorted(hit_legs):
        out.extend(outline(centres[k], pose[2], m["leg"]))
    return np.array(out)


def scene_information(scan, truth, model, hit_sigmas, edge_sigma_beams, seen_edges=True,
                      past_bloom=False):
    """Fisher information of (x, y, yaw, L, W) from the scan's returns on the target's legs and
    their outline edges; None when no return hits them. With `seen_edges`, only an edge the scan
    shows counts: the beam just past the leg's outermost hit there returns from farther behind (a
    background or a blend with it), not from something nearer, nothing, or the leg's own next
    return; otherwise every hit leg's two edges count. With `past_bloom`, returns at the leg's
    range (within hit_sigmas of the outer hit's) on beams past it are its bloom (the spot
    catching the leg on a beam whose centre misses it): the edge counts when the first beam past
    them returns from farther behind."""
    t = truth["target"]
    pose = np.array([t["x"], t["y"], t["yaw"]])
    sigma = truth["noise_sigma_m"]
    da = scan["angle_increment"]
    ranges = scan["ranges"]
    hits = target_hits(scan, truth, model, hit_sigmas)
    if not hits:
        return None
    beams = [(ux, uy, leg) for _, ux, uy, leg in hits]
    hit_legs = {leg for _, _, _, leg in hits}

    def range_at(i):
        """Beam i's range, None where the scan has no such beam or it returned nothing."""
        r = ranges[i] if 0 <= i < len(ranges) else None
        return r if r is not None and math.isfinite(r) else None

    def shows_edge(outer, neighbour):
        step = neighbour - outer
        if past_bloom:
            while (r := range_at(neighbour)) is not None and \
                    abs(r - ranges[outer]) <= hit_sigmas * sigma:
                neighbour += step
        r = range_at(neighbour)
        return r is not None and r > ranges[outer] + hit_sigmas * sigma

    edge_weights = []
    outward = 1 if da > 0 else -1  # beam index step toward higher bearings
    for k in sorted(hit_legs):
        idx = [i for i, _, _, leg in hits if leg == k]
        low, high = (min(idx), max(idx)) if da > 0 else (max(idx), min(idx))
        for outer, neighbour in ((low, low - outward), (high, high + outward)):  # outline() order
            edge_weights.append(1.0 if not seen_edges or shows_edge(outer, neighbour) else 0.0)
    theta = np.array([*pose, model["length"], model["width"]])
    eps = 1e-6
    columns = []
    for k in range(5):
        step = np.zeros(5)
        step[k] = eps
        up = measurements(theta + step, model, beams, hit_legs)
        down = measurements(theta - step, model, beams, hit_legs)
        if up is None or down is None:
            return None
        d = up - down
        # Bearings wrap; ranges do not, and their differences stay far below pi.
        d = np.array([math.remainder(v, 2 * math.pi) for v in d])
        columns.append(d / (2 * eps))
    jac = np.column_stack(columns)
    edge_w = 1.0 / (edge_sigma_beams * da)**2 if edge_sigma_beams > 0 else 0.0
    weights = np.concatenate([np.full(len(beams), 1.0 / sigma**2),
                              edge_w * np.array(edge_weights)])
    return jac.T @ (weights[:, None] * jac)


def phi(x):
    return 0.5 * math.erfc(-x / math.sqrt(2.0))


def bound(dump_dir, models, twin_within=0.05, hit_sigmas=3.0, edge_sigma_beams=1.0 / math.sqrt(12.0),
          seen_edges=True, past_bloom=False):
    """Per group ("all", "<legs> legs, <noise> mm", each lidar): scenes, the floor's expected count
    of wrong models and the detector's, over the scenes of `dump_dir` whose target has a twin in
    `models` (name -> model) and whose first detection stands at the target. Also how many such
    scenes had no return on the target's legs (skipped)."""

    def twin(name):
        a = models[name]
        for other, b in models.items():
            if other != name and b["leg"] == a["leg"] and \
                    abs(a["length"] - b["length"]) <= twin_within and \
                    abs(a["width"] - b["width"]) <= twin_within:
                return b
        return None

    groups = defaultdict(lambda: {"scenes": 0, "expected": 0.0, "wrong": 0})
    skipped = 0
    for path in sorted(glob.glob(os.path.join(dump_dir, "*.truth.json"))):
        truth = as_layout_truth(json.load(open(path)))
        target, first = truth.get("target"), truth.get("first")
        if not target or not first or truth.get("outcome") not in ("right-first", "wrong-first"):
            continue
        other = twin(target["model"])
        if other is None or math.hypot(first["x"] - target["x"], first["y"] - target["y"]) > 0.05:
            continue
        if first["model"] not in (target["model"], other["name"]):
            continue
        model = models[target["model"]]
        scan = json.load(open(path.replace(".truth.json", ".scan.json")))
        info = scene_information(scan, truth, model, hit_sigmas, edge_sigma_beams, seen_edges,
                                 past_bloom)
        if info is None:
            skipped += 1
            continue
        try:
            schur = info[3:, 3:] - info[3:, :3] @ np.linalg.solve(info[:3, :3], info[:3, 3:])
        except np.linalg.LinAlgError:
            skipped += 1
            continue
        delta = np.array([other["length"] - model["length"], other["width"] - model["width"]])
        d = math.sqrt(max(0.0, float(delta @ schur @ delta)))
        prob = phi(-0.5 * d)
        legs = f"{first['legs_used']} legs, " if first.get("legs_used") is not None else ""
        band = f"{legs}{truth['noise_sigma_m'] * 1000:.0f} mm"
        for key in ("all", band, truth["lidar"]):
            g = groups[key]
            g["scenes"] += 1
            g["expected"] += prob
            g["wrong"] += first["model"] != target["model"]
    return dict(groups), skipped


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("dir")
    ap.add_argument("--models", default=os.path.join(here, "..", "config", "models.yaml"))
    ap.add_argument("--twin-within", type=float, default=0.05,
                    help="[m] another model whose length and width are both this close is a twin")
    ap.add_argument("--hit-sigmas", type=float, default=3.0)
    ap.add_argument("--edge-sigma-beams", type=float, default=1.0 / math.sqrt(12.0),
                    help="std of an outline edge's bearing in beam spacings (0: ranges alone)")
    ap.add_argument("--all-edges", action="store_true",
                    help="count both outline edges of every hit leg, shown by the scan or not")
    ap.add_argument("--past-bloom", action="store_true",
                    help="an edge counts where the first beam past the leg's bloom returns (those\n"
                         "at its range past its outermost hit) returns from farther behind")
    args = ap.parse_args()
    models = {m["name"]: m for m in yaml.safe_load(open(args.models))["models"]}
    groups, skipped = bound(args.dir, models, args.twin_within, args.hit_sigmas,
                            args.edge_sigma_beams, not args.all_edges, args.past_bloom)
    print(f"scenes whose target has a twin model, first detection at the target ({skipped} "
          "skipped: no return on its legs)")
    print(f"{'':16s} {'n':>6s} {'floor: expected wrong':>22s} {'detector wrong':>15s}")
    for key in sorted(groups, key=lambda k: (k != "all", k)):
        g = groups[key]
        print(f"{key:16s} {g['scenes']:6d} {g['expected']:14.1f} "
              f"({100 * g['expected'] / g['scenes']:4.2f} %) {g['wrong']:8d} "
              f"({100 * g['wrong'] / g['scenes']:4.2f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
