#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The GLSL and OSL lobes follow the C core's float lobe step by step.

The C lobe (libpgloss/include/pgloss/detail/lobe.h, eval_pdf_unit) marks its steps in its body
as comments "N. title"; glsl/pgloss.glsl (pgloss_impl_eval_pdf) and osl/pgloss.h
(pgloss__eval_pdf_unit) must carry the same steps, numbered and titled alike, in the same
order. A step added, removed, renumbered or renamed in one of them fails this check until the
others follow.   python3 tests/shader_steps.py [ROOT]
"""
from __future__ import annotations

import re
import sys
from pathlib import Path

ROOT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[1]
LOBES = {
    "C": ("libpgloss/include/pgloss/detail/lobe.h", "PGLOSS_K(eval_pdf_unit)("),
    "GLSL": ("glsl/pgloss.glsl", "void pgloss_impl_eval_pdf("),
    "OSL": ("osl/pgloss.h", "void pgloss__eval_pdf_unit("),
}
STEP = re.compile(r"(?:/\*|//)\s*(\d+)\.\s+([^*\n]*?)\s*(?:\*/|$)", re.M)


def body(text: str, signature: str) -> str:
    """The function's text from its signature to the closing brace of its body."""
    start = text.index(signature)
    depth, k = 0, text.index("{", start)
    for k in range(k, len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0:
            return text[start:k + 1]
    raise SystemExit(f"{signature}: no end of body")


def steps(name: str) -> list[tuple[int, str]]:
    path, signature = LOBES[name]
    found = [(int(n), t) for n, t in STEP.findall(body((ROOT / path).read_text(encoding="utf-8"), signature))]
    if [n for n, _ in found] != list(range(1, len(found) + 1)) or not found:
        raise SystemExit(f"{name} ({path}): steps {[n for n, _ in found]} are not 1..N in order")
    return found


def main() -> int:
    want = steps("C")
    bad = 0
    for name in ("GLSL", "OSL"):
        got = steps(name)
        if got != want:
            bad += 1
            print(f"{name} ({LOBES[name][0]}) drifts from the C lobe:")
            for k in range(max(len(got), len(want))):
                g = got[k] if k < len(got) else None
                w = want[k] if k < len(want) else None
                print(f"  {'ok ' if g == w else 'BAD'} C {w}  {name} {g}")
    if not bad:
        print(f"GLSL and OSL follow the C lobe's {len(want)} steps: " + "; ".join(f"{n}. {t}" for n, t in want))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
