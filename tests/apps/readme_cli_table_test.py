#!/usr/bin/env python3
"""Keeps the README's CLI table in step with `shelfdock --help`.

Every subcommand that `shelfdock --help` lists must have a row in the README's CLI table (the rows
whose first cell starts with the subcommand in backticks), every option its `--help` lists must
appear in one of its rows, and no row may name an option the subcommand does not have.

usage: readme_cli_table_test.py SHELFDOCK README.md
"""
import re
import subprocess
import sys


def help_text(binary, *args):
    return subprocess.run([binary, *args, "--help"], capture_output=True, text=True, check=True).stdout


def children(text):
    """The subcommands a --help text lists (none when it lists none)."""
    for marker in ("Subcommands:", "SUBCOMMANDS:"):
        if marker in text:
            section = text.split(marker, 1)[1]
            return [m.group(1) for m in re.finditer(r"^\s{2}([a-z][a-z0-9-]*)\s", section, re.M)]
    return []


def subcommands(binary):
    """Every command line's subcommand path: "detect", ..., and "eval paper" for nested ones."""
    found = []
    for sub in children(help_text(binary)):
        nested = children(help_text(binary, sub))
        found.extend(f"{sub} {child}" for child in nested) if nested else found.append(sub)
    return found


def options(binary, sub):
    text = help_text(binary, *sub.split())
    found = set(re.findall(r"^\s{2}(?:-\w,)?(--[a-z0-9][a-z0-9-]*)", text, re.M))
    found.discard("--help")
    return found


def readme_rows(readme):
    """{subcommand: [row text, ...]} from the CLI table(s) under '## CLI'."""
    text = open(readme, encoding="utf-8").read()
    cli = text.split("\n## CLI", 1)[1].split("\n## ", 1)[0]
    rows = {}
    for line in cli.splitlines():
        m = re.match(r"^\| `([a-z][a-z0-9-]*(?: [a-z][a-z0-9-]*)?)([^`]*)` \|", line)
        if m:
            rows.setdefault(m.group(1), []).append(m.group(1) + m.group(2))
    return rows


def main():
    binary, readme = sys.argv[1], sys.argv[2]
    rows = readme_rows(readme)
    problems = []
    subs = subcommands(binary)
    if not subs:
        problems.append("no subcommands found in `shelfdock --help`")
    for sub in subs:
        if sub not in rows:
            problems.append(f"README CLI table: no row for `{sub}`")
            continue
        documented = set(re.findall(r"--[a-z0-9][a-z0-9-]*", " ".join(rows[sub])))
        for opt in sorted(options(binary, sub) - documented):
            problems.append(f"README CLI table: `{sub}` row misses {opt} (listed by `shelfdock {sub} --help`)")
        for opt in sorted(documented - options(binary, sub)):
            problems.append(f"README CLI table: `{sub}` row names {opt}, which `shelfdock {sub} --help` does not list")
    for sub in sorted(set(rows) - set(subs)):
        problems.append(f"README CLI table: row for `{sub}`, which `shelfdock --help` does not list")
    for p in problems:
        print(p)
    print(f"{len(subs)} subcommands checked, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
