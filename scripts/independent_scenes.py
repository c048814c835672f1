#!/usr/bin/env python3
"""Independent scene generator and evaluator for the shelfdock 2D-LiDAR shelf detector.

This file was written from the detector's interface specification alone, without reading the
repository's own simulator or layout generator (src/sim, src/eval, apps), so that it gives a
second opinion drawn by different modelling choices.  It draws seeded warehouse-like scenes,
ray casts them with its own sensor model, runs `shelfdock.Detector.detect` on each scan and
scores the result against the truth.

Usage
-----
    PYTHONPATH=build/python /usr/bin/python3 scripts/independent_scenes.py \
        --scenes-per-class 200 --seed 1 [--jobs 2] [--json FILE] [--dump DIR [--dump-all]]
        [--classes a,b] [--list-failures] [--echo first|strongest] [--spot-scale F]
        [--map-knows-model]

--dump DIR writes each failing scene as DIR/<class>_<seed>_<index>.scan.json (a LaserScan that
`shelfdock detect --scan` reads) and .truth.json (shelves, preset, class, seed, sensor draws,
noise, outcome and the `shelfdock detect ... --explain` command that re-runs it); with --dump-all
every scene, right or not (what a bound over all scenes, such as scripts/model_choice_bound.py's,
needs once converted to its truth format).  --echo and
--spot-scale are sensitivity knobs of the sensor model (below); the defaults are the model.
--map-knows-model detects each target scene with the target's model alone (the map names the
shelf's model as well as its place, as `shelfdock detect --model NAME`), clutter scenes with every
model: what is left of the failures then is not the close models' confusion.

The module is importable (tests/python/test_independent_scenes.py loads it by path):
`generate_scene(cls, seed, index)` draws one scene, `check_physical(scene)` lists what would make
it impossible, `evaluate_scene(det, scene)` scores a detector on it, `run(...)` does a whole sweep,
`summarise(...)` / `format_table(...)` make the report.

Modelling choices
-----------------
World.  Everything is 2-D at the scan height: a shelf is its four legs only (the deck is above the
scan plane; the robot docks under it); square legs are 40 mm squares turned with the shelf's yaw,
round legs 26 mm circles.  Boxes are rectangles (0.15-0.8 m), posts are 3-10 cm squares or
circles (plus exactly leg-sized ones: 40 mm squares and 26 mm circles), a person is two leg
circles of radius 5-7 cm whose centres are 0.1-0.4 m apart (never overlapping), walls are
segments.  A closed rectangular room 1-4 m beyond everything in the scene bounds the world, so
beams normally return something (the UST-10LX's 10 m range still loses the far corners).
Objects never overlap (a clearance check between polygons, circles and segments), nothing but
the robot stands inside a shelf's footprint (a person beside a leg may put a foot under the
deck's edge, never between the legs), and the sensor keeps 0.25 m from every object (the robot's
body); only in `large_close` may the sensor stand under the target shelf.  Shelves in rows are
hand-placed: +-15-20 mm and +-0.02 rad off the line.  `check_physical` verifies all this.

Each surface has a diffuse reflectivity drawn per object: painted legs 0.2-0.9, walls 0.3-0.9,
cardboard boxes 0.4-0.9, posts 0.2-0.9, trousers 0.05-0.6 (dark cloth is a weak target).

Beam footprint.  A beam is not a line.  SICK documents its TiM scanners' horizontal light spot
as (8.6 mrad per pulse + 5.8 mrad "HDDM+ supplement" at 0.33 deg resolution) x range + 7 mm at
the cover: one measured value accumulates many pulses fired while the mirror turns through one
step.  That is the "about 0.87 deg" spot of the specification.  The model: a Gaussian pulse
profile whose 1/e^2 full width is the per-pulse divergence, swept uniformly over the smear angle,
plus the exit aperture laterally.  Each beam is cast as K = 15 sub-rays across this profile, out
to 0.7 divergence beyond the sweep, each weighted by its share of the energy.  TiM571: 8.6 mrad,
5.8 mrad, 7 mm.  WLR-716 and UST-10LX (no published spot figures found): per-pulse divergence
4-9 mrad, smear 0-1 step, aperture 5-8 mm, drawn per scene.

Received amplitude.  Sub-ray k that hits a surface at range r with reflectivity rho and
incidence cosine c returns amplitude a_k = g_k rho c / max(r, 0.3)^2 (Lambertian, inverse
square for an extended target), scaled so that 1.0 is the detection threshold and a full spot on
a 10 %-reflective target at normal incidence reaches it at R10 (a per-sensor figure, drawn per
scene +-20 %).  Grazing walls and dark trousers far away therefore drop out by themselves.

Mixed pixels (the part that differs most from a naive model).  A naive simulator either returns
the range of the central ray (no mixing at all), or returns the energy-weighted MEAN of the
sub-ray ranges, which puts a point halfway between a leg and a wall 3 m behind it - something a
pulsed time-of-flight scanner does not do.  The sensors here are pulsed ToF scanners: what the
receiver sees is a waveform, the sum of one echo pulse per surface in the spot, each a Gaussian
of range width sigma_p (0.06-0.15 m, drawn per scene; a 2-5 ns pulse), scaled by its amplitude:

    s(tau) = sum_k a_k exp(-(tau - r_k)^2 / (2 sigma_p^2))

The timing discriminator is a leading-edge threshold: the range is the FIRST tau where s(tau)
crosses the threshold, corrected for amplitude walk with the peak amplitude A measured right after
the crossing (tau + sigma_p sqrt(2 ln A)), the way a scanner calibrates walk on single clean
echoes.  (A single tilted surface smears its echo; it is computed in closed form as one wider
Gaussian, which reads a few mm short, as real walk correction does on oblique surfaces.)  For a
beam on one surface square on this returns that surface's range exactly.  At a depth edge it
gives, without any special casing:
  * surfaces closer than ~2 sigma_p in depth: the echoes merge and the reading lands BETWEEN the
    two surfaces (a leg 5 cm in front of a wall blends into it; a veil of points between a leg
    and a box 30 cm behind);
  * surfaces far apart in depth: the nearer one wins if its share of the spot alone crosses the
    threshold (bright near edges "bloom": a leg looks wider than it is by up to a spot), else the
    far one is read with no blending at all (a weak near sliver is invisible);
  * nothing crosses the threshold: a dropout (NaN), e.g. a spot split between a dark leg and a
    far wall.
Which echo a single-return scanner reports when the echoes are apart is the least certain choice
here.  The default, 'first', is the textbook time-to-digital converter stopped by the first
threshold crossing; its consequence is that a bright leg near the sensor is seen by every beam
whose spot touches it, i.e. it looks wider by about one spot width (TiM571: +17 mm at 0.7 m,
+32 mm at 2 m, +38 mm at 4 m on a 40 mm leg in front of a wall).  `--echo strongest` instead
reports the echo with the highest peak (timed from its own rising edge): near edges then win only
when they carry more received energy than the background, and legs look only ~5-12 mm wider.
Both are run and reported; the tables of the default are the model's answer.
Then Gaussian range noise (10 or 20 mm, drawn per scene) is added, plus rare faults: a random
dropout per beam (0.1-0.5 %) and a rare short outlier (0.05-0.2 %: dust, a stray reflection,
uniform between 0.1 m and the true range).  Ranges outside [range_min, range_max] become NaN.

Findable.  A separate ideal cast (the central sub-ray of each beam: no spot, no noise, no
threshold) counts, per leg of the target, the beams whose first hit is that leg within
[range_min, range_max].  A leg with >= 2 such beams is in line of sight; a scene is findable when
at least three of the target's legs are.  The other scenes are reported apart: they must yield
no wrong shelf.

Preset.  The map's target pose in the LiDAR frame: the truth plus a position error of up to
0.2 m (uniform in direction, magnitude uniform in [0, 0.2]) and a heading error uniform in
[-0.1, 0.1] rad.  In clutter scenes: a pose 1-4 m in front (bearing within +-45 deg), any yaw.

Scoring.  right: first detection of the target's model within 0.05 m of the target's centre;
wrong_model: within 0.05 m but another model; wrong_place: the first detection is more than 0.05 m
from the target but within 0.05 m of another true shelf; phantom: ANY detection more than
0.05 m from every true shelf (flagged per scene, in every class); missed: no detection.  In
clutter scenes every detection counts (there is no shelf).  Heading errors are compared modulo
pi (pi/2 for the square 1250x1250).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

import numpy as np

# --------------------------------------------------------------------------------------------
# Shelf models and sensors (from the specification)
# --------------------------------------------------------------------------------------------
MODELS = {
    # name: leg centre-to-centre length L (shelf x axis), width W, leg shape and size [m]
    "t1-round-900x810": dict(L=0.90, W=0.81, shape="circle", leg=0.026),
    "t1-rect-1075x883": dict(L=1.075, W=0.883, shape="square", leg=0.04),
    "t1-rect-1250x1250": dict(L=1.25, W=1.25, shape="square", leg=0.04),
    "t1-rect-1080x856": dict(L=1.08, W=0.856, shape="square", leg=0.04),
}
MODEL_NAMES = list(MODELS)
ROUND = "t1-round-900x810"
SQUARE = "t1-rect-1250x1250"

DEG = math.pi / 180.0
SENSORS = {
    # div: single-pulse divergence (full width at 1/e^2) [rad], smear: the angle the mirror turns
    # while one measured value is integrated [rad], aperture: spot width at the cover [m] (all
    # drawn per scene from these ranges); r10: range at which a full spot on a 10 % target at
    # normal incidence just reaches the threshold [m] (x 0.8-1.2 per scene); pulse: echo pulse
    # sigma in range [m].  TiM571: SICK's TiM data (8.6 mrad per pulse + 5.8 mrad HDDM+
    # supplement at 0.33 deg + 7 mm at the cover = the "about 0.87 deg" spot; 8 m at 10 %).
    # WLR-716 and UST-10LX: no published spot figures found; a range around the same design.
    "wlr716": dict(n=811, inc=0.005817764173314432, amin=-2.356194490192345, rmin=0.05,
                   rmax=25.0, div=(0.004, 0.009), smear=(0.0, 0.0058), aperture=(0.005, 0.008),
                   r10=12.0, pulse=(0.06, 0.15)),
    "tim571": dict(n=811, inc=0.005817764173314432, amin=-2.356194490192345, rmin=0.05,
                   rmax=25.0, div=(0.0086, 0.0086), smear=(0.0058, 0.0058),
                   aperture=(0.007, 0.007), r10=8.0, pulse=(0.06, 0.15)),
    "ust10lx": dict(n=1081, inc=0.004363323129985824, amin=-2.356194490192345, rmin=0.06,
                    rmax=10.0, div=(0.004, 0.009), smear=(0.0, 0.0044), aperture=(0.005, 0.008),
                    r10=8.0, pulse=(0.06, 0.15)),
}
SENSOR_NAMES = list(SENSORS)

CLASSES = ["open", "row", "aisle", "occluded_leg", "person_beside_leg", "large_close",
           "mixed_neighbours", "round_noisy", "against_wall", "clutter"]

N_SUB = 15                       # sub-rays per beam (odd: the middle one is the ideal ray)
SUB_V = np.linspace(-1.0, 1.0, N_SUB)
SENSOR_CLEARANCE = 0.25          # robot body around the LiDAR [m]
MATCH_TOL = 0.05                 # centre distance for "the same shelf" [m]


def wrap(a):
    """Angle(s) to [-pi, pi)."""
    return (np.asarray(a) + math.pi) % (2.0 * math.pi) - math.pi


# --------------------------------------------------------------------------------------------
# Shapes and clearance
# --------------------------------------------------------------------------------------------
class Shape:
    """One physical outline: 'poly' (convex polygon, CCW vertices), 'circle' or 'seg' (wall)."""

    __slots__ = ("kind", "pts", "c", "r", "tag", "owner", "rho", "bc", "br")

    def __init__(self, kind, pts=None, c=None, r=0.0, tag="", owner=-1, rho=0.5):
        self.kind, self.tag, self.owner, self.rho = kind, tag, owner, rho
        self.pts = None if pts is None else np.asarray(pts, float)
        self.c = None if c is None else np.asarray(c, float)
        self.r = float(r)
        # bounding circle, for a quick "far apart" answer in shape_dist
        if kind == "circle":
            self.bc, self.br = self.c, self.r
        else:
            self.bc = self.pts.mean(0)
            self.br = float(np.hypot(*(self.pts - self.bc).T).max())

    def edges(self):
        if self.kind == "seg":
            return [(self.pts[0], self.pts[1])]
        n = len(self.pts)
        return [(self.pts[i], self.pts[(i + 1) % n]) for i in range(n)]

    def points(self):
        """Points that bound the shape (for the room's bounding box)."""
        if self.kind == "circle":
            return np.array([self.c + [self.r, 0], self.c - [self.r, 0],
                             self.c + [0, self.r], self.c - [0, self.r]])
        return self.pts


def rect(cx, cy, yaw, lx, ly):
    """CCW vertices of an lx x ly rectangle centred at (cx, cy), its x side along yaw."""
    c, s = math.cos(yaw), math.sin(yaw)
    hx, hy = lx / 2.0, ly / 2.0
    loc = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
    return loc @ np.array([[c, s], [-s, c]]) + [cx, cy]


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _pt_seg(p, a, b):
    px, py, ax, ay, bx, by = float(p[0]), float(p[1]), float(a[0]), float(a[1]), float(b[0]), \
        float(b[1])
    ex, ey = bx - ax, by - ay
    L2 = ex * ex + ey * ey
    t = 0.0 if L2 == 0 else min(1.0, max(0.0, ((px - ax) * ex + (py - ay) * ey) / L2))
    return math.hypot(ax + t * ex - px, ay + t * ey - py)


def _seg_seg(a, b, c, d):
    d1, d2 = _cross(b - a, c - a), _cross(b - a, d - a)
    d3, d4 = _cross(d - c, a - c), _cross(d - c, b - c)
    if d1 * d2 < 0 and d3 * d4 < 0:
        return 0.0
    return min(_pt_seg(a, c, d), _pt_seg(b, c, d), _pt_seg(c, a, b), _pt_seg(d, a, b))


def _inside(p, poly):
    """Point strictly inside a convex CCW polygon."""
    n = len(poly)
    return all(_cross(poly[(i + 1) % n] - poly[i], p - poly[i]) > 0 for i in range(n))


def point_dist(p, s):
    """Distance from point p to shape s (negative or zero when inside)."""
    p = np.asarray(p, float)
    if s.kind == "circle":
        return float(np.hypot(*(p - s.c))) - s.r
    d = min(_pt_seg(p, a, b) for a, b in s.edges())
    if s.kind == "poly" and _inside(p, s.pts):
        return -d
    return d


def shape_dist(a, b):
    """Clearance between two shapes (<= 0: they touch or overlap)."""
    far = math.hypot(a.bc[0] - b.bc[0], a.bc[1] - b.bc[1]) - a.br - b.br
    if far > 0.5:
        return far                   # a lower bound, enough for every clearance used here
    if a.kind == "circle" and b.kind == "circle":
        return float(np.hypot(*(a.c - b.c))) - a.r - b.r
    if a.kind == "circle":
        return point_dist(a.c, b) - a.r
    if b.kind == "circle":
        return point_dist(b.c, a) - b.r
    if a.kind == "poly" and any(_inside(v, a.pts) for v in b.pts):
        return -1.0
    if b.kind == "poly" and any(_inside(v, b.pts) for v in a.pts):
        return -1.0
    return min(_seg_seg(p, q, r, s) for p, q in a.edges() for r, s in b.edges())


# --------------------------------------------------------------------------------------------
# World: shelves, objects, clearance-checked placement
# --------------------------------------------------------------------------------------------
class World:
    def __init__(self):
        self.shapes = []         # physical outlines that the LiDAR sees
        self.owners = []         # owner labels: ("leg", shelf, j) / ("box", i) / ...
        self.shelves = []        # dicts: model, x, y, yaw, legs (owner ids)
        self.footprints = []     # (shelf index, Shape poly) keep-out areas of shelves

    def _owner(self, label):
        self.owners.append(label)
        return len(self.owners) - 1

    def add_shelf(self, model, x, y, yaw, rho):
        m = MODELS[model]
        si = len(self.shelves)
        c, s = math.cos(yaw), math.sin(yaw)
        legs = []
        for j, (lx, ly) in enumerate([(1, 1), (-1, 1), (-1, -1), (1, -1)]):
            px = x + c * lx * m["L"] / 2 - s * ly * m["W"] / 2
            py = y + s * lx * m["L"] / 2 + c * ly * m["W"] / 2
            o = self._owner(("leg", si, j))
            if m["shape"] == "circle":
                sh = Shape("circle", c=(px, py), r=m["leg"] / 2, tag="leg", owner=o, rho=rho)
            else:
                sh = Shape("poly", pts=rect(px, py, yaw, m["leg"], m["leg"]), tag="leg",
                           owner=o, rho=rho)
            self.shapes.append(sh)
            legs.append(o)
        self.shelves.append(dict(model=model, x=x, y=y, yaw=float(wrap(yaw)), legs=legs))
        fp = Shape("poly", pts=rect(x, y, yaw, m["L"] + m["leg"], m["W"] + m["leg"]))
        self.footprints.append((si, fp))
        return si

    def leg_shapes(self, si):
        legs = set(self.shelves[si]["legs"])
        return [s for s in self.shapes if s.owner in legs]

    def fits(self, shape, clearance=0.02, footprint=True, ignore=()):
        """True when `shape` keeps `clearance` from every object and stays out of every shelf
        footprint (unless footprint=False)."""
        for s in self.shapes:
            if s.owner in ignore:
                continue
            if shape_dist(shape, s) < clearance:
                return False
        if footprint:
            for _, fp in self.footprints:
                if shape_dist(shape, fp) < 0.005:
                    return False
        return True

    def add(self, shapes, tag, rho):
        """Adds the outlines of one object (one owner), e.g. a person's two legs."""
        o = self._owner((tag, len(self.owners)))
        for s in shapes:
            s.tag, s.owner, s.rho = tag, o, rho
            self.shapes.append(s)
        return o

    def sensor_ok(self, p, allow_under=()):
        for s in self.shapes:
            if point_dist(p, s) < SENSOR_CLEARANCE:
                return False
        for si, fp in self.footprints:
            if si not in allow_under and point_dist(p, fp) < 0.15:
                return False
        return True

    def close_room(self, rng, sensor_xy):
        pts = np.vstack([s.points() for s in self.shapes] + [np.asarray(sensor_xy)[None]])
        lo, hi = pts.min(0) - rng.uniform(1.0, 4.0, 2), pts.max(0) + rng.uniform(1.0, 4.0, 2)
        corners = [(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])]
        rho = rng.uniform(0.3, 0.9)
        segs = [Shape("seg", pts=[corners[i], corners[(i + 1) % 4]]) for i in range(4)]
        self.add(segs, "room", rho)


