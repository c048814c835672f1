"""The detector on the independent scene generator (scripts/independent_scenes.py), a generator
written from the specification alone, without the repository's own simulator.

It draws a modest fixed-seed set (30 scenes per class) and asserts only what must hold on ANY
realistic generator: no phantom shelf in any scene, no detection at all in clutter scenes,
and that reading the scan's bloom finds what strict leg widths miss (the real target,
99.5 %, is reported by the script, not asserted).  It also checks the generator itself: its
scenes are physically possible and its sensor model returns what its docstring says.

The module is located as conftest.py does (SHELFDOCK_PYTHON_DIR, else build/python); the
generator is loaded by path from the source tree.
"""
import json
import math

import numpy as np
import pytest

SEED = 7
PER_CLASS = 30


@pytest.fixture(scope="module")
def gen(load_script):
    return load_script("independent_scenes")


@pytest.fixture(scope="module")
def records(gen, models):
    pytest.importorskip("shelfdock")
    return gen.run(str(models), SEED, PER_CLASS, jobs=1)


def test_sensor_model_single_surface_and_edges(gen):
    """One surface returns its range; a depth edge blends only when the depths are close,
    and a weak sliver of a near surface is not seen in front of a far one."""
    sig = 0.1
    K = 15
    one = gen.discriminate(np.full((1, K), 2.0), np.full((1, K), 50.0 / K),
                           np.zeros((1, K), int), sig)[0]
    assert abs(one - 2.0) < 1e-6
    # near surface on 5 of 15 sub-rays, far one 5 cm behind: a blend between the two
    R = np.full((1, K), 2.05)
    R[0, :5] = 2.0
    A = np.full((1, K), 0.2)          # weak: neither part alone is far above the threshold
    own = (R > 2.0).astype(int)
    r = gen.discriminate(R, A, own, sig)[0]
    assert 2.0 < r < 2.05
    # far one 2 m behind and the near sliver below the threshold: the far surface, unblended
    R = np.full((1, K), 4.0)
    R[0, :1] = 2.0
    A = np.full((1, K), 0.5)
    r = gen.discriminate(R, A, (R > 2.0).astype(int), sig)[0]
    assert abs(r - 4.0) < 1e-3
    # nothing over the threshold: no return
    r = gen.discriminate(np.full((1, K), 3.0), np.full((1, K), 0.5 / K), np.zeros((1, K), int),
                         sig)[0]
    assert math.isnan(r)


def test_scenes_are_physically_possible(gen):
    bad = []
    for cls in gen.CLASSES:
        for i in range(PER_CLASS):
            sc = gen.generate_scene(cls, SEED, i)
            problems = gen.check_physical(sc)
            if problems:
                bad.append((cls, i, problems[:2]))
            if cls == "clutter":
                assert sc["target"] is None and not sc["shelves"]
            else:
                assert len(sc["legs_seen"]) == 4
    assert not bad, bad


def test_scenes_are_reproducible(gen):
    a = gen.generate_scene("aisle", SEED, 3)
    b = gen.generate_scene("aisle", SEED, 3)
    np.testing.assert_array_equal(a["ranges"], b["ranges"])
    assert a["preset"] == b["preset"]


def test_no_phantom_anywhere(gen, records):
    phantoms = [(r["cls"], r["index"], r["detections"]) for r in records if r["phantom"]]
    assert not phantoms, phantoms


def test_no_detection_in_clutter(gen, records):
    hits = [(r["index"], r["detections"]) for r in records
            if r["cls"] == "clutter" and r["n_det"] > 0]
    assert not hits, hits


def test_the_scans_bloom_read_finds_what_strict_widths_miss(gen, records, models, source_dir, tmp_path):
    """This generator's receiver reports a beam's first echo above a threshold from a finite spot,
    so its legs look 15-40 mm wider than they stand. The detector reads that bloom off the scan's
    thin objects (evidence.width_bloom_max_rad); with it off, the legs' width evidence takes most
    shelves for posts. Seed 7, 30 scenes per class: right first must gain at least 10 points of
    the findable scenes, lose at most one scene found without it, and add no phantom (the target,
    99.5 %, is not met on this generator: 90.4 % on seed 1 with 200 per class; see README). The
    scenes lost are counted with the bloom read for the leg widths alone: the model choice reads
    the bloom too (shelf_fit.one_edge_bloom_share), a trade measured on thousands of scenes
    (docs/detector_history.md, thirty-sixth session; here it costs against_wall 3)."""
    strict = _params_with(source_dir, tmp_path, "  width_bloom_max_rad: 0.02", "0.0")
    widths_only = _params_with(source_dir, tmp_path, "  one_edge_bloom_share: 0.5", "0.0")
    without = gen.run(str(models), SEED, PER_CLASS, params=str(strict), jobs=1)
    for_widths = gen.run(str(models), SEED, PER_CLASS, params=str(widths_only), jobs=1)
    with_rows, without_rows = gen.summarise(records), gen.summarise(without)
    print("\nbloom read:\n" + gen.format_table(with_rows))
    print("strict widths:\n" + gen.format_table(without_rows))
    assert with_rows["overall"]["findable"] >= 0.6 * len(records)
    assert with_rows["overall"]["right_pct"] >= without_rows["overall"]["right_pct"] + 10.0
    lost = [(a["cls"], a["index"]) for a, b in zip(for_widths, without)
            if b["outcome"] == "right" and a["outcome"] != "right"]
    assert len(lost) <= 1, lost


