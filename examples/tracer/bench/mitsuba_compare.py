# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss-tracer against Mitsuba 3 (llvm_ad_rgb) on the stimulus scene, side by side.

A benchmark (prints a Markdown table), not a test. Both renderers draw the same scene,
examples/tracer/scenes/stimulus.scene:

* geometry: the 4 x 3 x 4 m box as six UV-mapped faces whose Mitsuba ``checkerboard`` texture
  reproduces the tracer's 3-D checker (0.5 m checks, offset 0.125 m, rho_d .03 / .767), the
  0.5 m sphere, the 1 m^2 one-sided light (radiance 16, black surface);
* camera: the same pinhole (vertical fov 48 deg), box pixel filter (one pixel per sample);
* path rules: the tracer's max_depth 8 (eight shading vertices) is Mitsuba's max_depth 9,
  its Russian roulette after the fourth vertex (q = min(.95, max throughput)) is Mitsuba's
  rr_depth 4 with the same q; NEE + BSDF sampling combined with the power heuristic;
* material of the sphere ("paint"): Lambertian rho_d .193 (Mitsuba's ``diffuse``), or the
  paper's Fig. 4 stimulus (rho_d .193, rho_s .066, alpha .07), Ward eq. 2 written below as
  a Dr.Jit BSDF with pgloss's sampling (Walter 2005's half vector, lobe chosen by
  rho_s / (lum(rho_d) + rho_s));
* sampler: independent on both (the comparison); --sobol adds a row for the tracer with its
  Owen-scrambled Sobol' sampler; the same number of threads on both (default 2);
* light sampling: uniform by area on both (the tracer's default, Mitsuba's rectangle).

Per renderer and material it reports samples/s, the relative RMSE at N spp against the
renderer's *own* high-spp reference, the time to 1 % relative RMSE and the efficiency ratio
1/(relMSE x time) tracer / Mitsuba. Relative RMSE = ||x - ref|| / ||ref|| over all pixels and
RGB channels; the reference's own noise is taken out (relMSE_N = measured x Nref/(N + Nref),
exact for independent samples of one estimator). The time to 1 % is spp_1% / (spp/s) with
spp_1% = N (relRMSE_N / 0.01)^2. Runs of the two renderers alternate (tracer, Mitsuba,
Mitsuba, tracer, ...) so that machine load hits both alike; wall and CPU time are both given
(the tracer's render loop only; Mitsuba's whole mi.render call, kernel cache warm).
Finally the two references are compared per region (walls, floor, ceiling, sphere) with the
difference's standard error, to show that both converge to the same image.

    python examples/tracer/bench/mitsuba_compare.py [--quick] [--tracer PATH] [--threads 2]
        [--spp 16,64] [--ref-spp 1024] [--reps 2] [--size 320x240] [--materials diffuse,stimulus]
        [--sobol]