# Random objects -------------------------------------------------------------------------------
def person_legs(rng, c1, direction=None, r1=None):
    """Two leg circles: the first at c1, the second 0.1-0.4 m (centre to centre) away."""
    r1 = rng.uniform(0.05, 0.07) if r1 is None else r1
    r2 = float(np.clip(r1 + rng.normal(0, 0.005), 0.05, 0.07))
    sep = rng.uniform(max(0.10, r1 + r2 + 0.01), 0.40)
    ang = rng.uniform(-math.pi, math.pi) if direction is None else direction
    c2 = np.asarray(c1) + sep * np.array([math.cos(ang), math.sin(ang)])
    return [Shape("circle", c=c1, r=r1), Shape("circle", c=c2, r=r2)]


def random_object(rng, centre, kind=None):
    """A box, post, person or short wall around `centre`; returns (shapes, tag, rho)."""
    kind = kind or rng.choice(["box", "post", "post", "person", "wall"], p=[.3, .2, .2, .2, .1])
    cx, cy = centre
    yaw = rng.uniform(-math.pi, math.pi)
    if kind == "box":
        lx, ly = rng.uniform(0.15, 0.8), rng.uniform(0.15, 0.6)
        return [Shape("poly", pts=rect(cx, cy, yaw, lx, ly))], "box", rng.uniform(0.4, 0.9)
    if kind == "post":
        u = rng.random()
        if u < 0.25:        # exactly leg-sized square post
            return [Shape("poly", pts=rect(cx, cy, yaw, 0.04, 0.04))], "post", rng.uniform(0.2, 0.9)
        if u < 0.4:         # exactly leg-sized round post
            return [Shape("circle", c=(cx, cy), r=0.013)], "post", rng.uniform(0.2, 0.9)
        d = rng.uniform(0.03, 0.10)
        if rng.random() < 0.5:
            return [Shape("poly", pts=rect(cx, cy, yaw, d, d))], "post", rng.uniform(0.2, 0.9)
        return [Shape("circle", c=(cx, cy), r=d / 2)], "post", rng.uniform(0.2, 0.9)
    if kind == "person":
        return person_legs(rng, (cx, cy)), "person", rng.uniform(0.05, 0.6)
    L = rng.uniform(1.0, 4.0)
    d = np.array([math.cos(yaw), math.sin(yaw)]) * L / 2
    return [Shape("seg", pts=[(cx, cy) - d, (cx, cy) + d])], "wall", rng.uniform(0.3, 0.9)


