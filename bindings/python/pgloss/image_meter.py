# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The image gloss meter: the Ward paint (ρd, ρs, α) → (L*, c, d) that reproduces the sphere of a
linear render of the stimulus scene (``examples/tracer/scenes/stimulus.scene``), whichever
renderer made it.

The method (docs/bridge-validation.md has the derivation, the noise model and the checks):

* **Basis.** The sphere's pixels are affine in ρs for a fixed (ρd, α):
  I(ρs) = I(0) + (ρs / ρs_ref) · (I(ρs_ref) − I(0)). pgloss-tracer renders, at the paint's own ρd,
  one diffuse image I(0) and one Ward image I(ρs_ref, α_k) per α_k of a log-spaced grid
  (default 40 nodes, 0.01–0.3), all with the same seed (so that their noise is correlated and
  the residual is smooth in α). Rendering the Ward image at ρs_ref instead of ρd = 0 keeps the
  paths that hit the sphere twice (sphere → box → sphere), whose ρd·ρs share a ρd = 0 basis lacks.
  The basis is generated data: :func:`render_basis` caches it (``.npz``), never in git.
* **Fit.** Luminance (Rec. 709) least squares over the sphere's pixels (pixel centres on the
  sphere). For each node ρs is solved exactly; between nodes the basis is a cubic in log α
  (Catmull–Rom per pixel), and α is the minimum of the residual found on 8 sub-steps per interval
  and refined by golden section.