def test_dump_all_writes_every_scene_with_its_outcome(gen, models, tmp_path):
    """--dump-all writes every scene, not only the failing ones, each truth file with the outcome
    the sweep recorded for it (2 scenes of two classes)."""
    pytest.importorskip("shelfdock")
    recs = gen.run(str(models), SEED, 2, classes=["open", "clutter"], jobs=1, dump=str(tmp_path),
                   dump_all=True)
    truths = sorted(tmp_path.glob("*.truth.json"))
    assert len(truths) == len(recs) == 4
    by_name = {f"{r['cls']}_{r['seed']}_{r['index']:04d}": r["outcome"] for r in recs}
    for t in truths:
        name = t.name[: -len(".truth.json")]
        assert (tmp_path / f"{name}.scan.json").exists()
        assert json.loads(t.read_text())["outcome"] == by_name[name]


def _params_with(source_dir, tmp_path, setting, value):
    """A copy of config/detector.yaml (in tmp_path) with its `setting` line ("  key: value",
    asserted there) set to `value`; its path."""
    config = (source_dir / "config" / "detector.yaml").read_text()
    assert setting in config
    key = setting.split(":")[0]
    path = tmp_path / f"{key.strip()}_{value}.yaml"
    path.write_text(config.replace(setting, f"{key}: {value}"))
    return path


def _with_and_without(gen, models, source_dir, tmp_path, setting, off_value, scene):
    """One independent scene (class, seed, index) scored by the default detector and by one with
    config/detector.yaml's `setting` line ("  key: value", asserted there) set to `off_value`.
    Returns the scene and the two records."""
    shelfdock = pytest.importorskip("shelfdock")
    off = _params_with(source_dir, tmp_path, setting, off_value)
    sc = gen.generate_scene(*scene)
    rule = gen.evaluate_scene(shelfdock.Detector(models=str(models)), sc)
    without = gen.evaluate_scene(shelfdock.Detector(models=str(models), params=str(off)), sc)
    return sc, rule, without


def _assert_found_only_with_rule(gen, sc, rule, without, sensor, without_outcome="missed"):
    """The findable scene, seen by `sensor`, is right first within the match tolerance with the
    rule (`rule`) and `without_outcome` (missed, by default) with it off (`without`), as
    _with_and_without returns them."""
    assert sc["findable"] and sc["sensor"]["name"] == sensor
    assert rule["outcome"] == "right", rule
    assert rule["centre_err"] <= gen.MATCH_TOL
    assert without["outcome"] == without_outcome, without


def test_a_noise_spike_on_an_edge_line_is_no_leg(gen, models, source_dir, tmp_path):
    """Scene 19 of against_wall, seed 2001: a 1250x1250 against a wall, seen by a UST-10LX at
    20 mm noise. One wall return 9 cm (4.5 times the noise) nearer than its neighbours lies on
    the shelf's back edge line: one return with a depth step behind it on both sides, what a thin
    leg seen by one beam looks like. A step within evidence.edge_lone_step_sigmas (5) times the
    noise (x sqrt 2) is the noise's tail, no leg: the shelf is returned first, within 5 cm, its
    model. With the rule off (0) the spike counts as a neighbour's leg under the shelf's edge and
    the shelf is missed."""
    sc, rule, without = _with_and_without(gen, models, source_dir, tmp_path,
                                          "  edge_lone_step_sigmas: 5.0", "0.0",
                                          ("against_wall", 2001, 19))
    _assert_found_only_with_rule(gen, sc, rule, without, "ust10lx")


def test_a_blend_needs_something_to_blend_with(gen, models, source_dir, tmp_path):
    """Scene 22 of against_wall, seed 1001: three round-legged 900x810 shelves in a row against
    a wall, seen by a TiM571 at 20 mm noise, the target's back legs flush with the wall (not
    findable). Completing two of the target's legs, the search blended a third shelf's leg 0.29 m
    behind one corner and a wall piece 0.17 m behind the other into a 1075x883 standing 16 cm off
    the target: a phantom. A pulsed receiver blends a leg only with what stands within a pulse's
    length behind it, and the wall beside those returns stands 1.5 m behind the corners: with
    completion.blend_partner_max_m (0.8 m) nothing is returned there; with it off (0) the phantom
    is."""
    sc, rule, without = _with_and_without(gen, models, source_dir, tmp_path,
                                          "  blend_partner_max_m: 0.8", "0.0",
                                          ("against_wall", 1001, 22))
    assert not sc["findable"] and sc["sensor"]["name"] == "tim571"
    assert not rule["phantom"], rule
    assert without["phantom"], without


