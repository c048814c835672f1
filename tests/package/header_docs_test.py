#!/usr/bin/env python3
"""Every declaration at namespace scope in the installed (public) headers is documented with ///.

A declaration counts as documented when the block of declaration lines it belongs to (lines up
to the previous blank line, e.g. a group of overloads or of one-line helpers) starts right after
a /// comment, or when the line carries a ///< comment. Class members are not checked here.
usage: header_docs_test.py SOURCE_DIR
"""
import pathlib
import re
import sys

LAYERS = ["geometry", "perception", "sim", "docking", "eval", "io"]
DECL = re.compile(r"(struct|class|enum class|enum)\s+\w+|(inline |constexpr )|"
                  r"[\w:<>,\s\*&]+\s[\*&]?\w+\(")


def undocumented(header):
    lines = header.read_text().splitlines()
    for i, line in enumerate(lines):
        if not line or line[0] in " #/}" or line.startswith(("namespace", "using ", "template")):
            continue
        if not DECL.match(line) or "///" in line:
            continue
        if re.match(r"(struct|class) \w+;$", line):  # forward declaration
            continue
        j = i - 1
        while j >= 0 and lines[j] and not lines[j].startswith(("///", "};")):
            j -= 1
        if j < 0 or not lines[j].startswith("///"):
            yield f"{header}:{i + 1}: {line.strip()}"


def main():
    source = pathlib.Path(sys.argv[1])
    bad = [b for layer in LAYERS for h in sorted((source / "src" / layer).glob("*.hpp"))
           for b in undocumented(h)]
    for b in bad:
        print(f"undocumented: {b}")
    headers = sum(len(list((source / "src" / layer).glob("*.hpp"))) for layer in LAYERS)
    if bad:
        sys.exit(f"FAIL: {len(bad)} public declarations without a /// comment")
    print(f"{headers} public headers: every namespace-scope declaration documented with ///")


if __name__ == "__main__":
    main()
