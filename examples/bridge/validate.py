# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The gloss bridge measured in real renderers, with the image gloss meter (pgloss.image_meter).

Two reports, each written whole as a generated Markdown file (the command is named in it):

* ``harnesses`` → docs/bridge-harnesses.md: the instruments before any mapping —
  (1) a Lambertian sphere in pgloss-tracer, Mitsuba 3 and Cycles, region by region;
  (2) the meter's control: Ward renders of Fig. 4's 27 paints and Fig. 12's matched triplet by
      pgloss-tracer (and by Mitsuba 3, the same BRDF in a renderer that is not ours) read back
      within half the target tolerance (|Δc| ≤ 0.0025, |Δd| ≤ 0.005);
  (3) the noise model RMS Δc = √(0.0113²/spp + 0.00016²), RMS Δd = 0.030/√spp against repeated renders;
  (4) the facts of the gloss bridge reproduced: Ward fits of Mitsuba ``roughplastic`` GGX and
      Beckmann, and Principled against roughplastic at the same GGX α.
* ``table`` → docs/bridge-validation.md: each target's MAPPED parameters (``pgloss bridge TARGET
  L a b c d``) for the same 30 paints, rendered in that target's renderer and read back:
  requested against recovered c and d, pass when |Δc| ≤ 0.005 and |Δd| ≤ 0.01.

Renders are the meter's sphere crop (pgloss.image_meter.View.crop) of the 160 × 120 frame; the
basis is cached under --work (never in git). Run with the bridge venv (scripts/test-bridge.sh
makes .venv-bridge and .venv-bpy):

    nice .venv-bridge/bin/python examples/bridge/validate.py harnesses [--spp 1024] [--basis-spp 1024]
    nice .venv-bridge/bin/python examples/bridge/validate.py table [--targets gltf,…]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

import pgloss
from pgloss import image_meter as im

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
SCENE = ROOT / "examples" / "tracer" / "scenes" / "stimulus.scene"

#: Experiment 1's stimuli (paper §3.2.3.1, Fig. 4) and Fig. 12's white paint (§5.2).
RHO_D = (0.767, 0.193, 0.03)
RHO_S = (0.033, 0.066, 0.099)
ALPHA = (0.04, 0.07, 0.10)
TOL_C, TOL_D = 0.005, 0.01


def paints(which: str = "all") -> List[Tuple[str, float, float, float]]:
    """(label, ρd, ρs, α): Fig. 4's 27 stimuli, then Fig. 12's matched triplet (the white paint
    ρs .099, α .04, and the grey and black paints given its c and d by match_gloss);
    ``which="grey"``: those of ρd .193 alone (one basis)."""
    out = [(f"fig4 {rd:g}/{rs:g}/{a:g}", rd, rs, a) for rd in RHO_D for rs in RHO_S for a in ALPHA]
    _, _, d0 = pgloss.gloss_from_physical(RHO_D[0], 0.099, 0.04)
    for name, rd in zip(("white", "grey", "black"), RHO_D):
        rdm, rsm = pgloss.match_gloss(RHO_D[0], 0.099, pgloss.lightness_from_luminance(rd))
        out.append((f"fig12 {name}", float(rdm), float(rsm), float(1 - d0)))
    return [p for p in out if which == "all" or abs(p[1] - 0.193) < 1e-6]


def is_white(rho_d: float) -> bool:
    """The white row (ρd .767: Fig. 4's and Fig. 12's white paints). Its lobe is a small part of
    a bright sphere's image, so the meter's residual is nearly flat in α there and its reading
    needs more samples (--white-spp, --white-basis-spp; docs/image-meter.md, "White paints")."""
    return rho_d > 0.5


# ------------------------------------------------------------------------------ the renderers
@dataclass
class Job:
    material: dict   # the harness's material (Mitsuba BSDF, Cycles material) or {"tracer": scene line}
    spp: int
    seed: int


