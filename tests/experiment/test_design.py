# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The trial order is one algorithm in two languages (pgloss/experiment/design.py for the server
and the import, static/design.js for the jsPsych study): both against java.util.SplittableRandom's
outputs (an implementation of SplitMix64 we did not write), and against each other for both
procedures, their practice trials and several seeds, including the largest."""
from __future__ import annotations

import importlib.util
import json
import shutil
import subprocess
from itertools import islice

import pytest

from conftest import ROOT

STATIC = ROOT / "bindings/python/pgloss/experiment/static"
spec = importlib.util.spec_from_file_location("design", ROOT / "bindings/python/pgloss/experiment/design.py")
design = importlib.util.module_from_spec(spec)
spec.loader.exec_module(design)

#: `new java.util.SplittableRandom(s).nextLong()` three times, printed unsigned in hex (OpenJDK 17).
JAVA = {0: [0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F],
        169: [0xEB9F627FE00EA9ED, 0x790EE0943F6F3120, 0x11F98147FDC83608]}
SEEDS = [0, 1, 42, 123456789, 2**53 - 1]
IDS = [f"s{i:02d}" for i in range(1, 13)]


def node() -> str:
    exe = shutil.which("node")
    if not exe:
        pytest.fail("no node (Debian package nodejs; scripts/test-experiment.sh installs it)")
    return exe


def test_splitmix64_is_javas():
    for state, want in JAVA.items():
        assert list(islice(design.splitmix64(state), 3)) == want
    script = (f"const d = require({json.dumps(str(STATIC / 'design.js'))});"
              "const out = {}; for (const s of [0, 169]) { const n = d.splitmix64(BigInt(s));"
              " out[s] = [n(), n(), n()].map(String); } console.log(JSON.stringify(out));")
    got = json.loads(subprocess.run([node(), "-e", script], capture_output=True, text=True, check=True).stdout)
    assert {int(k): [int(x) for x in v] for k, v in got.items()} == JAVA


def test_python_and_javascript_agree():
    script = (f"const d = require({json.dumps(str(STATIC / 'design.js'))}); const ids = {json.dumps(IDS)};"
              f"const out = []; for (const s of {json.dumps(SEEDS)}) for (const p of ['pairs', 'magnitude'])"
              " out.push([s, p, d.trials(ids, p, s), d.practice(ids, p, s)]); console.log(JSON.stringify(out));")
    got = json.loads(subprocess.run([node(), "-e", script], capture_output=True, text=True, check=True).stdout)
    assert len(got) == 2 * len(SEEDS)
    for seed, procedure, trials, practice in got:
        assert [tuple(t) for t in trials] == design.trials(IDS, procedure, seed)
        assert [tuple(t) for t in practice] == design.practice(IDS, procedure, seed)


def test_design_properties():
    pairs = design.trials(IDS, "pairs", 7)
    assert len(pairs) == 66 and len({frozenset(p) for p in pairs}) == 66
    left = sum(IDS.index(a) < IDS.index(b) for a, b in pairs)
    assert 20 < left < 46  # both placements occur
    mag = design.trials(IDS, "magnitude", 7)
    assert len(mag) == 36 and all(sorted(s for (s,) in mag[r * 12:(r + 1) * 12]) == IDS for r in range(3))
    assert design.trials(IDS, "pairs", 7) != design.trials(IDS, "pairs", 8)
    for p in design.practice(IDS, "pairs", 7):
        assert len(p) == 2 and p[0] != p[1]
    for bad in (-1, 2**53, 1.5, "1"):
        with pytest.raises(ValueError):
            design.trials(IDS, "pairs", bad)
