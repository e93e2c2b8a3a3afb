# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The Blender extension (blender/pgloss_paint) with the bpy 5.0.1 module: install the built
zip as an extension, create a pgloss paint material, set the sliders, check the derived values
against the shared vectors, check the validity flag, and render a small image.

Run by scripts/test-blender.sh (which builds out/blender/pgloss_paint-*.zip and points
BLENDER_USER_RESOURCES at a fresh folder)."""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "osl"))
# tests/osl/oslrt.py imports bpy (and the OSL tools it bundles) and builds the furnace scene.
oslrt = pytest.importorskip("oslrt", reason="bpy (the Blender module) runs the add-on")
bpy = oslrt.bpy
oiio = oslrt.oiio
VECTORS = ROOT / "tests" / "vectors"
MODULE = "bl_ext.user_default.pgloss_paint"


def _num(x):
    return float(x) if not isinstance(x, str) else float.fromhex(x) if x.startswith(("0x", "-0x")) else float(x)


def _case(file: str, cid: str) -> dict:
    doc = json.loads((VECTORS / file).read_text())
    return next(c for c in doc["cases"] if c["id"] == cid)


@pytest.fixture(scope="module")
def addon():
    zips = sorted((ROOT / "out" / "blender").glob("pgloss_paint-*.zip"))
    assert zips, "build it first: scripts/build-blender-addon.sh"
    assert os.environ.get("BLENDER_USER_RESOURCES"), "set BLENDER_USER_RESOURCES to a scratch folder"
    r = bpy.ops.extensions.package_install_files(filepath=str(zips[-1]), repo="user_default",
                                                  enable_on_install=True)
    assert r == {"FINISHED"}
    assert MODULE in bpy.context.preferences.addons.keys()
    return sys.modules[MODULE]


def _scene(samples: int = 64, size: int = 32):
    """A white furnace (oslrt.furnace_setup) in the home file, which keeps the preferences and
    so the installed extension; the sphere is the active object."""
    bpy.ops.wm.read_homefile(use_empty=True)
    assert MODULE in bpy.context.preferences.addons.keys()
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.render.threads_mode = "FIXED"
    sc.render.threads = 2
    sc.view_settings.view_transform = "Raw"
    sc.render.resolution_percentage = 100
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.render.image_settings.color_depth = "32"
    oslrt.furnace_setup(sc, samples, size, segments=64, rings=32)
    return sc


def test_installs_and_creates_a_material(addon) -> None:
    sc = _scene()
    assert bpy.ops.material.pgloss_paint_new() == {"FINISHED"}
    ob = bpy.context.object
    mat = ob.active_material
    assert mat is not None and addon.paint_node(mat) is not None
    assert sc.cycles.shading_system  # OSL on
    node = addon.paint_node(mat)
    assert [s.name for s in node.inputs][:5] == ["L*", "a*", "b*", "c", "d"]
    script = next(n for n in node.node_tree.nodes if n.type == "SCRIPT")
    assert script.mode == "INTERNAL" and script.outputs  # compiled; travels inside the .blend


@pytest.mark.parametrize("file,cid", [("perceptual_material.json", "pm0009"), ("color_space.json", "cs0149")])
def test_derived_values_match_the_vectors(addon, file: str, cid: str) -> None:
    case = _case(file, cid)
    _scene()
    bpy.ops.material.pgloss_paint_new()
    mat = bpy.context.object.active_material
    q = case["input"]["q"]
    addon.set_paint(mat, L=_num(q["L"]), a=_num(q["a"]), b=_num(q["b"]), c=_num(q["c"]), d=_num(q["d"]),
                    space=int(case["input"].get("space", 0)))
    info = addon.derived(mat)
    e = case["expected"]
    # The sliders are float32 sockets: compare with the vectors' values at float32 inputs,
    # to the sensitivity of a float32 rounding of each input (well within 1e-5 here).
    np.testing.assert_allclose(info["rho_d"], [_num(x) for x in e["rho_d"]], rtol=1e-5, atol=1e-6)
    assert info["rho_s"] == pytest.approx(_num(e["rho_s"]), rel=1e-5)
    assert info["alpha"] == pytest.approx(_num(e["alpha_x"]), rel=1e-5)
    assert info["inside"] and info["reason"]


def test_flags_out_of_model_paints(addon) -> None:
    _scene()
    bpy.ops.material.pgloss_paint_new()
    mat = bpy.context.object.active_material
    addon.set_paint(mat, L=50.0, a=0.0, b=0.0, c=0.9, d=0.9)     # beyond the envelope (Fig. 10)
    info = addon.derived(mat)
    assert info["status"].c_name == "PGLOSS_ERR_ENVELOPE" and not info["inside"]
    assert "envelope" in info["reason"].lower()
    addon.set_paint(mat, c=0.05, b=-140.0)                        # no non-negative Rec. 709 RGB
    assert addon.derived(mat)["status"].c_name == "PGLOSS_ERR_GAMUT"
    addon.set_paint(mat, space=3)                                 # ... still outside Rec. 2020
    assert addon.derived(mat)["status"].c_name == "PGLOSS_ERR_GAMUT"
    addon.set_paint(mat, L=50.0, a=0.0, b=0.0, c=0.05, d=0.7)     # α = 0.3: a warning, inside
    info = addon.derived(mat)
    assert info["status"].c_name == "PGLOSS_WARN_ALPHA_UNTRUSTED" and info["inside"]


def test_renders_a_small_image(addon, tmp_path: Path) -> None:
    """L* = 50, a* = b* = 0, c = 0 in the furnace: the centre shows ρd = f⁻¹(50) = 0.18419
    (the shared vectors' value) in every channel."""
    sc = _scene(samples=64, size=32)
    bpy.ops.material.pgloss_paint_new()
    mat = bpy.context.object.active_material
    addon.set_paint(mat, L=50.0, a=0.0, b=0.0, c=0.0, d=0.96)
    sc.render.filepath = str(tmp_path / "paint.exr")
    bpy.ops.render.render(write_still=True)
    img = np.asarray(oiio.ImageBuf(sc.render.filepath).get_pixels(oiio.FLOAT))[:, :, :3]
    centre = img[14:19, 14:19].reshape(-1, 3).mean(axis=0)
    np.testing.assert_allclose(centre, 0.18418651851244414, rtol=0.02)
    assert img[0, 0].mean() == pytest.approx(1.0, abs=1e-3)  # the white environment around it