class Renderers:
    """pgloss-tracer, Mitsuba 3 (in this process) and Cycles (bpy in .venv-bpy, one process per
    batch), each rendering the meter's sphere crop."""

    def __init__(self, tracer: Path, work: Path, threads: int, bpy_python: Path):
        self.tracer, self.work, self.threads, self.bpy_python = tracer, work, threads, bpy_python
        self.view = im.View.from_scene(SCENE.read_text())
        self.crop = self.view.crop()
        self.crop_text, self.crop_size = im.crop_scene(SCENE.read_text(), self.view)
        work.mkdir(parents=True, exist_ok=True)

    def tracer_images(self, jobs: Sequence[Job]) -> List[np.ndarray]:
        out = []
        with tempfile.TemporaryDirectory(prefix="pgloss-validate-", dir=self.work) as tmp:
            for j in jobs:
                text = im.scene_with_paint(self.crop_text, j.material["tracer"])
                out.append(im.render_tracer(self.tracer, text, j.spp, self.crop_size, j.seed, self.threads, Path(tmp)))
        return out

    def mitsuba_images(self, jobs: Sequence[Job]) -> List[np.ndarray]:
        import harness_mitsuba  # noqa: PLC0415

        return [harness_mitsuba.render(j.material, spp=j.spp, seed=j.seed, size=(self.view.width, self.view.height),
                                       crop=self.crop, threads=self.threads) for j in jobs]

    def cycles_images(self, jobs: Sequence[Job]) -> List[np.ndarray]:
        with tempfile.TemporaryDirectory(prefix="pgloss-validate-", dir=self.work) as tmp:
            spec = [{"material": j.material, "out": str(Path(tmp) / f"{i}.exr"), "spp": j.spp, "seed": j.seed}
                    for i, j in enumerate(jobs)]
            (Path(tmp) / "jobs.json").write_text(json.dumps(spec))
            r = subprocess.run([str(self.bpy_python), str(HERE / "harness_cycles.py"), "--jobs",
                                str(Path(tmp) / "jobs.json"), "--size", f"{self.view.width}x{self.view.height}",
                                "--crop", ",".join(map(str, self.crop)), "--threads", str(self.threads)],
                               capture_output=True, text=True)
            if r.returncode != 0:
                raise RuntimeError(f"harness_cycles failed ({r.returncode}):\n{r.stderr[-3000:]}")
            return [im.read_linear(Path(s["out"])) for s in spec]

    def images(self, renderer: str, jobs: Sequence[Job]) -> List[np.ndarray]:
        return {"tracer": self.tracer_images, "mitsuba": self.mitsuba_images, "cycles": self.cycles_images}[renderer](jobs)


# ------------------------------------------------------------------------------------- targets
# `pgloss bridge TARGET …` prints the parameters under each target's own names (tools/cmd_bridge.c):
# MaterialX inputs, glTF material fields, Principled inputs, Mitsuba plugin parameters.
def _materialx(node: str) -> Callable[[dict, Path], dict]:
    def make(p: dict, work: Path) -> dict:
        import materialx_osl  # noqa: PLC0415

        return {"type": "osl", "file": str(materialx_osl.osl_shader(node, p, work / "materialx")), "output": "out"}
    return make


def _gltf(extensions: bool) -> Callable[[dict, Path], dict]:
    """The flat glTF fields as a glTF 2.0 material object (pbrMetallicRoughness, and
    KHR_materials_ior / KHR_materials_specular for the full target)."""
    def make(p: dict, work: Path) -> dict:
        m: dict = {"pbrMetallicRoughness": {"baseColorFactor": [float(x) for x in p["baseColorFactor"]],
                                            "metallicFactor": float(p.get("metallicFactor", 0.0)),
                                            "roughnessFactor": float(p["roughnessFactor"])}}
        if extensions:
            m["extensions"] = {"KHR_materials_ior": {"ior": float(p["ior"])},
                               "KHR_materials_specular": {"specularFactor": float(p["specularFactor"])}}
        return {"type": "gltf", "material": m}
    return make


