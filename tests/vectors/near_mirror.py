# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Near-mirror cases for the shader ports (tests/glsl, tests/osl): eq. 2 where the lobe lives.

The shared vectors bound each case by its condition number, which counts the rounding of the
terms of h = wo + wi as a perturbation; near the mirror direction that tolerates the error of
normalising unit directions in float before forming h (~6e-8/tanδ relative in tanδ: 2e-5 of
f at α = 0.07, 4e-4 at α = 0.01). These cases hold a port to what the C core's batched float
kernels reach with their cancellation-free half vector (libpgloss/src/batch_isa.c,
kernel_eval_pdf): relative error of f and pdf within

    bound(x) = (19 + 10 x) 2^-24        (x = tan²δ/α², the lobe exponent, here <= 10)

that is a few ulp of x, which exp amplifies by x, plus the 3 + 2x ulp that GLSL allows its exp.

The directions are unit vectors rounded to float (as a renderer hands them over, not
normalised again); the reference is eq. 2 and Walter 2005's pdf in double at the exactly
normalised float inputs, with the material's float α and ρs: independent of the ports' code.
"""
from __future__ import annotations

import numpy as np

ALPHAS = (0.01, 0.07)  # isotropic; the material is specular only, WARD normalisation (eq. 2)
RHO_S = 0.05
SEED = 20000


def bound(x: np.ndarray) -> np.ndarray:
    """The allowed relative error of f and pdf at lobe exponent x."""
    return (19.0 + 10.0 * np.asarray(x, np.float64)) * 2.0**-24


def cases(n_per_alpha: int = 2048) -> dict[str, np.ndarray]:
    """Deterministic cases: wo with cosθo in [0.1, 1], wi its reflection about a half vector
    at exponent x uniform in [0, 10] (cosθi >= 0.05, so no COS_MIN clamp), both rounded to
    float32. Returns alpha (float32), wo, wi (float32, n x 3) and x (the exact exponent)."""
    rng = np.random.default_rng(SEED)
    out: dict[str, list] = {"alpha": [], "wo": [], "wi": []}
    for alpha in ALPHAS:
        a = float(np.float32(alpha))
        got = 0
        while got < n_per_alpha:
            n = 2 * n_per_alpha
            z = rng.uniform(0.1, 1.0, n)
            ph = rng.uniform(0.0, 2.0 * np.pi, n)
            r = np.sqrt(1.0 - z * z)
            wo = np.stack([r * np.cos(ph), r * np.sin(ph), z], 1)
            t = a * np.sqrt(rng.uniform(0.0, 10.0, n))
            ps = rng.uniform(0.0, 2.0 * np.pi, n)
            h = np.stack([t * np.cos(ps), t * np.sin(ps), np.ones(n)], 1)
            h /= np.linalg.norm(h, axis=1)[:, None]
            wi = 2.0 * np.sum(wo * h, 1)[:, None] * h - wo
            keep = np.nonzero(wi[:, 2] > 0.05)[0][: n_per_alpha - got]
            out["wo"].append(wo[keep].astype(np.float32))
            out["wi"].append(wi[keep].astype(np.float32))
            out["alpha"].append(np.full(len(keep), a, np.float32))
            got += len(keep)
    res = {k: np.concatenate(v) for k, v in out.items()}
    res["x"] = reference(res["alpha"], res["wo"], res["wi"])[2]
    return res


def reference(alpha: np.ndarray, wo: np.ndarray, wi: np.ndarray,
              rho_s: float = RHO_S) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """f (eq. 2, specular lobe), pdf (Walter 2005) and the exponent x, in double, at the
    exactly normalised float directions, for the float α and ρs a port's material holds."""
    a = np.asarray(alpha, np.float64)
    rs = float(np.float32(rho_s))
    o = np.asarray(wo, np.float64)
    i = np.asarray(wi, np.float64)
    o = o / np.linalg.norm(o, axis=1)[:, None]
    i = i / np.linalg.norm(i, axis=1)[:, None]
    h = o + i
    x = (h[:, 0] ** 2 + h[:, 1] ** 2) / (h[:, 2] ** 2 * a * a)
    e = np.exp(-x)
    ci, co = i[:, 2], o[:, 2]
    f = rs / (4.0 * np.pi * a * a) * e / np.sqrt(ci * co)
    pdf = 2.0 / (4.0 * np.pi * a * a) * e * np.sum(h * h, 1) / (ci + co) ** 3
    return f, pdf, x


def check(f: np.ndarray, pdf: np.ndarray, f_swapped: np.ndarray, c: dict[str, np.ndarray]) -> str:
    """Asserts the bound on f and pdf and exact reciprocity f(wo, wi) = f(wi, wo); returns a
    one-line summary (largest error over the bound, per α)."""
    fr, pr, x = reference(c["alpha"], c["wo"], c["wi"])
    b = bound(x)
    rf = np.abs(np.asarray(f, np.float64) - fr) / fr / b
    rp = np.abs(np.asarray(pdf, np.float64) - pr) / pr / b
    parts = []
    for a in np.unique(c["alpha"]):
        m = c["alpha"] == a
        parts.append(f"alpha {float(a):.3g}: f {rf[m].max():.3f}, pdf {rp[m].max():.3f} of the bound")
    summary = "near-mirror cases (x <= 10): " + "; ".join(parts)
    worst = int(np.argmax(np.maximum(rf, rp)))
    assert rf.max() <= 1.0 and rp.max() <= 1.0, (
        f"{summary}; worst case {worst}: alpha {c['alpha'][worst]}, wo {c['wo'][worst]}, "
        f"wi {c['wi'][worst]}, x {x[worst]:.3g}")
    nonrecip = np.nonzero(np.asarray(f) != np.asarray(f_swapped))[0]
    assert len(nonrecip) == 0, f"f(wo, wi) != f(wi, wo) in {len(nonrecip)} cases, first {nonrecip[0]}"
    return summary
