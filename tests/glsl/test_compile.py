# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""glslangValidator compile matrix of glsl/pgloss.glsl: every target version x stage x
feature build (tests/glsl/compile_matrix.py), the include guard, the #error of an empty
build, and the SPIR-V size of the feature builds."""
from __future__ import annotations

import pytest

import compile_matrix as cm

CELLS = cm.matrix()


@pytest.mark.parametrize("target,stage,build", CELLS,
                         ids=[f"{t.name}-{s}-{b}" for t, s, b in CELLS])
def test_compiles(target: cm.Target, stage: str, build: str) -> None:
    r = cm.compile_one(target, stage, cm.BUILDS[build])
    assert r.returncode == 0, f"{r.stdout}{r.stderr}"


@pytest.mark.parametrize("target", cm.TARGETS, ids=[t.name for t in cm.TARGETS])
def test_include_guard(target: cm.Target) -> None:
    r = cm.compile_one(target, target.stages[0], (), twice=True)
    assert r.returncode == 0, f"{r.stdout}{r.stderr}"


def test_no_version_line() -> None:
    assert "#version" not in "\n".join(
        line for line in cm.GLSL.read_text().splitlines() if line.lstrip().startswith("#"))


def test_both_lobes_off_is_an_error() -> None:
    t = cm.TARGETS[0]
    r = cm.compile_one(t, "frag", ("PGLOSS_NO_DIFFUSE", "PGLOSS_NO_SPECULAR"))
    assert r.returncode != 0 and "leave no lobe" in r.stdout + r.stderr


def test_feature_switches_save_spirv() -> None:
    table = cm.size_table()
    print("\n" + table)
    rows = {line.split()[0]: [int(x) for x in line.split()[1:5]] for line in table.splitlines()[3:]}
    full = rows["full"]
    # shade probe, optimised: each lobe switch and the minimal build are smaller than full
    for name in ("diffuse-only", "specular-only", "eq2-only", "no-sampling", "minimal"):
        assert rows[name][3] < full[3], f"{name} does not save SPIR-V: {rows[name]} vs {full}"
    # all-functions probe: dropping the conversions removes them
    assert rows["no-perceptual"][0] < full[0]
