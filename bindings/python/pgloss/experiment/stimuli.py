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
WxH --spp N --out PREFIX --quiet``. Its linear image (PREFIX.exr, kept) is tone-mapped with the
scene's sigmoid and encoded for the stated display (:mod:`.display`; default the paper's,
0.7–108 cd/m², gamma 2.35) into PREFIX.png. The manifest (``manifest.json`` next to the PNGs)
records for each image its physical and perceptual parameters, file name and SHA-256, the
renderer's settings, the tone map and the display; the server refuses images whose hash no longer
matches.
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

from .display import Display, encode, read_exr, scene_tonemap, write_png
from .manifest import SpecError, sha256

MANIFEST_VERSION = 2  # 2: the display and tone map recorded, PNGs encoded for the display
#: Experiment 1's levels (§3.2.3.1).
FIG4 = {"rho_d": [0.03, 0.193, 0.767], "rho_s": [0.033, 0.066, 0.099], "alpha": [0.04, 0.07, 0.10]}
PHYSICAL = ("rho_d", "rho_s", "alpha")
PERCEPTUAL = ("L", "c", "d")
_PAINT = re.compile(r"^\s*material\s+paint\b.*$", re.MULTILINE)


def _is_file(path: str) -> bool:
    """Path(path).is_file(), False for a string no file can have (a grid of 300 bytes made
    is_file() raise "File name too long")."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def parse_spec(spec: Optional[str]) -> Dict[str, List[float]]:
    """The grid of a SPEC (see the module's doc): keys rho_d, rho_s, alpha or L, c, d."""
    if spec is None or spec == "fig4":
        return {k: list(v) for k, v in FIG4.items()}
    if _is_file(spec):
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
        try:  # a paint the model refuses (pgloss.PglossError, with its reason and code)
            if perceptual:
                L, c, d = values
                rd, rs, al = (float(x) for x in pgloss.physical_from_gloss(L, c, d))
            else:
                rd, rs, al = values
                L, c, d = (float(x) for x in pgloss.gloss_from_physical(rd, rs, al))
        except ValueError as e:
            names = ", ".join(f"{k}={v:g}" for k, v in zip(keys, values))
            raise SpecError(f"paint {names}: {e}") from None
        p = pgloss.Physical(rd, rs, al)
        status = p.check()
        if status.is_error or not all(np.isfinite([rd, rs, al, L, c, d])):
            raise SpecError(f"paint rho_d={rd:g} rho_s={rs:g} alpha={al:g} (L={L:g} c={c:g} d={d:g}): "
                            f"{status.reason if status.is_error else 'not finite'}")
        rows.append({"rho_d": rd, "rho_s": rs, "alpha": al, "L": L, "c": c, "d": d})
    if len(rows) < 3:
        raise SpecError(f"{len(rows)} stimuli: an experiment needs at least 3")
    return rows


#: Where scripts/run.sh (build/) and the test scripts (build-tracer-test/) build pgloss-tracer.
TRACER_BUILDS = ("build/examples/tracer/pgloss-tracer", "build-tracer-test/examples/tracer/pgloss-tracer")
SCENE = Path("examples/tracer/scenes/stimulus.scene")


def _checkouts(*starts: Path) -> List[Path]:
    """pgloss checkouts (folders holding examples/tracer/scenes/stimulus.scene) at or above each
    start, in order, once each."""
    out: List[Path] = []
    for start in starts:
        for folder in [start, *start.parents]:
            if (folder / SCENE).is_file() and folder not in out:
                out.append(folder)
                break
    return out


def _executable(path: Path) -> bool:
    return _is_file(str(path)) and os.access(path, os.X_OK)


def find_tracer(tracer: Optional[str]) -> str:
    """The pgloss-tracer binary: --tracer, else $PGLOSS_TRACER, else the one on PATH, else the
    one built in the pgloss checkout that holds the working directory or this package
    (build/ after scripts/run.sh, build-tracer-test/ after the test scripts)."""
    for given, what in ((tracer, "--tracer"), (os.environ.get("PGLOSS_TRACER"), "PGLOSS_TRACER")):
        if given:
            if not _executable(Path(given)):
                raise SpecError(f"{what} {given}: no pgloss-tracer program there (build it with scripts/run.sh: "
                                f"build/examples/tracer/pgloss-tracer)")
            return str(given)
    on_path = shutil.which("pgloss-tracer")
    if on_path:
        return on_path
    checkouts = _checkouts(Path.cwd(), Path(__file__).resolve().parent)
    for root in checkouts:
        for rel in TRACER_BUILDS:
            if _executable(root / rel):
                return str(root / rel)
    where = f" nor built in {', '.join(str(r) for r in checkouts)}" if checkouts else ""
    raise SpecError(f"no pgloss-tracer: not on PATH{where}. Build it with `bash scripts/run.sh` in the pgloss "
                    "repository (build/examples/tracer/pgloss-tracer) and run from there, or give --tracer PATH "
                    "(or set PGLOSS_TRACER)")


def find_scene(exe: str) -> Path:
    """The stimulus scene when --scene is not given: examples/tracer/scenes/stimulus.scene of the
    pgloss checkout that holds the working directory, this package or the tracer program."""
    starts = [Path.cwd(), Path(__file__).resolve().parent, Path(exe).resolve().parent]
    checkouts = _checkouts(*starts)
    if not checkouts:
        raise SpecError(f"no stimulus scene: {SCENE} is in none of the folders above {', '.join(map(str, starts))}; "
                        "give --scene FILE")
    return checkouts[0] / SCENE


def render(spec: Optional[str], outdir: Path, *, tracer: Optional[str] = None, scene: Optional[Path] = None,
           size: Sequence[int] = (320, 240), spp: int = 64, seed: int = 1, threads: Optional[int] = None,
           display: Optional[Display] = None, log=print) -> Path:
    """Renders the stimulus set of SPEC into outdir; returns the manifest's path."""
    exe = find_tracer(tracer)
    scene = find_scene(exe) if scene is None else Path(scene)  # default: the Fig. 4 environment
    if not _is_file(str(scene)):
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
    display = display or Display()
    tonemap = scene_tonemap(text)
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
        exr = outdir / f"{sid}.exr"
        if run.returncode != 0 or not exr.is_file():
            raise SpecError(f"pgloss-tracer failed on {sid} (exit {run.returncode}): {run.stderr.strip()[-500:]}")
        write_png(png, encode(read_exr(exr), tonemap, display))  # replaces the tracer's sRGB preview
        stimuli.append({"id": sid, "file": png.name, "sha256": sha256(png), **{k: round(v, 9) for k, v in p.items()}})
        log(f"{sid}: rho_d={p['rho_d']:.4g} rho_s={p['rho_s']:.4g} alpha={p['alpha']:.4g}  "
            f"L={p['L']:.2f} c={p['c']:.4f} d={p['d']:.4f}")
    manifest = {
        "version": MANIFEST_VERSION,
        "spec": spec or "fig4",
        "renderer": {"program": "pgloss-tracer", "scene": scene.name, "scene_sha256": sha256(scene), "width": w, "height": h, "spp": spp,
                     "seed": seed, "pgloss": pgloss.__version__},
        "tonemap": {"operator": "rational sigmoid Y / (1 + (Y/limit)^sharpness)^(1/sharpness) of exposure * Y",
                    **tonemap},
        "display": display.record(),
        "stimuli": stimuli,
    }
    path = outdir / "manifest.json"
    path.write_text(json.dumps(manifest, indent=1) + "\n", encoding="utf-8")
    return path
