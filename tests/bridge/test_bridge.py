# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The gloss bridge's instruments, CI-sized (scripts/test-bridge.sh runs this with .venv-bridge):

* the image gloss meter on pgloss-tracer Ward renders of known paints (the control: within half
  the validation tolerance, |Δc| ≤ 0.0025, |Δd| ≤ 0.005), against a small basis (α 0.02–0.2);
* its refusals (wrong size, NaN, a black sphere);
* one low-spp batch per real renderer: a Lambertian sphere agrees with pgloss-tracer's within
  noise (Mitsuba 3, Cycles); Mitsuba's own Ward reads back as its paint; the glTF importer's
  material renders as the Principled BSDF it should make; MaterialX open_pbr_surface through
  genosl in Cycles reads as a plausible (c, d) near Principled's;
* the bridge tables' model of Mitsuba's roughplastic against Mitsuba's own bsdf.eval, per direction.

The expected (c, d) come from the paper's eqs. 3–4 (pgloss.gloss_from_physical), the Lambertian
references from another renderer: nothing here is the meter's output pasted back.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import pgloss
from pgloss import image_meter as im

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples" / "bridge"))
SCENE = ROOT / "examples" / "tracer" / "scenes" / "stimulus.scene"
TRACER = Path(os.environ.get("PGLOSS_TRACER", ROOT / "build-tracer-test" / "examples" / "tracer" / "pgloss-tracer"))
WORK = ROOT / "build-bridge" / "ci"
BPY = ROOT / ".venv-bpy" / "bin" / "python"
TOOL = Path(os.environ.get("PGLOSS_TOOL", ROOT / "build-test" / "tools" / "pgloss"))
RD = 0.193
# 26 % steps over the α the tests use (interpolation error < 0.001 in d; docs/image-meter.md).
ALPHAS = tuple(float(a) for a in np.geomspace(0.02, 0.2, 11))


@pytest.fixture(scope="module")
def basis() -> im.Basis:
    assert TRACER.exists(), f"{TRACER}: build pgloss-tracer first (scripts/test-bridge.sh does)"
    return im.render_basis(TRACER, SCENE, RD, alphas=ALPHAS, spp=1024, threads=2, cache=WORK / "basis")


@pytest.fixture(scope="module")
def view() -> im.View:
    return im.View.from_scene(SCENE.read_text())


def _tracer(view: im.View, rd: float, rs: float, a: float, spp: int, seed: int) -> np.ndarray:
    text, size = im.crop_scene(SCENE.read_text(), view)
    WORK.mkdir(parents=True, exist_ok=True)
    return im.render_tracer(TRACER, im.scene_with_paint(text, im.paint_line(rd, rs, a)), spp, size, seed, 2, WORK)


#: The grey stimulus of Fig. 4 (ρd .193, ρs .066, α .07) as a paint: L*, c, d (eqs. 3-4).
GREY = tuple(float(v) for v in pgloss.gloss_from_physical(RD, 0.066, 0.07))


def _mapped(target: str, work: Path) -> dict:
    """The harness material of ``pgloss bridge TARGET`` for the grey stimulus."""
    import validate

    assert TOOL.exists(), f"{TOOL}: the pgloss tool (scripts/test-core.sh builds it)"
    params, status = validate.mapped(target, GREY[0], GREY[1], GREY[2], TOOL)
    assert status == "ok", (target, status)
    return validate.TARGETS[target][1](params, work)


def _loose(f: im.Fit, what: str) -> None:
    """A mapped paint read back at low spp: within twice the validation tolerance."""
    print(f"{what}: c {GREY[1]:.4f} -> {f.c:.4f}, d {GREY[2]:.4f} -> {f.d:.4f}, residual {f.residual:.3f}")
    assert abs(f.c - GREY[1]) <= 0.01 and abs(f.d - GREY[2]) <= 0.02, (what, f)