#: Target name (as ``pgloss bridge TARGET``) → (renderer, its material from the mapping's parameters).
TARGETS: Dict[str, Tuple[str, Callable[[dict, Path], dict]]] = {
    "roughplastic_ggx": ("mitsuba", lambda p, w: dict(p, type="roughplastic")),
    "roughplastic_beckmann": ("mitsuba", lambda p, w: dict(p, type="roughplastic")),
    "principled": ("cycles", lambda p, w: dict(p, type="principled", distribution="MULTI_GGX")),
    "openpbr": ("cycles", _materialx("open_pbr_surface")),
    "standard_surface": ("cycles", _materialx("standard_surface")),
    "gltf": ("cycles", _gltf(True)),
    "gltf_core": ("cycles", _gltf(False)),
}
RENDERER_NAMES = {"tracer": "pgloss-tracer", "mitsuba": "Mitsuba 3.9.1 (llvm_ad_rgb)", "cycles": "Cycles (bpy 5.0.1)"}


def mapped(target: str, L: float, c: float, d: float, tool: Optional[Path]) -> Tuple[dict, str]:
    """The mapping's parameters for paint (L*, 0, 0, c, d) and its status, from the C tool's
    ``pgloss bridge TARGET L a b c d`` (JSON)."""
    if tool is None or not tool.exists():
        raise RuntimeError(f"the mapping is not available: no pgloss tool with a 'bridge' command at {tool}")
    p = subprocess.run([str(tool), "bridge", target, repr(L), "0", "0", repr(c), repr(d)],
                       capture_output=True, text=True)
    if not p.stdout.strip().startswith("{"):
        raise RuntimeError(f"pgloss bridge {target}: exit {p.returncode}: {p.stderr.strip() or p.stdout.strip()}")
    r = json.loads(p.stdout)
    if "parameters" not in r:
        raise RuntimeError(f"pgloss bridge {target}: no parameters ({r.get('status')}: {r.get('reason')})")
    return dict(r["parameters"]), str(r.get("status", "ok")).lower()


# ---------------------------------------------------------------------------------- the meter
class Meter:
    def __init__(self, args: argparse.Namespace):
        self.args = args
        self.bases: Dict[float, im.Basis] = {}

    def basis(self, rho_d: float) -> im.Basis:
        key = round(rho_d, 9)
        if key not in self.bases:
            a = self.args
            spp = a.white_basis_spp if is_white(key) else a.basis_spp
            self.bases[key] = im.render_basis(a.tracer, SCENE, key, spp=spp, alphas=a.alphas,
                                              threads=a.threads, cache=a.work / "basis", progress=True)
        return self.bases[key]

    def read(self, img: np.ndarray, rho_d: float) -> Dict[str, im.Fit]:
        return im.measure(img, self.basis(rho_d))


def _flag(f: im.Fit) -> str:
    return "" if f.status == "ok" else f" ({f.status})"


def _fmt_row(cells: Sequence[object]) -> str:
    return "| " + " | ".join(str(c) for c in cells) + " |"


def _table(head: Sequence[str], rows: Sequence[Sequence[object]]) -> List[str]:
    return [_fmt_row(head), _fmt_row(["---"] * len(head)), *(_fmt_row(r) for r in rows)]