* **Setups.** Primary (``rho_d-known``): ρd given (from the paint's L*), free ρs, α. Sensitivity
  (``rho_d-fitted``): the diffuse image scaled too (ρd free). ``exclude_rim_deg`` leaves out the
  pixels seen at more than that angle from the normal (the rim, where Fresnel lobes differ most).
* **Residual.** ‖y − fit‖ / ‖y‖ over the pixels used (relative RMS).

Command: ``python -m pgloss image-meter RENDER.exr --L 51`` (``--help``).
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import warnings
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

import pgloss

#: Luminance least squares with ρd known (the primary setup) and with ρd fitted too.
SETUPS: Tuple[str, ...] = ("rho_d-known", "rho_d-fitted")
#: The α grid of the basis: 40 log-spaced nodes from 0.01 to 0.3.
DEFAULT_ALPHAS: Tuple[float, ...] = tuple(float(a) for a in np.geomspace(0.01, 0.3, 40))
#: ρs of the basis's Ward renders (the middle of Fig. 4's 0.033–0.099).
RHO_S_REF = 0.066
#: Version of the cached basis's layout (part of its cache key).
BASIS_FORMAT = 2
#: The meter's frame: the stimulus camera at 160 × 120 (2,114 sphere pixels).
DEFAULT_SIZE = (160, 120)
#: Noise of (c, d) fitted to a Ward render of n spp against a 4,096-spp basis (measured; see
#: docs/bridge-validation.md): RMS Δc = √(NOISE_C² / n + NOISE_C_FLOOR²), RMS Δd = NOISE_D / √n.
NOISE_C, NOISE_C_FLOOR, NOISE_D = 0.0113, 0.00016, 0.030


def expected_noise(spp: float) -> Tuple[float, float]:
    """RMS (Δc, Δd) that sampling noise alone gives a render of ``spp`` samples per pixel."""
    return math.sqrt(NOISE_C**2 / spp + NOISE_C_FLOOR**2), NOISE_D / math.sqrt(spp)


class MeterError(ValueError):
    """A render, basis or argument the meter cannot use; the message says why."""


# ------------------------------------------------------------------------------------ the view
def _fields(line: str) -> Dict[str, str]:
    return dict(f.split("=", 1) for f in line.split()[1:] if "=" in f)


def _vec(s: str) -> np.ndarray:
    return np.array([float(v) for v in s.split(",")], dtype=np.float64)


@dataclass(frozen=True)
class View:
    """The stimulus camera and sphere (read from the scene file) at a given image size."""

    width: int
    height: int
    position: Tuple[float, float, float]
    look_at: Tuple[float, float, float]
    up: Tuple[float, float, float]
    fov_deg: float
    center: Tuple[float, float, float]
    radius: float

    @classmethod
    def from_scene(cls, text: str, size: Tuple[int, int] = DEFAULT_SIZE) -> "View":
        cam = sph = None
        for line in text.splitlines():
            words = line.split()
            if words and words[0] == "camera":
                cam = _fields(line)
            elif words and words[0] == "sphere":
                if sph is not None:
                    raise MeterError("the scene has more than one sphere; the meter needs the stimulus's one")
                sph = _fields(line)
        if cam is None or sph is None:
            raise MeterError("the scene needs a 'camera' and a 'sphere' line (the stimulus scene)")
        return cls(size[0], size[1], tuple(_vec(cam["position"])), tuple(_vec(cam["look_at"])),
                   tuple(_vec(cam.get("up", "0,1,0"))), float(cam["fov"]), tuple(_vec(sph["center"])),
                   float(sph["radius"]))

    def rays(self) -> np.ndarray:
        """Unit directions through the pixel centres, (height, width, 3), as pgloss-tracer's
        pinhole (examples/tracer/src/render.cpp, Pinhole)."""
        o, at, up = (np.array(v) for v in (self.position, self.look_at, self.up))
        f = (at - o) / np.linalg.norm(at - o)
        r = np.cross(f, up)
        r /= np.linalg.norm(r)
        u = np.cross(r, f)
        th = math.tan(math.radians(self.fov_deg) / 2)
        ys, xs = np.mgrid[0:self.height, 0:self.width] + 0.5
        sx = (2 * xs / self.width - 1) * (self.width / self.height) * th
        sy = (1 - 2 * ys / self.height) * th
        d = f + sx[..., None] * r + sy[..., None] * u
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def sphere(self) -> Tuple[np.ndarray, np.ndarray]:
        """(mask, cos θo): the pixels whose centre ray hits the sphere, and the cosine between
        the normal and the direction to the camera there (0 off the sphere)."""
        d = self.rays()
        oc = np.array(self.position) - np.array(self.center)
        b = d @ oc
        disc = b * b - (oc @ oc - self.radius**2)
        hit = disc > 0
        t = -b - np.sqrt(np.where(hit, disc, 0.0))
        hit &= t > 0
        n = (oc + t[..., None] * d) / self.radius
        cos = np.where(hit, -np.sum(n * d, axis=-1), 0.0)
        return hit, np.clip(cos, 0.0, 1.0)

    def crop(self) -> Tuple[int, int, int, int]:
        """(x0, y0, w, h): the smallest window centred in the frame that holds every sphere pixel
        with one pixel of margin. The harnesses render this window alone (the same pixels, a
        fifth of the samples). Being centred, it is also the whole frame of the same camera with
        the field of view :meth:`crop_fov_deg`, which is how pgloss-tracer renders it."""
        m, _ = self.sphere()
        ys, xs = np.nonzero(m)
        half_w = max(self.width / 2 - xs.min(), xs.max() + 1 - self.width / 2) + 1
        half_h = max(self.height / 2 - ys.min(), ys.max() + 1 - self.height / 2) + 1
        w, h = min(int(2 * math.ceil(half_w)), self.width), min(int(2 * math.ceil(half_h)), self.height)
        w += (self.width - w) % 2  # centred on whole pixels
        h += (self.height - h) % 2
        return (self.width - w) // 2, (self.height - h) // 2, w, h

    def crop_fov_deg(self) -> float:
        """The vertical field of view whose whole frame is :meth:`crop` (the same pixel rays:
        the pinhole's image-plane coordinates scale with tan(fov / 2) / height)."""
        h = self.crop()[3]
        return math.degrees(2 * math.atan(math.tan(math.radians(self.fov_deg) / 2) * h / self.height))


# ------------------------------------------------------------------------------------- images
def read_linear(path: Path) -> np.ndarray:
    """A linear image file (EXR, …) as float64 RGB (height, width, 3), through OpenImageIO."""
    try:
        import OpenImageIO as oiio  # noqa: PLC0415
    except ImportError as e:
        raise MeterError("reading images needs OpenImageIO's Python module (pip install openimageio)") from e
    buf = oiio.ImageBuf(str(path))
    if buf.has_error:
        raise MeterError(f"{path}: {buf.geterror()}")
    px = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)
    if px.ndim == 2:
        px = px[..., None]
    if px.shape[-1] == 1:
        px = np.repeat(px, 3, axis=-1)
    return px[..., :3]


