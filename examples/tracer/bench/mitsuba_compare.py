# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss-tracer against Mitsuba 3 (llvm_ad_rgb) on a tracer scene, side by side.

A benchmark (prints Markdown tables), not a test. Both renderers draw the same scene, read from
the tracer's scene file (read_scene) and translated for Mitsuba (mitsuba_dict):

* geometry: boxes as six UV-mapped faces whose Mitsuba ``checkerboard`` texture reproduces the
  tracer's 3-D checker; meshes from the same OBJ files with ``face_normals`` (the tracer shades
  with the triangle's own normal) and ``to_world`` = translate . scale (scale first), each
  surface in a ``twosided`` BSDF (the tracer turns the normal towards the ray); spheres;
  one-sided rectangle lights (black surface); a uniform environment as ``constant``;
* camera: the same pinhole (vertical fov), box pixel filter (one pixel per sample);
* path rules: the tracer's max_depth (shading vertices) is Mitsuba's max_depth + 1, its Russian
  roulette after the fourth vertex (q = min(.95, max throughput)) is Mitsuba's rr_depth 4 with
  the same q; NEE + BSDF sampling combined with the power heuristic;
* materials: Lambertian as Mitsuba's ``diffuse``; Ward eq. 2 (isotropic, ``norm=ward``) as a
  Dr.Jit BSDF below with pgloss's sampling (Walter 2005's half vector, lobe chosen by
  rho_s / (luminance(rho_d) + rho_s)); perceptual paints converted by ``pgloss to-physical``,
  as the tracer converts them;
* sampler: independent on both (the comparison); --sobol adds a row for the tracer with its
  Owen-scrambled Sobol' sampler; the same number of threads on both (default 2);
* light sampling: uniform by area on both (the tracer's default, Mitsuba's rectangle).

