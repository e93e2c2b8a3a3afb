#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Checks that two generated BENCHMARKS.md files differ only in their numbers: the same
sections, tables, rows and words in the same order. Masks every number (1,048,576; -3.1e-07;
2^20 …) and the values of the header's CPU, OS, compilers, Python and commit rows (the machine's
description; the commit's hash and its "dirty" note), collapses runs of spaces (the C tables pad their
columns to the numbers' width), then compares line by line. Exit 0 when they match; else prints
the first differing lines and exits 1.

    python bench/check_stable.py OLD NEW
"""
from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import List

MACHINE_ROWS = ("| CPU |", "| OS |", "| compilers |", "| Python |", "| commit |")
NUMBER = re.compile(r"[-+−]?(?:\d[\d,]*)?\.?\d+(?:[eE][-+]?\d+)?")


def masked(text: str) -> List[str]:
    out = []
    for line in text.splitlines():
        row = next((r for r in MACHINE_ROWS if line.startswith(r)), None)
        if row:
            line = row + " … |"
        line = NUMBER.sub("N", line)
        out.append(re.sub(r"\s+", " ", line).strip())
    return out


def main(argv: List[str]) -> int:
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-1].strip(), file=sys.stderr)
        return 2
    a, b = (masked(Path(p).read_text(encoding="utf-8")) for p in argv)
    bad = [(k, x, y) for k, (x, y) in enumerate(zip(a, b)) if x != y]
    if len(a) != len(b):
        print(f"{argv[0]}: {len(a)} lines, {argv[1]}: {len(b)} lines")
    for k, x, y in bad[:10]:
        print(f"line {k + 1}:\n  - {x}\n  + {y}")
    if bad or len(a) != len(b):
        print(f"differ beyond numbers: {len(bad)} lines" + (" (and the line counts)" if len(a) != len(b) else ""))
        return 1
    print(f"{argv[0]} and {argv[1]}: {len(a)} lines, the same but for numbers")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