def test_view_is_the_stimulus_sphere(view: im.View) -> None:
    mask, cos = view.sphere()
    # A 0.5 m sphere 2.65 m from a 48° camera spans ~26 px of radius at 160 x 120: π 26² ≈ 2,120.
    assert 2000 < mask.sum() < 2250
    x0, y0, w, h = view.crop()
    assert mask[y0:y0 + h, x0:x0 + w].sum() == mask.sum()
    assert (x0 * 2 + w, y0 * 2 + h) == (view.width, view.height)  # centred


def test_report_names_the_command_that_wrote_it() -> None:
    # A generated doc must name a command that regenerates it: `all` runs both reports and each is
    # named by its own, but the value of `--paints all` is the paints, not the report.
    import validate

    argv = ["all", "--paints", "all", "--spp", "256", "--quick"]
    assert validate.command_line(argv, "table") == ["table", "--paints", "all", "--spp", "256", "--quick"]
    assert validate.command_line(["--paints", "all", "table"], "table") == ["--paints", "all", "table"]


@pytest.mark.parametrize("rs,a", [(0.066, 0.07), (0.033, 0.04), (0.099, 0.1)])
def test_meter_control_tracer_ward(basis: im.Basis, view: im.View, rs: float, a: float) -> None:
    img = _tracer(view, RD, rs, a, 512, 91)
    f = im.fit(img, basis)
    _, c, d = pgloss.gloss_from_physical(RD, rs, a)
    print(f"\nWard {RD}/{rs}/{a}: c {c:.4f} -> {f.c:.4f}, d {d:.4f} -> {f.d:.4f}, residual {f.residual:.4f}")
    assert abs(f.c - c) <= 0.0025 and abs(f.d - d) <= 0.005, f
    assert f.status == "ok" and f.residual < 0.1
    g = im.fit(img, basis, setup="rho_d-fitted")
    assert abs(g.rho_d - RD) < 0.01 and abs(g.c - c) <= 0.005 and abs(g.d - d) <= 0.01, g


def test_meter_refuses_what_it_cannot_read(basis: im.Basis, view: im.View) -> None:
    with pytest.raises(im.MeterError, match="160x120"):
        im.fit(np.ones((10, 10, 3)), basis)
    img = np.full((view.height, view.width, 3), 0.1)
    img[view.sphere()[0]] = np.nan
    with pytest.raises(im.MeterError, match="NaN"):
        im.fit(img, basis)
    with pytest.raises(im.MeterError, match="black"):
        im.fit(np.zeros((view.height, view.width, 3)), basis)
    with pytest.raises(im.MeterError, match="setup"):
        im.fit(np.ones((view.height, view.width, 3)), basis, setup="bogus")


def _sphere_mean(img: np.ndarray, view: im.View) -> float:
    return float(im.sphere_pixels(img, view).mean())


def test_mitsuba_harness(basis: im.Basis, view: im.View) -> None:
    import harness_mitsuba

    crop = view.crop()
    lam = harness_mitsuba.render({"type": "diffuse", "reflectance": RD}, spp=256, seed=5, size=(160, 120), crop=crop,
                                 threads=2)
    want = float(basis.diffuse.mean())
    print(f"\nLambertian sphere: Mitsuba {_sphere_mean(lam, view):.5f}, pgloss-tracer {want:.5f}")
    assert abs(_sphere_mean(lam, view) / want - 1) < 0.01  # per-pixel noise ~4 %, over 2,114 pixels ~0.2 %
    ward = harness_mitsuba.render({"type": "ward", "rho_d": RD, "rho_s": 0.066, "alpha": 0.07}, spp=512, seed=6,
                                  size=(160, 120), crop=crop, threads=2)
    f = im.fit(ward, basis)
    _, c, d = pgloss.gloss_from_physical(RD, 0.066, 0.07)
    print(f"Mitsuba Ward: c {c:.4f} -> {f.c:.4f}, d {d:.4f} -> {f.d:.4f}")
    assert abs(f.c - c) <= 0.005 and abs(f.d - d) <= 0.01, f
    ggx = harness_mitsuba.render(_mapped("roughplastic_ggx", WORK), spp=512, seed=8, size=(160, 120), crop=crop,
                                 threads=2)
    _loose(im.fit(ggx, basis), "Mitsuba roughplastic GGX, mapped")