The stimulus scene is rendered with each sphere material of --materials (Lambertian rho_d
.193, the Fig. 4 stimulus rho_d .193, rho_s .066, alpha .07); any other scene as written
(--scene mug: Fig. 14's glossy red mug). Per renderer it reports samples/s, the relative RMSE
at N spp against the renderer's *own* high-spp reference, the time to 1 % relative RMSE and the
efficiency ratio 1/(relMSE x time) tracer / Mitsuba. Relative RMSE = ||x - ref|| / ||ref|| over
all pixels and RGB channels; the reference's own noise is taken out (relMSE_N = measured x
Nref/(N + Nref), exact for independent samples of one estimator). The time to 1 % is spp_1% /
(spp/s) with spp_1% = N (relRMSE_N / 0.01)^2. Runs of the two renderers alternate (tracer,
Mitsuba, Mitsuba, tracer, ...) so that machine load hits both alike, and the efficiency ratio
is taken per round from that round's two times (the errors, which do not depend on the load,
pooled over the rounds): median and range. Wall and CPU time are both given (the tracer's
render loop only; Mitsuba's whole mi.render call, kernel cache warm; neither includes loading
the scene). Finally the two references are compared per region (the first hit through each
pixel centre, by Mitsuba's ray cast: walls, floor, ceiling, each mesh, sphere) with the
difference's standard error, to show that both converge to the same image.

--scale N1,N2,... then renders the scene with each mesh triangle cut into N^2
(subdivide_mesh.py: the same surface, so the same image) and reports each size's build time,
memory, samples/s and efficiency ratio. --write FILE puts the report in this command's own
section of FILE (bench/results/tracer.md), written whole.

    bash examples/tracer/bench/run.sh [--quick] [--scene stimulus|mug|FILE.scene] [--spp 16,64]
        [--ref-spp 1024] [--reps 3] [--size WxH] [--materials diffuse,stimulus] [--sobol]
        [--scale 1,10,32] [--write bench/results/tracer.md]
"""
from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SCENES = HERE.parent / "scenes"
SCENE = SCENES / "stimulus.scene"

# The stimulus scene's sphere materials (its material `paint`, replaced line for line).
MATERIALS = {
    "diffuse": {"label": "diffuse sphere (rho_d .193)", "line": "material paint diffuse=0.193"},
    "stimulus": {"label": "Fig. 4 stimulus (rho_d .193, rho_s .066, alpha .07)",
                 "line": "material paint physical rho_d=0.193 rho_s=0.066 alpha=0.07"},
}


# Rec. 709 luminance weights (libpgloss/include/pgloss/color.h: PGLOSS_LUMA_R, _G, _B).
LUMA = (0.21263900587151036, 0.71516867876775593, 0.072192315360733715)


# ------------------------------------------------------------------------------- Mitsuba side
def ward_bsdf_class(mi, dr):
    """Ward eq. 2 (rho_d/pi + rho_s e^{-tan^2 d/a^2} / (4 pi a^2 sqrt(ci co))) with pgloss's
    sampling and pdf (pgloss/brdf.h), as a Mitsuba BSDF in Dr.Jit."""

    class Ward(mi.BSDF):
        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            rd = mi.ScalarColor3f(props["rho_d"])  # a grey number or r, g, b (linear Rec. 709)
            self.rho_d = tuple(float(rd[k]) for k in range(3))
            self.rho_s = float(props["rho_s"])
            self.alpha = float(props["alpha"])
            grey = self.rho_d[0] == self.rho_d[1] == self.rho_d[2]
            lum = self.rho_d[0] if grey else sum(w * c for w, c in zip(LUMA, self.rho_d))
            self.ps = self.rho_s / (lum + self.rho_s)  # pgloss: ws / (luminance(rho_d) + ws)
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
            f = mi.Color3f(*self.rho_d) / dr.pi + self.rho_s * e / (4 * dr.pi * a2 * dr.sqrt(ci * co))
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


def box_faces_obj(folder: Path, lo, hi, check: float, offset, prefix: str = "face") -> list[Path]:
    """The box's six faces as one-quad OBJ files with UVs such that Mitsuba's checkerboard
    (colour0 where frac(u) > .5 equals frac(v) > .5) is the tracer's parity
    (floor((x-o)/s) + floor((y-o)/s) + floor((z-o)/s)) & 1 -> white: u is shifted by half a
    period on faces whose constant coordinate lies in an odd check."""
    out = []
    lo, hi, offset = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float), np.asarray(offset, dtype=float)
    shift = max(10, int(np.ceil(np.max(np.abs(np.concatenate([lo, hi]) - np.tile(offset, 2))) / (2 * check))) + 1)
    for axis in range(3):
        for side in (lo[axis], hi[axis]):
            a, b = [k for k in range(3) if k != axis]
            corners = []
            for ua, ub in ((lo[a], lo[b]), (hi[a], lo[b]), (hi[a], hi[b]), (lo[a], hi[b])):
                p = np.zeros(3)
                p[axis], p[a], p[b] = side, ua, ub
                corners.append(p)
            # u, v = (coordinate - offset) / (2 check) + shift: one period = two checks
            fc = int(np.floor((side - offset[axis]) / check)) & 1
            lines = []
            for p in corners:
                lines.append("v %.9g %.9g %.9g" % tuple(p))
            for p in corners:
                u = (p[a] - offset[a]) / (2 * check) + shift + (0.5 if fc else 0.0)
                v = (p[b] - offset[b]) / (2 * check) + shift
                lines.append("vt %.9g %.9g" % (u, v))
            lines.append("f 1/1 2/2 3/3")
            lines.append("f 1/1 3/3 4/4")
            path = folder / f"{prefix}{axis}{int(side == hi[axis])}.obj"
            path.write_text("\n".join(lines) + "\n")
            out.append(path)
    return out


# ---------------------------------------------------------------- the tracer's scene, read here
@dataclass
class TracerScene:
    """What the translation to Mitsuba reads from a tracer scene file (grammar: src/scene.hpp)."""
    path: Path
    width: int = 256
    height: int = 192
    camera: dict = field(default_factory=lambda: {"position": (0, 1, 3), "look_at": (0, 0, 0),
                                                  "up": (0, 1, 0), "fov": 45.0})
    max_depth: int = 8
    materials: dict = field(default_factory=dict)  # name -> {"rho_d": (r, g, b), "rho_s", "alpha"} or a checker
    shapes: list = field(default_factory=list)     # {"kind": box|quad|mesh|sphere, fields…, "material"}
    lights: list = field(default_factory=list)     # {"corner", "edge1", "edge2", "radiance"}
    environment: tuple | None = None


def _numbers(text: str, n: tuple[int, ...], what: str) -> tuple[float, ...]:
    v = tuple(float(x) for x in text.split(","))
    if len(v) not in n:
        raise ValueError(f"{what}: expected {' or '.join(map(str, n))} numbers, got {text!r}")
    return v * 3 if len(v) == 1 and 3 in n else v


def to_physical(pgloss: Path, L, a, b, c, d, norm: str = "ward") -> dict:
    """A perceptual paint (paper Fig. 13) as pgloss's own conversion gives it (`pgloss to-physical`)."""
    r = subprocess.run([str(pgloss), "to-physical", L, a, b, c, d, norm], capture_output=True, text=True)
    m = re.search(r"rho_d = \(([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+)\)\s+rho_s = ([-0-9.e]+)\s+alpha = ([-0-9.e]+)",
                  r.stdout)
    if r.returncode != 0 or not m:
        raise RuntimeError(f"pgloss to-physical {L} {a} {b} {c} {d}: {r.stdout.strip()} {r.stderr.strip()}")
    v = [float(x) for x in m.groups()]
    return {"rho_d": tuple(v[:3]), "rho_s": v[3], "alpha": v[4]}


def read_scene(path: Path, pgloss: Path | None = None, text: str | None = None) -> TracerScene:
    """The parts of a tracer scene that the benchmark translates; anything it cannot translate
    faithfully (anisotropic or non-Ward lobes, isotropic emitters, checkers off a box) is an error."""
    sc = TracerScene(path)
    for n, raw in enumerate((path.read_text() if text is None else text).splitlines(), 1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        kw, pos = words[0], [w for w in words[1:] if "=" not in w]
        f = dict(w.split("=", 1) for w in words[1:] if "=" in w)
        where = f"{path.name}:{n}"
        if kw == "image":
            sc.width, sc.height = int(f["width"]), int(f["height"])
        elif kw == "camera":
            sc.camera = {"position": _numbers(f["position"], (3,), where), "look_at": _numbers(f["look_at"], (3,), where),
                         "up": _numbers(f.get("up", "0,1,0"), (3,), where), "fov": float(f.get("fov", 45))}
        elif kw == "render":
            sc.max_depth = int(f.get("max_depth", sc.max_depth))
        elif kw == "material":
            name, kind = pos[0], pos[1] if len(pos) > 1 else ""
            if kind == "checker":
                sc.materials[name] = {"checker": (f["a"], f["b"]), "size": float(f["size"]),
                                      "offset": _numbers(f.get("offset", "0"), (1, 3), where)}
            elif kind == "physical":
                if float(f.get("alpha_y", f["alpha"])) != float(f["alpha"]) or f.get("norm", "ward") != "ward":
                    raise ValueError(f"{where}: the benchmark's Mitsuba BSDF is the isotropic Ward lobe (norm=ward)")
                sc.materials[name] = {"rho_d": _numbers(f["rho_d"], (1, 3), where), "rho_s": float(f["rho_s"]),
                                      "alpha": float(f["alpha"])}
            elif kind == "perceptual":
                if f.get("norm", "ward") != "ward" or pgloss is None:
                    raise ValueError(f"{where}: a perceptual paint needs the pgloss tool (--pgloss) and norm=ward")
                sc.materials[name] = to_physical(pgloss, f["L"], f.get("a", "0"), f.get("b", "0"), f["c"], f["d"])
            elif "diffuse" in f:
                sc.materials[name] = {"rho_d": _numbers(f["diffuse"], (1, 3), where), "rho_s": 0.0, "alpha": 0.1}
            else:
                raise ValueError(f"{where}: material kind {kind!r} is not translated")
        elif kw == "box":
            sc.shapes.append({"kind": "box", "min": _numbers(f["min"], (3,), where),
                              "max": _numbers(f["max"], (3,), where), "material": f["material"]})
        elif kw == "quad":
            sc.shapes.append({"kind": "quad", "corner": _numbers(f["corner"], (3,), where),
                              "edge1": _numbers(f["edge1"], (3,), where), "edge2": _numbers(f["edge2"], (3,), where),
                              "material": f["material"]})
        elif kw == "sphere":
            sc.shapes.append({"kind": "sphere", "center": _numbers(f["center"], (3,), where),
                              "radius": float(f["radius"]), "material": f["material"]})
        elif kw == "mesh":
            file = Path(f["file"]) if f["file"].startswith("/") else path.parent / f["file"]
            sc.shapes.append({"kind": "mesh", "file": file, "scale": float(f.get("scale", 1)),
                              "translate": _numbers(f.get("translate", "0,0,0"), (3,), where),
                              "material": f["material"]})
        elif kw == "light":
            if f.get("emission", "cosine") != "cosine":
                raise ValueError(f"{where}: only Lambertian (emission=cosine) lights are translated")
            sc.lights.append({k: _numbers(f[k], (3,), where) for k in ("corner", "edge1", "edge2")}
                             | {"radiance": _numbers(f["radiance"], (1, 3), where)})
        elif kw == "environment":
            sc.environment = _numbers(f["radiance"], (1, 3), where)
        elif kw != "tonemap":
            raise ValueError(f"{where}: keyword {kw!r} is not translated")
    return sc


def scene_with_paint(material: str) -> str:
    """stimulus.scene with its sphere's material `paint` replaced by MATERIALS[material]."""
    return re.sub(r"^material paint .*$", MATERIALS[material]["line"], SCENE.read_text(), flags=re.M)


# ---------------------------------------------------------------- the same scene in Mitsuba 3
def plain_bsdf(m: dict) -> dict:
    """A tracer material (two-sided: the tracer turns the normal towards the ray)."""
    if m["rho_s"] > 0:
        inner = {"type": "ward_pgloss", "rho_d": list(m["rho_d"]), "rho_s": m["rho_s"], "alpha": m["alpha"]}
    else:
        inner = {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(m["rho_d"])}}
    return {"type": "twosided", "bsdf": inner}


def mitsuba_dict(mi, sc: TracerScene, width: int, height: int, folder: Path) -> dict:
    """The tracer scene as a Mitsuba scene dictionary: the same camera (vertical fov), box
    pixel filter, depth (the tracer's max_depth shading vertices = Mitsuba's max_depth + 1) and
    Russian roulette (after the fourth vertex, q = min(.95, max throughput): rr_depth 4);
    meshes with the triangles' own normals (face_normals) placed by translate . scale;
    boxes as six UV-mapped faces (a checker as Mitsuba's checkerboard); one-sided
    Lambertian rectangle lights with a black surface."""
    cam = sc.camera
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": sc.max_depth + 1, "rr_depth": 4, "hide_emitters": False},
        "sensor": {
            "type": "perspective", "fov": cam["fov"], "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["position"], target=cam["look_at"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "pixel_format": "rgb",
                     "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": 16},
        },
    }
    black = {"type": "diffuse", "reflectance": {"type": "rgb", "value": 0.0}}
    for k, l in enumerate(sc.lights):
        e1, e2 = np.array(l["edge1"]), np.array(l["edge2"])
        n = np.cross(e1, e2)
        c = np.array(l["corner"]) + (e1 + e2) / 2
        m = np.eye(4)
        m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = e1 / 2, e2 / 2, n / np.linalg.norm(n), c  # [-1, 1]^2, +z emits
        d["light" if k == 0 else f"light{k}"] = {
            "type": "rectangle", "to_world": mi.ScalarTransform4f(mi.ScalarMatrix4f(m.tolist())),
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": list(l["radiance"])}}, "bsdf": black}
    if sc.environment is not None:
        d["environment"] = {"type": "constant", "radiance": {"type": "rgb", "value": list(sc.environment)}}
    counts: dict = {}
    for shape in sc.shapes:
        kind = shape["kind"]
        k = counts[kind] = counts.get(kind, -1) + 1
        m = sc.materials[shape["material"]]
        if "checker" in m and kind != "box":
            raise ValueError(f"{sc.path.name}: a checker on a {kind} is not translated (boxes only)")
        if kind == "sphere":
            d["sphere" if k == 0 else f"sphere{k}"] = {"type": "sphere", "center": list(shape["center"]),
                                                     "radius": shape["radius"], "bsdf": plain_bsdf(m)}
        elif kind == "mesh":
            s, t = shape["scale"], shape["translate"]
            d[f"mesh{k}_{shape['file'].stem}"] = {
                "type": "obj", "filename": str(shape["file"]), "face_normals": True,
                "to_world": mi.ScalarTransform4f().translate(list(t)) @ mi.ScalarTransform4f().scale([s, s, s]),
                "bsdf": plain_bsdf(m)}
        elif kind == "quad":
            p0, e1, e2 = (np.array(shape[x]) for x in ("corner", "edge1", "edge2"))
            path = folder / f"quad{k}.obj"
            path.write_text("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in (p0, p0 + e1, p0 + e1 + e2, p0 + e2))
                            + "f 1 2 3\nf 1 3 4\n")
            d[path.stem] = {"type": "obj", "filename": str(path), "face_normals": True, "bsdf": plain_bsdf(m)}
        else:  # box: the first one's faces are the room (regions floor, ceiling, walls)
            if "checker" in m:
                a, b = (sc.materials[x] for x in m["checker"])
                if a.get("rho_s", 1) > 0 or b.get("rho_s", 1) > 0:
                    raise ValueError(f"{sc.path.name}: a checker of glossy materials is not translated")
                bsdf = {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": {
                    "type": "checkerboard", "color0": {"type": "rgb", "value": list(a["rho_d"])},
                    "color1": {"type": "rgb", "value": list(b["rho_d"])}}}}
                check, offset = m["size"], m["offset"]
            else:
                bsdf, check, offset = plain_bsdf(m), 1.0, (0.0, 0.0, 0.0)
            for path in box_faces_obj(folder, shape["min"], shape["max"], check, offset,
                                      "face" if k == 0 else f"box{k}face"):
                d[path.stem] = {"type": "obj", "filename": str(path), "face_normals": True,
                                "flip_tex_coords": False, "bsdf": bsdf}
    return d