"""
from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SCENE = HERE.parent / "scenes" / "stimulus.scene"

MATERIALS = {
    "diffuse": {"label": "diffuse sphere (rho_d .193)", "line": "material paint diffuse=0.193",
                "rho_d": 0.193, "rho_s": 0.0, "alpha": 0.07},
    "stimulus": {"label": "Fig. 4 stimulus (rho_d .193, rho_s .066, alpha .07)",
                 "line": "material paint physical rho_d=0.193 rho_s=0.066 alpha=0.07",
                 "rho_d": 0.193, "rho_s": 0.066, "alpha": 0.07},
}

# The scene's numbers (stimulus.scene); the tracer reads them from the file itself.
BOX_MIN, BOX_MAX = np.array([-2.0, 0.0, -2.0]), np.array([2.0, 3.0, 2.0])
CHECK, OFFSET = 0.5, 0.125
SPHERE_C, SPHERE_R = np.array([0.0, 0.5, -0.5]), 0.5
CAM_POS, CAM_AT, CAM_UP, FOV = (0, 1.5, 1.95), (0, 0.45, -0.5), (0, 1, 0), 48.0


# ------------------------------------------------------------------------------- Mitsuba side
def ward_bsdf_class(mi, dr):
    """Ward eq. 2 (rho_d/pi + rho_s e^{-tan^2 d/a^2} / (4 pi a^2 sqrt(ci co))) with pgloss's
    sampling and pdf (pgloss/brdf.h), as a Mitsuba BSDF in Dr.Jit."""

    class Ward(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            self.rho_d = float(props["rho_d"])
            self.rho_s = float(props["rho_s"])
            self.alpha = float(props["alpha"])
            self.ps = self.rho_s / (self.rho_d + self.rho_s)  # grey: luminance(rho_d) = rho_d
            flags = (mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.GlossyReflection
                     | mi.BSDFFlags.FrontSide)
            self.m_components = [flags]
            self.m_flags = flags

        def _eval_pdf(self, wi, wo, active):
            ci, co = mi.Frame3f.cos_theta(wo), mi.Frame3f.cos_theta(wi)
            ok = active & (ci > 0) & (co > 0)
            h = dr.normalize(wi + wo)
            a2 = self.alpha * self.alpha
            e = dr.exp(-(h.x * h.x + h.y * h.y) / (a2 * h.z * h.z))
            f = self.rho_d / dr.pi + self.rho_s * e / (4 * dr.pi * a2 * dr.sqrt(ci * co))
            p_spec = e / (4 * dr.pi * a2 * dr.dot(wi, h) * h.z * h.z * h.z)
            pdf = (1 - self.ps) * ci / dr.pi + self.ps * p_spec
            return dr.select(ok, f, 0.0), dr.select(ok, pdf, 0.0), ci

        def sample(self, ctx, si, sample1, sample2, active):
            wi = si.wi
            spec = sample1 < self.ps
            s = dr.sqrt(-dr.log(1 - sample2.x))
            sn, cs = dr.sincos(2 * dr.pi * sample2.y)
            h = dr.normalize(mi.Vector3f(self.alpha * s * cs, self.alpha * s * sn, 1.0))
            wh = dr.dot(wi, h)
            wo_s = 2 * wh * h - wi
            wo_d = mi.warp.square_to_cosine_hemisphere(sample2)
            wo = dr.select(spec, wo_s, wo_d)
            good = active & (mi.Frame3f.cos_theta(wi) > 0) & (~spec | (wh > 0))
            f, pdf, ci = self._eval_pdf(wi, wo, good)
            good &= pdf > 0
            bs = dr.zeros(mi.BSDFSample3f)
            bs.wo = wo
            bs.pdf = dr.select(good, pdf, 0.0)
            bs.eta = 1.0
            bs.sampled_type = dr.select(spec, mi.UInt32(+mi.BSDFFlags.GlossyReflection),
                                        mi.UInt32(+mi.BSDFFlags.DiffuseReflection))
            bs.sampled_component = mi.UInt32(0)
            weight = dr.select(good, f * ci / dr.select(good, pdf, 1.0), 0.0)
            return bs, mi.Color3f(weight)

        def eval(self, ctx, si, wo, active):
            f, _, ci = self._eval_pdf(si.wi, wo, active)
            return mi.Color3f(f * ci)

        def pdf(self, ctx, si, wo, active):
            return self._eval_pdf(si.wi, wo, active)[1]

        def eval_pdf(self, ctx, si, wo, active):
            f, pdf, ci = self._eval_pdf(si.wi, wo, active)
            return mi.Color3f(f * ci), pdf

        def traverse(self, callback):
            pass

        def parameters_changed(self, keys):
            pass

        def to_string(self):
            return f"Ward[rho_d={self.rho_d}, rho_s={self.rho_s}, alpha={self.alpha}]"

    return Ward


def box_faces_obj(folder: Path) -> list[Path]:
    """The box's six faces as one-quad OBJ files with UVs such that Mitsuba's checkerboard
    (colour0 where frac(u) > .5 equals frac(v) > .5) is the tracer's parity
    (floor((x-o)/s) + floor((y-o)/s) + floor((z-o)/s)) & 1 -> white: u is shifted by half a
    period on faces whose constant coordinate lies in an odd check."""
    out = []
    lo, hi = BOX_MIN, BOX_MAX
    for axis in range(3):
        for side in (lo[axis], hi[axis]):
            a, b = [k for k in range(3) if k != axis]
            corners = []
            for ua, ub in ((lo[a], lo[b]), (hi[a], lo[b]), (hi[a], hi[b]), (lo[a], hi[b])):
                p = np.zeros(3)
                p[axis], p[a], p[b] = side, ua, ub
                corners.append(p)
            # u, v = (coordinate - offset) / (2 check) + 10: one period = two checks
            fc = int(np.floor((side - OFFSET) / CHECK)) & 1
            lines = []
            for p in corners:
                lines.append("v %.9g %.9g %.9g" % tuple(p))
            for p in corners:
                u = (p[a] - OFFSET) / (2 * CHECK) + 10 + (0.5 if fc else 0.0)
                v = (p[b] - OFFSET) / (2 * CHECK) + 10
                lines.append("vt %.9g %.9g" % (u, v))
            lines.append("f 1/1 2/2 3/3")
            lines.append("f 1/1 3/3 4/4")
            path = folder / f"face{axis}{int(side == hi[axis])}.obj"
            path.write_text("\n".join(lines) + "\n")
            out.append(path)
    return out


def mitsuba_scene(mi, material: str, width: int, height: int, folder: Path, *, paint: dict | None = None,
                  crop: tuple[int, int, int, int] | None = None):
    """The stimulus scene; ``paint`` (a Mitsuba BSDF dict) replaces MATERIALS[material]'s sphere,
    ``crop`` = (x0, y0, w, h) renders that window of the film alone (the gloss bridge's harness)."""
    m = MATERIALS[material]
    black = {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.0}}
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 9, "rr_depth": 4, "hide_emitters": False},
        "sensor": {
            "type": "perspective", "fov": FOV, "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=CAM_POS, target=CAM_AT, up=CAM_UP),
            "film": {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb",
                     "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": 16},
        },
        "light": {
            "type": "rectangle",
            "to_world": mi.ScalarTransform4f().translate([0, 2.999, -0.5])
            @ mi.ScalarTransform4f().rotate([1, 0, 0], 90) @ mi.ScalarTransform4f().scale([0.5, 0.5, 1]),
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": 16.0}},
            "bsdf": black,
        },
    }
    if crop is not None:
        film = d["sensor"]["film"]
        film.update(crop_offset_x=crop[0], crop_offset_y=crop[1], crop_width=crop[2], crop_height=crop[3])
    if paint is None and m["rho_s"] > 0:
        paint = {"type": "ward_pgloss", "rho_d": m["rho_d"], "rho_s": m["rho_s"], "alpha": m["alpha"]}
    elif paint is None:
        paint = {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": m["rho_d"]}}}
    d["sphere"] = {"type": "sphere", "center": SPHERE_C.tolist(), "radius": SPHERE_R, "bsdf": paint}
    for path in box_faces_obj(folder):
        c0, c1 = 0.03, 0.767
        d[path.stem] = {
            "type": "obj", "filename": str(path), "face_normals": True, "flip_tex_coords": False,
            "bsdf": {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": {
                "type": "checkerboard",
                "color0": {"type": "rgb", "value": c0}, "color1": {"type": "rgb", "value": c1}}}},
        }
    return mi.load_dict(d)


