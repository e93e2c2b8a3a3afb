# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The bridge's MaterialX nodes measured in a renderer: each paper paint (Fig. 4's 27, Fig. 12's
triplet; and two coloured paints at one gloss, the sample's Fig. 14 red and a light blue) as <pgloss_open_pbr_surface> / <pgloss_standard_surface> (materialx/pgloss/
pgloss_bridge.mtlx), ShaderGen's OSL rendered in Cycles in the stimulus scene, and (c, d) read
back by the image gloss meter (pgloss.image_meter, ρd known from L*), as examples/bridge/
validate.py does for the C bridge's parameters. Prints a Markdown table.

    nice .venv-bridge/bin/python materialx/validate_renders.py [--spp 256] [--targets openpbr,standard_surface]
        [--paints all|paper|colour]

(.venv-bridge and .venv-bpy: scripts/test-bridge.sh; the meter's basis is cached under --work.)
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples" / "bridge"))
import materialx_osl  # noqa: E402  (ShaderGen's OSL of a surface node, for Cycles)
import validate as v  # noqa: E402  (the renderers, the meter, the paints of the bridge's validation)

import pgloss  # noqa: E402
from pgloss import bridge  # noqa: E402

LIBRARY = ROOT / "materialx" / "pgloss" / "pgloss_bridge.mtlx"
NODES = {"openpbr": "pgloss_open_pbr_surface", "standard_surface": "pgloss_standard_surface"}
#: Coloured paints of one gloss (label, L*, a*, b*, c, d): the Fig. 14 red of materialx/examples
#: and a light blue; the meter reads luminance, with ρd the luminance of L*.
COLOURED = [("red L*35 a*45 b*25", 35.0, 45.0, 25.0, 0.06, 0.95),
            ("light blue L*70 a*-5 b*-30", 70.0, -5.0, -30.0, 0.06, 0.95)]


def paints(which: str):
    """(label, ρd, paint (L*, a*, b*, c, d)) of validate.py's 30 paper paints and/or COLOURED."""
    out = []
    if which in ("all", "paper"):
        for label, rd, rs, a in v.paints("all"):
            L, c, d = (float(x) for x in pgloss.gloss_from_physical(rd, rs, a))
            out.append((label, rd, (L, 0.0, 0.0, c, d)))
    if which in ("all", "colour"):
        out += [(label, float(pgloss.luminance_from_lightness(p[0])), p) for label, *p in COLOURED]
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--basis-spp", type=int, default=1024)
    ap.add_argument("--alphas", type=int, default=21)
    ap.add_argument("--targets", default="openpbr,standard_surface")
    ap.add_argument("--paints", choices=("all", "paper", "colour"), default="all")
    ap.add_argument("--tracer", type=Path, default=Path(os.environ.get(
        "PGLOSS_TRACER", "build-tracer-test/examples/tracer/pgloss-tracer")))
    ap.add_argument("--bpy-python", type=Path, default=Path(".venv-bpy/bin/python"))
    ap.add_argument("--work", type=Path, default=Path("build-materialx/validate"))
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    args.alphas = tuple(float(a) for a in np.geomspace(0.01, 0.3, args.alphas))
    r = v.Renderers(args.tracer, args.work, args.threads, args.bpy_python)
    meter = v.Meter(args)
    ps = paints(args.paints)
    print(f"Paints mapped by the MaterialX nodes (not the C bridge), ShaderGen OSL in Cycles at {args.spp} spp, "
          f"read by the image gloss meter (basis {args.basis_spp} spp). Pass: |Δc| ≤ {v.TOL_C}, |Δd| ≤ {v.TOL_D}.\n")
    for target in args.targets.split(","):
        jobs, meta = [], []
        for i, (label, rd, paint) in enumerate(ps):
            st = int(np.asarray(bridge.from_paint(target, list(paint), errors="status").status))
            osl = materialx_osl.osl_shader(NODES[target], dict(zip(("lightness", "a", "b", "c", "d"), paint)),
                                           args.work / "osl", library=LIBRARY)
            jobs.append(v.Job({"type": "osl", "file": str(osl), "output": "out"}, args.spp, 6000 + i))
            meta.append((label, rd, paint[3], paint[4], st))
        rows, npass, nreach, worst = [], 0, 0, [0.0, 0.0]
        for (label, rd, c, d, st), img in zip(meta, r.images("cycles", jobs)):
            f = meter.read(img, rd)["primary"]
            dc, dd = f.c - c, f.d - d
            reach = st not in bridge.REACH_STATUSES
            ok = abs(dc) <= v.TOL_C and abs(dd) <= v.TOL_D
            nreach += reach
            npass += ok and reach
            if reach:
                worst = [max(worst[0], abs(dc)), max(worst[1], abs(dd))]
            rows.append((label, f"{c:.4f}", f"{f.c:.4f}", f"{abs(dc):.4f}", f"{d:.3f}", f"{f.d:.4f}", f"{abs(dd):.4f}",
                         ("pass" if ok else "**FAIL**") if reach else f"({bridge.status_names(st).lower()})"))
        print(f"## {target} ({NODES[target]})\n")
        print("\n".join(v._table(("paint", "c", "c read", "|Δc|", "d", "d read", "|Δd|", "result"), rows)))
        print(f"\n**{npass}/{nreach} reachable paints pass**; worst reachable |Δc| {worst[0]:.4f}, |Δd| {worst[1]:.4f}\n",
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
