# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""A stimulus set: a grid of paints rendered by pgloss-tracer, and its manifest.

A SPEC is one of

* ``fig4`` (the default): Experiment 1's 27 paints, ρd ∈ {0.03, 0.193, 0.767} × ρs ∈ {0.033,
  0.066, 0.099} × α ∈ {0.04, 0.07, 0.10} (paper §3.2.3.1, Fig. 4);
* a grid in physical terms, ``rho_d=0.03,0.193 rho_s=0.033,0.099 alpha=0.04,0.1``;
* a grid in perceptual terms, ``L=51 c=0.04,0.08,0.12 d=0.9,0.93,0.96`` (eqs. 3, 4, inverted by
  pgloss.physical_from_gloss);
* the path of a JSON file ``{"rho_d": [...], "rho_s": [...], "alpha": [...]}`` or ``{"L": …, "c": …, "d": …}``.

Each paint replaces the ``paint`` material of the scene (default examples/tracer/scenes/
stimulus.scene, the Fig. 4 environment) and is rendered with ``pgloss-tracer render SCENE --size
WxH --spp N --out PREFIX --quiet``. The manifest (``manifest.json`` next to the PNGs) records for
each image its physical and perceptual parameters, file name and SHA-256, and the renderer's
settings; the server refuses images whose hash no longer matches.
"""

from __future__ import annotations

import itertools
import json
import os
import re
import shutil
import subprocess
from pathlib import Path
from typing import Dict, List, Optional, Sequence

import numpy as np

import pgloss

from .manifest import SpecError, sha256

MANIFEST_VERSION = 1
#: Experiment 1's levels (§3.2.3.1).
FIG4 = {"rho_d": [0.03, 0.193, 0.767], "rho_s": [0.033, 0.066, 0.099], "alpha": [0.04, 0.07, 0.10]}
PHYSICAL = ("rho_d", "rho_s", "alpha")
PERCEPTUAL = ("L", "c", "d")
_PAINT = re.compile(r"^\s*material\s+paint\b.*$", re.MULTILINE)


def parse_spec(spec: Optional[str]) -> Dict[str, List[float]]:
    """The grid of a SPEC (see the module's doc): keys rho_d, rho_s, alpha or L, c, d."""
    if spec is None or spec == "fig4":
        return {k: list(v) for k, v in FIG4.items()}
    if Path(spec).is_file():
        try:
            grid = json.loads(Path(spec).read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            raise SpecError(f"{spec}: not a JSON grid ({e})") from None
        if not isinstance(grid, dict):
            raise SpecError(f"{spec}: want a JSON object of lists")
    else:
        grid = {}
        for part in spec.replace(";", " ").split():
            key, sep, values = part.partition("=")
            if not sep:
                raise SpecError(f"'{part}': want KEY=v1,v2,… (or 'fig4' or a JSON file)")
            try:
                grid[key] = [float(v) for v in values.split(",")]
            except ValueError:
                raise SpecError(f"'{part}': values must be numbers") from None
    keys = set(grid)
    if keys not in (set(PHYSICAL), set(PERCEPTUAL)):
        raise SpecError(f"grid keys {sorted(keys)}: want exactly rho_d, rho_s, alpha or L, c, d")
    out: Dict[str, List[float]] = {}
    for k, v in grid.items():
        if not isinstance(v, list) or not v or not all(isinstance(x, (int, float)) and np.isfinite(x) for x in v):
            raise SpecError(f"{k}: want a non-empty list of finite numbers")
        out[k] = [float(x) for x in v]
    return out


def paints(grid: Dict[str, List[float]]) -> List[Dict[str, float]]:
    """Every combination of the grid, with both its physical and perceptual parameters."""
    perceptual = "L" in grid
    keys = PERCEPTUAL if perceptual else PHYSICAL
    rows = []
    for values in itertools.product(*(grid[k] for k in keys)):
        if perceptual:
            L, c, d = values
            rd, rs, al = (float(x) for x in pgloss.physical_from_gloss(L, c, d))
        else:
            rd, rs, al = values
            L, c, d = (float(x) for x in pgloss.gloss_from_physical(rd, rs, al))
        p = pgloss.Physical(rd, rs, al)
        status = p.check()
        if status.is_error or not all(np.isfinite([rd, rs, al, L, c, d])):
            raise SpecError(f"paint rho_d={rd:g} rho_s={rs:g} alpha={al:g} (L={L:g} c={c:g} d={d:g}): "
                            f"{status.reason if status.is_error else 'not finite'}")
        rows.append({"rho_d": rd, "rho_s": rs, "alpha": al, "L": L, "c": c, "d": d})
    if len(rows) < 3:
        raise SpecError(f"{len(rows)} stimuli: an experiment needs at least 3")
    return rows


def find_tracer(tracer: Optional[str]) -> str:
    """The pgloss-tracer binary: --tracer, else $PGLOSS_TRACER, else the one on PATH."""
    path = tracer or os.environ.get("PGLOSS_TRACER") or shutil.which("pgloss-tracer")
    if not path or not (Path(path).is_file() and os.access(path, os.X_OK)):
        raise SpecError(f"no pgloss-tracer at {path!r}: build examples/tracer (scripts/test-tracer.sh) and give "
                        "--tracer PATH or set PGLOSS_TRACER")
    return str(path)


def render(spec: Optional[str], outdir: Path, *, tracer: Optional[str] = None, scene: Optional[Path] = None,
           size: Sequence[int] = (320, 240), spp: int = 64, seed: int = 1, threads: Optional[int] = None,
           log=print) -> Path:
    """Renders the stimulus set of SPEC into outdir; returns the manifest's path."""
    exe = find_tracer(tracer)
    if scene is None:  # the repository's Fig. 4 environment: from the working directory or this source tree
        rel = Path("examples/tracer/scenes/stimulus.scene")
        scene = next((p for p in (rel, Path(__file__).resolve().parents[4] / rel) if p.is_file()), rel)
    scene = Path(scene)
    if not scene.is_file():
        raise SpecError(f"no scene file {scene} (give --scene)")
    text = scene.read_text(encoding="utf-8")
    if re.search(r"^\s*mesh\b", text, re.MULTILINE):
        raise SpecError(f"{scene}: scenes with meshes are not supported (the per-stimulus scenes live elsewhere)")
    if len(_PAINT.findall(text)) != 1:
        raise SpecError(f"{scene}: want exactly one 'material paint …' line to replace")
    w, h = (int(x) for x in size)
    if not (8 <= w <= 4096 and 8 <= h <= 4096) or not (1 <= spp <= 1 << 20):
        raise SpecError("--size wants 8..4096 per side and --spp 1..1048576")
    rows = paints(parse_spec(spec))
    outdir.mkdir(parents=True, exist_ok=True)
    scenes = outdir / "scenes"
    scenes.mkdir(exist_ok=True)
    stimuli = []
    for i, p in enumerate(rows):
        sid = f"s{i + 1:02d}"
        line = f"material paint physical rho_d={p['rho_d']:.9g} rho_s={p['rho_s']:.9g} alpha={p['alpha']:.9g}"
        sfile = scenes / f"{sid}.scene"  # kept: with the manifest it documents how each image was made
        sfile.write_text(_PAINT.sub(line, text), encoding="utf-8")
        cmd = [exe, "render", str(sfile), "--size", f"{w}x{h}", "--spp", str(spp), "--seed", str(seed),
               "--out", str(outdir / sid), "--quiet"]
        if threads:
            cmd += ["--threads", str(threads)]
        run = subprocess.run(cmd, capture_output=True, text=True)
        png = outdir / f"{sid}.png"
        if run.returncode != 0 or not png.is_file():
            raise SpecError(f"pgloss-tracer failed on {sid} (exit {run.returncode}): {run.stderr.strip()[-500:]}")
        stimuli.append({"id": sid, "file": png.name, "sha256": sha256(png), **{k: round(v, 9) for k, v in p.items()}})
        log(f"{sid}: rho_d={p['rho_d']:.4g} rho_s={p['rho_s']:.4g} alpha={p['alpha']:.4g}  "
            f"L={p['L']:.2f} c={p['c']:.4f} d={p['d']:.4f}")
    manifest = {
        "version": MANIFEST_VERSION,
        "spec": spec or "fig4",
        "renderer": {"program": "pgloss-tracer", "scene": scene.name, "scene_sha256": sha256(scene), "width": w, "height": h, "spp": spp,
                     "seed": seed, "pgloss": pgloss.__version__},
        "stimuli": stimuli,
    }
    path = outdir / "manifest.json"
    path.write_text(json.dumps(manifest, indent=1) + "\n", encoding="utf-8")
    return path