class MitsubaRunner:
    def __init__(self, threads: int, width: int, height: int, folder: Path):
        import drjit as dr  # noqa: PLC0415
        import mitsuba as mi  # noqa: PLC0415

        mi.set_variant("llvm_ad_rgb")
        dr.set_thread_count(threads)
        mi.register_bsdf("ward_pgloss", lambda props: ward_bsdf_class(mi, dr)(props))
        self.mi, self.dr = mi, dr
        self.width, self.height, self.folder = width, height, folder
        self.scenes: dict = {}

    def scene(self, material: str):
        if material not in self.scenes:
            self.scenes[material] = mitsuba_scene(self.mi, material, self.width, self.height, self.folder)
        return self.scenes[material]

    def render(self, material: str, spp: int, seed: int) -> tuple[np.ndarray, float, float]:
        sc = self.scene(material)
        w0, c0 = time.perf_counter(), time.process_time()
        img = np.array(self.mi.render(sc, spp=spp, seed=seed), dtype=np.float64)
        return img[..., :3], time.perf_counter() - w0, time.process_time() - c0


SOBOL = "pgloss-tracer, Sobol'"

# -------------------------------------------------------------------------------- tracer side
class TracerRunner:
    def __init__(self, exe: Path, threads: int, width: int, height: int, folder: Path,
                 extra: list[str] | None = None):
        self.exe, self.threads, self.width, self.height, self.folder = exe, threads, width, height, folder
        self.extra = extra or []  # more pgloss-tracer options (--sampler sobol)
        self.scenes: dict = {}

    def scene(self, material: str) -> Path:
        if material not in self.scenes:
            text = SCENE.read_text()
            text = re.sub(r"^material paint .*$", MATERIALS[material]["line"], text, flags=re.M)
            p = self.folder / f"stimulus-{material}.scene"
            p.write_text(text)
            self.scenes[material] = p
        return self.scenes[material]

    def render(self, material: str, spp: int, seed: int) -> tuple[np.ndarray, float, float]:
        import mitsuba as mi  # noqa: PLC0415  (EXR reader)

        out = self.folder / f"tracer-{material}-{spp}-{seed}"
        r = subprocess.run([str(self.exe), "render", str(self.scene(material)), "--spp", str(spp),
                            "--seed", str(seed), "--threads", str(self.threads),
                            "--size", f"{self.width}x{self.height}", "--quiet", "--out", str(out), *self.extra],
                           check=True, capture_output=True, text=True)
        m = re.search(r", ([0-9.]+) s, .*?, ([0-9.]+) s CPU", r.stdout)
        if not m:
            raise RuntimeError(f"unexpected pgloss-tracer output: {r.stdout!r}")
        img = np.array(mi.Bitmap(str(out) + ".exr"), dtype=np.float64)[..., :3]
        return img, float(m.group(1)), float(m.group(2))