def test_one_return_near_the_sensor_is_no_leg(gen, models, source_dir, tmp_path):
    """Scene 1 of round_noisy, seed 2001: a round-legged 900x810 seen by a TiM571 at 20 mm
    noise, one return 1.5 m away in mid-air (an outlier) on its edge line, where a 26 mm leg
    spans three beams. A leg that near returns from two beams or more
    (evidence.edge_lone_max_beams, 2): the return is no neighbour's leg and the shelf is returned
    first, within 5 cm, its model. With the rule off (0) the outlier costs the shelf its
    confidence and it is missed."""
    sc, rule, without = _with_and_without(gen, models, source_dir, tmp_path,
                                          "  edge_lone_max_beams: 2.0", "0.0",
                                          ("round_noisy", 2001, 1))
    _assert_found_only_with_rule(gen, sc, rule, without, "tim571")


def test_a_leg_placed_by_its_bloomed_edge_does_not_choose_the_model(gen, models, source_dir,
                                                                      tmp_path):
    """Scene 21 of row, seed 1001: a 1080x856 in a row, seen by a WLR-716 at 20 mm noise. One of
    its legs shows one outline edge (its other side behind a neighbour's nearer leg), bloomed by
    the beam's spot: fitted against that edge it sits 2 cm off across its beam, and on the legs'
    chi-square as fitted that leg chose the 1075x883. With shelf_fit.one_edge_bloom_share
    (0.5) its std across the beam is widened by half the bloom the shelf's legs show, and the
    other legs choose: the 1080x856 is returned first, within 5 cm; with it off (0) the
    1075x883 is, at the right place."""
    sc, rule, without = _with_and_without(gen, models, source_dir, tmp_path,
                                          "  one_edge_bloom_share: 0.5", "0.0",
                                          ("row", 1001, 21))
    assert sc["shelves"][sc["target"]]["model"] == "t1-rect-1080x856"
    _assert_found_only_with_rule(gen, sc, rule, without, "wlr716", without_outcome="wrong_model")


def test_the_map_naming_the_model_leaves_no_model_confusion(gen, records, models):
    """With --map-knows-model each target scene is detected with its model alone (clutter scenes
    with every model). Over the fixture's scenes, the scenes whose first detection stood at the
    target with the other close model (1075x883 / 1080x856, told apart by 5 and 27 mm) are run
    again that way: none is the wrong model then (it cannot be), each is right (its model, centre
    within 5 cm of the truth), and no scene anywhere shows a phantom. The seed's scenes must hold
    at least one such confusion, or the test would prove nothing."""
    confused = [r for r in records if r["outcome"] == "wrong_model"]
    assert confused, "the fixture's scenes hold no model confusion to clear"
    classes = sorted({r["cls"] for r in confused})
    known = gen.run(str(models), SEED, PER_CLASS, classes=classes, jobs=1, map_knows_model=True)
    by_scene = {(r["cls"], r["index"]): r for r in known}
    for r in confused:
        again = by_scene[(r["cls"], r["index"])]
        assert again["outcome"] == "right", (r["cls"], r["index"], again["outcome"],
                                             again["detections"])
    assert not [r for r in known if r["phantom"] or r["outcome"] == "wrong_model"]


def test_a_beams_spot_reaches_the_front_of_a_leg_it_passes(gen, records, models, source_dir,
                                                           tmp_path):
    """This generator's beams return a thin leg they pass within their spot. A leg turned a little
    from square to the beams shows its back corner as its outline's edge; a bloomed return past it
    came from the leg's front, a leg's depth nearer. Measured against the back corner it pulled the
    shelf toward the sensor (1 mm per metre of range on seeds 1-2001); with
    shelf_fit.spot_bloom_share (0.5: half the bloom on each side of the beam) the fit on the legs'
    returns measures it against the nearest corner the spot reaches. Seed 7, 30 scenes per class:
    the right-first scenes' RMS centre error 4.48 mm with it, 4.89 mm with it off (0). Asserted:
    lower with it, no phantom either way, and at most one right-first scene fewer."""
    off = _params_with(source_dir, tmp_path, "  spot_bloom_share: 0.5", "0.0")
    without = gen.run(str(models), SEED, PER_CLASS, params=str(off), jobs=1)

    def rms(recs):
        e = [r["centre_err"] for r in recs if r["outcome"] == "right"]
        return math.sqrt(sum(x * x for x in e) / len(e)), len(e)

    (with_rms, with_n), (without_rms, without_n) = rms(records), rms(without)
    print(f"\nRMS centre error {with_rms * 1e3:.2f} mm over {with_n} scenes with the spot, "
          f"{without_rms * 1e3:.2f} mm over {without_n} without")
    assert with_rms < without_rms
    assert with_n >= without_n - 1
    assert not [r for r in without if r["phantom"]]