def add_distractors(rng, w, n, sensor_xy, around, radius):
    """Up to n random objects within `radius` of `around`, clear of everything and the sensor."""
    for _ in range(n):
        for _try in range(30):
            c = np.asarray(around) + rng.uniform(-radius, radius, 2)
            shapes, tag, rho = random_object(rng, c, kind=rng.choice(["box", "post", "person"]))
            if all(w.fits(s, 0.10) for s in shapes) and \
                    all(point_dist(sensor_xy, s) > SENSOR_CLEARANCE + 0.1 for s in shapes):
                w.add(shapes, tag, rho)
                break


# Rows -----------------------------------------------------------------------------------------
def row_layout(rng, models, along, jitter=True):
    """Shelves side by side along local x with leg-surface gaps of 0.2-0.5 m, front leg centres
    on y = 0, shelves extending to +y (their front faces -y).  along: 'length' puts each shelf's
    length along the row, 'width' its width.  Returns [(model, x, y, yaw)]."""
    out, x_edge = [], 0.0
    for i, m in enumerate(models):
        M = MODELS[m]
        sx, sy = (M["L"], M["W"]) if along == "length" else (M["W"], M["L"])
        yaw = 0.0 if along == "length" else math.pi / 2
        if rng.random() < 0.5:
            yaw += math.pi              # the map's heading convention is arbitrary
        if i > 0:
            x_edge += rng.uniform(0.2, 0.5)
        cx = x_edge + M["leg"] / 2 + sx / 2
        x_edge = cx + sx / 2 + M["leg"] / 2
        cy = sy / 2
        if jitter:                      # hand-placed shelves are a little off the line
            cx += rng.uniform(-0.015, 0.015)
            cy += rng.uniform(-0.02, 0.02)
            yaw += rng.uniform(-0.02, 0.02)
        out.append((m, cx, cy, yaw))
    return out


def transform(layout, ox, oy, oyaw):
    c, s = math.cos(oyaw), math.sin(oyaw)
    return [(m, ox + c * x - s * y, oy + s * x + c * y, y_ + oyaw) for m, x, y, y_ in layout]


def add_layout(rng, w, layout):
    """Adds shelves; returns their indices or None when two of them would overlap."""
    ids = []
    for m, x, y, yaw in layout:
        # a shelf's legs must clear everything already there, and its footprint other shelves'
        M = MODELS[m]
        fp = Shape("poly", pts=rect(x, y, yaw, M["L"] + M["leg"], M["W"] + M["leg"]))
        if any(shape_dist(fp, s) < 0.05 for s in w.shapes):
            return None
        ids.append(w.add_shelf(m, x, y, yaw, rng.uniform(0.2, 0.9)))
    return ids


def place_sensor(rng, w, target_xy, dist, approach, bearing_max, allow_under=(), tries=60):
    """A sensor pose at `dist` (range) from target_xy, seen from a direction in `approach`
    (range of angles from the target), heading so that the target lies within +-bearing_max."""
    for _ in range(tries):
        d = rng.uniform(*dist)
        a = rng.uniform(*approach)
        p = np.asarray(target_xy) + d * np.array([math.cos(a), math.sin(a)])
        if not w.sensor_ok(p, allow_under):
            continue
        yaw = math.atan2(target_xy[1] - p[1], target_xy[0] - p[0]) + rng.uniform(-bearing_max,
                                                                                   bearing_max)
        return (float(p[0]), float(p[1]), float(wrap(yaw)))
    return None


# --------------------------------------------------------------------------------------------
# Ray casting
# --------------------------------------------------------------------------------------------
def _pairs(sorted_ang, lo, hi):
    """(ray index into sorted_ang, primitive index) for every ray within [lo, hi] of each
    primitive (angular intervals may wrap around +-pi)."""
    width = hi - lo
    lo = wrap(lo)
    hi = lo + width
    ids = np.arange(len(lo))
    extra = hi > math.pi
    LO = np.concatenate([lo, np.full(extra.sum(), -math.pi)])
    HI = np.concatenate([np.minimum(hi, math.pi), hi[extra] - 2 * math.pi])
    IDS = np.concatenate([ids, ids[extra]])
    i0 = np.searchsorted(sorted_ang, LO, "left")
    i1 = np.searchsorted(sorted_ang, HI, "right")
    cnt = np.maximum(i1 - i0, 0)
    total = int(cnt.sum())
    prim = np.repeat(IDS, cnt)
    ray = np.arange(total) + np.repeat(i0 - (np.cumsum(cnt) - cnt), cnt)
    return ray, prim