# ------------------------------------------------------------------------------- measurement
def rel_mse(img: np.ndarray, ref: np.ndarray, spp: int, ref_spp: int) -> float:
    """||img - ref||^2 / ||ref||^2, less the reference's own share of the noise."""
    measured = float(np.sum((img - ref) ** 2) / np.sum(ref**2))
    return measured * ref_spp / (spp + ref_spp)


def regions(width: int, height: int) -> np.ndarray:
    """Region of the primary hit through each pixel centre (numpy ray cast of the scene):
    0 walls, 1 floor, 2 ceiling, 3 sphere, 4 light."""
    f = np.subtract(CAM_AT, CAM_POS)
    f = f / np.linalg.norm(f)
    r = np.cross(f, CAM_UP)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    th = np.tan(np.radians(FOV) / 2)
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    sx = (2 * xs / width - 1) * (width / height) * th
    sy = (1 - 2 * ys / height) * th
    d = f + sx[..., None] * r + sy[..., None] * u
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    o = np.array(CAM_POS, dtype=float)
    # box interior: the exit distance
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(d > 0, (BOX_MAX - o) / d, (BOX_MIN - o) / d)
    axis = np.argmin(t1, axis=-1)
    t = np.min(t1, axis=-1)
    p = o + t[..., None] * d
    reg = np.where(axis == 1, np.where(d[..., 1] < 0, 1, 2), 0)
    light = (axis == 1) & (d[..., 1] > 0) & (np.abs(p[..., 0]) < 0.5) & (np.abs(p[..., 2] + 0.5) < 0.5)
    reg = np.where(light, 4, reg)
    oc = o - SPHERE_C
    b = np.sum(d * oc, axis=-1)
    disc = b * b - (oc @ oc - SPHERE_R**2)
    ts = -b - np.sqrt(np.maximum(disc, 0))
    reg = np.where((disc > 0) & (ts > 0) & (ts < t), 3, reg)
    return reg