def sphere_pixels(image: np.ndarray, view: View) -> np.ndarray:
    """Luminance of the sphere's pixels (in the mask's row-major order) of a full-frame image or
    of its :meth:`View.crop` window."""
    img = np.asarray(image, dtype=np.float64)
    if img.ndim != 3 or img.shape[-1] < 3:
        raise MeterError(f"expected an RGB image (height, width, 3), got shape {img.shape}")
    mask, _ = view.sphere()
    x0, y0, w, h = view.crop()
    if img.shape[:2] == (view.height, view.width):
        sel = img[mask]
    elif img.shape[:2] == (h, w):
        sel = img[mask[y0:y0 + h, x0:x0 + w]]
    else:
        raise MeterError(f"the image is {img.shape[1]}x{img.shape[0]}; the meter's frame is {view.width}x"
                         f"{view.height}, or its sphere crop {w}x{h} at ({x0}, {y0})")
    if not np.all(np.isfinite(sel)):
        raise MeterError("the sphere's pixels hold NaN or Inf")
    y = np.asarray(pgloss.luminance(sel[:, :3]), dtype=np.float64)
    if not np.any(y > 0):
        raise MeterError("the sphere's pixels are black: not a render of the lit stimulus scene")
    return y


# -------------------------------------------------------------------------------------- basis
@dataclass
class Basis:
    """Sphere-pixel luminances of pgloss-tracer renders at one ρd: ``diffuse`` (ρs = 0) and
    ``ward[k]`` (ρs = ``rho_s_ref``, α = ``alphas[k]``), each the mean of two renders of spp/2
    with seeds s and s + 1; ``diffuse_half``, ``ward_half`` are half their differences (the
    basis's own noise, for the fit's correction)."""

    rho_d: float
    rho_s_ref: float
    alphas: np.ndarray
    diffuse: np.ndarray
    ward: np.ndarray
    diffuse_half: np.ndarray
    ward_half: np.ndarray
    spp: int
    view: View
    meta: Dict[str, str] = field(default_factory=dict)

    def save(self, path: Path) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".tmp.npz")
        np.savez_compressed(tmp, alphas=self.alphas, diffuse=self.diffuse, ward=self.ward,
                            diffuse_half=self.diffuse_half, ward_half=self.ward_half, header=json.dumps({"rho_d": self.rho_d, "rho_s_ref": self.rho_s_ref, "spp": self.spp,
                                               "view": asdict(self.view), "meta": self.meta}))
        os.replace(tmp, path)

    @classmethod
    def load(cls, path: Path) -> "Basis":
        with np.load(path) as z:
            h = json.loads(str(z["header"]))
            v = h["view"]
            view = View(**{k: tuple(x) if isinstance(x, list) else x for k, x in v.items()})
            return cls(h["rho_d"], h["rho_s_ref"], z["alphas"], z["diffuse"], z["ward"], z["diffuse_half"],
                       z["ward_half"], h["spp"], view, h["meta"])


def scene_with_paint(text: str, line: str) -> str:
    out, n = re.subn(r"^material paint .*$", line, text, flags=re.M)
    if n != 1:
        raise MeterError("the scene needs exactly one 'material paint ...' line (the sphere's material)")
    return out


def crop_scene(text: str, view: View) -> Tuple[str, Tuple[int, int]]:
    """The scene whose whole frame is ``view``'s crop window (the same camera, the narrower
    field of view of :meth:`View.crop_fov_deg`) and that frame's size."""
    out, n = re.subn(r"^(camera .*\bfov=)\S+", lambda m: m.group(1) + repr(view.crop_fov_deg()), text, flags=re.M)
    if n != 1:
        raise MeterError("the scene needs exactly one 'camera ... fov=' line")
    return out, view.crop()[2:]


def paint_line(rho_d: float, rho_s: float = 0.0, alpha: float = 0.1) -> str:
    """The scene line of the sphere's Ward paint (Lambertian when ρs = 0)."""
    rho_d, rho_s, alpha = float(rho_d), float(rho_s), float(alpha)
    if rho_s == 0:
        return f"material paint diffuse={rho_d!r}"
    return f"material paint physical rho_d={rho_d!r} rho_s={rho_s!r} alpha={alpha!r}"


def basis_key(scene_text: str, tracer_version: str, rho_d: float, alphas: Sequence[float], spp: int,
              size: Tuple[int, int], seed: int, rho_s_ref: float = RHO_S_REF) -> str:
    """The cache file name: ρd, spp and a hash of everything else the pixels depend on."""
    h = hashlib.sha256(json.dumps([BASIS_FORMAT, scene_text, tracer_version, list(map(float, alphas)), size, seed, rho_s_ref,
                                   float(rho_d)]).encode()).hexdigest()[:12]
    return f"basis-rd{rho_d:.6g}-spp{spp}-{h}.npz"


