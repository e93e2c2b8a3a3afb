# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Renders Fig. 12 of Pellacini, Ferwerda & Greenberg (SIGGRAPH 2000) in Cycles with
osl/pgloss_material.osl: the paper's stimulus — a sphere in a checkerboard box (diffuse
checks ρd = 0.03 and 0.767) under an overhead area light — for white, grey and black spheres
(ρd = 0.767, 0.193, 0.03: Munsell N9, N5, N2):

  top row     the same physical gloss, ρs = 0.099, α = 0.04 (the shader's physical inputs);
  bottom row  the same perceptual gloss: c and d of the white sphere (c ≈ 0.057, d = 0.96) at
              each sphere's lightness L* (the shader's perceptual inputs), which is
              pgloss_match_gloss (§5.2): ρs' = (c + cbrt(ρd'/2))³ - ρd'/2 (eq. 7).

The matched ρs' are printed, computed by libpgloss's pgloss_match_gloss (through ctypes) and by
the shader's pgloss_physical_from_perceptual; both must agree. Output: out/osl/fig12.png
(and the six linear EXRs). Run from the repository root (after scripts/test-osl.sh has made
the venv):

    .venv-bpy/bin/python examples/osl/fig12.py [--size 256] [--samples 64]
"""
from __future__ import annotations

import argparse
import ctypes as C
import math
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tests" / "osl"))
import cref  # noqa: E402  (libpgloss through ctypes)
import oslrt  # noqa: E402  (sets up bpy + the bundled oslquery / OpenImageIO)

import bpy  # noqa: E402
import OpenImageIO as oiio  # noqa: E402

OUT = REPO / "out" / "osl"
SPHERES = [("white", 0.767), ("grey", 0.193), ("black", 0.03)]
RHO_S, ALPHA = 0.099, 0.04          # Fig. 12, top row
CHECKS = (0.03, 0.767)              # §3.2.3.1: the checkerboard's diffuse reflectances


def lightness(y: float) -> float:
    L = C.c_double()
    assert cref.lib().pgloss_lightness_from_luminance(C.c_double(y), C.byref(L)) == 0
    return L.value


def match_gloss(rho_d: float, rho_s: float, L_target: float) -> tuple[float, float]:
    rd, rs = C.c_double(), C.c_double()
    st = cref.lib().pgloss_match_gloss(C.c_double(rho_d), C.c_double(rho_s), C.c_double(L_target),
                                       C.byref(rd), C.byref(rs))
    assert st == 0, st
    return rd.value, rs.value


def gloss_of(rho_d: float, rho_s: float, alpha: float) -> tuple[float, float, float]:
    L, c, d = C.c_double(), C.c_double(), C.c_double()
    cref.lib().pgloss_gloss_from_physical(C.c_double(rho_d), C.c_double(rho_s), C.c_double(alpha),
                                          C.byref(L), C.byref(c), C.byref(d))
    return L.value, c.value, d.value


def build_scene(size: int, samples: int) -> tuple[bpy.types.Scene, bpy.types.Node]:
    sc = oslrt.reset_scene()
    sc.cycles.samples = samples
    sc.cycles.use_denoising = True
    sc.cycles.max_bounces = 6
    sc.render.resolution_x = sc.render.resolution_y = size
    sc.render.image_settings.file_format = "OPEN_EXR"
    sc.view_settings.view_transform = "Standard"

    # The box: a cube seen from inside, checkerboard walls.
    bpy.ops.mesh.primitive_cube_add(size=8.0, location=(0, 0, 3.0))
    box = bpy.context.object
    m, nt, out = oslrt.empty_material("checks")
    bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
    chk = nt.nodes.new("ShaderNodeTexChecker")
    chk.inputs["Scale"].default_value = 8.0
    chk.inputs["Color1"].default_value = (CHECKS[1],) * 3 + (1,)
    chk.inputs["Color2"].default_value = (CHECKS[0],) * 3 + (1,)
    nt.links.new(chk.outputs["Color"], bsdf.inputs["Color"])
    nt.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    box.data.materials.append(m)

    # The sphere with pgloss_material.osl.
    bpy.ops.mesh.primitive_uv_sphere_add(radius=1.0, location=(0, 0, 0.0), segments=96, ring_count=48)
    sphere = bpy.context.object
    bpy.ops.object.shade_smooth()
    sm, nt, script, out = oslrt.osl_material("pgloss", REPO / "osl" / "pgloss_material.osl")
    nt.links.new(script.outputs["BSDF"], out.inputs["Surface"])
    sphere.data.materials.append(sm)

    # Overhead area light and the camera, inside the box.
    light = bpy.data.lights.new("area", "AREA")
    light.size = 1.5
    light.energy = 800.0
    lo = bpy.data.objects.new("area", light)
    lo.location = (0, 0, 6.9)
    sc.collection.objects.link(lo)
    cam = bpy.data.cameras.new("cam")
    cam.lens = 40
    co = bpy.data.objects.new("cam", cam)
    co.location = (0.0, -3.9, 1.4)
    co.rotation_euler = (math.radians(70.0), 0.0, 0.0)
    sc.collection.objects.link(co)
    sc.camera = co
    world = bpy.data.worlds.new("black")
    world.color = (0, 0, 0)
    sc.world = world
    for n in world.node_tree.nodes if world.node_tree else []:
        if n.type == "BACKGROUND":
            n.inputs["Color"].default_value = (0, 0, 0, 1)
    return sc, script


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--samples", type=int, default=64)
    args = ap.parse_args()
    OUT.mkdir(parents=True, exist_ok=True)

    L_w, c_w, d_w = gloss_of(SPHERES[0][1], RHO_S, ALPHA)
    print(f"white sphere: rho_d {SPHERES[0][1]}, rho_s {RHO_S}, alpha {ALPHA} -> L* {L_w:.2f}, c {c_w:.4f}, d {d_w:.2f}")
    sc, script = build_scene(args.size, args.samples)
    tiles = {}
    for row in ("physical", "perceptual"):
        for name, rho_d in SPHERES:
            L = lightness(rho_d)
            if row == "physical":
                script.inputs["use_physical"].default_value = True
                script.inputs["rho_d"].default_value = (rho_d, rho_d, rho_d, 1.0)
                script.inputs["rho_s"].default_value = RHO_S
                script.inputs["alpha"].default_value = ALPHA
                label = f"rho_s {RHO_S}"
                rs = RHO_S
            else:
                script.inputs["use_physical"].default_value = False
                script.inputs["Lightness"].default_value = L
                script.inputs["a_star"].default_value = 0.0
                script.inputs["b_star"].default_value = 0.0
                script.inputs["contrast_gloss"].default_value = c_w
                script.inputs["distinctness_gloss"].default_value = d_w
                _, rs = match_gloss(SPHERES[0][1], RHO_S, L)
                label = f"L* {L:.1f}, c {c_w:.4f}, d {d_w:.2f} (match_gloss: rho_s {rs:.4f})"
            t0 = time.time()
            path = OUT / f"fig12_{row}_{name}.exr"
            sc.render.filepath = str(path)
            bpy.ops.render.render(write_still=True)
            print(f"{row:10s} {name:5s} rho_d {rho_d:5.3f} {label}: {time.time() - t0:.1f} s", flush=True)
            tiles[(row, name)] = path

    # 3 x 2 sheet, display-referred: clamp-free rational sigmoid L/(1+L) per channel after an
    # exposure that maps the white check to about 0.8 — the paper used Tumblin's sigmoid too.
    import numpy as np

    s = args.size
    sheet = np.zeros((2 * s, 3 * s, 3), np.float32)
    for r, row in enumerate(("physical", "perceptual")):
        for k, (name, _) in enumerate(SPHERES):
            px = oiio.ImageBuf(str(tiles[(row, name)])).get_pixels(oiio.FLOAT)[:, :, :3]
            sheet[r * s:(r + 1) * s, k * s:(k + 1) * s] = px
    ref = np.percentile(sheet, 90)
    x = sheet * (2.0 / max(ref, 1e-6))
    disp = (x / (1.0 + x)) ** (1 / 2.2)
    out = oiio.ImageBuf(oiio.ImageSpec(3 * s, 2 * s, 3, oiio.UINT8))
    out.set_pixels(oiio.ROI(0, 3 * s, 0, 2 * s, 0, 1, 0, 3), np.clip(disp * 255 + 0.5, 0, 255).astype(np.uint8))
    png = OUT / "fig12.png"
    out.write(str(png))
    print(f"wrote {png} (top: same physical gloss; bottom: same perceptual gloss)")


if __name__ == "__main__":
    main()
