# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""(c, d) read back by the image gloss meter (pgloss.image_meter, docs/image-meter.md) from the
picker's own WebGL2 renders: for paints of the paper's Fig. 4, the paint view (the Ward paint
beside a bridge target's own BRDF) renders the meter's frame of the stimulus scene, the linear
sums are read back as float32 and the meter fits them against a pgloss-tracer Ward basis.
Bounds: the bridge validation's |Δc| ≤ 0.005, |Δd| ≤ 0.01 for the targets, half of that for the
Ward paint (the control). Writes the table to out/web/picker-meter.md.

The frame is the meter's sphere crop (View.crop: 54 × 58 of the 160 × 120 frame), which a
pinhole renders as its whole frame with the narrower field of view View.crop_fov_deg; the page
reads stimulus.scene itself, so only the camera's fov is set here, on the page's parsed scene.
The bounds have teeth: with α 15 % high in every tile (Ward and target), the grey paint's d reads
0.012–0.013 low, and the test fails.
"""
from __future__ import annotations

import json
import os
import subprocess
import time
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest
from playwright.sync_api import Browser
from test_picker import EXPORT_PY, OUT, ROOT, open_page

TRACER = os.environ.get("PGLOSS_TRACER", str(ROOT / "build-tracer-test/examples/tracer/pgloss-tracer"))
#: The meter's basis as tests/bridge and tests/blender render it (the same cache and key).
BASIS_DIR = ROOT / "build-bridge/ci/basis"
BASIS_SPP = 1024
BASIS_ALPHAS = [float(a) for a in np.geomspace(0.02, 0.2, 11)]
#: Samples per pixel of each page render (≤ the basis's: docs/image-meter.md, "Noise"), in passes of
#: PASS_SPP. Each target is one render (seed 1, 2, …) of the two tiles; the Ward control is the mean
#: of their Ward tiles (len(TARGETS) × SPP samples).
SPP, PASS_SPP = 512, 8
#: Fig. 4 paints (ρd, ρs, α): the stimulus grey and a black.
PAINTS = [(0.193, 0.066, 0.07), (0.03, 0.066, 0.07)]
TARGETS = ["roughplastic_ggx", "principled"]
TOL_C, TOL_D = 0.005, 0.01


def _meter(req: Dict[str, Any]) -> Dict[str, Any]:
    if not Path(EXPORT_PY).is_file():
        pytest.fail(f"no Python with pgloss and OpenImageIO at {EXPORT_PY} (scripts/test-web.sh makes .venv-bridge)")
    r = subprocess.run([EXPORT_PY, str(ROOT / "tests/web/meter_read.py")], input=json.dumps(req), capture_output=True,
                       text=True, cwd="/")
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_picker_renders_read_back_by_the_image_meter(browser: Browser, base_url: str, tmp_path: Path) -> None:
    assert Path(TRACER).is_file(), f"no pgloss-tracer at {TRACER} (scripts/test-web.sh builds it)"
    crop = _meter({"cmd": "view"})
    W, H = crop["width"], crop["height"]
    images: List[Dict[str, Any]] = []
    rows: List[Dict[str, Any]] = []
    t0 = time.time()
    for rd, rs, a in PAINTS:
        ward = np.zeros((H, W, 3), dtype=np.float32)
        for k, target in enumerate(TARGETS):
            h = f"#mode=physical&rd_r={rd}&rd_g={rd}&rd_b={rd}&rho_s={rs}&alpha={a}&view=single&target={target}"
            page = open_page(browser, f"{base_url}/index.html?autorun=0&size={W}x{H}{h}")
            assert page.inner_text("#target-status") == "PGLOSS_OK", (rd, rs, a, target)
            res = page.evaluate(f"""() => {{
                const t = window.picker.tracer;
                t.seed = {k + 1};
                t.scene.camera.fov = {crop['fov']!r};  // the meter's crop window (View.crop_fov_deg)
                t.reset();
                for (let i = 0; i < {SPP // PASS_SPP}; i++) t.step({PASS_SPP});
                const s = t.readSums();
                return {{w: s.width, h: s.height, n: s.count, sums: Array.from(s.sums)}};
            }}""")
            assert not page.errors, page.errors  # type: ignore[attr-defined]
            page.close()
            assert (res["w"], res["h"], res["n"]) == (2 * W, H, SPP)
            mean = np.array(res["sums"], dtype=np.float32).reshape(H, 2 * W, 4)[..., :3] / SPP
            ward += mean[:, :W] / len(TARGETS)
            tiles = [(target, mean[:, W:], SPP)] + ([("Ward", ward, len(TARGETS) * SPP)] if k == len(TARGETS) - 1 else [])
            for name, img, spp in tiles:
                stem = tmp_path / f"{rd}-{rs}-{a}-{name}"
                np.save(f"{stem}.npy", img)
                images.append({"npy": f"{stem}.npy", "exr": f"{stem}.exr", "rho_d": rd})
                rows.append({"paint": (rd, rs, a), "target": name, "spp": spp})
    t_render = time.time() - t0
    res = _meter({"cmd": "fit", "tracer": TRACER, "basis_dir": str(BASIS_DIR), "basis_spp": BASIS_SPP,
                  "alphas": BASIS_ALPHAS, "spp": [SPP, len(TARGETS) * SPP], "images": images})
    asked = {p: tuple(_asked(p)) for p in PAINTS}
    lines = [f"Image gloss meter on the picker's WebGL2 renders (SwiftShader) of the stimulus scene's meter crop "
             f"({W}×{H}), {SPP} spp per render; basis pgloss-tracer {BASIS_SPP} spp, α {BASIS_ALPHAS[0]:g}–{BASIS_ALPHAS[-1]:g} "
             f"({len(BASIS_ALPHAS)} nodes), ρd known. Render noise (RMS, image_meter.expected_noise): "
             + "; ".join(f"{n} spp Δc {nc:.4f}, Δd {nd:.4f}" for n, (nc, nd) in res["noise"].items()) + ". "
             f"Bounds: targets |Δc| ≤ {TOL_C}, |Δd| ≤ {TOL_D}; Ward (control) half of that.", "",
             "| paint (ρd, ρs, α) | rendered | spp | asked c | asked d | read c | read d | Δc | Δd | residual |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    bad = []
    for row, f in zip(rows, res["fits"]):
        c, d = asked[row["paint"]]
        dc, dd = f["c"] - c, f["d"] - d
        scale = 0.5 if row["target"] == "Ward" else 1.0
        ok = f["status"] == "ok" and abs(dc) <= scale * TOL_C and abs(dd) <= scale * TOL_D
        lines.append(f"| {', '.join(f'{v:g}' for v in row['paint'])} | {row['target']} | {row['spp']} | {c:.4f} | {d:.4f} | {f['c']:.4f} | "
                     f"{f['d']:.4f} | {dc:+.4f} | {dd:+.4f} | {100 * f['residual']:.2f} % |" + ("" if ok else " **FAIL**"))
        if not ok:
            bad.append((row, f))
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "picker-meter.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"\n  (page renders {t_render:.1f} s)\n" + "\n".join(lines))
    assert not bad, bad


def _asked(p: tuple) -> tuple:
    """The asked (c, d) of a physical paint: eqs. 3–4 (c = cbrt(ρs + ρd/2) − cbrt(ρd/2), d = 1 − α)."""
    rd, rs, a = p
    return np.cbrt(rs + rd / 2) - np.cbrt(rd / 2), 1 - a