def _machine() -> str:
    """The CPU model and logical core count (/proc/cpuinfo), for the reports' headers."""
    model = "unknown CPU"
    try:
        model = next(line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                     if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    return f"{model}, {os.cpu_count()} logical cores"


def _header(title: str, args: argparse.Namespace, argv: Sequence[str], started: float, load0: float) -> List[str]:
    cmd = "nice .venv-bridge/bin/python examples/bridge/validate.py " + " ".join(argv)
    return [f"# {title}", "",
            f"Generated by `{cmd}` (written whole; do not edit by hand). "
            f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {time.time() - started:.0f} s, "
            f"load average {load0:.1f} before and {os.getloadavg()[0]:.1f} after on {_machine()}. "
            f"Renders: the sphere crop {'x'.join(map(str, im.View.from_scene(SCENE.read_text()).crop()[2:]))} "
            f"of the 160×120 stimulus frame, {args.spp} spp; meter basis: pgloss-tracer, {args.basis_spp} spp, "
            f"{len(args.alphas)} α from {min(args.alphas):g} to {max(args.alphas):g}. Fit: "
            "luminance least squares over the sphere's 2,114 pixels, ρd known (primary); the method is in "
            "docs/image-meter.md.", ""]


# ------------------------------------------------------------------------------------ harnesses
def regions(view: im.View) -> Dict[str, np.ndarray]:
    """Masks over the crop: the sphere, its centre (θo ≤ 60°), its rim, the rest of the crop."""
    mask, cos = view.sphere()
    x0, y0, w, h = view.crop()
    m, c = mask[y0:y0 + h, x0:x0 + w], cos[y0:y0 + h, x0:x0 + w]
    return {"sphere": m, "sphere, θo ≤ 60°": m & (c >= 0.5), "sphere, θo > 60° (rim)": m & (c < 0.5),
            "crop around the sphere (floor, wall)": ~m}


def lambertian(r: Renderers, args: argparse.Namespace) -> List[str]:
    """(1) A Lambertian ρd 0.193 sphere: region means per renderer in K independent chunks."""
    k, spp = 4, max(args.lambert_spp // 4, 1)
    mats = {"tracer": {"tracer": im.paint_line(0.193)}, "mitsuba": {"type": "diffuse", "reflectance": 0.193},
            "cycles": {"type": "diffuse", "reflectance": 0.193}}
    regs = regions(r.view)
    stats: Dict[str, Dict[str, Tuple[float, float]]] = {}
    for name, mat in mats.items():
        imgs = r.images(name, [Job(mat, spp, 500 + i) for i in range(k)])
        ys = [np.asarray(pgloss.luminance(img)) for img in imgs]
        stats[name] = {g: (float(np.mean([y[m].mean() for y in ys])),
                           float(np.std([y[m].mean() for y in ys], ddof=1) / math.sqrt(k))) for g, m in regs.items()}
        print(f"  lambertian: {name} done", file=sys.stderr, flush=True)
    rows, ok_all = [], True
    for g in regs:
        t, te = stats["tracer"][g]
        for name in ("mitsuba", "cycles"):
            v, ve = stats[name][g]
            diff, se = 100 * (v - t) / t, 100 * math.hypot(te, ve) / t
            ok = abs(diff) <= 4 * se + 0.05
            ok_all &= ok
            rows.append((g, RENDERER_NAMES[name], f"{t:.5f}", f"{v:.5f}", f"{diff:+.3f} %", f"{se:.3f} %",
                         "yes" if ok else "**NO**"))
    return ["## 1. A Lambertian sphere (ρd 0.193) in the three renderers", "",
            f"Mean luminance per region, {k} independent renders of {spp} spp each per renderer; the "
            "standard error is from the spread of the four. Agree: |difference| < 4 standard errors + 0.05 %.", "",
            *_table(("region", "renderer", "pgloss-tracer", "renderer's", "difference", "std. error", "agree"), rows),
            "", f"All regions agree: **{'yes' if ok_all else 'NO'}**.", ""]


def control(r: Renderers, meter: Meter, args: argparse.Namespace) -> List[str]:
    """(2) Ward renders of known paints read back (pgloss-tracer, and Mitsuba's Dr.Jit Ward)."""
    ps = paints(args.paints)
    if args.quick:
        ps = [p for p in ps if p[3] == 0.07]
    out = ["## 2. The meter's control: Ward renders of known paints read back", "",
           f"Each paint rendered at {args.spp} spp (the white row, ρd .767, at {args.white_spp} spp against a "
           f"{args.white_basis_spp}-spp basis; seeds other than the basis's) and fitted (ρd known). "
           "Pass: |Δc| ≤ 0.0025 and |Δd| ≤ 0.005 (half the target tolerance). The sensitivities are the "
           "largest |Δc|, |Δd| between the primary fit and the ρd-fitted / rim-excluded fits.", ""]
    for renderer, mat in (("tracer", lambda rd, rs, a: {"tracer": im.paint_line(rd, rs, a)}),
                          ("mitsuba", lambda rd, rs, a: {"type": "ward", "rho_d": rd, "rho_s": rs, "alpha": a})):
        imgs = r.images(renderer, [Job(mat(rd, rs, a), args.white_spp if is_white(rd) else args.spp, 2000 + i)
                                   for i, (_, rd, rs, a) in enumerate(ps)])
        rows, npass, sens = [], 0, [0.0, 0.0, 0.0, 0.0]
        for (label, rd, rs, a), img in zip(ps, imgs):
            _, c0, d0 = (float(v) for v in pgloss.gloss_from_physical(rd, rs, a))
            fits = meter.read(img, rd)
            f = fits["primary"]
            dc, dd = f.c - c0, f.d - d0
            ok = abs(dc) <= TOL_C / 2 and abs(dd) <= TOL_D / 2
            npass += ok
            for i, other in enumerate(("rho_d-fitted", "rim-excluded")):
                sens[2 * i] = max(sens[2 * i], abs(fits[other].c - f.c))
                sens[2 * i + 1] = max(sens[2 * i + 1], abs(fits[other].d - f.d))
            rows.append((label, f"{c0:.4f}", f"{f.c:.4f}", f"{dc:+.4f}", f"{d0:.3f}", f"{f.d:.4f}", f"{dd:+.4f}",
                         f"{100 * f.residual:.2f} %{_flag(f)}", "pass" if ok else "**FAIL**"))
        out += [f"### {RENDERER_NAMES[renderer]}{' (the Dr.Jit Ward of mitsuba_compare.py)' if renderer == 'mitsuba' else ''}",
                "", *_table(("paint ρd/ρs/α", "c", "c read", "Δc", "d", "d read", "Δd", "residual", "control"), rows), "",
                f"**{npass}/{len(ps)} pass.** Setup sensitivity: ρd fitted moves c by ≤ {sens[0]:.4f} and d by ≤ "
                f"{sens[1]:.4f}; leaving out the rim (θo > 60°) moves c by ≤ {sens[2]:.4f} and d by ≤ {sens[3]:.4f}.", ""]
        print(f"  control: {renderer} done", file=sys.stderr, flush=True)
    return out


def noise(r: Renderers, meter: Meter, args: argparse.Namespace) -> List[str]:
    """(3) RMS (Δc, Δd) over repeated pgloss-tracer renders of the grey stimulus, per spp."""
    rows = []
    stimuli = [(0.193, 0.066, 0.07), (0.193, 0.033, 0.04)]
    if args.paints == "all":  # the white and black rows too: the model was fitted on grey paints
        stimuli += [(0.767, 0.066, 0.07), (0.767, 0.033, 0.04), (0.03, 0.066, 0.07)]
    for rd, rs, a in stimuli:
        _, c0, d0 = (float(v) for v in pgloss.gloss_from_physical(rd, rs, a))
        for spp in sorted(set(args.noise_spp) | ({args.white_spp} if is_white(rd) else set())):
            imgs = r.images("tracer", [Job({"tracer": im.paint_line(rd, rs, a)}, spp, 3000 + i)
                                       for i in range(args.noise_reps)])
            fs = [meter.read(img, rd)["primary"] for img in imgs]
            dc = np.array([f.c - c0 for f in fs])
            dd = np.array([f.d - d0 for f in fs])
            ec, ed = im.expected_noise(spp)
            rows.append((f"{rd:g}/{rs:g}/{a:g}", spp, args.noise_reps, f"{np.sqrt(np.mean(dc**2)):.5f}", f"{ec:.5f}",
                         f"{dc.mean():+.5f}", f"{np.sqrt(np.mean(dd**2)):.5f}", f"{ed:.5f}", f"{dd.mean():+.5f}"))
    return ["## 3. The noise model", "",
            f"{'Grey, white and black' if args.paints == 'all' else 'Two grey'} stimuli rendered by pgloss-tracer "
            f"with independent seeds and read back against the basis ({args.basis_spp} spp; ρd .767: "
            f"{args.white_basis_spp} spp). Model (4,096-spp basis, fitted on grey paints): RMS Δc = √(0.0113²/spp + "
            "0.00016²), RMS Δd = 0.030/√spp.", "",
            *_table(("paint ρd/ρs/α", "spp", "renders", "RMS Δc", "model", "mean Δc", "RMS Δd", "model", "mean Δd"), rows),
            ""]


def facts(r: Renderers, meter: Meter, args: argparse.Namespace) -> List[str]:
    """(4) Ward fits of roughplastic GGX/Beckmann and of Principled against roughplastic."""
    alphas = (0.03, 0.07, 0.15)
    jobs, labels = [], []
    for dist in ("ggx", "beckmann"):
        for a in alphas:
            jobs.append(Job({"type": "roughplastic", "distribution": dist, "alpha": a, "int_ior": 1.5,
                             "diffuse_reflectance": 0.193, "nonlinear": False}, args.spp, 4000 + len(jobs)))
            labels.append((dist, a))
    imgs = r.images("mitsuba", jobs)
    rows = []
    for (dist, a), img in zip(labels, imgs):
        fits = meter.read(img, 0.193)
        f, g, h = fits["primary"], fits["rho_d-fitted"], fits["rim-excluded"]
        rows.append((f"roughplastic {dist}", a, f"{f.alpha:.4f}", f"{100 * (f.alpha / a - 1):+.0f} %", f"{f.rho_s:.4f}",
                     f"{f.c:.4f}", f"{f.d:.4f}", f"{100 * f.residual:.1f} %" + _flag(f),
                     f"{g.c - f.c:+.4f} / {g.d - f.d:+.4f}",
                     f"{h.c - f.c:+.4f} / {h.d - f.d:+.4f}"))
    out = ["## 4. The gloss bridge's facts reproduced", "",
           "Mitsuba `roughplastic` (int_ior 1.5, diffuse_reflectance 0.193, nonlinear false) read with ρd 0.193 "
           "known. Facts: Beckmann's fitted Ward α within −4 % … +7 % of its α; GGX's +41 %, +17 %, −12 % at "
           "0.03, 0.07, 0.15; model residual 9–18 % (GGX); rim exclusion moves c, d by < 0.001; the two setups "
           "move c by 0.003–0.021 and d by 0.002–0.033.", "",
           *_table(("sphere", "α", "Ward α", "Ward α / α − 1", "ρs", "c", "d", "residual",
                    "ρd fitted − primary (c / d)", "rim out − primary (c / d)"), rows), ""]
    rows = []
    for rough in (0.1, 0.25):
        a = rough * rough
        mit = r.images("mitsuba", [Job({"type": "roughplastic", "distribution": "ggx", "alpha": a, "int_ior": 1.5,
                                        "diffuse_reflectance": 0.193, "nonlinear": False}, args.spp, 4100)])[0]
        cyc = r.images("cycles", [Job({"type": "principled", "Base Color": 0.193, "Roughness": rough, "IOR": 1.5},
                                      args.spp, 4100)])[0]
        fm, fc = meter.read(mit, 0.193)["primary"], meter.read(cyc, 0.193)["primary"]
        rows.append((rough, f"{a:.4f}", f"{fm.c:.4f} / {fm.d:.4f}", f"{fc.c:.4f} / {fc.d:.4f}", f"{fc.c - fm.c:+.4f}",
                     f"{fc.d - fm.d:+.4f}", f"{100 * fm.residual:.1f} %{_flag(fm)} / {100 * fc.residual:.1f} %{_flag(fc)}"))
    out += ["Principled BSDF (Cycles; Base Color 0.193, IOR 1.5, Specular IOR Level 0.5, multiscatter GGX) against "
            "roughplastic GGX at α = roughness². Facts: Δc −0.0008, Δd +0.0007 at roughness 0.1; Δc +0.0024, "
            "Δd −0.0049 at 0.25 (Principled − roughplastic).", "",
            *_table(("roughness", "α", "roughplastic c / d", "Principled c / d", "Δc", "Δd",
                     "residual (roughplastic / Principled)"), rows), ""]
    return out


# ----------------------------------------------------------------------------------- the table
def white_note(args: argparse.Namespace) -> str:
    """How the white row's reachable paints are rendered and read, where that differs."""
    if (args.white_spp, args.white_basis_spp) == (args.spp, args.basis_spp):
        return ""
    return (f" (the reachable paints of the white row, ρd .767, at {args.white_spp} spp, read against a "
            f"{args.white_basis_spp}-spp basis)")


def validation_table(r: Renderers, meter: Meter, args: argparse.Namespace,
                     progress: Optional[Callable[[List[str]], None]] = None) -> List[str]:
    out = ["Each paint's (L*, c, d) mapped by `pgloss bridge TARGET L 0 0 c d`, rendered in the target's own "
           f"renderer at {args.spp} spp{white_note(args)}, read back by the image gloss meter (ρd known from L*). Paints: "
           f"{'all 30' if args.paints == 'all' else 'the 10 of ρd .193 (Fig. 4 grey row, Fig. 12 grey)'}. Pass: |Δc| ≤ 0.005 "
           "and |Δd| ≤ 0.01. Paints the mapping reports out of reach are listed with its status and not counted.", ""]
    ps = paints(args.paints)
    for target in args.targets:
        renderer, make = TARGETS[target]
        jobs, meta = [], []
        for i, (label, rd, rs, a) in enumerate(ps):
            L, c, d = (float(v) for v in pgloss.gloss_from_physical(rd, rs, a))
            params, status = mapped(target, L, c, d, args.tool)
            reach = "bridge" not in status
            jobs.append(Job(make(params, args.work), args.white_spp if reach and is_white(rd) else args.spp, 6000 + i))
            meta.append((label, rd, c, d, status))
        imgs = r.images(renderer, jobs)
        rows, npass, nreach = [], 0, 0
        for (label, rd, c, d, status), img in zip(meta, imgs):
            f = meter.read(img, rd)["primary"]
            dc, dd = f.c - c, f.d - d
            reach = "bridge" not in status  # OK or a warning (α untrusted); BRIDGE_*: out of reach
            ok = abs(dc) <= TOL_C and abs(dd) <= TOL_D
            nreach += reach
            npass += ok and reach
            rows.append((label, f"{c:.4f}", f"{f.c:.4f}", f"{abs(dc):.4f}", f"{d:.3f}", f"{f.d:.4f}", f"{abs(dd):.4f}",
                         f"{100 * f.residual:.1f} %", ("pass" if ok else "**FAIL**") if reach else f"({status})"))
        out += [f"## {target} — {RENDERER_NAMES[renderer]}", "",
                *_table(("paint", "c", "c read", "|Δc|", "d", "d read", "|Δd|", "residual", "result"), rows), "",
                f"**{npass}/{nreach} reachable paints pass** ({len(ps) - nreach} out of reach).", ""]
        print(f"  table: {target} done", file=sys.stderr, flush=True)
        if progress is not None and target != args.targets[-1]:
            progress(out + [f"(The run is still going: {args.targets.index(target) + 1} of {len(args.targets)} "
                            "targets done.)", ""])
    return out


def command_line(argv: Sequence[str], report: str) -> List[str]:
    """The command that writes ``report``: argv with the positional ``all`` written as ``report``;
    an option's value ``all`` (``--paints all``) stays as it is."""
    out: List[str] = []
    value_next = False
    for a in argv:
        if a == "all" and not value_next:
            a = report
        value_next = a.startswith("--") and "=" not in a and a != "--quick"
        out.append(a)
    return out


def main(argv: Optional[List[str]] = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("report", choices=("harnesses", "table", "all"), help="all: the table, then the harnesses")
    ap.add_argument("--spp", type=int, default=1024, help="spp of each validation render (%(default)s)")
    ap.add_argument("--basis-spp", type=int, default=2048, help="spp of the meter's basis renders (%(default)s)")
    ap.add_argument("--white-spp", type=int, help="spp of the white row's reachable paints in the table (default --spp)")
    ap.add_argument("--white-basis-spp", type=int, help="spp of the ρd .767 basis (default --basis-spp)")
    ap.add_argument("--lambert-spp", type=int, default=4096, help="total spp per renderer of check 1 (%(default)s)")
    ap.add_argument("--noise-spp", default="256,1024")
    ap.add_argument("--noise-reps", type=int, default=6)
    ap.add_argument("--alphas", type=int, default=21, help="log-spaced α nodes of the basis, 0.01-0.3 (%(default)s; "
                    "19 %% steps interpolate to 0.0003 in d, docs/image-meter.md)")
    ap.add_argument("--targets", default=",".join(TARGETS))
    ap.add_argument("--paints", choices=("all", "grey"), default="all",
                    help="all 30 paints, or the 10 of ρd .193 (one basis; the machine-time-limited run)")
    ap.add_argument("--quick", action="store_true", help="grey paints only (a smoke run; the report is printed, not written)")
    ap.add_argument("--tracer", type=Path, default=Path(os.environ.get("PGLOSS_TRACER",
                                                                         "build-bridge/examples/tracer/pgloss-tracer")))
    ap.add_argument("--tool", type=Path, default=Path(os.environ.get("PGLOSS_TOOL", "build-bridge/tools/pgloss")),
                    help="the C tool whose bridge command maps the paints (%(default)s)")
    ap.add_argument("--bpy-python", type=Path, default=Path(".venv-bpy/bin/python"))
    ap.add_argument("--work", type=Path, default=Path("build-bridge/validate"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", type=Path, help="the Markdown file (default docs/bridge-REPORT.md)")
    args = ap.parse_args(argv)
    args.alphas = tuple(float(a) for a in np.geomspace(0.01, 0.3, args.alphas))
    args.white_spp = args.white_spp or args.spp
    args.white_basis_spp = args.white_basis_spp or args.basis_spp
    args.noise_spp = [int(v) for v in args.noise_spp.split(",")]
    args.targets = [t for t in args.targets.split(",") if t]
    for t in args.targets:
        if t not in TARGETS:
            ap.error(f"unknown target {t!r} ({', '.join(TARGETS)})")
    r = Renderers(args.tracer, args.work, args.threads, args.bpy_python)
    meter = Meter(args)
    # The bases first: their progress is what the first minutes show.
    for rd in (0.193,) if args.quick or args.paints == "grey" else RHO_D:
        meter.basis(rd)
    reports = ["table", "harnesses"] if args.report == "all" else [args.report]
    for report in reports:
        t0, l0 = time.time(), os.getloadavg()[0]
        cmd = command_line(argv, report)
        if report == "harnesses":
            title, default = "The gloss bridge's instruments: harnesses and image gloss meter", "docs/bridge-harnesses.md"
        else:
            title, default = "The gloss bridge validated in real renderers", "docs/bridge-validation.md"
        out = args.out or ROOT / default

        def write(body: List[str]) -> None:
            text = "\n".join(_header(title, args, cmd, t0, l0) + body) + "\n"
            if args.quick:
                print(text)
                return
            out.write_text(text)
            print(f"wrote {out}", file=sys.stderr, flush=True)

        if report == "harnesses":
            write(lambertian(r, args) + control(r, meter, args) + noise(r, meter, args) + facts(r, meter, args))
        else:
            write(validation_table(r, meter, args, None if args.quick else write))
    return 0


if __name__ == "__main__":
    sys.exit(main())