def cast(phi, org, prims):
    """First hit along each ray.  phi (R,) ray angles, org (R, 2) ray origins (a few mm from the
    LiDAR centre).  prims: dict of segs (M,2,2), seg_owner, circ (C,3), circ_owner.
    Returns t (R,) [inf: none], owner (R,) [-1], cos of incidence (R,)."""
    R = len(phi)
    order = np.argsort(phi)
    ph = phi[order]
    O = org[order]
    D = np.stack([np.cos(ph), np.sin(ph)], 1)
    out_ray, out_t, out_o, out_c = [], [], [], []
    segs = prims["segs"]
    if len(segs):
        p0, p1 = segs[:, 0], segs[:, 1]
        a0, a1 = np.arctan2(p0[:, 1], p0[:, 0]), np.arctan2(p1[:, 1], p1[:, 0])
        dd = wrap(a1 - a0)
        lo = np.where(dd > 0, a0, a1)
        e = p1 - p0
        L2 = np.maximum((e * e).sum(1), 1e-12)
        tt = np.clip(-(p0 * e).sum(1) / L2, 0, 1)
        dist0 = np.hypot(*(p0 + tt[:, None] * e).T)
        m = 0.002 + 0.01 / np.maximum(dist0, 0.02)
        ray, prim = _pairs(ph, lo - m, lo + np.abs(dd) + m)
        E = e[prim]
        Dr = D[ray]
        W = p0[prim] - O[ray]
        den = Dr[:, 0] * E[:, 1] - Dr[:, 1] * E[:, 0]
        ok = np.abs(den) > 1e-12
        den = np.where(ok, den, 1.0)
        t = (W[:, 0] * E[:, 1] - W[:, 1] * E[:, 0]) / den
        u = (W[:, 0] * Dr[:, 1] - W[:, 1] * Dr[:, 0]) / den
        ok &= (t > 1e-6) & (u >= 0) & (u <= 1)
        out_ray.append(ray[ok])
        out_t.append(t[ok])
        out_o.append(prims["seg_owner"][prim[ok]])
        out_c.append((np.abs(den) / np.sqrt(L2[prim]))[ok])
    circ = prims["circ"]
    if len(circ):
        C, r = circ[:, :2], circ[:, 2]
        d = np.hypot(C[:, 0], C[:, 1])
        ca = np.arctan2(C[:, 1], C[:, 0])
        half = np.arcsin(np.clip(r / np.maximum(d, 1e-9), 0, 1)) + 0.002 + 0.01 / np.maximum(d, 0.02)
        ray, prim = _pairs(ph, ca - half, ca + half)
        Cr = C[prim] - O[ray]
        Dr = D[ray]
        b = (Cr * Dr).sum(1)
        disc = r[prim] ** 2 - ((Cr * Cr).sum(1) - b * b)
        ok = disc >= 0
        sq = np.sqrt(np.where(ok, disc, 0))
        t = b - sq
        ok &= t > 1e-6
        out_ray.append(ray[ok])
        out_t.append(t[ok])
        out_o.append(prims["circ_owner"][prim[ok]])
        out_c.append((sq / r[prim])[ok])
    t_best = np.full(R, np.inf)
    o_best = np.full(R, -1, int)
    c_best = np.zeros(R)
    if out_ray:
        ray = np.concatenate(out_ray)
        t = np.concatenate(out_t)
        o = np.concatenate(out_o)
        c = np.concatenate(out_c)
        if len(ray):
            idx = np.lexsort((t, ray))
            ray, t, o, c = ray[idx], t[idx], o[idx], c[idx]
            first = np.ones(len(ray), bool)
            first[1:] = ray[1:] != ray[:-1]
            sel = order[ray[first]]
            t_best[sel], o_best[sel], c_best[sel] = t[first], o[first], c[first]
    return t_best, o_best, c_best


def to_sensor_frame(w, pose):
    """The world's outlines as arrays in the LiDAR frame (x forward, y left)."""
    sx, sy, syaw = pose
    c, s = math.cos(syaw), math.sin(syaw)
    Rt = np.array([[c, -s], [s, c]])     # p_s = (p - t) @ Rt  (i.e. R^T (p - t))

    def tf(p):
        return (np.asarray(p) - [sx, sy]) @ Rt
    segs, so, circ, co = [], [], [], []
    for sh in w.shapes:
        if sh.kind == "circle":
            q = tf(sh.c)
            circ.append((q[0], q[1], sh.r))
            co.append(sh.owner)
        else:
            for a, b in sh.edges():
                segs.append((tf(a), tf(b)))
                so.append(sh.owner)
    return dict(segs=np.array(segs, float).reshape(-1, 2, 2), seg_owner=np.array(so, int),
                circ=np.array(circ, float).reshape(-1, 3), circ_owner=np.array(co, int))


def shelf_in_sensor(sh, pose):
    sx, sy, syaw = pose
    c, s = math.cos(syaw), math.sin(syaw)
    dx, dy = sh["x"] - sx, sh["y"] - sy
    return (c * dx + s * dy, -s * dx + c * dy, float(wrap(sh["yaw"] - syaw)))


# --------------------------------------------------------------------------------------------
# Sensor model: spot, waveform, leading-edge discriminator, noise
# --------------------------------------------------------------------------------------------
def draw_sensor(rng, name, noise=None, spot_scale=1.0, echo="first"):
    """One scene's sensor: the fixed geometry and the per-scene draws.  spot_scale multiplies
    divergence, smear and aperture (a sensitivity knob; 1 = the model above)."""
    S = SENSORS[name]
    return dict(name=name, n=S["n"], inc=S["inc"], amin=S["amin"], rmin=S["rmin"],
                rmax=S["rmax"], echo=echo, spot_scale=spot_scale,
                div=spot_scale * rng.uniform(*S["div"]), smear=spot_scale * rng.uniform(*S["smear"]),
                aperture=spot_scale * rng.uniform(*S["aperture"]),
                r10=S["r10"] * rng.uniform(0.8, 1.2), pulse=rng.uniform(*S["pulse"]),
                noise=float(noise if noise is not None else rng.choice([0.01, 0.02])),
                p_drop=rng.uniform(0.001, 0.005), p_out=rng.uniform(0.0005, 0.002))


def _waveform(Rk, Ak, sig, tau):
    """s(tau) for beams: Rk, Ak (B, K); tau (B, J) -> (B, J)."""
    z = (tau[:, :, None] - Rk[:, None, :]) / sig
    return (Ak[:, None, :] * np.exp(-0.5 * z * z)).sum(2)


def discriminate(Rk, Ak, Ok, sig, echo="first"):
    """Leading-edge range of each beam's waveform, walk-corrected by its first peak.
    Rk, Ak, Ok: (B, K) sub-ray ranges (inf = no hit), amplitudes (threshold = 1) and owners.
    echo: 'first' reports the first echo that crosses the threshold; 'strongest' the echo with
    the highest peak (timed from its own rising edge, so echoes merged with it still blend).
    Returns (B,) ranges, NaN where the waveform never reaches the threshold."""
    B, K = Rk.shape
    out = np.full(B, np.nan)
    hit = np.isfinite(Rk) & (Ak > 0)
    Rz = np.where(hit, Rk, 0.0)
    Az = np.where(hit, Ak, 0.0)
    tot = Az.sum(1)
    # One surface within one pulse width (a face seen square on or obliquely): the sub-ray
    # echoes add up to one pulse, Gaussian to a good approximation, of mean mu, width
    # sig_e = sqrt(sig^2 + var) and peak tot * sig / sig_e.  Its leading edge walk-corrected
    # as for a clean pulse of width sig: mu - (sig_e - sig) sqrt(2 ln peak), i.e. an oblique
    # surface reads slightly short, as a real receiver's walk correction does.
    rmin = np.where(hit, Rk, np.inf).min(1)
    rmax = np.where(hit, Rk, -np.inf).max(1)
    omin = np.where(hit, Ok, np.iinfo(int).max).min(1)
    omax = np.where(hit, Ok, -1).max(1)
    simple = (rmax - rmin < sig) & (omin == omax) & (tot > 0)
    mu = (Az * Rz).sum(1) / np.maximum(tot, 1e-300)
    var = (Az * (Rz - mu[:, None]) ** 2).sum(1) / np.maximum(tot, 1e-300)
    sig_e = np.sqrt(sig * sig + var)
    peak = tot * sig / sig_e
    good = simple & (peak >= 1.0)
    out[good] = mu[good] - (sig_e[good] - sig) * np.sqrt(2 * np.log(peak[good]))
    cx = np.nonzero(~simple & (tot > 0))[0]
    if len(cx) == 0:
        return out
    # Several surfaces (a depth edge) or a long smear: the waveform, numerically.
    R = np.where(hit[cx], Rk[cx], np.nan)
    A = Az[cx]
    Rf = np.where(np.isnan(R), 0.0, R)
    # candidate crossings: a grid from -4.5 to +0.5 sigma around every sub-ray's echo
    offs = np.linspace(-4.5, 0.5, 21) * sig
    G = (R[:, :, None] + offs).reshape(len(cx), -1)
    G = np.where(np.isnan(G), np.inf, G)
    G.sort(1)
    finite = np.isfinite(G)
    S = _waveform(Rf, A, sig, np.where(finite, G, 0.0))
    S = np.where(finite, S, 0.0)
    above = S >= 1.0
    anyab = above.any(1)
    if echo == "first":
        j = np.argmax(above, 1)
    else:
        # the rising edge (below -> above) last before the waveform's highest sample
        ipk = np.argmax(S, 1)
        rise = above & ~np.concatenate([np.zeros((len(cx), 1), bool), above[:, :-1]], 1)
        idx = np.arange(G.shape[1])[None, :]
        j = np.where(rise & (idx <= ipk[:, None]), idx, -1).max(1)
        j = np.maximum(j, 0)
    rows = np.nonzero(anyab)[0]
    if len(rows) == 0:
        return out
    jj = j[rows]
    hi_t = G[rows, jj]
    lo_t = np.where(jj > 0, G[rows, np.maximum(jj - 1, 0)], hi_t - 0.5 * sig)
    lo_t = np.maximum(lo_t, hi_t - 0.5 * sig)
    Rr, Ar = Rf[rows], A[rows]
    for _ in range(12):          # bisection to the crossing
        mid = 0.5 * (lo_t + hi_t)
        sm = _waveform(Rr, Ar, sig, mid[:, None])[:, 0]
        up = sm >= 1.0
        hi_t = np.where(up, mid, hi_t)
        lo_t = np.where(up, lo_t, mid)
    tau0 = hi_t
    # the first peak after the crossing: the amplitude the scanner corrects walk with
    m = np.linspace(0.0, 5.0, 41) * sig
    Sp = _waveform(Rr, Ar, sig, tau0[:, None] + m[None, :])
    dec = np.diff(Sp, axis=1) < 0
    k = np.where(dec.any(1), np.argmax(dec, 1), len(m) - 1)
    # parabolic refinement of the peak's height
    k1 = np.clip(k, 1, len(m) - 2)
    ii = np.arange(len(rows))
    y0, y1, y2 = Sp[ii, k1 - 1], Sp[ii, k1], Sp[ii, k1 + 1]
    den = y0 - 2 * y1 + y2
    pk = np.where(den < 0, y1 - 0.125 * (y2 - y0) ** 2 / np.where(den < 0, den, -1), y1)
    peak = np.maximum(np.maximum(pk, Sp[ii, k]), 1.0)
    out[cx[rows]] = tau0 + sig * np.sqrt(2.0 * np.log(peak))
    return out