def render_tracer(tracer: Path, scene_text: str, spp: int, size: Tuple[int, int], seed: int, threads: int,
                  folder: Path) -> np.ndarray:
    """One pgloss-tracer render of ``scene_text``: linear RGB (height, width, 3)."""
    scene = folder / "scene.scene"
    scene.write_text(scene_text)
    out = folder / "render"
    r = subprocess.run([str(tracer), "render", str(scene), "--spp", str(spp), "--seed", str(seed), "--threads",
                        str(threads), "--size", f"{size[0]}x{size[1]}", "--quiet", "--out", str(out)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        raise MeterError(f"pgloss-tracer failed ({r.returncode}): {r.stderr.strip() or r.stdout.strip()}")
    return read_linear(out.with_suffix(".exr"))


def tracer_version(tracer: Path) -> str:
    r = subprocess.run([str(tracer), "--version"], capture_output=True, text=True)
    if r.returncode != 0:
        raise MeterError(f"{tracer}: not a working pgloss-tracer ({r.stderr.strip()})")
    return r.stdout.strip()


def render_basis(tracer: Path, scene_path: Path, rho_d: float, *, alphas: Sequence[float] = DEFAULT_ALPHAS,
                 spp: int = 4096, size: Tuple[int, int] = DEFAULT_SIZE, seed: int = 1,
                 threads: Optional[int] = None, cache: Optional[Path] = None, progress: bool = False) -> Basis:
    """The basis at ``rho_d`` (from ``cache`` if it holds it, else rendered and stored there)."""
    if not 0 < rho_d < 1:
        raise MeterError(f"rho_d must be in (0, 1), not {rho_d}")
    alphas = np.asarray(sorted(float(a) for a in alphas))
    if alphas.size < 4 or alphas[0] <= 0:
        raise MeterError("the α grid needs at least 4 positive nodes")
    text = Path(scene_path).read_text()
    view = View.from_scene(text, size)
    version = tracer_version(tracer)
    path = None
    if cache is not None:
        path = Path(cache) / basis_key(text, version, rho_d, alphas, spp, size, seed)
        if path.exists():
            return Basis.load(path)
    threads = threads or os.cpu_count() or 1
    text_crop, crop_size = crop_scene(text, view)  # the crop window alone (View.crop)
    t0 = time.monotonic()
    if spp < 2 or spp % 2:
        raise MeterError(f"the basis's spp must be even (two halves), not {spp}")
    with tempfile.TemporaryDirectory(prefix="pgloss-meter-") as tmp:
        def lum(line: str) -> Tuple[np.ndarray, np.ndarray]:
            y = [sphere_pixels(render_tracer(tracer, scene_with_paint(text_crop, line), spp // 2, crop_size, sd,
                                             threads, Path(tmp)), view) for sd in (seed, seed + 1)]
            return (y[0] + y[1]) / 2, (y[0] - y[1]) / 2

        diffuse, diffuse_half = lum(paint_line(rho_d))
        ward, ward_half = np.empty((alphas.size, diffuse.size)), np.empty((alphas.size, diffuse.size))
        for k, a in enumerate(alphas):
            ward[k], ward_half[k] = lum(paint_line(rho_d, RHO_S_REF, a))
            if progress:
                print(f"  basis rho_d {rho_d:g}: alpha {a:.4f} ({k + 1}/{alphas.size}), "
                      f"{time.monotonic() - t0:.0f} s", file=sys.stderr, flush=True)
    b = Basis(float(rho_d), RHO_S_REF, alphas, diffuse, ward, diffuse_half, ward_half, spp, view,
              {"tracer": version, "scene": str(scene_path), "seed": str(seed)})
    if path is not None:
        b.save(path)
    return b


# ---------------------------------------------------------------------------------------- fit
@dataclass
class Fit:
    """A fitted Ward paint and what it reads as."""

    setup: str
    rho_d: float
    rho_s: float
    alpha: float
    L: float
    c: float
    d: float
    residual: float      # ‖y − fit‖ / ‖y‖ over the pixels used
    pixels: int
    status: str = "ok"   # "ok", or why the value is a bound (α at the grid's edge, ρs at 0)

    def as_dict(self) -> Dict[str, object]:
        return asdict(self)


def _catmull_rom(u: np.ndarray, k: int, t: float, nodes: np.ndarray) -> np.ndarray:
    """Per-pixel cubic through nodes[k−1..k+2] in the variable u (non-uniform Catmull–Rom with
    finite-difference tangents), at u = u[k] + t (u[k+1] − u[k])."""
    n = len(u) - 1
    p0, p1 = nodes[k], nodes[k + 1]
    h = u[k + 1] - u[k]
    m0 = (p1 - nodes[k - 1]) / (u[k + 1] - u[k - 1]) * h if k > 0 else p1 - p0
    m1 = (nodes[k + 2] - p0) / (u[k + 2] - u[k]) * h if k + 1 < n else p1 - p0
    t2, t3 = t * t, t * t * t
    return (2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 + (t3 - t2) * m1


def fit(image: np.ndarray, basis: Basis, *, setup: str = "rho_d-known",
        exclude_rim_deg: Optional[float] = None) -> Fit:
    """The Ward paint whose basis image best fits ``image`` (full frame or the sphere crop)."""
    if setup not in SETUPS:
        raise MeterError(f"setup must be one of {', '.join(SETUPS)}, not {setup!r}")
    y_all = sphere_pixels(image, basis.view)
    keep = np.ones(y_all.size, dtype=bool)
    if exclude_rim_deg is not None:
        mask, cos = basis.view.sphere()
        keep = cos[mask] >= math.cos(math.radians(exclude_rim_deg))
    y, D, W = y_all[keep], basis.diffuse[keep], basis.ward[:, keep]
    dlt = W - D  # (K, n): the specular part of ρs_ref at each α
    # The basis's own noise: half the difference of its two half-spp renders estimates the
    # noise of their mean, pixel by pixel (docs/image-meter.md, "Noise").
    nD = basis.diffuse_half[keep]
    ndlt = basis.ward_half[:, keep] - nD
    u = np.log(basis.alphas)
    yy = float(y @ y)

    def solve(delta: np.ndarray, ndelta: np.ndarray) -> Tuple[float, float, float, float]:
        """(corrected residual², residual², scale of the diffuse image, t = ρs / ρs_ref) at one α.
        The model s D + t Δ carries the basis's noise s nD + t nΔ, whose expected square adds
        to the residual and favours the α whose basis is least noisy; the corrected residual
        ‖y − s D − t Δ‖² − ‖s nD + t nΔ‖² takes it out (errors-in-variables least squares)."""
        if setup == "rho_d-known":
            den = float(delta @ delta - ndelta @ ndelta)
            if den <= 0:
                den = float(delta @ delta)
            s_, t = 1.0, max(float(delta @ (y - D) + nD @ ndelta) / den, 0.0)
        else:
            a = np.array([[D @ D - nD @ nD, D @ delta - nD @ ndelta], [D @ delta - nD @ ndelta,
                                                                      delta @ delta - ndelta @ ndelta]])
            s_, t = (float(v) for v in np.linalg.solve(a, np.array([D @ y, delta @ y])))
            if t < 0:
                s_, t = float(D @ y) / float(D @ D - nD @ nD), 0.0
        r = y - s_ * D - t * delta
        n = s_ * nD + t * ndelta
        r2 = float(r @ r)
        return r2 - float(n @ n), r2, s_, t

    def at(x: float) -> Tuple[float, float, float, float]:
        k = min(int(np.searchsorted(u, x, side="right")) - 1, len(u) - 2)
        k = max(k, 0)
        tk = (x - u[k]) / (u[k + 1] - u[k])
        return solve(_catmull_rom(u, k, tk, dlt), _catmull_rom(u, k, tk, ndlt))

    xs = np.concatenate([np.linspace(u[k], u[k + 1], 8, endpoint=False) for k in range(len(u) - 1)] + [u[-1:]])
    rs = np.array([at(x)[0] for x in xs])
    i = int(np.argmin(rs))
    lo, hi = xs[max(i - 1, 0)], xs[min(i + 1, len(xs) - 1)]
    g = (math.sqrt(5) - 1) / 2  # golden section on [lo, hi]
    a_, b_ = hi - g * (hi - lo), lo + g * (hi - lo)
    fa, fb = at(a_)[0], at(b_)[0]
    for _ in range(40):
        if fa < fb:
            hi, b_, fb = b_, a_, fa
            a_ = hi - g * (hi - lo)
            fa = at(a_)[0]
        else:
            lo, a_, fa = a_, b_, fb
            b_ = lo + g * (hi - lo)
            fb = at(b_)[0]
    x = (lo + hi) / 2
    _, r2, s, t = at(x)
    status = "ok"
    if i == 0 or i == len(xs) - 1:
        status = f"alpha at the basis's edge ({math.exp(x):.4g}): the render may be outside its range"
    if t == 0.0:
        status = "no specular lobe found (rho_s = 0)"
    rho_d, rho_s, alpha = basis.rho_d * s, basis.rho_s_ref * t, math.exp(x)
    with warnings.catch_warnings():  # α > 0.2 (outside what the paper trusts): said in status
        warnings.simplefilter("ignore", pgloss.AlphaUntrustedWarning)
        L, c, d = (float(v) for v in pgloss.gloss_from_physical(rho_d, rho_s, alpha))
    if status == "ok" and alpha > pgloss.ALPHA_TRUSTED_MAX:
        status = f"alpha {alpha:.3g} above the paper's trusted {pgloss.ALPHA_TRUSTED_MAX:g}"
    return Fit(setup, rho_d, rho_s, alpha, L, c, d, math.sqrt(r2 / yy), int(y.size), status)


def measure(image: np.ndarray, basis: Basis) -> Dict[str, Fit]:
    """The primary fit and its two sensitivities: ρd fitted too, and the rim (> 60°) left out."""
    return {"primary": fit(image, basis),
            "rho_d-fitted": fit(image, basis, setup="rho_d-fitted"),
            "rim-excluded": fit(image, basis, exclude_rim_deg=60.0)}


# ------------------------------------------------------------------------------------ command
def _default(path: str, env: str) -> Path:
    return Path(os.environ.get(env, path))


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("image", type=Path, help="linear render of the stimulus scene (EXR), full frame or sphere crop")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--L", type=float, help="the sphere's lightness L* (its ρd is the luminance of L*)")
    g.add_argument("--rho-d", type=float, help="the sphere's ρd")
    p.add_argument("--tracer", type=Path, default=_default("build-bridge/examples/tracer/pgloss-tracer", "PGLOSS_TRACER"),
                   help="pgloss-tracer that renders the basis (default $PGLOSS_TRACER or %(default)s)")
    p.add_argument("--scene", type=Path, default=Path("examples/tracer/scenes/stimulus.scene"))
    p.add_argument("--basis-dir", type=Path, default=_default("build-bridge/meter-basis", "PGLOSS_METER_BASIS"),
                   help="cache of rendered bases (default $PGLOSS_METER_BASIS or %(default)s)")
    p.add_argument("--basis-spp", type=int, default=4096)
    p.add_argument("--size", default="160x120", help="the meter's frame, WxH (%(default)s)")
    p.add_argument("--json", action="store_true", help="print the fits as JSON")


def run(args: argparse.Namespace) -> int:
    try:
        rho_d = args.rho_d if args.rho_d is not None else float(pgloss.luminance_from_lightness(args.L))
        w, h = (int(v) for v in args.size.split("x"))
        basis = render_basis(args.tracer, args.scene, rho_d, spp=args.basis_spp, size=(w, h),
                             cache=args.basis_dir, progress=True)
        fits = measure(read_linear(args.image), basis)
    except (MeterError, OSError, pgloss.PglossError) as e:
        print(f"image-meter: {e}", file=sys.stderr)
        return 2
    if args.json:
        print(json.dumps({k: f.as_dict() for k, f in fits.items()}, indent=2))
        return 0
    print(f"{args.image}: Ward fit over the sphere's pixels (basis: pgloss-tracer, {basis.spp} spp, rho_d {rho_d:.6g})")
    print(f"{'setup':<14} {'rho_d':>8} {'rho_s':>8} {'alpha':>8} {'L*':>7} {'c':>8} {'d':>7} {'residual':>9} pixels")
    for name, f in fits.items():
        print(f"{name:<14} {f.rho_d:8.4f} {f.rho_s:8.4f} {f.alpha:8.4f} {f.L:7.2f} {f.c:8.4f} {f.d:7.4f} "
              f"{100 * f.residual:8.2f}% {f.pixels}" + ("" if f.status == "ok" else f"  [{f.status}]"))
    return 0
