#!/usr/bin/env python3
"""ROS 1 bag -> scan JSON Lines -> ROS 2 MCAP -> scan JSON Lines: the ranges come back identical.

For every LaserScan topic of every real bag given: `shelfdock bag` writes the topic's scans,
tools/mcap/scans_to_mcap.mjs writes the first MAX of them as a rosbag2 MCAP file (CDR, zstd
chunks), and tools/mcap/mcap_to_scans.mjs reads them back. Ranges (null = no return), every
other field and the order must survive exactly (float32 values widened to double both ways);
the stamp within 1 ns. Also checks the topic listing and that bad input exits 2 naming the file.

usage: mcap_roundtrip_test.py SHELFDOCK NODE TOOLS_DIR WORK_DIR MAX BAG...
"""
import json
import pathlib
import shutil
import subprocess
import sys

FIELDS = ["angle_min", "angle_max", "angle_increment", "range_min", "range_max",
          "time_increment", "scan_time", "frame_id"]


def run(cmd, expect=0):
    p = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    if p.returncode != expect:
        sys.exit(f"FAIL: {' '.join(map(str, cmd))}: exit {p.returncode}, expected {expect}\n"
                 f"{p.stdout}{p.stderr}")
    return p


def read_jsonl(path):
    return [json.loads(line) for line in pathlib.Path(path).read_text().splitlines() if line]


def main():
    shelfdock, node, tools, work, max_scans = sys.argv[1:6]
    bags = sys.argv[6:]
    max_scans = int(max_scans)
    work = pathlib.Path(work) / "mcap_roundtrip"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    to_mcap = pathlib.Path(tools) / "scans_to_mcap.mjs"
    to_scans = pathlib.Path(tools) / "mcap_to_scans.mjs"
    if not bags:
        sys.exit("FAIL: no bags given")

    checked = 0
    for bag in bags:
        listing = json.loads(run([shelfdock, "bag", "--bag", bag]).stdout)
        topics = [t["topic"] for t in listing["laser_scan_topics"]]
        if not topics:
            sys.exit(f"FAIL: {bag}: no LaserScan topic")
        for i, topic in enumerate(topics):
            stem = f"{pathlib.Path(bag).stem}_{i}"
            ros1 = work / f"{stem}_ros1.jsonl"
            mcap = work / f"{stem}.mcap"
            back = work / f"{stem}_ros2.jsonl"
            run([shelfdock, "bag", "--bag", bag, "--topic", topic, "--out", ros1])
            run([node, to_mcap, "--scans", ros1, "--topic", topic, "--out", mcap,
                 "--max", max_scans])
            listed = json.loads(run([node, to_scans, mcap]).stdout)["laser_scan_topics"]
            expected = read_jsonl(ros1)[:max_scans]
            if listed != [{"topic": topic, "messages": len(expected)}]:
                sys.exit(f"FAIL: {mcap}: topic listing {listed}")
            run([node, to_scans, mcap, "--topic", topic, "--out", back])
            got = read_jsonl(back)
            if len(got) != len(expected):
                sys.exit(f"FAIL: {bag} {topic}: {len(got)} scans back, {len(expected)} written")
            for k, (a, b) in enumerate(zip(expected, got)):
                if a["ranges"] != b["ranges"]:
                    bad = next(j for j, (x, y) in enumerate(zip(a["ranges"], b["ranges"]))
                               if x != y) if len(a["ranges"]) == len(b["ranges"]) else "length"
                    sys.exit(f"FAIL: {bag} {topic} scan {k}: ranges differ at {bad}")
                for f in FIELDS:
                    if a[f] != b[f]:
                        sys.exit(f"FAIL: {bag} {topic} scan {k}: {f} {a[f]} != {b[f]}")
                if abs(a["stamp"] - b["stamp"]) > 1e-9 * max(1.0, abs(a["stamp"])) + 1e-9:
                    sys.exit(f"FAIL: {bag} {topic} scan {k}: stamp {a['stamp']} != {b['stamp']}")
                if a.get("intensities") != b.get("intensities"):
                    sys.exit(f"FAIL: {bag} {topic} scan {k}: intensities differ")
            checked += len(got)
            print(f"{bag} {topic}: {len(got)} scans identical after the round trip")

    # Bad input: exit 2 and the message names what is wrong (a recording cut off in the middle
    # has no summary to index it by).
    cut = work / "cut.mcap"
    cut.write_bytes(mcap.read_bytes()[: mcap.stat().st_size // 2])
    for cmd, needle in [([node, to_scans, work / "missing.mcap"], "missing.mcap"),
                        ([node, to_scans, ros1], "not a readable MCAP file"),
                        ([node, to_scans, cut], "without its summary"),
                        ([node, to_scans, mcap, "--topic", "/nope"], "/nope"),
                        ([node, to_mcap, "--scans", work / "missing.jsonl", "--topic", "/s",
                          "--out", work / "x.mcap"], "missing.jsonl")]:
        err = run(cmd, expect=2).stderr
        if needle not in err:
            sys.exit(f"FAIL: {cmd}: message {err!r} does not name {needle!r}")
    print(f"mcap round trip: {checked} scans identical")


if __name__ == "__main__":
    main()
