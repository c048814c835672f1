#!/usr/bin/env python3
"""Long commands show progress on a terminal and stay quiet otherwise.

Runs `shelfdock eval-docking --runs 2` twice: with stderr captured (a pipe) it must print nothing
there; with stderr on a pseudo-terminal it must draw the counter up to 2/2. stdout is the same
JSON summary both times.

usage: progress_test.py SHELFDOCK REPO_ROOT
"""
import json
import os
import pty
import subprocess
import sys

binary, root = sys.argv[1], sys.argv[2]
args = [binary, "eval-docking", "--runs", "2", "--method", "continuous", "--seed0", "7"]

piped = subprocess.run(args, cwd=root, capture_output=True, text=True)
failures = []
if piped.returncode != 0:
    failures.append(f"eval-docking exited {piped.returncode}: {piped.stderr}")
if piped.stderr != "":
    failures.append(f"stderr is not a terminal, yet eval-docking wrote to it: {piped.stderr!r}")

leader, follower = pty.openpty()
tty = subprocess.Popen(args, cwd=root, stdout=subprocess.PIPE, stderr=follower)
os.close(follower)
drawn = b""
while True:
    try:
        chunk = os.read(leader, 4096)
    except OSError:  # the pty closes when the process exits
        break
    if not chunk:
        break
    drawn += chunk
out = tty.stdout.read()
tty.wait()
os.close(leader)
text = drawn.decode(errors="replace")
if "eval-docking 2/2" not in text:
    failures.append(f"on a terminal, no '2/2' counter on stderr: {text!r}")
if tty.returncode != 0:
    failures.append(f"eval-docking on a terminal exited {tty.returncode}")
try:
    a, b = json.loads(piped.stdout), json.loads(out)
    if a != b:
        failures.append("stdout differs between the terminal and the piped run")
except json.JSONDecodeError as e:
    failures.append(f"stdout is not one JSON document: {e}")

for f in failures:
    print("FAIL", f)
print("ok" if not failures else f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