@dataclass
class Row:
    spp: int
    walls: list = field(default_factory=list)
    cpus: list = field(default_factory=list)
    errs: list = field(default_factory=list)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tracer", type=Path, default=Path("build-tracer-bench/examples/tracer/pgloss-tracer"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spp", default="16,64")
    ap.add_argument("--ref-spp", type=int, default=1024)
    ap.add_argument("--reps", type=int, default=2)
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--materials", default="diffuse,stimulus")
    ap.add_argument("--quick", action="store_true", help="160x120, 4/16 spp, reference 256 spp, 1 rep")
    ap.add_argument("--sobol", action="store_true",
                    help="add a row for pgloss-tracer with its Owen-scrambled Sobol' sampler (--sampler sobol)")
    ap.add_argument("--keep", type=Path, help="folder for the images (default: a temporary one)")
    a = ap.parse_args(argv)
    if a.quick:
        a.size, a.spp, a.ref_spp, a.reps = "160x120", "4,16", 256, 1
    width, height = (int(v) for v in a.size.split("x"))
    spps = [int(v) for v in a.spp.split(",")]
    mats = a.materials.split(",")
    tmp = tempfile.TemporaryDirectory(prefix="pgloss-mitsuba-")
    folder = a.keep or Path(tmp.name)
    folder.mkdir(parents=True, exist_ok=True)
    if not a.tracer.exists():
        print(f"pgloss-tracer not found at {a.tracer}", file=sys.stderr)
        return 2
    mits = MitsubaRunner(a.threads, width, height, folder)
    trc = TracerRunner(a.tracer, a.threads, width, height, folder)
    runners = {"pgloss-tracer": trc, "Mitsuba 3": mits}
    if a.sobol:
        # Measured against the independent sampler's reference (the same image), its noise taken
        # out by subtraction: randomised QMC's error need not fall as 1/spp, so "spp to 1 %" for
        # this row is an extrapolation as if it did.
        runners[SOBOL] = TracerRunner(a.tracer, a.threads, width, height, folder, ["--sampler", "sobol"])

    print(f"# pgloss-tracer vs Mitsuba 3.9.1 llvm_ad_rgb: {width}x{height}, {a.threads} threads each, "
          f"reference {a.ref_spp} spp, load before: {os.getloadavg()[0]:.2f}", flush=True)
    region_names = ["walls", "floor", "ceiling", "sphere", "light"]
    reg = regions(width, height)
    table, checks = [], []
    for mat in mats:
        # Mitsuba's kernels are compiled once per scene and spp-independent; warm the cache.
        for spp in spps:
            mits.render(mat, spp, 999)
        refs = {}
        for name, rn in runners.items():
            if name == SOBOL:
                continue
            chunk = max(1, a.ref_spp // 16)  # 16 chunks: the reference's own variance
            acc = np.zeros((height, width, 3))
            var = np.zeros((height, width, 3))
            for k in range(a.ref_spp // chunk):
                img, _, _ = rn.render(mat, chunk, 10_000 + k)
                acc += img
                var += img**2
            n = a.ref_spp // chunk
            mean = acc / n
            refs[name] = (mean, np.maximum(var / n - mean**2, 0) / max(n - 1, 1))  # variance of the mean (per chunk)
            print(f"  {mat}: {name} reference done", flush=True)
        rows = {name: [Row(s) for s in spps] for name in runners}
        order = list(runners)
        for rep in range(a.reps):
            for i, spp in enumerate(spps):
                seq = order if (rep + i) % 2 == 0 else order[::-1]
                for name in seq:
                    img, wall, cpu = runners[name].render(mat, spp, 1 + 100 * rep + i)
                    row = rows[name][i]
                    row.walls.append(wall)
                    row.cpus.append(cpu)
                    if name == SOBOL:
                        ref, ref_var = refs["pgloss-tracer"]
                        row.errs.append(max(0.0, (float(np.sum((img - ref) ** 2)) - float(ref_var.sum()))
                                            / float(np.sum(ref**2))))
                    else:
                        row.errs.append(rel_mse(img, refs[name][0], spp, a.ref_spp))
        npix = width * height
        for i, spp in enumerate(spps):
            res = {}
            for name in runners:
                row = rows[name][i]
                wall, cpu = statistics.median(row.walls), statistics.median(row.cpus)
                rmse = float(np.sqrt(np.mean(row.errs)))
                spp1 = spp * (rmse / 0.01) ** 2
                res[name] = dict(sps=npix * spp / wall, cps=npix * spp / cpu, rmse=rmse,
                                 t1=spp1 * wall / spp, c1=spp1 * cpu / spp, spp1=spp1)
            for name in runners:
                r = res[name]
                table.append((MATERIALS[mat]["label"], spp, name, r["sps"] * 1e-6, r["cps"] * 1e-6,
                              100 * r["rmse"], r["spp1"], r["t1"], r["c1"],
                              res["Mitsuba 3"]["t1"] / r["t1"], res["Mitsuba 3"]["c1"] / r["c1"]))
        (ta, tv), (ma, mv) = refs["pgloss-tracer"], refs["Mitsuba 3"]
        for k, rname in enumerate(region_names):
            sel = reg == k
            if not sel.any():
                continue
            tm, mm = ta[sel].mean(), ma[sel].mean()
            se = np.sqrt(tv[sel].sum() + mv[sel].sum()) / sel.sum()
            checks.append((MATERIALS[mat]["label"], rname, int(sel.sum()), tm, mm, 100 * (tm - mm) / mm,
                           100 * se / mm))
        whole = float(np.linalg.norm(ta - ma) / np.linalg.norm(ma))
        expect = float(np.sqrt((tv.sum() + mv.sum())) / np.linalg.norm(ma))
        checks.append((MATERIALS[mat]["label"], "whole image ||t-m||/||m||", npix, float("nan"), float("nan"),
                       100 * whole, 100 * expect))

    print()
    print("| material | spp | renderer | Msamples/s (wall) | Msamples/s (CPU) | rel. RMSE | spp to 1 % "
          "| time to 1 % (wall) | CPU time to 1 % | efficiency ratio (wall / CPU) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for lab, spp, name, sps, cps, rm, spp1, t1, c1, rw, rc in table:
        ratio = f"**{rw:.2f} / {rc:.2f}**" if name == "pgloss-tracer" else f"{rw:.2f} / {rc:.2f}" if name == SOBOL else "1"
        print(f"| {lab} | {spp} | {name} | {sps:.2f} | {cps:.2f} | {rm:.2f} % | {spp1:.0f} | {t1:.1f} s "
              f"| {c1:.1f} s | {ratio} |")
    print()
    print("Both converge to the same image: region means of the two references "
          "(difference, and its standard error from the references' noise):")
    print()
    print("| material | region | pixels | tracer | Mitsuba | difference | std. error | agree (< 4 std. errors + 0.05 %) |")
    print("|---|---|---|---|---|---|---|---|")
    for lab, rname, n, tm, mm, diff, se in checks:
        if np.isnan(tm):  # whole image: the difference's norm against what noise alone gives
            ok = diff < 1.1 * se + 0.05
            print(f"| {lab} | {rname} | {n} | | | {diff:.2f} % | {se:.2f} % (noise alone) | {'yes' if ok else 'NO'} (< 1.1x noise + 0.05 %) |")
        else:
            ok = abs(diff) < 4 * se + 0.05
            print(f"| {lab} | {rname} | {n} | {tm:.5f} | {mm:.5f} | {diff:+.3f} % | {se:.3f} % | {'yes' if ok else 'NO'} |")
    ru = resource.getrusage(resource.RUSAGE_SELF)
    print(f"\nload after: {os.getloadavg()[0]:.2f}; max RSS {ru.ru_maxrss / 1024:.0f} MiB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
