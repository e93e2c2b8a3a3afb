# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The Blender extension (blender/pgloss_paint) with the bpy 5.0.1 module: install the built
zip as an extension, create a pgloss paint material in each mode, set its inputs, check the
derived values against the shared vectors, check the validity flags, and render:

* Ward (OSL): the furnace's centre is ρd = f⁻¹(L*) (the shared vectors);
* both modes in the stimulus scene (examples/bridge/harness_cycles.py, Cycles CPU, the meter's
  sphere crop, 256 spp), read back by the image gloss meter (pgloss.image_meter, a pgloss-tracer
  Ward basis) within the bridge validation's tolerance |Δc| ≤ 0.005, |Δd| ≤ 0.01
  (docs/bridge-validation.md);
* Principled: out-of-reach paints render the nearest reachable paint, said with its status;
  gloss units and finishes give the material the virtual glossmeter reads as asked.

Run by scripts/test-blender.sh (which builds out/blender/pgloss_paint-*.zip and pgloss-tracer and
points BLENDER_USER_RESOURCES at a fresh folder)."""
from __future__ import annotations

import json
import math
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
sys.path.insert(0, str(ROOT / "examples" / "bridge"))
SCENE = ROOT / "examples" / "tracer" / "scenes" / "stimulus.scene"
TRACER = Path(os.environ.get("PGLOSS_TRACER", ROOT / "build-tracer-test" / "examples" / "tracer" / "pgloss-tracer"))
#: The meter's basis as tests/bridge renders it (the same cache: one render for both suites).
BASIS_CACHE = ROOT / "build-bridge" / "ci" / "basis"
BASIS_ALPHAS = tuple(float(a) for a in np.geomspace(0.02, 0.2, 11))
RD = 0.193
#: The bridge validation's tolerance (docs/bridge-validation.md: 1,024-spp basis, 256-spp renders).
TOL_C, TOL_D = 0.005, 0.01


def _num(x):
    return float(x) if not isinstance(x, str) else float.fromhex(x) if x.startswith(("0x", "-0x")) else float(x)


def _case(file: str, cid: str) -> dict:
    doc = json.loads((VECTORS / file).read_text())
    return next(c for c in doc["cases"] if c["id"] == cid)


@pytest.fixture(scope="module")
def addon():
    import harness_cycles

    zips = sorted((ROOT / "out" / "blender").glob("pgloss_paint-*.zip"))
    assert zips, "build it first: scripts/build-blender-addon.sh"
    return harness_cycles.install_extension(bpy, zips[-1], MODULE)


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


# ---------------------------------------------------------------------- the Principled mode
def _grey(rs: float, a: float):
    """Fig. 4's grey stimulus (ρd .193, ρs, α) as a paint (L*, 0, 0, c, d), by eqs. 3-4."""
    import pgloss

    L, c, d = (float(v) for v in pgloss.gloss_from_physical(RD, rs, a))
    return L, c, d


def test_principled_mode_writes_the_bridge_values(addon) -> None:
    import pgloss
    from pgloss import bridge

    _scene()
    assert bpy.ops.material.pgloss_paint_new(mode="PRINCIPLED") == {"FINISHED"}
    mat = bpy.context.object.active_material
    kinds = sorted(n.type for n in mat.node_tree.nodes)
    assert kinds == ["BSDF_PRINCIPLED", "OUTPUT_MATERIAL"]  # no OSL: EEVEE and Cycles on the GPU
    assert addon.paint_node(mat) is None and addon.principled_node(mat) is not None
    L, c, d = _grey(0.066, 0.07)
    p = addon.set_principled(mat, L=L, a=0.0, b=0.0, c=c, d=d)
    node = addon.principled_node(mat)
    assert node.distribution == "MULTI_GGX"
    assert p.status == 0 and mat.pgloss.status == 0 and p.exact
    # The node's inputs read back (bridge.to_paint, the forward reading) as the requested paint.
    got = {"Base Color": tuple(node.inputs["Base Color"].default_value)[:3],
           **{k: node.inputs[k].default_value for k in ("Roughness", "IOR", "Specular IOR Level")}}
    back = bridge.to_paint("principled", got).paint
    # float32 sockets: c and d to 1e-5, L* to 1e-4
    np.testing.assert_allclose(back, [L, 0, 0, c, d], atol=1e-4)
    assert node.inputs["Metallic"].default_value == 0.0
    assert all(math.isfinite(g) and g > 0 for g in mat.pgloss.readings)
    assert pgloss.__version__


