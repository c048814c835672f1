"""Helpers shared by the eval CLI tests in this folder (imported from the script's directory)."""
import subprocess


def run(shelfdock, args, cwd):
    return subprocess.run([shelfdock] + args, cwd=cwd, capture_output=True, text=True)


def expect_bad_input(shelfdock, source, args, must_mention):
    r = run(shelfdock, args, source)
    assert r.returncode == 2, f"{args}: exit {r.returncode}, expected 2\n{r.stdout}{r.stderr}"
    assert must_mention in r.stdout + r.stderr, f"{args}: no '{must_mention}' in\n{r.stderr}"