def spot_profile(div, smear):
    """Sub-ray angle offsets and energy weights of one measured value: a Gaussian pulse of
    1/e^2 full width `div` (sigma div/4) swept uniformly over `smear` (the HDDM-style
    accumulation of pulses fired while the mirror turns), sampled out to 0.7 div beyond the
    sweep (the Gaussian's tail, where a bright near edge still triggers)."""
    from math import erf
    sg = max(div / 4.0, 1e-9)
    half = smear / 2.0 + 0.7 * div
    delta = SUB_V * half
    if smear < 1e-9:
        g = np.exp(-0.5 * (delta / sg) ** 2)
    else:
        k = 1.0 / (math.sqrt(2.0) * sg)
        g = np.array([erf(k * (d + smear / 2)) - erf(k * (d - smear / 2)) for d in delta])
    return delta, g / g.sum()


def simulate_scan(rng, prims, sensor, rho_of_owner):
    """Ranges of one scan, NaN = no return; also the ideal cast's first-hit owner per beam."""
    n, K = sensor["n"], N_SUB
    ang = sensor["amin"] + sensor["inc"] * np.arange(n)
    delta, g = spot_profile(sensor["div"], sensor["smear"])
    phi = (ang[:, None] + delta[None, :]).ravel()
    lat = SUB_V * sensor["aperture"] / 2
    org = np.stack([-np.sin(ang)[:, None] * lat[None, :], np.cos(ang)[:, None] * lat[None, :]],
                   2).reshape(-1, 2)
    t, own, cosi = cast(phi, org, prims)
    t, own, cosi = t.reshape(n, K), own.reshape(n, K), cosi.reshape(n, K)
    # ideal cast: the central sub-ray (no offset, no spread)
    k0 = K // 2
    ideal_t, ideal_owner = t[:, k0].copy(), own[:, k0].copy()
    inr = (ideal_t >= sensor["rmin"]) & (ideal_t <= sensor["rmax"])
    ideal_owner[~inr] = -1
    # amplitudes; threshold 1 at r10 for a full spot on a 10 % target at normal incidence
    rho = np.where(own >= 0, rho_of_owner[np.maximum(own, 0)], 0.0)
    scale = sensor["r10"] ** 2 / 0.1
    A = g[None, :] * rho * np.clip(cosi, 0.0, 1.0) * scale / np.maximum(t, 0.3) ** 2
    A = np.where(np.isfinite(t), A, 0.0)
    tot = A.sum(1, keepdims=True)
    A = A * np.minimum(1.0, 5000.0 / np.maximum(tot, 1e-12))  # receiver dynamic range
    r = discriminate(t, A, own, sensor["pulse"], sensor["echo"])
    # noise and faults
    r = r + rng.normal(0.0, sensor["noise"], n)
    out = rng.random(n) < sensor["p_out"]
    r[out] = rng.uniform(0.1, 1.0, out.sum()) * np.where(np.isfinite(r[out]), r[out], 5.0)
    r[rng.random(n) < sensor["p_drop"]] = np.nan
    r[(r < sensor["rmin"]) | (r > sensor["rmax"])] = np.nan
    return r, ideal_owner, ideal_t


# --------------------------------------------------------------------------------------------
# Scene classes
# --------------------------------------------------------------------------------------------
def _model(rng, exclude=()):
    return str(rng.choice([m for m in MODEL_NAMES if m not in exclude]))


def _ideal_leg_hits(rng, w, pose, sensor, si):
    """Beams of the ideal cast on each leg of shelf si (for placing people and occluders)."""
    prims = to_sensor_frame(w, pose)
    n = sensor["n"]
    ang = sensor["amin"] + sensor["inc"] * np.arange(n)
    t, own, _ = cast(ang, np.zeros((n, 2)), prims)
    own[(t < sensor["rmin"]) | (t > sensor["rmax"])] = -1
    return [int((own == o).sum()) for o in w.shelves[si]["legs"]]


def gen_open(rng, sensor, round_only=False):
    w = World()
    m = ROUND if round_only else _model(rng)
    t = w.add_shelf(m, 0.0, 0.0, rng.uniform(-math.pi, math.pi), rng.uniform(0.2, 0.9))
    pose = place_sensor(rng, w, (0, 0), (1.0, 4.0), (-math.pi, math.pi), 120 * DEG)
    if pose is None:
        return None
    if rng.random() < 0.4:
        add_distractors(rng, w, rng.integers(1, 3), pose[:2], (0, 0), 3.0)
    return w, t, pose


def _row_scene(rng, models, target_i, back_wall_p=0.5):
    w = World()
    along = str(rng.choice(["length", "width"]))
    lay = row_layout(rng, models, along)
    ids = add_layout(rng, w, lay)
    if ids is None:
        return None
    t = ids[target_i]
    if rng.random() < back_wall_p:
        ymax = max(p[1] for s in w.shapes for p in s.points())
        yw = ymax + rng.uniform(0.05, 1.0)
        x0 = min(p[0] for s in w.shapes for p in s.points()) - rng.uniform(0.5, 3.0)
        x1 = max(p[0] for s in w.shapes for p in s.points()) + rng.uniform(0.5, 3.0)
        w.add([Shape("seg", pts=[(x0, yw), (x1, yw)])], "wall", rng.uniform(0.3, 0.9))
    tx, ty = w.shelves[t]["x"], w.shelves[t]["y"]
    # robot in front of the row (y < 0), looking at the target from within +-60 deg of the normal
    pose = place_sensor(rng, w, (tx, ty), (1.0, 4.0), (-math.pi / 2 - 1.05, -math.pi / 2 + 1.05),
                        90 * DEG)
    if pose is None or pose[1] > -0.3:
        return None
    return w, t, pose


def gen_row(rng, sensor, round_only=False):
    m = ROUND if round_only else _model(rng)
    n = int(rng.integers(3, 6))
    r = _row_scene(rng, [m] * n, int(rng.integers(0, n)))
    if r is not None and rng.random() < 0.3:
        add_distractors(rng, r[0], 1, r[2][:2], (r[0].shelves[r[1]]["x"], -1.0), 2.0)
    return r


def gen_mixed(rng, sensor):
    n = int(rng.integers(3, 6))
    ti = int(rng.integers(0, n))
    mt = _model(rng)
    models = [mt if i == ti else _model(rng, exclude=(mt,)) for i in range(n)]
    return _row_scene(rng, models, ti)


def gen_aisle(rng, sensor):
    w = World()
    a = rng.uniform(1.4, 3.0)                 # between the two rows' front leg lines
    layA = row_layout(rng, [_model(rng)] * int(rng.integers(3, 7)), str(rng.choice(["length", "width"])))
    layB = row_layout(rng, [_model(rng)] * int(rng.integers(3, 7)), str(rng.choice(["length", "width"])))
    layA = transform(layA, rng.uniform(-1.0, 1.0), a / 2, 0.0)
    layB = transform(layB, rng.uniform(3.0, 5.0), -a / 2, math.pi)
    if add_layout(rng, w, layA + layB) is None:
        return None
    xs = [s["x"] for s in w.shelves]
    for side in (1, -1):                      # walls behind the rows, sometimes
        if rng.random() < 0.4:
            pts = np.vstack([s.points() for s in w.shapes])
            yw = (pts[:, 1].max() if side > 0 else pts[:, 1].min()) + side * rng.uniform(0.05, 1.0)
            w.add([Shape("seg", pts=[(min(xs) - 3, yw), (max(xs) + 3, yw)])], "wall",
                  rng.uniform(0.3, 0.9))
    for _ in range(40):
        p = np.array([rng.uniform(min(xs) - 1.0, max(xs) + 1.0),
                      rng.uniform(-a / 2 + 0.3, a / 2 - 0.3)])
        if not w.sensor_ok(p):
            continue
        yaw = (0.0 if rng.random() < 0.5 else math.pi) + rng.uniform(-0.8, 0.8)
        if rng.random() < 0.2:                # sometimes facing one side of the aisle
            yaw = (1 if rng.random() < 0.5 else -1) * math.pi / 2 + rng.uniform(-0.5, 0.5)
        cand = []
        for i, s in enumerate(w.shelves):
            x, y, _ = shelf_in_sensor(s, (p[0], p[1], yaw))
            if 1.0 <= math.hypot(x, y) <= 4.0 and abs(math.atan2(y, x)) <= 120 * DEG:
                cand.append(i)
        if cand:
            if rng.random() < 0.3:
                add_distractors(rng, w, 1, p, p + [2.0 * math.cos(yaw), 2.0 * math.sin(yaw)], 1.0)
            return w, int(rng.choice(cand)), (float(p[0]), float(p[1]), float(wrap(yaw)))
    return None