#: Linear Rec. 709 → ACEScg (Bradford from D65 to the ACES white), as colour-science's
#: RGB_to_RGB(sRGB, ACEScg, chromatic_adaptation_transform="Bradford") gives it.
REC709_TO_ACESCG = np.array([[0.6131324224, 0.3395380158, 0.0474166960],
                             [0.0701243808, 0.9163940113, 0.0134515240],
                             [0.0206153959, 0.1095697616, 0.8698883771]])


def test_principled_base_color_follows_the_working_space(addon) -> None:
    """Blender 5's per-file working space: the bridge's Rec. 709 base colour is written in it, as
    Blender itself converts colours when the space changes."""
    _scene()
    bpy.ops.material.pgloss_paint_new(mode="PRINCIPLED")
    mat = bpy.context.object.active_material
    p = addon.set_principled(mat, L=30.0, a=45.0, b=30.0, c=0.08, d=0.95)
    rec709 = np.array(p.inputs["Base Color"])
    node = addon.principled_node(mat)
    np.testing.assert_allclose(node.inputs["Base Color"].default_value[:3], rec709, rtol=1e-6)
    # Blender's own conversion (its OCIO config) of the node's colour is the reference.
    assert bpy.ops.wm.set_working_color_space(working_space="ACEScg", convert_colors=True) == {"FINISHED"}
    blender = np.array(node.inputs["Base Color"].default_value[:3])
    np.testing.assert_allclose(blender, REC709_TO_ACESCG @ rec709, atol=2e-4)
    node.inputs["Base Color"].default_value = (0, 0, 0, 1)
    addon.apply_principled(mat)
    np.testing.assert_allclose(node.inputs["Base Color"].default_value[:3], blender, atol=2e-4)


def test_principled_out_of_reach_renders_the_nearest_paint(addon) -> None:
    """Fig. 12's black paint (c of the white one at L* 18.4): F0 would be below 0.01. The node gets
    the nearest reachable paint, the settings say which, with the status: never a silent clamp."""
    import pgloss
    from pgloss import bridge

    _scene()
    bpy.ops.material.pgloss_paint_new(mode="PRINCIPLED")
    mat = bpy.context.object.active_material
    rdm, rsm = pgloss.match_gloss(0.767, 0.099, pgloss.lightness_from_luminance(0.03))
    L, c, d = (float(v) for v in pgloss.gloss_from_physical(float(rdm), float(rsm), 0.04))
    p = addon.set_principled(mat, L=L, c=c, d=d)
    s = mat.pgloss
    assert s.status_name == "PGLOSS_ERR_BRIDGE_SPECULAR" and s.status == bridge.ERR_BRIDGE_SPECULAR
    assert "specular" in s.reason.lower() or "f0" in s.reason.lower(), s.reason
    reached = np.array(s.reached)
    assert reached[3] > c + 0.001 and abs(reached[4] - d) < 0.01  # more gloss than asked, the nearest
    node = addon.principled_node(mat)
    got = {"Base Color": tuple(node.inputs["Base Color"].default_value)[:3],
           **{k: node.inputs[k].default_value for k in ("Roughness", "IOR", "Specular IOR Level")}}
    # The node sits on the reach's edge (F0 0.01): its float32 IOR may round just outside, where
    # to_paint reads at the edge and says so.
    back = bridge.to_paint("principled", got, errors="status")
    assert back.status in (0, bridge.ERR_BRIDGE_SPECULAR)
    np.testing.assert_allclose(back.paint, reached, atol=1e-4)
    np.testing.assert_allclose(reached, p.reached, atol=1e-6)
    assert any("nearest reachable paint" in t for t in _panel_text(addon, mat))
    # A paint outside the model itself (beyond the envelope) leaves the node as it was, and says why.
    before = tuple(node.inputs["Base Color"].default_value)
    addon.set_principled(mat, L=50.0, c=0.9, d=0.9)
    assert s.status_name == "PGLOSS_ERR_ENVELOPE" and tuple(node.inputs["Base Color"].default_value) == before
    text = _panel_text(addon, mat)
    assert any("envelope" in t.lower() for t in text) and any("previous inputs" in t for t in text)
    assert not any("nearest reachable" in t for t in text)


