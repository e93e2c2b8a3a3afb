# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The OSL that MaterialX's ShaderGen made from the bridge's nodes (materialx/pgloss/
pgloss_bridge.mtlx; tests/materialx/test_materialx_bridge.py writes it to out/materialx/), in
Cycles (bpy 5.0.1):

- the <pgloss_bridge_from_perceptual> outputs, one paint per plane rendered as emission, against
  the C bridge within the errors of docs/materialx.md (as the GLSL test);
- the sample's OpenPBR and Standard Surface materials made by the nodes render like the same
  surfaces with the C bridge's own parameters, within noise (a white furnace).

Run by scripts/test-materialx.sh with .venv-bpy after the ShaderGen tests."""
from __future__ import annotations

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
sys.path[:0] = [str(ROOT / "tests" / "osl"), str(ROOT / "materialx"), str(HERE.parent)]
oslrt = pytest.importorskip("oslrt", reason="bpy (the Blender module) renders the shaders")
import bridge_graph as bg  # noqa: E402  (the C bridge through ctypes)
import bridge_paints as bp  # noqa: E402

bpy = oslrt.bpy
GENERATED = ROOT / "out" / "materialx"
MX_INCLUDE = ROOT / "build-materialx" / "mx_include"  # filled by scripts/test-materialx.sh


def _stage(name: str, tmp: Path) -> Path:
    """The generated shader next to MaterialX's genosl headers, where Cycles' compiler finds them."""
    src = GENERATED / name
    assert src.exists(), f"{src}: run the ShaderGen tests first (scripts/test-materialx.sh does)"
    for h in MX_INCLUDE.glob("*.h"):
        shutil.copy(h, tmp / h.name)
    shutil.copy(src, tmp / name)
    return tmp / name


def _render_paints(osl: Path, paints: np.ndarray, work: Path) -> np.ndarray:
    """One camera-facing unit plane per paint, its material the shader with the paint's inputs,
    rendered as emission (1 sample, box pixel filter): the output's value per paint."""
    n = len(paints)
    sc = oslrt.emission_scene(n, 4)
    mat0 = oslrt.osl_material("paint", osl)[0]
    for i, p in enumerate(paints):
        mesh = bpy.data.meshes.new(f"plane{i}")
        x0 = i - n / 2
        mesh.from_pydata([(x0, -2, 0), (x0 + 1, -2, 0), (x0 + 1, 2, 0), (x0, 2, 0)], [], [(0, 1, 2, 3)])
        obj = bpy.data.objects.new(f"plane{i}", mesh)
        sc.collection.objects.link(obj)
        mat = mat0.copy()
        script = next(node for node in mat.node_tree.nodes if node.type == "SCRIPT")
        out = next(node for node in mat.node_tree.nodes if node.type == "OUTPUT_MATERIAL")
        for key, v in zip(("lightness", "a", "b", "c", "d"), p):
            script.inputs[f"BR_{key}"].default_value = float(v)
        mat.node_tree.links.new(script.outputs[0], out.inputs["Surface"])
        mesh.materials.append(mat)
    return oslrt.render_exr(sc, work / f"{osl.stem}.exr")[1].astype(float)


def test_bridge_outputs_in_cycles_against_the_c_bridge(tmp_path: Path) -> None:
    paints = np.array(bp.paper_paints() + bp.random_paints(40, seed=11) + bp.INVALID, dtype=float)
    base = _render_paints(_stage("bridge_o_base.osl", tmp_path), paints, tmp_path)
    spec = _render_paints(_stage("bridge_o_spec.osl", tmp_path), paints, tmp_path)
    got = np.concatenate([base, spec[:, :2]], axis=1)
    print("\nbridge graph, OSL in Cycles: " + bp.check_against_c(bg, paints, got, min_reachable=35))


def _furnace(osl: Path) -> np.ndarray:
    """A sphere in a white furnace (oslrt.furnace_setup, 48 px); the 9 x 9 centre pixels' mean."""
    sc = oslrt.reset_scene()
    mat, nt, script, out = oslrt.osl_material(osl.stem, osl)
    nt.links.new(script.outputs["out"], out.inputs["Surface"])
    oslrt.furnace_setup(sc, samples=128, size=48, segments=64, rings=32).data.materials.append(mat)
    return oslrt.render_centre(sc, oslrt.WORK / "mx_bridge_furnace.exr").reshape(-1, 3).mean(axis=0)


@pytest.mark.parametrize("target", ["openpbr", "standard_surface"])
def test_bridge_surface_renders_like_the_c_parameters(target: str, tmp_path: Path) -> None:
    got = _furnace(_stage(f"M_fig14_red_{target}.osl", tmp_path))
    want = _furnace(_stage(f"M_fig14_red_{target}_c_bridge.osl", tmp_path))
    print(f"\n{target}: the bridge's nodes {got}, the C bridge's parameters {want}")
    assert np.all(want > 0.01), want
    np.testing.assert_allclose(got, want, rtol=0.02)