def gen_occluded(rng, sensor):
    w = World()
    m = _model(rng)
    t = w.add_shelf(m, 0.0, 0.0, rng.uniform(-math.pi, math.pi), rng.uniform(0.2, 0.9))
    # a view with all four legs in sight, so that hiding one leaves three (most of the time)
    for _ in range(10):
        pose = place_sensor(rng, w, (0, 0), (1.5, 4.0), (-math.pi, math.pi), 100 * DEG)
        if pose is None:
            return None
        hits = _ideal_leg_hits(rng, w, pose, sensor, t)
        if min(hits) >= 2:
            break
    legs = w.leg_shapes(t)
    order = [j for j in rng.permutation(4) if hits[j] >= 2]
    sp = np.array(pose[:2])
    for j in order:
        lc = legs[j].c if legs[j].kind == "circle" else legs[j].pts.mean(0)
        u = (lc - sp) / np.linalg.norm(lc - sp)
        nrm = np.array([-u[1], u[0]])
        dist = rng.uniform(0.2, 0.4)          # occluder centre in front of the leg, on the LOS
        oc = lc - dist * u
        if rng.random() < 0.5:
            lx, ly = rng.uniform(0.1, 0.3), rng.uniform(0.15, 0.5)
            yaw = math.atan2(u[1], u[0]) + rng.uniform(-0.3, 0.3)
            shapes, tag, rho = [Shape("poly", pts=rect(oc[0], oc[1], yaw, lx, ly))], "box", \
                rng.uniform(0.4, 0.9)
        else:
            r1 = rng.uniform(0.05, 0.07)
            oc = oc + nrm * rng.uniform(-0.3, 0.3) * r1
            shapes, tag, rho = person_legs(rng, oc, r1=r1), "person", rng.uniform(0.05, 0.6)
        if not all(w.fits(s, 0.02) for s in shapes):
            continue
        if not all(point_dist(sp, s) > SENSOR_CLEARANCE for s in shapes):
            continue
        w.add(shapes, tag, rho)
        if _ideal_leg_hits(rng, w, pose, sensor, t)[j] >= 2:   # must hide the leg
            w.shapes = [s for s in w.shapes if s.owner != w.shapes[-1].owner]
            continue
        return w, t, pose
    return None


def _place_beside(rng, leg, centre_xy, r, gap):
    """A circle of radius r at `gap` from a leg outline, in a random direction away from the
    shelf's centre (within the 270 deg outside the shelf's corner)."""
    lc = leg.c if leg.kind == "circle" else leg.pts.mean(0)
    out = lc - np.asarray(centre_xy)
    base = math.atan2(out[1], out[0])
    ang = base + rng.uniform(-0.75 * math.pi, 0.75 * math.pi)
    u = np.array([math.cos(ang), math.sin(ang)])
    lo, hi = 0.0, 0.5                         # bisection: distance from the leg = r + gap
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        if point_dist(lc + mid * u, leg) < r + gap:
            lo = mid
        else:
            hi = mid
    return lc + hi * u, ang


def gen_person_beside(rng, sensor):
    w = World()
    m = _model(rng)
    t = w.add_shelf(m, 0.0, 0.0, rng.uniform(-math.pi, math.pi), rng.uniform(0.2, 0.9))
    pose = place_sensor(rng, w, (0, 0), (1.0, 4.0), (-math.pi, math.pi), 100 * DEG)
    if pose is None:
        return None
    hits = _ideal_leg_hits(rng, w, pose, sensor, t)
    legs = w.leg_shapes(t)
    M = MODELS[m]
    inner = Shape("poly", pts=rect(0.0, 0.0, w.shelves[t]["yaw"], M["L"], M["W"]))
    sp = np.array(pose[:2])
    for j in [j for j in rng.permutation(4) if hits[j] >= 2]:
        for _ in range(10):
            r1 = rng.uniform(0.05, 0.07)
            gap = rng.uniform(0.002, 0.10)     # touching (2 mm) to 10 cm
            c1, ang = _place_beside(rng, legs[j], (0, 0), r1, gap)
            shapes = person_legs(rng, c1, r1=r1)
            # the person may stand with a foot under the deck's edge, but not between the legs:
            # neither leg circle overlaps the rectangle of leg centres
            if not all(w.fits(s, 0.0015, footprint=False, ignore={legs[j].owner}) for s in shapes):
                continue
            if any(shape_dist(s, inner) <= 0.0 for s in shapes):
                continue
            if shape_dist(shapes[1], legs[j]) < 0.0015:
                continue
            if not all(point_dist(sp, s) > SENSOR_CLEARANCE for s in shapes):
                continue
            w.add(shapes, "person", rng.uniform(0.05, 0.6))
            if _ideal_leg_hits(rng, w, pose, sensor, t)[j] < 2:   # the leg must stay visible
                w.shapes = [s for s in w.shapes if s.owner != w.shapes[-1].owner]
                continue
            return w, t, pose
    return None


def gen_large_close(rng, sensor):
    w = World()
    t = w.add_shelf(SQUARE, 0.0, 0.0, rng.uniform(-math.pi, math.pi), rng.uniform(0.2, 0.9))
    for _ in range(60):
        d = rng.uniform(0.2, 1.1)
        a = rng.uniform(-math.pi, math.pi)
        p = d * np.array([math.cos(a), math.sin(a)])
        if not w.sensor_ok(p, allow_under=(t,)):
            continue
        yaw = math.atan2(-p[1], -p[0]) + rng.uniform(-60, 60) * DEG
        pose = (float(p[0]), float(p[1]), float(wrap(yaw)))
        if rng.random() < 0.3:
            add_distractors(rng, w, 1, pose[:2], (0, 0), 2.5)
        return w, t, pose
    return None


def gen_against_wall(rng, sensor):
    w = World()
    m = _model(rng)
    along = str(rng.choice(["length", "width"]))
    n_nb = int(rng.choice([0, 0, 1, 2]))
    models = [m] * (n_nb + 1)
    ti = int(rng.integers(0, n_nb + 1))
    lay = row_layout(rng, models, along)
    ids = add_layout(rng, w, lay)
    if ids is None:
        return None
    t = ids[ti]
    # the wall 2-10 cm behind the target's back legs (leg surface to wall)
    tl = w.leg_shapes(t)
    ymax = max(p[1] for s in tl for p in s.points())
    yw = ymax + rng.uniform(0.02, 0.10)
    others = [s for s in w.shapes if s.tag == "leg" and s.owner not in w.shelves[t]["legs"]]
    if others and max(p[1] for s in others for p in s.points()) > yw - 0.01:
        return None                           # a neighbour's leg would be in the wall
    x0 = min(p[0] for s in w.shapes for p in s.points()) - rng.uniform(1.0, 3.0)
    x1 = max(p[0] for s in w.shapes for p in s.points()) + rng.uniform(1.0, 3.0)
    w.add([Shape("seg", pts=[(x0, yw), (x1, yw)])], "wall", rng.uniform(0.3, 0.9))
    corner = None
    if rng.random() < 0.3:                    # a corner on one side
        xc = corner = x0 if rng.random() < 0.5 else x1
        w.add([Shape("seg", pts=[(xc, yw), (xc, yw - rng.uniform(2.0, 5.0))])], "wall",
              rng.uniform(0.3, 0.9))
    tx, ty = w.shelves[t]["x"], w.shelves[t]["y"]
    pose = place_sensor(rng, w, (tx, ty), (1.0, 4.0), (-math.pi / 2 - 1.2, -math.pi / 2 + 1.2),
                        90 * DEG)
    if pose is None or pose[1] > yw - 0.5:
        return None
    if corner is not None and not (x0 + 0.3 < pose[0] < x1 - 0.3):
        return None                           # the robot stands on the far side of the corner
    return w, t, pose


def gen_clutter(rng, sensor):
    w = World()
    pose = (0.0, 0.0, 0.0)
    counts = dict(box=int(rng.integers(2, 7)), post=int(rng.integers(3, 11)),
                  person=int(rng.integers(0, 4)), wall=int(rng.integers(1, 4)))
    for kind, n in counts.items():
        for _ in range(n):
            for _try in range(30):
                r = rng.uniform(0.6, 6.0)
                a = rng.uniform(-140, 140) * DEG
                c = r * np.array([math.cos(a), math.sin(a)])
                shapes, tag, rho = random_object(rng, c, kind=kind)
                if all(w.fits(s, 0.05) for s in shapes) and \
                        all(point_dist((0, 0), s) > SENSOR_CLEARANCE + 0.1 for s in shapes):
                    w.add(shapes, tag, rho)
                    break
    return w, None, pose