def mitsuba_scene(mi, material: str, width: int, height: int, folder: Path, *, paint: dict | None = None,
                  crop: tuple[int, int, int, int] | None = None):
    """The stimulus scene with the sphere's material MATERIALS[material]; ``paint`` (a Mitsuba
    BSDF dict) replaces it, ``crop`` = (x0, y0, w, h) renders that window of the film alone (the
    gloss bridge's harness)."""
    d = mitsuba_dict(mi, read_scene(SCENE, text=scene_with_paint(material)), width, height, folder)
    if paint is not None:
        d["sphere"]["bsdf"] = paint
    if crop is not None:
        d["sensor"]["film"].update(crop_offset_x=crop[0], crop_offset_y=crop[1], crop_width=crop[2], crop_height=crop[3])
    return mi.load_dict(d)


def rss_mib() -> float:
    """The process's resident set (Linux /proc/self/statm), MiB."""
    return int(Path("/proc/self/statm").read_text().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


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
        self.build: dict = {}  # key -> (wall s, CPU s, RSS growth MiB) of load_dict: OBJ parsing and BVH

    def scene(self, key: str, sc: TracerScene):
        if key not in self.scenes:
            d = mitsuba_dict(self.mi, sc, self.width, self.height, self.folder)
            m0, w0, c0 = rss_mib(), time.perf_counter(), time.process_time()
            self.scenes[key] = self.mi.load_dict(d)
            self.build[key] = (time.perf_counter() - w0, time.process_time() - c0, rss_mib() - m0)
        return self.scenes[key]

    def render(self, key: str, sc: TracerScene, spp: int, seed: int) -> tuple[np.ndarray, float, float]:
        scene = self.scene(key, sc)
        w0, c0 = time.perf_counter(), time.process_time()
        img = np.array(self.mi.render(scene, spp=spp, seed=seed), dtype=np.float64)
        return img[..., :3], time.perf_counter() - w0, time.process_time() - c0

    def regions(self, key: str, sc: TracerScene) -> tuple[np.ndarray, list[str]]:
        """The shape that the ray through each pixel centre hits first (Mitsuba's own ray
        cast), as a region: walls, floor, ceiling (the first box), each mesh by its file's
        name, sphere, quad, light; -1 where nothing is hit."""
        mi = self.mi
        # Without load_dict's optimisations, which merge the shapes that share a material.
        scene = mi.load_dict(mitsuba_dict(mi, sc, self.width, self.height, self.folder), optimize=False)
        cam = sc.camera
        f = np.subtract(cam["look_at"], cam["position"])
        f = f / np.linalg.norm(f)
        r = np.cross(f, cam["up"])
        r /= np.linalg.norm(r)
        u = np.cross(r, f)
        th = np.tan(np.radians(cam["fov"]) / 2)
        ys, xs = np.mgrid[0 : self.height, 0 : self.width] + 0.5
        sx = (2 * xs / self.width - 1) * (self.width / self.height) * th
        sy = (1 - 2 * ys / self.height) * th
        dirs = f + sx[..., None] * r + sy[..., None] * u
        dirs = (dirs / np.linalg.norm(dirs, axis=-1, keepdims=True)).reshape(-1, 3)
        orgs = np.broadcast_to(np.array(cam["position"], dtype=np.float32), dirs.shape)
        si = scene.ray_intersect(mi.Ray3f(mi.Point3f(orgs.T.astype(np.float32)), mi.Vector3f(dirs.T.astype(np.float32))))
        names: list[str] = []
        reg = np.full(dirs.shape[0], -1)
        for shape in scene.shapes():
            sid = shape.id()
            m = re.fullmatch(r"face(\d)(\d)", sid)
            name = (("floor", "ceiling")[int(m.group(2))] if m.group(1) == "1" else "walls") if m else \
                re.sub(r"^mesh\d+_", "", sid) if sid.startswith("mesh") else re.sub(r"\d+$", "", re.sub(r"face\d\d$", "", sid))
            if name not in names:
                names.append(name)
            reg[np.array(si.shape == mi.ShapePtr(shape), dtype=bool)] = names.index(name)
        return reg.reshape(self.height, self.width), names


SOBOL = "pgloss-tracer, Sobol'"

# -------------------------------------------------------------------------------- tracer side
class TracerRunner:
    def __init__(self, exe: Path, threads: int, width: int, height: int, folder: Path,
                 extra: list[str] | None = None):
        self.exe, self.threads, self.width, self.height, self.folder = exe, threads, width, height, folder
        self.extra = extra or []  # more pgloss-tracer options (--sampler sobol)
        self.build: dict = {}  # key -> (load s, BVH s, their CPU s, RSS growth MiB, max RSS MiB), from a first render

    def render(self, key: str, sc: TracerScene, spp: int, seed: int) -> tuple[np.ndarray, float, float]:
        import mitsuba as mi  # noqa: PLC0415  (EXR reader)

        out = self.folder / f"tracer-{key}-{spp}-{seed}"
        cmd = [str(self.exe), "render", str(sc.path), "--spp", str(spp), "--seed", str(seed), "--threads",
               str(self.threads), "--size", f"{self.width}x{self.height}", "--quiet", "--out", str(out), *self.extra]
        with tempfile.TemporaryFile("w+") as so, tempfile.TemporaryFile("w+") as se:
            proc = subprocess.Popen(cmd, stdout=so, stderr=se)
            _, status, ru = os.wait4(proc.pid, 0)  # the child's own peak memory
            proc.returncode = os.waitstatus_to_exitcode(status)
            so.seek(0), se.seek(0)
            stdout, stderr = so.read(), se.read()
        if proc.returncode:
            raise RuntimeError(f"pgloss-tracer failed ({proc.returncode}): {stderr.strip()}")
        m = re.search(r", ([0-9.]+) s, .*?, ([0-9.]+) s CPU", stdout)
        if not m:
            raise RuntimeError(f"unexpected pgloss-tracer output: {stdout!r}")
        b = re.search(r"scene: load ([0-9.]+) s, BVH ([0-9.]+) s \(CPU ([0-9.]+) s, ([0-9.]+) s\), \+([0-9.]+) MiB", stdout)
        if b and key not in self.build:
            self.build[key] = (*(float(x) for x in b.groups()), ru.ru_maxrss / 1024)
        img = np.array(mi.Bitmap(str(out) + ".exr"), dtype=np.float64)[..., :3]
        out.with_suffix(".exr").unlink(missing_ok=True)
        out.with_suffix(".png").unlink(missing_ok=True)
        return img, float(m.group(1)), float(m.group(2))


# ------------------------------------------------------------------------------- measurement
def rel_mse(img: np.ndarray, ref: np.ndarray, spp: int, ref_spp: int) -> float:
    """||img - ref||^2 / ||ref||^2, less the reference's own share of the noise."""
    measured = float(np.sum((img - ref) ** 2) / np.sum(ref**2))
    return measured * ref_spp / (spp + ref_spp)


@dataclass
class Runs:  # one renderer's renders at one spp, a list entry per round
    walls: list = field(default_factory=list)
    cpus: list = field(default_factory=list)
    errs: list = field(default_factory=list)


def log(*args) -> None:
    print(*args, file=sys.stderr, flush=True)


def reference(runner, key: str, sc: TracerScene, ref_spp: int, chunks: int = 16) -> tuple[np.ndarray, np.ndarray]:
    """The renderer's own high-spp image, in chunks: its mean and the variance of that mean
    (from the chunks' spread; 0 for one chunk)."""
    chunk = max(1, ref_spp // chunks)
    n = ref_spp // chunk
    acc = var = 0.0
    for k in range(n):
        img, _, _ = runner.render(key, sc, chunk, 10_000 + k)
        acc, var = acc + img, var + img**2
    mean = acc / n
    return mean, np.maximum(var / n - mean**2, 0) / max(n - 1, 1)


def compare(runners: dict, key: str, sc: TracerScene, spps: list[int], ref_spp: int, reps: int,
            chunks: int = 16) -> tuple[list, dict]:
    """Paired, alternating rounds of every renderer at each spp (tracer, Mitsuba, Mitsuba,
    tracer, …, so that the machine's load hits both alike) against each one's own reference.
    Returns one row per spp and renderer, and the references."""
    mits = runners["Mitsuba 3"]
    for spp in spps:  # Mitsuba's kernels are compiled once per scene and spp-independent: warm the cache
        mits.render(key, sc, spp, 999)
    refs = {}
    for name, rn in runners.items():
        if name != SOBOL:
            refs[name] = reference(rn, key, sc, ref_spp, chunks)
            log(f"  {key}: {name} reference done")
    runs = {name: [Runs() for _ in spps] for name in runners}
    order = list(runners)
    for rep in range(reps):
        for i, spp in enumerate(spps):
            for name in order if (rep + i) % 2 == 0 else order[::-1]:
                img, wall, cpu = runners[name].render(key, sc, spp, 1 + 100 * rep + i)
                r = runs[name][i]
                r.walls.append(wall)
                r.cpus.append(cpu)
                if name == SOBOL:
                    # Against the independent sampler's reference (the same image), its noise taken out by
                    # subtraction: randomised QMC's error need not fall as 1/spp, so "spp to 1 %" for this
                    # row is an extrapolation as if it did.
                    ref, ref_var = refs["pgloss-tracer"]
                    r.errs.append(max(0.0, (float(np.sum((img - ref) ** 2)) - float(ref_var.sum())) / float(np.sum(ref**2))))
                else:
                    r.errs.append(rel_mse(img, refs[name][0], spp, ref_spp))
        log(f"  {key}: round {rep + 1} of {reps} done")
    npix = runners["Mitsuba 3"].width * runners["Mitsuba 3"].height
    rows = []
    for i, spp in enumerate(spps):
        m = runs["Mitsuba 3"][i]
        em = float(np.mean(m.errs))
        for name in runners:
            r = runs[name][i]
            e = float(np.mean(r.errs))  # the error does not depend on the load: pooled over the rounds
            # efficiency ratio of each round: (relMSE x time) Mitsuba / tracer, with the round's own times
            rw = [em * mw / (e * w) for mw, w in zip(m.walls, r.walls)]
            rc = [em * mc / (e * c) for mc, c in zip(m.cpus, r.cpus)]
            wall, cpu = statistics.median(r.walls), statistics.median(r.cpus)
            spp1 = spp * e / 1e-4
            rows.append({"spp": spp, "name": name, "sps": npix * spp / wall * 1e-6, "cps": npix * spp / cpu * 1e-6,
                         "rmse": 100 * np.sqrt(e), "spp1": spp1, "t1": spp1 * wall / spp, "c1": spp1 * cpu / spp,
                         "rw": rw, "rc": rc})
    return rows, refs


def agreement(refs: dict, reg: np.ndarray, names: list[str]) -> list[tuple]:
    """Region means of the two references, the difference and its standard error."""
    (ta, tv), (ma, mv) = refs["pgloss-tracer"], refs["Mitsuba 3"]
    out = []
    for k, rname in enumerate(names):
        sel = reg == k
        if not sel.any():
            continue
        tm, mm = ta[sel].mean(), ma[sel].mean()
        se = np.sqrt(tv[sel].sum() + mv[sel].sum()) / sel.sum() / 3
        out.append((rname, int(sel.sum()), tm, mm, 100 * (tm - mm) / mm, 100 * se / mm))
    whole = float(np.linalg.norm(ta - ma) / np.linalg.norm(ma))
    expect = float(np.sqrt(tv.sum() + mv.sum()) / np.linalg.norm(ma))
    out.append(("whole image ‖t − m‖/‖m‖", reg.size, float("nan"), float("nan"), 100 * whole, 100 * expect))
    return out


def fmt_ratio(v: list[float]) -> str:
    return f"{statistics.median(v):.2f} ({min(v):.2f}–{max(v):.2f})" if len(v) > 1 else f"{v[0]:.2f}"


def speed_table(label: str, rows: list) -> list[str]:
    out = [f"| {label} | spp | renderer | Msamples/s (wall) | Msamples/s (CPU) | rel. RMSE | spp to 1 % "
           "| time to 1 % (wall) | CPU time to 1 % | efficiency ratio, wall: median (range) | CPU: median (range) |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for lab, r in rows:
        mine = r["name"] != "Mitsuba 3"
        rw, rc = (fmt_ratio(r["rw"]), fmt_ratio(r["rc"])) if mine else ("1", "1")
        if r["name"] == "pgloss-tracer":
            rw, rc = f"**{rw}**", f"**{rc}**"
        out.append(f"| {lab} | {r['spp']} | {r['name']} | {r['sps']:.2f} | {r['cps']:.2f} | {r['rmse']:.2f} % "
                   f"| {r['spp1']:.0f} | {r['t1']:.1f} s | {r['c1']:.1f} s | {rw} | {rc} |")
    return out


def agreement_table(checks: list) -> list[str]:
    out = ["| scene | region | pixels | tracer | Mitsuba | difference | std. error | agree |", "|---|---|---|---|---|---|---|---|"]
    for lab, rname, n, tm, mm, diff, se in checks:
        if np.isnan(tm):  # whole image: the difference's norm against what noise alone gives
            ok = diff < 1.1 * se + 0.05
            out.append(f"| {lab} | {rname} | {n} | | | {diff:.2f} % | {se:.2f} % (noise alone) "
                       f"| {'yes' if ok else 'NO'} (< 1.1× noise + 0.05 %) |")
        else:
            ok = abs(diff) < 4 * se + 0.05
            out.append(f"| {lab} | {rname} | {n} | {tm:.5f} | {mm:.5f} | {diff:+.3f} % | {se:.3f} % "
                       f"| {'yes' if ok else 'NO'} (< 4 std. errors + 0.05 %) |")
    return out


def commit() -> str:
    """HEAD's short hash, with "dirty" when tracked files differ (other than the reports)."""
    git = ["git", "-C", str(Path(__file__).resolve().parent)]
    head = subprocess.run([*git, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run([*git, "status", "--porcelain", "--untracked-files=no", "--", ":/",
                            ":!/bench/results", ":!/BENCHMARKS.md"], capture_output=True, text=True).stdout.strip()
    return f"{head or 'unknown'}{' (dirty)' if dirty else ''}"


def machine() -> str:
    model = "unknown CPU"
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("model name"):
            model = line.split(":", 1)[1].strip()
            break
    return f"{model}, {os.cpu_count()} logical cores"


TRACER_MD = "bench/results/tracer.md"
TRACER_HEAD = """<!-- SPDX-FileCopyrightText: 2026 The pgloss authors -->
<!-- SPDX-License-Identifier: Apache-2.0 -->
# pgloss-tracer against Mitsuba 3

Written by `bash examples/tracer/bench/run.sh [options] --write bench/results/tracer.md`
(examples/tracer/bench/mitsuba_compare.py): each section below is the whole output of the command
in its heading, which states its own date, machine and load; a run of that command replaces its
section and leaves the others. Do not edit by hand. Not run by `bash bench/run.sh` (minutes to
hours); BENCHMARKS.md links here.
"""


def write_section(path: Path, marker: str, text: str) -> None:
    """Replaces the section between this command's markers in path (bench/results/tracer.md), or
    adds it at the end; a new file starts with TRACER_HEAD."""
    begin = f"<!-- {marker}: written whole by that command; edit the script, not this section -->"
    end = f"<!-- end {marker} -->"
    block = f"{begin}\n{text.rstrip()}\n{end}\n"
    old = path.read_text(encoding="utf-8") if path.exists() else TRACER_HEAD
    i, j = old.find(begin), old.find(end)
    if i >= 0 and j > i:
        rest = old[j + len(end):].lstrip("\n")
        new = old[:i] + block + ("\n" + rest if rest else "")
    else:
        new = old.rstrip("\n") + "\n\n" + block
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(new, encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tracer", type=Path, default=Path("build-tracer-bench/examples/tracer/pgloss-tracer"))
    ap.add_argument("--pgloss", type=Path, default=Path("build-tracer-bench/tools/pgloss"),
                    help="the pgloss tool, for perceptual paints (pgloss to-physical)")
    ap.add_argument("--scene", default="stimulus", help="a scene of examples/tracer/scenes by name, or a path")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spp", default="16,64")
    ap.add_argument("--ref-spp", type=int, default=1024)
    ap.add_argument("--reps", type=int, default=3, help="paired rounds per spp")
    ap.add_argument("--size", help="WxH (default: the scene's own)")
    ap.add_argument("--materials", default="diffuse,stimulus", help="stimulus scene: the sphere's materials")
    ap.add_argument("--scale", help="N1,N2,…: also the scene with each mesh triangle subdivided into N^2 "
                                    "(subdivide_mesh.py; 1,10,32 gives about 1k, 100k and 1M triangles for the mug)")
    ap.add_argument("--scale-spp", type=int, default=16)
    ap.add_argument("--scale-ref-spp", type=int, default=256)
    ap.add_argument("--quick", action="store_true", help="160x120, 4/16 spp, reference 256 spp, 1 round")
    ap.add_argument("--sobol", action="store_true",
                    help="add a row for pgloss-tracer with its Owen-scrambled Sobol' sampler (--sampler sobol)")
    ap.add_argument("--keep", type=Path, help="folder for the images and generated scenes (default: a temporary one)")
    ap.add_argument("--write", type=Path, help=f"write the report as this command's section of FILE ({TRACER_MD})")
    a = ap.parse_args(argv)
    argv = sys.argv[1:] if argv is None else argv
    scene_path = Path(a.scene) if a.scene.endswith(".scene") else SCENES / f"{a.scene}.scene"
    stimulus = scene_path.resolve() == SCENE.resolve()
    if a.quick:
        a.size, a.spp, a.ref_spp, a.reps, a.scale_ref_spp = "160x120", "4,16", 256, 1, 64
    tmp = tempfile.TemporaryDirectory(prefix="pgloss-mitsuba-")
    folder = a.keep or Path(tmp.name)
    folder.mkdir(parents=True, exist_ok=True)
    for exe, what in ((a.tracer, "pgloss-tracer"), (a.pgloss, "the pgloss tool")):
        if not exe.exists():
            print(f"{what} not found at {exe} (bash examples/tracer/bench/run.sh builds both)", file=sys.stderr)
            return 2
    base = read_scene(scene_path, a.pgloss)
    width, height = (int(v) for v in a.size.split("x")) if a.size else (base.width, base.height)
    spps = [int(v) for v in a.spp.split(",")]
    mits = MitsubaRunner(a.threads, width, height, folder)
    trc = TracerRunner(a.tracer, a.threads, width, height, folder)
    runners = {"pgloss-tracer": trc, "Mitsuba 3": mits}
    if a.sobol:
        runners[SOBOL] = TracerRunner(a.tracer, a.threads, width, height, folder, ["--sampler", "sobol"])
    load0 = os.getloadavg()
    t_start = time.strftime("%Y-%m-%d %H:%M", time.gmtime())

    # The scene as written (the stimulus: once per sphere material).
    cases = []
    if stimulus:
        for mat in a.materials.split(","):
            path = folder / f"stimulus-{mat}.scene"
            path.write_text(scene_with_paint(mat))
            cases.append((MATERIALS[mat]["label"], mat, read_scene(path, a.pgloss)))
    else:
        cases.append((scene_path.stem, scene_path.stem, base))
    table, checks, medians = [], [], {"rw": [], "rc": []}
    for label, key, sc in cases:
        rows, refs = compare(runners, key, sc, spps, a.ref_spp, a.reps)
        table += [(label, r) for r in rows]
        for r in rows:
            if r["name"] == "pgloss-tracer":
                medians["rw"] += r["rw"]
                medians["rc"] += r["rc"]
        reg, names = mits.regions(key, sc)
        checks += [(label, *c) for c in agreement(refs, reg, names)]

    # The same scene at growing triangle counts.
    scale_rows = []
    for n in [int(v) for v in a.scale.split(",")] if a.scale else []:
        import subdivide_mesh  # noqa: PLC0415

        path, tris = subdivide_mesh.make_scene(scene_path, n, folder / f"n{n}")
        sc = read_scene(path, a.pgloss)
        key = f"{scene_path.stem}-n{n}"
        log(f"== {key}: {tris} mesh triangles")
        # References in one render each: no region check here, and a tracer run reads the OBJ anew.
        rows, _ = compare({"pgloss-tracer": trc, "Mitsuba 3": mits}, key, sc, [a.scale_spp], a.scale_ref_spp, a.reps, 1)
        scale_rows.append((n, tris, trc.build.get(key), mits.build[key], rows))
        del mits.scenes[key]  # its memory before the next size's

    load1 = os.getloadavg()
    cmd_args = []
    skip = False
    for w in argv:  # run.sh's own --tracer and --pgloss are not part of the command
        if skip:
            skip = False
        elif w in ("--tracer", "--pgloss", "--write", "--keep"):
            skip = True
        elif not w.startswith(("--tracer=", "--pgloss=", "--write=", "--keep=")):
            cmd_args.append(w)
    command = " ".join(["bash examples/tracer/bench/run.sh", *cmd_args])
    out = [f"### `{command}`", "",
           f"pgloss-tracer against Mitsuba 3.9.1 `llvm_ad_rgb` on `{scene_path.name}` ({width}×{height}, "
           f"{a.threads} threads each), run {t_start} UTC on {machine()}, commit {commit()}, load average "
           f"{load0[0]:.2f} before and {load1[0]:.2f} after (shared machine: compare the ratios, which pair "
           "the two renderers round by round). References: "
           f"{a.ref_spp} spp each. Relative RMSE = ‖x − ref‖/‖ref‖ against the renderer's own reference "
           "(its noise taken out); spp to 1 % = N (relRMSE_N / 1 %)²; the efficiency ratio "
           "1/(relMSE × time) tracer over Mitsuba is taken per round from that round's two renders "
           "(the errors pooled over the rounds), by wall and by CPU time; the tracer's time is its "
           "render loop, Mitsuba's the `mi.render` call (kernels cached); neither includes loading "
           "and building the scene.", ""]
    out += speed_table("scene", table)
    if len(medians["rw"]) > 1:
        out += ["", f"Median of all {len(medians['rw'])} paired rounds: efficiency ratio "
                    f"**{statistics.median(medians['rw']):.2f} by wall time, {statistics.median(medians['rc']):.2f} "
                    "by CPU time**."]
    out += ["", "Both converge to the same image: region means of the two references (first hit through "
                "each pixel centre), the difference and its standard error from the references' noise:", ""]
    out += agreement_table(checks)
    if scale_rows:
        out += ["", f"Scaling: `{scene_path.name}` with each mesh triangle cut into n² (`bench/subdivide_mesh.py`, "
                    "the same surface, so the same image), "
                    f"{a.scale_spp} spp, references {a.scale_ref_spp} spp, {a.reps} paired rounds; build = "
                    "reading the scene and building the BVH (the tracer: its parser and Embree 3 on one "
                    f"thread; Mitsuba: `load_dict`, {a.threads} threads); memory = resident-set growth "
                    "while loading (the tracer's peak RSS in brackets):", "",
                    "| n | mesh triangles | tracer build: load + BVH (wall / CPU) | tracer memory | Mitsuba build (wall / CPU) "
                    "| Mitsuba memory | Msamples/s wall: tracer / Mitsuba | CPU: tracer / Mitsuba "
                    "| efficiency ratio, wall: median (range) | CPU: median (range) |",
                    "|---|---|---|---|---|---|---|---|---|---|"]
        for n, tris, tb, mb, rows in scale_rows:
            t, m = rows[0], rows[1]
            tbs = f"{tb[0]:.2f} + {tb[1]:.2f} s / {tb[2]:.2f} + {tb[3]:.2f} s" if tb else "?"
            tms = f"+{tb[4]:.0f} MiB ({tb[5]:.0f} MiB)" if tb else "?"
            out.append(f"| {n} | {tris} | {tbs} | {tms} | {mb[0]:.2f} / {mb[1]:.2f} s | +{mb[2]:.0f} MiB "
                       f"| {t['sps']:.2f} / {m['sps']:.2f} | {t['cps']:.2f} / {m['cps']:.2f} "
                       f"| **{fmt_ratio(t['rw'])}** | **{fmt_ratio(t['rc'])}** |")
    text = "\n".join(out) + "\n"
    print(text)
    if a.write:
        write_section(a.write, f"mitsuba_compare.py {' '.join(cmd_args)}".strip(), text)
        log(f"wrote this command's section of {a.write}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
