# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Procrustes alignment and property fitting: reading an MDS configuration against known
coordinates (paper §3.2.2: "it is the experimenter's job to find meaningful axes").

* :func:`procrustes` — the similarity transform (rotation/reflection, one scale, translation)
  that best maps a configuration onto a target in least squares (B&G ch. 20, Schönemann 1966).
* :func:`property_fit` — regression of an external property (c, d, a city's longitude …) on
  the configuration's coordinates: the direction in the space along which it grows and the r²
  (B&G §4.3 "external scales"). Rotation-invariant, so it reads any MDS solution.
* :func:`axis_r2` — r² of each axis of the configuration against each property.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ProcrustesResult:
    """``aligned`` = scale · (X − mean X) · rotation + translation; ``rms`` is the root mean
    square distance between aligned and target points, ``r2`` = 1 − Σ‖aligned − target‖² /
    Σ‖target − mean‖² (the share of the target's spread explained)."""

    aligned: np.ndarray
    rotation: np.ndarray
    scale: float
    translation: np.ndarray
    rms: float
    r2: float


def procrustes(x, target, *, scaling: bool = True, reflection: bool = True) -> ProcrustesResult:
    """Aligns configuration x (n, p) to target (n, p) by an orthogonal transform (a proper
    rotation only if ``reflection=False``), a scale (1 if ``scaling=False``) and a translation."""
    x = np.asarray(x, dtype=np.float64)
    t = np.asarray(target, dtype=np.float64)
    if x.ndim != 2 or x.shape != t.shape:
        raise ValueError(f"x and target must be (n, p) arrays of one shape; got {x.shape} and {t.shape}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(t))):
        raise ValueError("x and target must be finite")
    xm, tm = x.mean(axis=0), t.mean(axis=0)
    xc, tc = x - xm, t - tm
    u, s, vt = np.linalg.svd(xc.T @ tc)
    if not reflection and np.linalg.det(u @ vt) < 0:
        u[:, -1] = -u[:, -1]
        s[-1] = -s[-1]
    r = u @ vt
    ss = float(np.sum(xc * xc))
    scale = float(np.sum(s) / ss) if (scaling and ss > 0) else 1.0
    aligned = scale * xc @ r + tm
    res = float(np.sum((aligned - t) ** 2))
    tot = float(np.sum(tc * tc))
    return ProcrustesResult(aligned=aligned, rotation=r, scale=scale, translation=tm - scale * xm @ r,
                            rms=float(np.sqrt(res / x.shape[0])), r2=1.0 - res / tot if tot > 0 else 0.0)


@dataclass(frozen=True)
class PropertyFit:
    """A property regressed on the coordinates: unit ``direction`` in the space, ``r2``,
    ``coef`` (regression weights per axis) and ``intercept``."""

    direction: np.ndarray
    r2: float
    coef: np.ndarray
    intercept: float


def property_fit(config, prop) -> PropertyFit:
    """Least-squares fit prop ≈ intercept + config · coef; r² and the unit direction of coef."""
    x = np.asarray(config, dtype=np.float64)
    y = np.asarray(prop, dtype=np.float64).ravel()
    if x.ndim != 2 or x.shape[0] != y.size:
        raise ValueError(f"config (n, p) and prop (n,) must have one n; got {x.shape} and {y.shape}")
    a = np.column_stack([np.ones(len(y)), x])
    beta = np.linalg.lstsq(a, y, rcond=None)[0]
    res = y - a @ beta
    tot = float(np.sum((y - y.mean()) ** 2))
    coef = beta[1:]
    norm = float(np.linalg.norm(coef))
    return PropertyFit(direction=coef / norm if norm > 0 else coef, r2=1.0 - float(res @ res) / tot if tot > 0 else 0.0,
                       coef=coef, intercept=float(beta[0]))


def axis_r2(config, props) -> np.ndarray:
    """Squared Pearson correlations, (p axes) × (m properties), of each axis with each property
    (props: (n, m) or a sequence of m arrays of n values)."""
    x = np.asarray(config, dtype=np.float64)
    y = np.asarray(props, dtype=np.float64)
    if y.ndim == 2 and y.shape[0] != x.shape[0]:
        y = y.T
    if y.ndim == 1:
        y = y[:, None]
    xc = x - x.mean(0)
    yc = y - y.mean(0)
    num = xc.T @ yc
    den = np.sqrt(np.outer(np.sum(xc * xc, 0), np.sum(yc * yc, 0)))
    with np.errstate(invalid="ignore", divide="ignore"):
        r = np.where(den > 0, num / den, 0.0)
    return r * r
