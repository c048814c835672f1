#!/usr/bin/env python3
"""`shelfdock eval-layouts` through the CLI: the table and JSON come out, bad input exits 2, and
every dumped failing scene (with --dump-all every scene) is reproduced by the `shelfdock detect`
command written beside it (same first detection, or none). Usage: eval_layouts_cli_test.py SHELFDOCK SOURCE WORK
"""
import json
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from cli_test_util import expect_bad_input, run


def check_reproduction(shelfdock, source, truth_file):
    truth = json.loads(truth_file.read_text())
    argv = shlex.split(truth["detect"])
    assert argv[0] == "shelfdock"
    r = subprocess.run([shelfdock] + argv[1:], cwd=source, capture_output=True, text=True,
                       check=True)
    detections = json.loads(r.stdout.splitlines()[0])["detections"]
    first = truth["first"]
    if first is None:
        assert not detections, f"{truth_file.name}: detect found {detections[0]}, sweep none"
        return
    assert detections, f"{truth_file.name}: detect found nothing, sweep {first}"
    d = detections[0]
    assert d["model"] == first["model"], f"{truth_file.name}: {d['model']} vs {first['model']}"
    assert abs(d["x"] - first["x"]) < 1e-6 and abs(d["y"] - first["y"]) < 1e-6, truth_file.name


def dump_every_scene(shelfdock, source, directory, args):
    """Runs `eval-layouts ARGS --dump-failures DIRECTORY --dump-all` (DIRECTORY emptied first),
    asserts exit 0 and returns the run and the dumped truth files, sorted."""
    shutil.rmtree(directory, ignore_errors=True)
    r = run(shelfdock, ["eval-layouts"] + args + ["--dump-failures", str(directory), "--dump-all"],
            source)
    assert r.returncode == 0, f"eval-layouts {' '.join(args)}: exit {r.returncode}\n{r.stderr}"
    return r, sorted(directory.glob("*.truth.json"))


def main():
    shelfdock, source, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    dump, report = work / "layout_failures", work / "layouts.json"
    shutil.rmtree(dump, ignore_errors=True)
    # Classes where today's detector fails often enough that something is dumped.
    r = run(shelfdock, ["eval-layouts", "--scenes-per-class", "25", "--class", "occluded_leg",
                        "--class", "clutter", "--json", str(report), "--dump-failures",
                        str(dump)], source)
    assert r.returncode == 0, f"eval-layouts: exit {r.returncode}\n{r.stdout}{r.stderr}"
    assert "occluded_leg" in r.stdout and "overall" in r.stdout, r.stdout
    doc = json.loads(report.read_text())
    assert [row["class"] for row in doc["rows"]] == ["occluded_leg", "clutter", "overall"]
    assert doc["rows"][-1]["scenes"] == 50
    truths = sorted(dump.glob("*.truth.json")) if dump.exists() else []
    assert len(truths) == len(doc["failures"]), f"{len(truths)} dumped, {len(doc['failures'])} failed"
    for t in truths:
        check_reproduction(shelfdock, source, t)
    print(f"eval-layouts: {len(truths)} failing scenes reproduced by detect")

    # --dump-all: every scene, right ones too, each reproduced the same way.
    _, truths = dump_every_scene(shelfdock, source, work / "layout_scenes",
                                 ["--scenes-per-class", "6", "--class", "open"])
    assert len(truths) == 6, f"{len(truths)} scenes dumped of 6"
    assert any(json.loads(t.read_text())["outcome"] == "right-first" for t in truths)
    for t in truths:
        check_reproduction(shelfdock, source, t)
    expect_bad_input(shelfdock, source, ["eval-layouts", "--dump-all"], "--dump-failures")

    # --map-knows-model: the target's model alone; each dumped detect line names it (--model)
    # and reproduces the sweep's first detection; the JSON says how the sweep ran.
    known_report = work / "layouts_known_model.json"
    r, truths = dump_every_scene(shelfdock, source, work / "layout_known_model",
                                 ["--scenes-per-class", "6", "--class", "against_wall",
                                  "--map-knows-model", "--json", str(known_report)])
    assert "the map names the target's model" in r.stdout, r.stdout
    assert json.loads(known_report.read_text())["map_knows_model"] is True
    assert len(truths) == 6, f"{len(truths)} scenes dumped of 6"
    for t in truths:
        truth = json.loads(t.read_text())
        assert f"--model {truth['target']['model']}" in truth["detect"], truth["detect"]
        check_reproduction(shelfdock, source, t)

    # --row-gaps: rows drawn with other gaps; each dumped scene's detect line reproduces it.
    _, truths = dump_every_scene(shelfdock, source, work / "layout_row_gaps",
                                 ["--scenes-per-class", "4", "--class", "row",
                                  "--row-gaps", "0.9", "1.1"])
    for t in truths:
        check_reproduction(shelfdock, source, t)
    expect_bad_input(shelfdock, source, ["eval-layouts", "--row-gaps", "0.5", "0.2"], "--row-gaps")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--row-gaps", "-1", "0.2"], "--row-gaps")

    # --as-built: shelves off their drawings; the dump names each leg's offset and reproduces.
    _, truths = dump_every_scene(shelfdock, source, work / "layout_as_built",
                                 ["--scenes-per-class", "2", "--class", "open",
                                  "--as-built", "0.01", "0.05"])
    assert len(truths) == 2, f"{len(truths)} scenes dumped of 2"
    for t in truths:
        truth = json.loads(t.read_text())
        legs = [leg for s in truth["shelves"] for leg in s["legs_as_built"]]
        assert len(legs) == 4 * len(truth["shelves"]), truth["shelves"]
        assert all(abs(leg["x"]) <= 0.01 and abs(leg["y"]) <= 0.01 and abs(leg["yaw"]) <= 0.05
                   for leg in legs), legs
        check_reproduction(shelfdock, source, t)
    expect_bad_input(shelfdock, source, ["eval-layouts", "--as-built", "0.1", "0"], "--as-built")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--as-built", "0.005", "-1"],
                     "--as-built")

    expect_bad_input(shelfdock, source, ["eval-layouts", "--class", "warehouse"], "--class")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--scenes-per-class", "0"],
                     "--scenes-per-class")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--lidar", "tests/data/missing_lidar.yaml"],
                     "missing_lidar.yaml")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--models", "tests/data/missing.yaml"],
                     "missing.yaml")
    expect_bad_input(shelfdock, source, ["eval-layouts", "--params",
                                         "tests/data/detector_unknown_key.yaml"],
                     "detector_unknown_key.yaml")


if __name__ == "__main__":
    main()