GENERATORS = {
    "open": gen_open,
    "row": gen_row,
    "aisle": gen_aisle,
    "occluded_leg": gen_occluded,
    "person_beside_leg": gen_person_beside,
    "large_close": gen_large_close,
    "mixed_neighbours": gen_mixed,
    "round_noisy": lambda rng, s: (gen_open if rng.random() < 0.6 else gen_row)(rng, s, True),
    "against_wall": gen_against_wall,
    "clutter": gen_clutter,
}


# --------------------------------------------------------------------------------------------
# One scene
# --------------------------------------------------------------------------------------------
def generate_scene(cls, seed, index, spot_scale=1.0, echo="first"):
    """Draws scene `index` of class `cls` for `seed` (reproducible, independent of the order
    scenes are drawn in).  Returns a dict: scan (ranges, angles, limits), truth and bookkeeping.
    spot_scale, echo: sensitivity knobs of the sensor model (see draw_sensor, discriminate)."""
    rng = np.random.default_rng([int(seed), CLASSES.index(cls), int(index)])
    sname = str(rng.choice(SENSOR_NAMES))
    sensor = draw_sensor(rng, sname, noise=0.02 if cls == "round_noisy" else None,
                         spot_scale=spot_scale, echo=echo)
    for attempt in range(500):
        r = GENERATORS[cls](rng, sensor)
        if r is not None:
            break
    else:
        raise RuntimeError(f"could not draw a {cls} scene (seed {seed}, index {index})")
    w, t, pose = r
    w.close_room(rng, pose[:2])
    prims = to_sensor_frame(w, pose)
    rho = np.array([0.5] * len(w.owners))
    for s in w.shapes:
        rho[s.owner] = s.rho
    ranges, ideal_owner, _ = simulate_scan(rng, prims, sensor, rho)
    shelves = []
    for s in w.shelves:
        x, y, yaw = shelf_in_sensor(s, pose)
        shelves.append(dict(model=s["model"], x=x, y=y, yaw=yaw))
    if t is not None:
        legs_seen = [int((ideal_owner == o).sum()) for o in w.shelves[t]["legs"]]
        findable = sum(h >= 2 for h in legs_seen) >= 3
        tx, ty, tyaw = shelves[t]["x"], shelves[t]["y"], shelves[t]["yaw"]
        e = rng.uniform(0.0, 0.2)
        a = rng.uniform(-math.pi, math.pi)
        preset = (tx + e * math.cos(a), ty + e * math.sin(a),
                  float(wrap(tyaw + rng.uniform(-0.1, 0.1))))
    else:
        legs_seen, findable = [], False
        d, b = rng.uniform(1.0, 4.0), rng.uniform(-45, 45) * DEG
        preset = (d * math.cos(b), d * math.sin(b), float(rng.uniform(-math.pi, math.pi)))
    return dict(cls=cls, seed=int(seed), index=int(index), sensor=sensor, ranges=ranges,
                angle_min=sensor["amin"], angle_increment=sensor["inc"],
                range_min=sensor["rmin"], range_max=sensor["rmax"], shelves=shelves, target=t,
                preset=tuple(float(v) for v in preset), legs_seen=legs_seen, findable=findable,
                objects=sorted({lab[0] for lab in w.owners}), world=w, pose=pose)


def check_physical(sc, touch=0.001):
    """Problems that make a scene physically impossible (empty when there are none): two
    objects overlapping (closer than `touch`; walls may meet), the sensor within 0.2 m of an object,
    an object other than the robot inside a shelf's footprint (between its legs)."""
    w, pose = sc["world"], sc["pose"]
    out = []
    sh = w.shapes
    for i in range(len(sh)):
        if point_dist(pose[:2], sh[i]) < 0.2:
            out.append(f"sensor within 0.2 m of {w.owners[sh[i].owner]}")
        for j in range(i + 1, len(sh)):
            if sh[i].kind == "seg" and sh[j].kind == "seg":
                continue                      # walls may meet in a corner
            if sh[i].owner != sh[j].owner and shape_dist(sh[i], sh[j]) < touch:
                out.append(f"{w.owners[sh[i].owner]} overlaps {w.owners[sh[j].owner]}")
    for si, _ in w.footprints:
        s = w.shelves[si]
        M = MODELS[s["model"]]
        inner = Shape("poly", pts=rect(s["x"], s["y"], s["yaw"], M["L"] - M["leg"], M["W"] - M["leg"]))
        for x in sh:
            if x.owner not in s["legs"] and shape_dist(x, inner) < 0:
                out.append(f"{w.owners[x.owner]} inside shelf {si}")
    return out


def heading_error(model, a, b):
    period = math.pi / 2 if MODELS[model]["L"] == MODELS[model]["W"] else math.pi
    return abs((a - b + period / 2) % period - period / 2)


def evaluate_scene(det, sc):
    """Runs the detector on one scene and classifies the outcome."""
    t0 = time.perf_counter()
    res = det.detect(sc["ranges"], sc["angle_min"], sc["angle_increment"], preset=sc["preset"],
                     range_min=sc["range_min"], range_max=sc["range_max"])
    dt = time.perf_counter() - t0
    dets = [dict(model=d["model"], x=float(d["x"]), y=float(d["y"]), yaw=float(d["yaw"]),
                 confidence=float(d.get("confidence", float("nan")))) for d in res["detections"]]
    shelves = sc["shelves"]

    def near(d):
        return [i for i, s in enumerate(shelves) if math.hypot(d["x"] - s["x"], d["y"] - s["y"]) <= MATCH_TOL]
    phantom = any(not near(d) for d in dets)
    rec = dict(cls=sc["cls"], seed=sc["seed"], index=sc["index"], sensor=sc["sensor"]["name"],
               noise=sc["sensor"]["noise"], findable=sc["findable"], legs_seen=sc["legs_seen"],
               n_det=len(dets), phantom=phantom, time=dt, detections=dets)
    t = sc["target"]
    if t is None:
        rec.update(outcome="clutter_detection" if dets else "none", dist=None)
        return rec
    tg = shelves[t]
    rec["dist"] = math.hypot(tg["x"], tg["y"])
    if not dets:
        rec["outcome"] = "missed"
        return rec
    d = dets[0]
    err = math.hypot(d["x"] - tg["x"], d["y"] - tg["y"])
    rec["centre_err"] = err
    if err <= MATCH_TOL:
        if d["model"] == tg["model"]:
            rec["outcome"] = "right"
            rec["heading_err"] = heading_error(tg["model"], d["yaw"], tg["yaw"])
        else:
            rec["outcome"] = "wrong_model"
    elif near(d):
        rec["outcome"] = "wrong_place"
    else:
        rec["outcome"] = "phantom_first"
    return rec


def is_failure(rec):
    if rec["phantom"]:
        return True
    if rec["cls"] == "clutter":
        return rec["outcome"] == "clutter_detection"
    if rec["findable"]:
        return rec["outcome"] != "right"
    return rec["outcome"] in ("wrong_model", "wrong_place", "phantom_first")


def dump_scene(sc, rec, d, only_model=None):
    """Writes <cls>_<seed>_<index>.scan.json (a LaserScan `shelfdock detect` reads) and
    .truth.json (shelves, preset, class, seed, sensor, noise, outcome, the command; with
    `only_model`, the command detects that model alone)."""
    os.makedirs(d, exist_ok=True)
    base = os.path.join(d, f"{sc['cls']}_{sc['seed']}_{sc['index']:04d}")
    r = sc["ranges"]
    scan = dict(angle_min=sc["angle_min"],
                angle_max=sc["angle_min"] + sc["angle_increment"] * (len(r) - 1),
                angle_increment=sc["angle_increment"], range_min=sc["range_min"],
                range_max=sc["range_max"],
                ranges=[None if not np.isfinite(v) else round(float(v), 5) for v in r],
                frame_id="lidar")
    with open(base + ".scan.json", "w") as f:
        json.dump(scan, f)
    p = sc["preset"]
    root = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    cmd = (f"{root}/build/bin/shelfdock detect --models {root}/config/models.yaml "
           f"--scan {os.path.abspath(base)}.scan.json "
           f"--preset {p[0]:.4f},{p[1]:.4f},{p[2]:.4f} --explain"
           + (f" --model {only_model}" if only_model else ""))
    truth = dict(cls=sc["cls"], seed=sc["seed"], index=sc["index"], sensor=sc["sensor"],
                 noise=sc["sensor"]["noise"], shelves=sc["shelves"], target=sc["target"],
                 preset=p, legs_seen=sc["legs_seen"], findable=sc["findable"],
                 objects=sc["objects"], outcome=rec["outcome"], phantom=rec["phantom"],
                 detections=rec["detections"], command=cmd)
    with open(base + ".truth.json", "w") as f:
        json.dump(truth, f, indent=1)


