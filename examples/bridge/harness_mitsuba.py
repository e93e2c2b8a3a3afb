# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Render the stimulus scene in Mitsuba 3 (llvm_ad_rgb) with a given sphere BSDF; write a
linear EXR for the image gloss meter (pgloss.image_meter).

The scene is examples/tracer/bench/mitsuba_compare.py's (the tracer's geometry, camera, light,
box pixel filter, max_depth 9 = the tracer's 8 vertices, Russian roulette from depth 4); only
the sphere's BSDF and the film's window change. The BSDF is a JSON object of Mitsuba's own
plugin parameters (https://mitsuba.readthedocs.io, "roughplastic"), e.g.

    {"type": "roughplastic", "distribution": "ggx", "alpha": 0.1, "int_ior": 1.5,
     "diffuse_reflectance": 0.193, "nonlinear": false}

or the output of ``pgloss bridge mitsuba-… L a b c d`` (its "parameters" object). Also
``{"type": "diffuse", "reflectance": ρ}`` (Lambertian, the harness check) and
``{"type": "ward", "rho_d": …, "rho_s": …, "alpha": …}`` (eq. 2 as a Dr.Jit BSDF: the meter's
control in a renderer that is not ours).

    python examples/bridge/harness_mitsuba.py BSDF.json|'{…}' --out sphere.exr [--spp 1024]
        [--seed 1] [--size 160x120] [--full] [--threads 2]

Dr.Jit loads the first libLLVM it finds, and clang's LLVM 14 aborts it ("Cannot select:
fminimum"): unless DRJIT_LIBLLVM_PATH is set, LLVM 19's (Debian's libllvm19) is chosen here.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples" / "tracer" / "bench"))
import harness_json  # noqa: E402  (examples/bridge, this script's folder)
import mitsuba_compare  # noqa: E402  (the scene's construction, shared with the benchmark)

#: Reflectances that Mitsuba takes as textures: a number or an RGB triple becomes an "rgb" value.
_SPECTRA = ("reflectance", "diffuse_reflectance", "specular_reflectance")


def parameters(text: str) -> dict:
    """The BSDF object (harness_json.parameters)."""
    return harness_json.parameters(text, "roughplastic, diffuse, ward, …")


def bsdf_dict(p: dict) -> dict:
    """Mitsuba's dict for the JSON object: spectra as RGB, 'ward' as the Dr.Jit Ward BSDF."""
    p = dict(p)
    if p["type"] == "ward":
        return {"type": "ward_pgloss", "rho_d": float(p["rho_d"]), "rho_s": float(p["rho_s"]),
                "alpha": float(p["alpha"])}
    for k in _SPECTRA:
        if k in p and not isinstance(p[k], dict):
            v = p[k]
            p[k] = {"type": "rgb", "value": [float(x) for x in v] if isinstance(v, (list, tuple)) else float(v)}
    if p["type"] == "diffuse":  # Lambertian both sides, as the benchmark's sphere
        return {"type": "twosided", "bsdf": p}
    return p


LLVM_19 = ("/usr/lib/x86_64-linux-gnu/libLLVM-19.so", "/usr/lib/llvm-19/lib/libLLVM-19.so")


def render(bsdf: dict, *, spp: int, seed: int, size: tuple[int, int], crop: tuple[int, int, int, int] | None,
           threads: int) -> np.ndarray:
    """Linear RGB (rows, columns, 3) of the scene with ``bsdf`` on the sphere."""
    if "DRJIT_LIBLLVM_PATH" not in os.environ:
        os.environ.update({"DRJIT_LIBLLVM_PATH": p for p in LLVM_19 if os.path.exists(p)})
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    mi.set_variant("llvm_ad_rgb")
    dr.set_thread_count(threads)
    mi.register_bsdf("ward_pgloss", lambda props: mitsuba_compare.ward_bsdf_class(mi, dr)(props))
    with tempfile.TemporaryDirectory(prefix="pgloss-mitsuba-") as tmp:
        scene = mitsuba_compare.mitsuba_scene(mi, "diffuse", size[0], size[1], Path(tmp), paint=bsdf_dict(bsdf),
                                              crop=crop)
        img = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)[..., :3]
    return img


def write_exr(img: np.ndarray, path: Path) -> None:
    import mitsuba as mi  # noqa: PLC0415

    path.parent.mkdir(parents=True, exist_ok=True)
    mi.Bitmap(np.ascontiguousarray(img, dtype=np.float32), mi.Bitmap.PixelFormat.RGB).write(str(path))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bsdf", help="JSON object (or a file holding one)")
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--size", default="160x120")
    ap.add_argument("--crop", help="x0,y0,w,h: render this window of the frame alone (the meter's sphere crop)")
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args(argv)
    try:
        bsdf = parameters(a.bsdf)
    except (ValueError, OSError) as e:
        print(f"harness_mitsuba: {e}", file=sys.stderr)
        return 2
    w, h = (int(v) for v in a.size.split("x"))
    crop = tuple(int(v) for v in a.crop.split(",")) if a.crop else None
    img = render(bsdf, spp=a.spp, seed=a.seed, size=(w, h), crop=crop, threads=a.threads)
    write_exr(img, a.out)
    print(f"{a.out}: {img.shape[1]}x{img.shape[0]}, {a.spp} spp, Mitsuba 3 llvm_ad_rgb, {json.dumps(bsdf)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
