#!/usr/bin/env python3
"""The installed package, as another team uses it.

1. `cmake --install` into a temporary prefix puts the CLI, the libraries, the headers, the
   default configs and the CMake package there.
2. The README's library example (its CMakeLists.txt and main.cpp, cut from README.md between
   the library-example markers) is configured against that prefix with find_package(shelfdock),
   built, and run on the installed example scan: it must print the shelf the simulator placed
   there (t1-rect-1075x883 at (2.0, 0.2) m, yaw 0.1 rad; tests/perception/make_example_scan.cpp)
   within 20 mm / 20 mrad.
3. The installed CLI, run from an unrelated working directory without --models, finds its
   default configs in the install and finds the same shelf; its --help names where it looks;
   SHELFDOCK_CONFIG_DIR comes first when set. The build tree's CLI also runs from anywhere.

usage: install_test.py CMAKE GENERATOR BUILD_DIR SOURCE_DIR WORK_DIR
"""
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys

TRUE_MODEL, TRUE_X, TRUE_Y, TRUE_YAW = "t1-rect-1075x883", 2.0, 0.2, 0.1
TOL_M, TOL_RAD = 0.020, 0.020


def run(cmd, cwd=None, env=None, expect=0):
    p = subprocess.run([str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True)
    if p.returncode != expect:
        sys.exit(f"FAIL: {' '.join(map(str, cmd))} (in {cwd}): exit {p.returncode}\n"
                 f"{p.stdout}\n{p.stderr}")
    return p.stdout


def check_pose(what, model, x, y, yaw):
    err_xy = math.hypot(x - TRUE_X, y - TRUE_Y)
    err_yaw = abs(math.remainder(yaw - TRUE_YAW, math.pi))
    if model != TRUE_MODEL or err_xy > TOL_M or err_yaw > TOL_RAD:
        sys.exit(f"FAIL: {what}: {model} ({x}, {y}, {yaw}) is not the true shelf")
    print(f"{what}: {model}, centre error {err_xy * 1000:.1f} mm, heading {err_yaw * 1000:.1f} mrad")


def readme_block(readme, lang, marker):
    text = readme.read_text()
    section = re.search(rf"<!-- {marker}:begin -->(.*?)<!-- {marker}:end -->", text, re.S)
    if not section:
        sys.exit(f"FAIL: {readme}: no {marker} markers")
    block = re.search(rf"```{lang}\n(.*?)```", section.group(1), re.S)
    if not block:
        sys.exit(f"FAIL: {readme}: no ```{lang} block between the {marker} markers")
    return block.group(1)


def main():
    cmake, generator, build, source, work = sys.argv[1:6]
    build, source, work = pathlib.Path(build), pathlib.Path(source), pathlib.Path(work)
    work = work / "install_test"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    prefix = work / "prefix"

    # 1. Install.
    run([cmake, "--install", build, "--prefix", prefix])
    config = prefix / "share/shelfdock/config"
    for rel in ["bin/shelfdock", "lib/cmake/shelfdock/shelfdockConfig.cmake",
                "lib/cmake/shelfdock/shelfdockTargets.cmake", "lib/libshelfdock_perception.a",
                "include/shelfdock/perception/detector.hpp", "include/shelfdock/io/models_yaml.hpp",
                "share/shelfdock/config/models.yaml", "share/shelfdock/config/detector.yaml",
                "share/shelfdock/config/lidar_wlr716.yaml", "share/shelfdock/config/robot.yaml",
                "share/shelfdock/config/camera.yaml", "share/shelfdock/config/docking.yaml",
                "share/shelfdock/config/scenarios/paper_docking.yaml"]:
        if not (prefix / rel).is_file():
            sys.exit(f"FAIL: {rel} not installed")

    # 2. The README's library example, built against the install.
    outside = work / "outside"
    outside.mkdir()
    (outside / "CMakeLists.txt").write_text(readme_block(source / "README.md", "cmake",
                                                         "library-example"))
    (outside / "main.cpp").write_text(readme_block(source / "README.md", "cpp",
                                                   "library-example"))
    run([cmake, "-S", outside, "-B", outside / "build", "-G", generator,
         "-DCMAKE_BUILD_TYPE=Release", f"-DCMAKE_PREFIX_PATH={prefix}"])
    run([cmake, "--build", outside / "build"])
    exe = outside / "build" / "find_shelf"
    out = run([exe, config / "models.yaml", config / "example_scan.json"], cwd=work)
    first = out.split("\n")[0].split()
    if len(first) != 5 or first[0] != "scan":
        sys.exit(f"FAIL: the library example printed {out!r}")
    check_pose("README library example", first[1], *map(float, first[2:5]))

    # 3. The installed CLI from an unrelated directory, default models from the install.
    elsewhere = work / "elsewhere"
    elsewhere.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "SHELFDOCK_CONFIG_DIR"}
    line = json.loads(run([prefix / "bin/shelfdock", "detect", "--scan",
                           config / "example_scan.json"], cwd=elsewhere, env=env))
    d = line["detections"][0]
    check_pose("installed CLI, default models", d["model"], d["x"], d["y"], d["yaw"])
    help_text = run([prefix / "bin/shelfdock", "detect", "--help"], cwd=elsewhere, env=env)
    if str(config) not in help_text:
        sys.exit(f"FAIL: detect --help does not name {config}:\n{help_text}")
    custom = work / "my_config"
    custom.mkdir()
    shutil.copy(config / "models.yaml", custom / "models.yaml")
    help_text = run([prefix / "bin/shelfdock", "detect", "--help"], cwd=elsewhere,
                    env={**env, "SHELFDOCK_CONFIG_DIR": str(custom)})
    if str(custom / "models.yaml") not in help_text:
        sys.exit(f"FAIL: with SHELFDOCK_CONFIG_DIR the default models are not {custom}")
    line = json.loads(run([build / "bin/shelfdock", "detect", "--scan",
                           config / "example_scan.json"], cwd=elsewhere, env=env))
    d = line["detections"][0]
    check_pose("build-tree CLI from another directory", d["model"], d["x"], d["y"], d["yaw"])


if __name__ == "__main__":
    main()