def test_cycles_harnesses(basis: im.Basis, view: im.View, tmp_path: Path) -> None:
    import materialx_osl

    principled = {"type": "principled", "Base Color": RD, "Roughness": 0.3, "IOR": 1.5, "Specular IOR Level": 0.5}
    gltf = {"type": "gltf", "material": {
        "pbrMetallicRoughness": {"baseColorFactor": [RD, RD, RD, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.3},
        "extensions": {"KHR_materials_ior": {"ior": 1.5}, "KHR_materials_specular": {"specularFactor": 1.0}}}}
    openpbr = {"type": "osl", "output": "out", "file": str(materialx_osl.osl_shader(
        "open_pbr_surface", {"base_color": RD, "specular_roughness": 0.3, "specular_ior": 1.5}, tmp_path))}
    mats = {"diffuse": {"type": "diffuse", "reflectance": RD}, "principled": principled, "gltf": gltf,
            "openpbr": openpbr, **{f"mapped {t}": _mapped(t, tmp_path) for t in ("principled", "gltf", "openpbr")}}
    jobs = [{"material": m, "out": str(tmp_path / f"{k}.exr"), "spp": 512 if "mapped" in k else 256, "seed": 7}
            for k, m in mats.items()]
    (tmp_path / "jobs.json").write_text(json.dumps(jobs))
    assert BPY.exists(), f"{BPY}: scripts/test-osl.sh makes the bpy venv"
    r = subprocess.run([str(BPY), str(ROOT / "examples" / "bridge" / "harness_cycles.py"), "--jobs",
                        str(tmp_path / "jobs.json"), "--crop", ",".join(map(str, view.crop())), "--threads", "2"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-3000:]
    img = {k: im.read_linear(tmp_path / f"{k}.exr") for k in mats}
    want = float(basis.diffuse.mean())
    print(f"\nLambertian sphere: Cycles {_sphere_mean(img['diffuse'], view):.5f}, pgloss-tracer {want:.5f}")
    assert abs(_sphere_mean(img["diffuse"], view) / want - 1) < 0.01
    # The importer turns this glTF material into that Principled BSDF: the same image, same seed.
    np.testing.assert_allclose(img["gltf"], img["principled"], rtol=1e-4, atol=1e-6)
    fp, fo = im.fit(img["principled"], basis), im.fit(img["openpbr"], basis)
    print(f"Principled roughness 0.3: c {fp.c:.4f} d {fp.d:.4f}; OpenPBR (genosl): c {fo.c:.4f} d {fo.d:.4f}")
    # Both are GGX α 0.09 over a Lambertian-like base with F0 0.04: glossy, about as the paper's grey stimuli.
    for f in (fp, fo):
        assert 0.02 < f.c < 0.15 and 0.85 < f.d < 0.97 and f.status == "ok", f
    assert abs(fp.c - fo.c) < 0.02 and abs(fp.d - fo.d) < 0.02
    for t in ("principled", "gltf", "openpbr"):
        _loose(im.fit(img[f"mapped {t}"], basis), f"Cycles {t}, mapped")


GENERATOR = Path(os.environ.get("PGLOSS_BRIDGE_TABLES", ROOT / "build-test" / "tools" / "pgloss_bridge_tables"))


def _directions(n: int, rng: np.random.Generator) -> np.ndarray:
    """n pairs (wi, wo) over the upper hemisphere: half uniform, half within 0.03 rad of the
    mirror direction (where a sharp lobe lives)."""
    def hemi(k: int) -> np.ndarray:
        z, ph = rng.uniform(0.05, 1, k), rng.uniform(0, 2 * np.pi, k)
        s = np.sqrt(1 - z * z)
        return np.stack([s * np.cos(ph), s * np.sin(ph), z], axis=-1)
    wi = hemi(n)
    wo = hemi(n)
    mirror = wi[n // 2:] * np.array([-1, -1, 1]) + rng.normal(0, 0.015, (n - n // 2, 3))
    wo[n // 2:] = mirror / np.linalg.norm(mirror, axis=-1, keepdims=True)
    keep = wo[:, 2] > 0.05
    return np.concatenate([wi[keep], wo[keep]], axis=-1)


@pytest.mark.parametrize("target,paint", [("roughplastic_ggx", (0.767, 0.033, 0.04)),
                                          ("roughplastic_beckmann", (0.767, 0.033, 0.04)),
                                          ("roughplastic_ggx", (0.193, 0.066, 0.07))])
def test_roughplastic_model_is_mitsubas_bsdf_eval(target: str, paint: tuple) -> None:
    """The tables' model of roughplastic (tools/bridge_tables.c: specular F D G / (4 μi), diffuse
    t(μi) t(μo) μo / (π η² (1 − R_int)) per unit diffuse_reflectance) against Mitsuba's own
    bsdf.eval, component by component, at the parameters the bridge maps a paint to (the white
    paint maps to α 0.005 GGX, the sharpest lobe the tables hold)."""
    import harness_mitsuba

    assert GENERATOR.exists(), f"{GENERATOR}: scripts/test-bridge.sh builds pgloss_bridge_tables"
    assert TOOL.exists(), f"{TOOL}: the pgloss tool (scripts/test-core.sh builds it)"
    import validate

    L, c, d = (float(v) for v in pgloss.gloss_from_physical(*paint))
    p, status = validate.mapped(target, L, c, d, TOOL)
    assert status == "ok", (target, status)
    eta = p["int_ior"] / p["ext_ior"]
    dirs = _directions(200, np.random.default_rng(29))
    r = subprocess.run([str(GENERATOR), "--eval", target, f"{eta:.17g}", f"{p['alpha']:.17g}"],
                       input="\n".join(" ".join(f"{x:.17g}" for x in row) for row in dirs) + "\n",
                       capture_output=True, text=True, check=True)
    ours = np.array([[float(x) for x in line.split()] for line in r.stdout.splitlines()])
    if "DRJIT_LIBLLVM_PATH" not in os.environ:
        os.environ.update({"DRJIT_LIBLLVM_PATH": q for q in harness_mitsuba.LLVM_19 if os.path.exists(q)})
    import mitsuba as mi

    mi.set_variant("scalar_rgb")
    bsdf = mi.load_dict(harness_mitsuba.bsdf_dict({**p, "type": "roughplastic", "diffuse_reflectance": 1.0}))
    si = mi.SurfaceInteraction3f()
    theirs = np.zeros_like(ours)
    for k, row in enumerate(dirs):
        si.wi = mi.Vector3f(*row[:3])
        for comp in (0, 1):
            ctx = mi.BSDFContext()
            ctx.component = comp
            theirs[k, comp] = bsdf.eval(ctx, si, mi.Vector3f(*row[3:]))[0]
    spec, diff = ours[:, 0], ours[:, 1]
    big = theirs[:, 0] > 1e-3 * theirs[:, 0].max()
    worst_s, worst_d = np.max(np.abs(spec[big] / theirs[big, 0] - 1)), np.max(np.abs(diff / theirs[:, 1] - 1))
    print(f"\n{target} {paint}: alpha {p['alpha']:.4g}, eta {eta:.4f}: specular worst rel. {worst_s:.1e} "
          f"over {big.sum()} pairs, diffuse worst rel. {worst_d:.1e}")
    # Mitsuba evaluates in float (H normalised in single precision: 1e-4 of a lobe this sharp);
    # its t and R_int come from its own Gauss-Legendre quadrature (docs/bridge.md: 1e-3).
    np.testing.assert_allclose(spec[big], theirs[big, 0], rtol=1e-3)
    np.testing.assert_allclose(spec[~big], theirs[~big, 0], atol=2e-3 * theirs[:, 0].max())
    np.testing.assert_allclose(diff, theirs[:, 1], rtol=2e-3)