# --------------------------------------------------------------------------------------------
# Sweep
# --------------------------------------------------------------------------------------------
_DET = None
_OPTS = {}


_ONE_MODEL = {}


def _init(models, params, dump, model_opts, dump_all=False, map_knows_model=False):
    global _DET
    import shelfdock
    _DET = shelfdock.Detector(models=models, params=params)
    _ONE_MODEL.clear()
    if map_knows_model:
        # The map names the target's model too (as `shelfdock detect --model NAME` and
        # `eval-layouts --map-knows-model`): one detector per model, that model alone.
        for name in MODEL_NAMES:
            _ONE_MODEL[name] = shelfdock.Detector(models=models, params=params, only=[name])
    _OPTS["dump"] = dump
    _OPTS["dump_all"] = dump_all
    _OPTS["model"] = model_opts


def _work(task):
    cls, seed, idx = task
    sc = generate_scene(cls, seed, idx, **_OPTS.get("model", {}))
    det, only_model = _DET, None
    if _ONE_MODEL and sc["target"] is not None:
        only_model = sc["shelves"][sc["target"]]["model"]
        det = _ONE_MODEL[only_model]
    rec = evaluate_scene(det, sc)
    if _OPTS.get("dump") and (_OPTS.get("dump_all") or is_failure(rec)):
        dump_scene(sc, rec, _OPTS["dump"], only_model)
    return rec


def run(models, seed, per_class, classes=CLASSES, params=None, jobs=1, dump=None,
        spot_scale=1.0, echo="first", dump_all=False, map_knows_model=False):
    """All scenes of a sweep; returns the list of per-scene records."""
    tasks = [(c, seed, i) for c in classes for i in range(per_class)]
    mo = dict(spot_scale=spot_scale, echo=echo)
    init_args = (models, params, dump, mo, dump_all, map_knows_model)
    if jobs <= 1:
        _init(*init_args)
        return [_work(t) for t in tasks]
    import multiprocessing as mp
    with mp.get_context("fork").Pool(jobs, _init, init_args) as pool:
        return pool.map(_work, tasks, chunksize=8)


def _p95(v):
    return float(np.percentile(v, 95)) if len(v) else float("nan")


def summarise(records, classes=CLASSES):
    rows = {}
    for c in list(classes) + ["overall"]:
        rs = [r for r in records if c == "overall" or r["cls"] == c]
        if not rs:
            continue
        fin = [r for r in rs if r["findable"]]
        nf = [r for r in rs if not r["findable"] and r["cls"] != "clutter"]
        right = [r for r in fin if r["outcome"] == "right"]
        acc = [r for r in right if r["noise"] == 0.01 and r["dist"] <= 3.5]
        rows[c] = dict(
            scenes=len(rs), findable=len(fin), right=len(right),
            right_pct=100.0 * len(right) / len(fin) if fin else float("nan"),
            wrong_model=sum(r["outcome"] == "wrong_model" for r in fin),
            wrong_place=sum(r["outcome"] == "wrong_place" for r in fin),
            phantom_first=sum(r["outcome"] == "phantom_first" for r in fin),
            missed=sum(r["outcome"] == "missed" for r in fin),
            phantom_scenes=sum(r["phantom"] for r in rs),
            clutter_detections=sum(r["outcome"] == "clutter_detection" for r in rs),
            not_findable=len(nf),
            not_findable_right=sum(r["outcome"] == "right" for r in nf),
            not_findable_wrong=sum(r["outcome"] in ("wrong_model", "wrong_place", "phantom_first")
                                   for r in nf),
            acc_n=len(acc),
            centre_p95_mm=1000 * _p95([r["centre_err"] for r in acc]),
            heading_p95_mrad=1000 * _p95([r["heading_err"] for r in acc]),
            det_ms_mean=1000 * float(np.mean([r["time"] for r in rs])),
        )
    return rows


def sensor_breakdown(records):
    """right % of findable scenes per sensor (all classes)."""
    out = {}
    for sn in SENSOR_NAMES:
        fin = [r for r in records if r["sensor"] == sn and r["findable"]]
        if fin:
            out[sn] = dict(findable=len(fin), right=sum(r["outcome"] == "right" for r in fin),
                           right_pct=100.0 * sum(r["outcome"] == "right" for r in fin) / len(fin))
    return out


def format_table(rows):
    hdr = (f"{'class':<18}{'scenes':>7}{'find':>6}{'right%':>8}{'wrMod':>6}{'wrPlc':>6}"
           f"{'phF':>5}{'miss':>6}{'phant':>6}{'clut':>6}{'nf':>5}{'nfR':>5}{'nfWr':>5}"
           f"{'accN':>6}{'ctr95':>7}{'hdg95':>7}{'ms':>6}")
    lines = [hdr, "-" * len(hdr)]
    for c, r in rows.items():
        if c == "overall":
            lines.append("-" * len(hdr))
        lines.append(
            f"{c:<18}{r['scenes']:>7}{r['findable']:>6}{r['right_pct']:>8.2f}{r['wrong_model']:>6}"
            f"{r['wrong_place']:>6}{r['phantom_first']:>5}{r['missed']:>6}{r['phantom_scenes']:>6}"
            f"{r['clutter_detections']:>6}{r['not_findable']:>5}{r['not_findable_right']:>5}"
            f"{r['not_findable_wrong']:>5}{r['acc_n']:>6}{r['centre_p95_mm']:>7.1f}"
            f"{r['heading_p95_mrad']:>7.1f}{r['det_ms_mean']:>6.2f}")
    lines.append("find: findable (>= 3 target legs hit by >= 2 ideal beams); right%: first detection "
                 "right, of findable; wrMod/wrPlc/phF/miss: findable scenes whose first detection "
                 "is the wrong model / another shelf / no shelf, or none; phant: scenes with any "
                 "detection > 5 cm from every shelf; clut: clutter scenes with any detection; "
                 "nf/nfR/nfWr: not findable scenes, right anyway, wrong shelf; accN/ctr95/hdg95: "
                 "right findable scenes at 10 mm noise within 3.5 m, p95 centre error [mm] and "
                 "heading error [mrad]; ms: mean detect time.")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--models", default=os.path.join(here, "..", "config", "models.yaml"))
    ap.add_argument("--params", default=None)
    ap.add_argument("--scenes-per-class", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--classes", default=",".join(CLASSES))
    ap.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--json", default=None, help="write the tables and failing scenes here")
    ap.add_argument("--dump", default=None, help="write failing scenes (scan + truth JSON) here")
    ap.add_argument("--dump-all", action="store_true",
                    help="with --dump: every scene, not only the failing ones")
    ap.add_argument("--list-failures", action="store_true", help="print one line per failure")
    ap.add_argument("--spot-scale", type=float, default=1.0,
                    help="sensitivity: scale every beam's spot (divergence, smear, aperture)")
    ap.add_argument("--echo", choices=["first", "strongest"], default="first",
                    help="sensitivity: which echo a beam reports (default: the first one)")
    ap.add_argument("--map-knows-model", action="store_true",
                    help="the map names the target's model too: detect with that model alone "
                         "(clutter scenes with every model)")
    a = ap.parse_args(argv)
    classes = [c for c in a.classes.split(",") if c]
    for c in classes:
        if c not in CLASSES:
            ap.error(f"unknown class {c}; one of {', '.join(CLASSES)}")
    t0 = time.time()
    recs = run(os.path.abspath(a.models), a.seed, a.scenes_per_class, classes, a.params, a.jobs,
               a.dump, a.spot_scale, a.echo, a.dump_all, a.map_knows_model)
    wall = time.time() - t0
    rows = summarise(recs, classes)
    print(f"independent scenes: seed {a.seed}, {a.scenes_per_class} per class, "
          f"{len(recs)} scenes, {wall:.1f} s wall, {a.jobs} jobs"
          + (f", spot x{a.spot_scale}" if a.spot_scale != 1.0 else "")
          + (f", {a.echo} echo" if a.echo != "first" else "")
          + (", the map knows the model" if a.map_knows_model else ""))
    print(format_table(rows))
    sb = sensor_breakdown(recs)
    print("per sensor (findable, right %): " + "; ".join(
        f"{k} {v['findable']} {v['right_pct']:.2f}" for k, v in sb.items()))
    fails = [r for r in recs if is_failure(r)]
    if a.list_failures:
        for r in fails:
            d0 = r["detections"][0] if r["detections"] else None
            print(f"  {r['cls']}_{r['seed']}_{r['index']:04d} {r['sensor']} noise {r['noise']} "
                  f"legs {r['legs_seen']} {r['outcome']}{' phantom' if r['phantom'] else ''}"
                  + (f" first {d0['model']} ({d0['x']:.3f},{d0['y']:.3f})" if d0 else ""))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(dict(seed=a.seed, scenes_per_class=a.scenes_per_class, wall_s=wall,
                           spot_scale=a.spot_scale, echo=a.echo, map_knows_model=a.map_knows_model,
                           table=rows, per_sensor=sb,
                           failures=fails), f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