class _Layout:
    """Records what a panel's draw() writes (no UI in background mode)."""

    def __init__(self, out):
        self.out, self.alert = out, False

    def label(self, text="", icon="NONE"):
        self.out.append(text)

    def prop(self, data, name, **kw):
        self.out.append(f"[{name}]")

    def operator(self, idname, **kw):
        self.out.append(f"<{idname}>")
        return type("Props", (), {})()

    def column(self, **kw):
        return self

    row = box = column


def _panel_text(addon, mat) -> list:
    out: list = []
    addon._draw_principled(_Layout(out), mat)
    return out


def test_principled_gloss_units_and_finishes(addon) -> None:
    """A 60° gloss in GU gives the material that the virtual glossmeter (ISO 2813 geometry, the
    material's own Fresnel lobe) reads so; a finish gives the middle of its MPI range."""
    from pgloss import glossmeter

    _scene()
    bpy.ops.material.pgloss_paint_new(mode="PRINCIPLED")
    mat = bpy.context.object.active_material
    node = addon.principled_node(mat)

    def g60() -> float:
        params = {"Base Color": tuple(node.inputs["Base Color"].default_value)[:3],
                  **{k: node.inputs[k].default_value for k in ("Roughness", "IOR", "Specular IOR Level")}}
        return float(glossmeter.readings_bridge("principled", params).gloss_60)

    p = addon.set_principled(mat, source="GLOSS_UNITS", L=50.0, gloss_60=30.0, d=0.93)
    assert p.status >= 0 and abs(g60() - 30.0) < 0.02, (p, g60())
    assert abs(mat.pgloss.reached[4] - 0.93) < 1e-6 and 0.0 < mat.pgloss.reached[3] < 0.3
    p = addon.set_principled(mat, source="FINISH", finish="satin")   # satin: 60° 20-35 GU
    assert p.status >= 0 and abs(g60() - 27.5) < 0.02 and "satin" in mat.pgloss.note.lower()
    p = addon.set_principled(mat, source="GLOSS_UNITS", gloss_60=99.0)  # beyond F0 0.25 at d .93
    assert p.status_name == "PGLOSS_ERR_BRIDGE_SPECULAR" and "outside" in mat.pgloss.note
    assert g60() < 99.0


@pytest.fixture(scope="module")
def basis():
    from pgloss import image_meter as im

    assert TRACER.exists(), f"{TRACER}: build pgloss-tracer first (scripts/test-blender.sh does)"
    return im.render_basis(TRACER, SCENE, RD, alphas=BASIS_ALPHAS, spp=1024, threads=2, cache=BASIS_CACHE)


def _stimulus(make, path: Path, spp: int = 256):
    """The meter's sphere crop of the stimulus scene in Cycles (examples/bridge/harness_cycles.py),
    the sphere's material made by ``make(bpy, scene_fields)`` with the add-on enabled."""
    import harness_cycles
    from pgloss import image_meter as im

    view = im.View.from_scene(SCENE.read_text())
    sc = harness_cycles.build(bpy, make, path.parent, spp=spp, seed=3, size=(view.width, view.height),
                              crop=view.crop(), threads=2, keep_preferences=True)
    sc.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)
    return im.read_linear(path)


@pytest.mark.parametrize("mode", ["PRINCIPLED", "WARD_OSL"])
@pytest.mark.parametrize("rs,a", [(0.066, 0.07), (0.099, 0.04)])
def test_renders_read_back_as_the_paint(addon, basis, tmp_path: Path, mode: str, rs: float, a: float) -> None:
    from pgloss import image_meter as im

    L, c, d = _grey(rs, a)

    def make(bpy_, fields):
        if mode == "PRINCIPLED":
            mat = addon.new_principled_material()
            addon.set_principled(mat, L=L, a=0.0, b=0.0, c=c, d=d)
            assert mat.pgloss.status == 0
        else:
            mat = addon.new_material()
            addon.set_paint(mat, L=L, a=0.0, b=0.0, c=c, d=d)
            bpy_.context.scene.cycles.shading_system = True
        return mat

    f = im.fit(_stimulus(make, tmp_path / f"{mode}.exr"), basis)
    print(f"\n{mode} paint L* {L:.2f} c {c:.4f} d {d:.4f}: read c {f.c:.4f} (Δ {f.c - c:+.4f}) "
          f"d {f.d:.4f} (Δ {f.d - d:+.4f}), residual {100 * f.residual:.1f} %")
    assert f.status == "ok", f
    assert abs(f.c - c) <= TOL_C and abs(f.d - d) <= TOL_D, f
