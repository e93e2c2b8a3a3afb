# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The OSL that MaterialX's ShaderGen made from materialx/pgloss (tests/materialx writes it to
out/materialx/) compiles with Cycles' OSL compiler and renders in Cycles (bpy 5.0.1) like the
project's own osl/pgloss_material.osl on the same scene, within noise.

Run by scripts/test-materialx.sh with .venv-bpy after the ShaderGen tests."""
from __future__ import annotations

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tests" / "osl"))
oslrt = pytest.importorskip("oslrt", reason="bpy (the Blender module) renders the shaders")
bpy = oslrt.bpy

GENERATED = ROOT / "out" / "materialx"
MX_INCLUDE = ROOT / "build-materialx" / "mx_include"  # filled by scripts/test-materialx.sh


def _furnace(setup) -> np.ndarray:
    """A sphere in a white furnace (oslrt.furnace_setup, 48 px); the 9 x 9 centre pixels' mean."""
    sc = oslrt.reset_scene()
    oslrt.furnace_setup(sc, samples=128, size=48, segments=64, rings=32).data.materials.append(setup())
    return oslrt.render_centre(sc, oslrt.WORK / "mx_furnace.exr").reshape(-1, 3).mean(axis=0)


def _materialx_material(name: str, tmp: Path):
    src = GENERATED / f"{name}.osl"
    assert src.exists(), f"{src}: run the ShaderGen tests first (scripts/test-materialx.sh does)"
    for h in MX_INCLUDE.glob("*.h"):  # MaterialX's genosl headers next to the shader
        shutil.copy(h, tmp / h.name)
    shutil.copy(src, tmp / src.name)

    def setup():
        mat, nt, scr, out = oslrt.osl_material(name, tmp / src.name)
        nt.links.new(scr.outputs["out"], out.inputs["Surface"])
        return mat
    return setup


def _project_material(inputs: dict):
    def setup():
        mat, nt, scr, out = oslrt.osl_material("ref", oslrt.OSL_DIR / "pgloss_material.osl")
        for k, v in inputs.items():
            scr.inputs[k].default_value = v
        nt.links.new(scr.outputs["BSDF"], out.inputs["Surface"])
        return mat
    return setup


CASES = {
    "M_fig14_red": {"use_physical": False, "Lightness": 35.0, "a_star": 45.0, "b_star": 25.0,
                    "contrast_gloss": 0.06, "distinctness_gloss": 0.95},
    "M_grey": {"use_physical": True, "rho_d": (0.193, 0.193, 0.193, 1.0), "rho_s": 0.066, "alpha": 0.07},
}


@pytest.mark.parametrize("name", list(CASES))
def test_generated_osl_renders_like_the_project_shader(name: str, tmp_path: Path) -> None:
    got = _furnace(_materialx_material(name, tmp_path))
    want = _furnace(_project_material(CASES[name]))
    print(f"\n{name}: MaterialX {got}, pgloss_material.osl {want}")
    assert np.all(want > 0.01), want
    np.testing.assert_allclose(got, want, rtol=0.03)
