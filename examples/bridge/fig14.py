# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Our Fig. 14 (paper §5.2): a dark red and a light blue mug matched in gloss — the same (c, d) —
rendered twice from ``examples/tracer/scenes/fig14.scene``:

* left, Blender Cycles: each paint mapped by the gloss bridge to a Principled BSDF through the
  pgloss paint add-on's Principled mode (blender/pgloss_paint, installed from its zip);
* right, pgloss-tracer: each paint as the paper's Ward BRDF (eq. 2).

Under each mug, the (c, d) that the image gloss meter (pgloss.image_meter) recovers from renders of
that mug's material in that renderer — on the meter's instrument, the stimulus sphere (the bridge
defines a material's paint by it; docs/bridge.md) — against the paint asked for. Writes
OUT/fig14.png and OUT/fig14/*.exr. Run with the bpy venv (scripts/fig14.sh sets it all up):

    BLENDER_USER_RESOURCES=$(mktemp -d) .venv-bpy/bin/python examples/bridge/fig14.py \\
        --tracer build/examples/tracer/pgloss-tracer --addon out/blender/pgloss_paint-0.1.0.zip --out out
"""
from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Dict, List, Tuple

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
import harness_cycles  # noqa: E402

SCENE = ROOT / "examples" / "tracer" / "scenes" / "fig14.scene"
STIMULUS = ROOT / "examples" / "tracer" / "scenes" / "stimulus.scene"
MODULE = "bl_ext.user_default.pgloss_paint"
#: The α grid of the meter's basis: 0.02–0.2 in 11 log steps (as tests/bridge).
ALPHAS = tuple(float(a) for a in np.geomspace(0.02, 0.2, 11))


def paints(scene: Path) -> Dict[str, Dict[str, float]]:
    """The scene's perceptual materials on meshes: name → {L, a, b, c, d}."""
    st = harness_cycles.read_scene(scene)
    mats = {m["name"]: m for m in st["material"]}
    out = {}
    for m in st.get("mesh", []):
        f = mats[m["material"]]
        if f["kind"] != "perceptual":
            raise ValueError(f"{scene}: mesh material {f['name']} is not a perceptual paint")
        out[f["name"]] = {k: float(f[k]) for k in ("L", "a", "b", "c", "d")}
    return out


def principled(addon, name: str, p: Dict[str, float], log: List[str]):
    """The add-on's Principled-mode material of paint ``p``; an out-of-reach paint renders as the
    nearest reachable one, and ``log`` says so."""
    mat = addon.new_principled_material(name)
    r = addon.set_principled(mat, L=p["L"], a=p["a"], b=p["b"], c=p["c"], d=p["d"])
    if r.status < 0:
        log.append(f"{name}: {r.status_name}: {r.reason}; renders L* {r.reached[0]:.2f} c {r.reached[3]:.4f} "
                   f"d {r.reached[4]:.4f}")
    return mat


def display(img: np.ndarray, exposure: float):
    """Linear Rec. 709 → 8-bit sRGB, the same for both renderers: exposure, clip, the sRGB curve
    (IEC 61966-2-1) through OpenImageIO."""
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(oiio.ImageSpec(img.shape[1], img.shape[0], 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(), np.clip(exposure * img, 0.0, 1.0).astype(np.float32))
    return oiio.ImageBufAlgo.colorconvert(buf, "linear", "sRGB")


def compose(left: np.ndarray, right: np.ndarray, captions: List[Tuple[str, List[List[str]]]], exposure: float,
            out: Path, oiiotool: str) -> None:
    """The two renders side by side; under each its title, then one column of lines per mug (the
    mugs stand left and right in the scene, in the order of the captions). The text is drawn by
    ``oiiotool --text`` (Debian's OpenImageIO has FreeType; bpy's has not)."""
    import OpenImageIO as oiio

    h, w = left.shape[:2]
    pad, line = 8, 15
    rows = max(len(col) for c in captions for col in c[1]) + 1
    W, H = 2 * w + 3 * pad, h + 2 * pad + line * rows + 4
    sheet = oiio.ImageBuf(oiio.ImageSpec(W, H, 3, oiio.FLOAT))
    oiio.ImageBufAlgo.fill(sheet, (1.0, 1.0, 1.0))
    text: List[str] = []

    def put(x: int, y: int, size: int, t: str) -> None:
        text.extend([f"--text:x={x}:y={y}:size={size}:color=0,0,0:font=DejaVuSans", t])

    for k, img in enumerate((left, right)):
        x0 = pad + k * (w + pad)
        oiio.ImageBufAlgo.paste(sheet, x0, pad, 0, 0, display(img, exposure))
        title, columns = captions[k]
        put(x0, pad + h + line, 12, title)
        for j, col in enumerate(columns):
            for i, t in enumerate(col):
                put(x0 + j * w // len(columns), pad + h + line * (i + 2) + 4, 11, t)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="pgloss-fig14-") as tmp:
        plain = Path(tmp) / "sheet.png"
        if not sheet.write(str(plain), oiio.UINT8):
            raise RuntimeError(f"{plain}: {sheet.geterror()}")
        r = subprocess.run([oiiotool, str(plain), *text, "-o", str(out)], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"oiiotool failed ({r.returncode}): {r.stderr.strip()}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tracer", type=Path, required=True)
    ap.add_argument("--addon", type=Path, required=True, help="the pgloss paint extension zip")
    ap.add_argument("--out", type=Path, default=ROOT / "out")
    ap.add_argument("--spp", type=int, default=64, help="samples per pixel of the two mug renders")
    ap.add_argument("--meter-spp", type=int, default=256, help="of the sphere renders the meter reads")
    ap.add_argument("--basis-spp", type=int, default=512, help="of the meter's Ward basis (pgloss-tracer)")
    ap.add_argument("--cache", type=Path, default=ROOT / "build-bridge" / "fig14", help="the meter's bases")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--oiiotool", default="oiiotool", help="draws the captions (Debian: openimageio-tools)")
    a = ap.parse_args(argv)
    t0 = time.monotonic()
    bpy = harness_cycles._bpy()
    addon = harness_cycles.install_extension(bpy, a.addon, MODULE)
    import pgloss
    from pgloss import image_meter as im

    table = paints(SCENE)
    work = a.out / "fig14"
    work.mkdir(parents=True, exist_ok=True)
    notes: List[str] = []
    size = tuple(int(harness_cycles.read_scene(SCENE)["image"][0][k]) for k in ("width", "height"))
    exposure = float(harness_cycles.read_scene(SCENE)["tonemap"][0].get("exposure", 1))

    # The mugs: Principled (the add-on) in Cycles, Ward in pgloss-tracer, the same scene file.
    sc = harness_cycles.build(bpy, lambda b, f: principled(addon, f["name"], table[f["name"]], notes), work, spp=a.spp, seed=1, size=size,
                              crop=None, threads=a.threads, scene_path=SCENE, keep_preferences=True)
    sc.render.filepath = str(work / "principled.exr")
    bpy.ops.render.render(write_still=True)
    left = im.read_linear(work / "principled.exr")
    with tempfile.TemporaryDirectory(prefix="pgloss-fig14-") as tmp:
        right = im.render_tracer(a.tracer, SCENE.read_text().replace("file=models/", f"file={SCENE.parent}/models/"),
                                 a.spp, size, 1, a.threads, Path(tmp))
    print(f"fig14: mugs rendered ({time.monotonic() - t0:.0f} s)", flush=True)

    # Each paint read back by the meter from the stimulus sphere in each renderer.
    view = im.View.from_scene(STIMULUS.read_text())
    crop_text, crop_size = im.crop_scene(STIMULUS.read_text(), view)
    read: Dict[str, Dict[str, im.Fit]] = {}
    for name, p in table.items():
        rho_d = float(pgloss.luminance_from_lightness(p["L"]))
        basis = im.render_basis(a.tracer, STIMULUS, rho_d, alphas=ALPHAS, spp=a.basis_spp, threads=a.threads,
                                cache=a.cache)
        line = f"material paint perceptual L={p['L']!r} a={p['a']!r} b={p['b']!r} c={p['c']!r} d={p['d']!r}"
        with tempfile.TemporaryDirectory(prefix="pgloss-fig14-") as tmp:
            ward = im.render_tracer(a.tracer, im.scene_with_paint(crop_text, line), a.meter_spp, crop_size, 3,
                                    a.threads, Path(tmp))
        sc = harness_cycles.build(bpy, lambda b, f, n=name, p=p: principled(addon, n, p, []), work, spp=a.meter_spp, seed=3,
                                  size=(view.width, view.height), crop=view.crop(), threads=a.threads,
                                  keep_preferences=True)
        sc.render.filepath = str(work / f"sphere-{name}.exr")
        bpy.ops.render.render(write_still=True)
        read[name] = {"principled": im.fit(im.read_linear(work / f"sphere-{name}.exr"), basis),
                      "ward": im.fit(ward, basis)}
    print(f"fig14: meter readings done ({time.monotonic() - t0:.0f} s)", flush=True)

    captions = []
    print(f"{'paint':<11} {'renderer':<11} {'c asked':>8} {'c read':>8} {'d asked':>8} {'d read':>8} residual")
    for key, title in (("principled", "Blender Cycles: Principled BSDF (gloss bridge)"),
                       ("ward", "pgloss-tracer: Ward BRDF (eq. 2)")):
        columns = []
        for name, p in table.items():
            f = read[name][key]
            columns.append([f"{name.replace('_', ' ')}, L* {p['L']:g}", f"read: c {f.c:.3f}, d {f.d:.3f}",
                            f"asked: c {p['c']:.3f}, d {p['d']:.3f}"])
            print(f"{name:<11} {key:<11} {p['c']:8.4f} {f.c:8.4f} {p['d']:8.4f} {f.d:8.4f} {100 * f.residual:7.1f} %")
        captions.append((title, columns))
    for n in notes:
        print(f"fig14: {n}")
    compose(left, right, captions, exposure, a.out / "fig14.png", a.oiiotool)
    print(f"fig14: {a.out / 'fig14.png'} ({time.monotonic() - t0:.0f} s; (c, d) read by the image gloss meter "
          f"from the stimulus sphere, {a.meter_spp} spp against a {a.basis_spp}-spp basis)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
