# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The paper's analysis figures (matplotlib, Agg backend; PNG + SVG):

* :func:`cities_map` — Fig. 2, the MDS reconstruction of the U.S. map (Procrustes-aligned to
  the cities' projected true positions, which are drawn as the reference in place of an outline);
* :func:`stress_curve_figure` — Figs. 3 and 5, stress against dimensionality;
* :func:`configuration_figure` — Fig. 6, a 2-D solution with Fig. 4's kind of stimulus symbols
  (fill = diffuse colour ρd, shape = specular energy ρs, size = lobe spread α), its legend the
  levels of the stimulus set drawn, and the directions along which c and d grow (property fitting);
* :func:`magnitude_figure` — Figs. 7 and 8, magnitude estimates against a hypothesis with the
  regression line and r².
"""

from __future__ import annotations

from pathlib import Path
from typing import List, Optional, Sequence

import numpy as np

from .magnitude import LinearFit
from .mds import StressCurve
from .procrustes import procrustes, property_fit

_NAME = {0.03: "black", 0.193: "grey", 0.767: "white"}  # Fig. 4's paints (Munsell N2, N5, N9)
_MARKERS = ("o", "s", "D", "^", "v", "p", "h", "<", ">", "*")  # one per ρs level (Fig. 4: o, s, D)
_SIZES = (80.0, 20.0)  # marker area of the smallest and the largest α (Fig. 4: sharp lobes drawn large)
_KIND = {"stress1": "stress-1 (Kruskal)", "normalized": "normalised raw stress", "raw": "raw stress (eq. 1)"}


def _pyplot():
    try:
        import matplotlib
    except ImportError:  # pragma: no cover - depends on the environment
        raise SystemExit("the figures need matplotlib: pip install 'pgloss[figures]'") from None
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "pgloss"  # reproducible SVG ids
    import matplotlib.pyplot as plt

    return plt


def _save(fig, outdir: Path, stem: str) -> List[Path]:
    outdir.mkdir(parents=True, exist_ok=True)
    paths = []
    for ext in ("png", "svg"):
        path = outdir / f"{stem}.{ext}"
        meta = {"Date": None} if ext == "svg" else {"Software": None}
        fig.savefig(path, dpi=150 if ext == "png" else None, metadata=meta, bbox_inches="tight")
        paths.append(path)
    return paths


def cities_map(config: np.ndarray, names: Sequence[str], truth_xy: np.ndarray, outdir: Path,
               stem: str = "fig02_us_cities") -> List[Path]:
    """Fig. 2: the 2-D solution aligned (rotation/reflection, scale, shift) to the true map."""
    plt = _pyplot()
    al = procrustes(config, truth_xy)
    fig, ax = plt.subplots(figsize=(8.0, 5.0))
    ax.scatter(truth_xy[:, 0], truth_xy[:, 1], s=150, facecolors="none", edgecolors="tab:blue", lw=1.5,
               label="true position (azimuthal equidistant projection of lat./long.)")
    ax.scatter(al.aligned[:, 0], al.aligned[:, 1], s=18, c="k", zorder=3,
               label=f"MDS of Table 1 after Procrustes (RMS error {al.rms:.1f} mi)")
    for (x, y), name in zip(al.aligned, names):
        ax.annotate(name, (x, y), textcoords="offset points", xytext=(7, 5), fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel("miles east")
    ax.set_ylabel("miles north")
    ax.set_title("Fig. 2 — MDS reconstruction of the U.S. map (Table 1, 2-D metric SMACOF)")
    ax.legend(fontsize=8, loc="lower left")
    ax.margins(0.12)
    paths = _save(fig, outdir, stem)
    plt.close(fig)
    return paths


def stress_curve_figure(curve: StressCurve, outdir: Path, stem: str, *, kind: str = "stress1",
                        title: str = "stress vs. dimensionality", chosen: Optional[int] = None) -> List[Path]:
    """Figs. 3 and 5: stress of the best solution in each dimensionality, the choice marked."""
    plt = _pyplot()
    s = curve.values(kind)
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    ax.plot(curve.dims, s, "ko-", lw=1.5)
    if chosen is not None:
        ax.plot([chosen], [s[curve.dims.index(chosen)]], "o", ms=14, mfc="none", mec="tab:red", mew=2,
                label=f"elbow: {chosen} dimensions")
        ax.legend(fontsize=9)
    ax.set_xticks(curve.dims)
    ax.set_xlabel("dimensions")
    ax.set_ylabel(_KIND[kind])
    ax.set_ylim(bottom=0)
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    paths = _save(fig, outdir, stem)
    plt.close(fig)
    return paths


def _levels(values) -> np.ndarray:
    """The distinct values (6 significant digits) of a stimulus parameter, ascending."""
    return np.unique(np.array([float(f"{float(v):.6g}") for v in np.asarray(values, dtype=np.float64)]))


def _grey(rho_d: float) -> str:
    """The fill of a diffuse reflectance: its CIE 1976 lightness L*/100 as a matplotlib grey."""
    y = min(max(float(rho_d), 0.0), 1.0)
    lightness = 116.0 * np.cbrt(y) - 16.0 if y > (6 / 29) ** 3 else (29 / 3) ** 3 * y
    return f"{min(max(lightness / 100.0, 0.0), 1.0):.3f}"


def symbol_legend(rho_d, rho_s, alpha) -> List[dict]:
    """Fig. 6's symbols for a stimulus set: fill = L* of ρd, shape = ρs level, area = α level
    (the sharpest lobe the largest), each level of *this* set listed once, ascending (the
    legend listed Fig. 4's levels whatever the set). Entries: label, marker, ms, mfc. More ρs
    levels than shapes share the circle; more than :data:`_MARKERS` levels of any parameter are
    listed as their range."""
    out: List[dict] = []
    for name, values in (("ρd", rho_d), ("ρs", rho_s), ("α", alpha)):
        levels = _levels(values)
        shown = levels if len(levels) <= len(_MARKERS) else levels[[0, -1]]
        for k, v in enumerate(shown):
            label = f"{name} = {v:g}" + (f" ({_NAME[v]})" if name == "ρd" and v in _NAME else "")
            if len(shown) < len(levels):
                label += " (lowest)" if k == 0 else f" (highest; {len(levels)} levels)"
            entry = {"label": label, "marker": "o", "ms": 8.0, "mfc": "none"}
            if name == "ρd":
                entry["mfc"] = _grey(v)
            elif name == "ρs":
                entry["marker"], entry["ms"] = _marker(v, levels), 7.0
            else:
                entry["ms"], entry["mfc"] = float(np.sqrt(_size(v, levels))), "0.7"
            out.append(entry)
    return out


def _marker(v: float, levels: np.ndarray) -> str:
    return _MARKERS[int(np.searchsorted(levels, v))] if len(levels) <= len(_MARKERS) else "o"


def _size(v: float, levels: np.ndarray) -> float:
    span = levels[-1] - levels[0]
    return _SIZES[0] + (_SIZES[1] - _SIZES[0]) * ((v - levels[0]) / span if span > 0 else 0.5)


def configuration_figure(config: np.ndarray, rho_d, rho_s, alpha, outdir: Path, stem: str = "fig06_configuration",
                         *, c=None, d=None, title: str = "Fig. 6 — two-dimensional MDS solution") -> List[Path]:
    """Fig. 6: the stimuli at their 2-D positions with Fig. 4's kind of symbols (:func:`symbol_legend`);
    with c and d given, arrows show the directions in which they grow (and the r² of that linear fit)."""
    plt = _pyplot()
    x = np.asarray(config, dtype=np.float64)
    if x.ndim != 2 or x.shape[1] != 2:
        raise ValueError(f"configuration_figure needs a 2-D configuration (n, 2); got {x.shape}")
    fig, ax = plt.subplots(figsize=(7.0, 6.0))
    s_levels, a_levels = _levels(rho_s), _levels(alpha)
    for i in range(x.shape[0]):
        ax.scatter(x[i, 0], x[i, 1], s=_size(float(f"{float(alpha[i]):.6g}"), a_levels),
                   marker=_marker(float(f"{float(rho_s[i]):.6g}"), s_levels), c=_grey(rho_d[i]),
                   edgecolors="k", zorder=3)
    handles = [plt.Line2D([], [], ls="", mec="k", **e) for e in symbol_legend(rho_d, rho_s, alpha)]
    if c is not None and d is not None:
        # The paper's "cross in the lower right corner": where c and d grow, placed beside the points.
        lo, hi = x.min(axis=0), x.max(axis=0)
        span = 0.18 * float(np.max(hi - lo))
        centre = np.array([hi[0] + 1.6 * span, lo[1] + 1.2 * span])
        for prop, name, col in ((c, "c", "tab:red"), (d, "d", "tab:blue")):
            pf = property_fit(x, prop)
            ax.annotate("", xy=centre + span * pf.direction, xytext=centre,
                        arrowprops=dict(arrowstyle="->", color=col, lw=2))
            ax.annotate(f"{name}\n(r² {pf.r2:.2f})", centre + 1.15 * span * pf.direction, color=col, fontsize=9,
                        ha="center", va="center")
        ax.set_xlim(lo[0] - 0.1 * span, centre[0] + 1.8 * span)
        ax.set_ylim(min(lo[1], centre[1] - 1.6 * span) - 0.1 * span, max(hi[1], centre[1] + 1.6 * span) + 0.1 * span)
    ax.set_aspect("equal")
    ax.set_xlabel("dimension 1")
    ax.set_ylabel("dimension 2")
    ax.set_title(title, fontsize=10)
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    paths = _save(fig, outdir, stem)
    plt.close(fig)
    return paths


def magnitude_figure(fit: LinearFit, outdir: Path, stem: str, *, xlabel: str, title: str,
                     ratings: Optional[np.ndarray] = None) -> List[Path]:
    """Figs. 7 and 8: mean magnitude estimates (± one standard deviation over observations when
    ``ratings`` (n_obs, n) are given) against the hypothesis, with the fitted line and r²."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    if ratings is not None and np.ndim(ratings) == 2:
        ax.errorbar(fit.x, fit.y, yerr=np.nanstd(ratings, axis=0), fmt="none", ecolor="0.6", lw=0.8)
    ax.plot(fit.x, fit.y, "ko", ms=5, label="mean magnitude estimate")
    xs = np.linspace(fit.x.min(), fit.x.max(), 50)
    ax.plot(xs, fit.intercept + fit.slope * xs, "k-", lw=1.2, label=f"linear fit, r² = {fit.r2:.2f}")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("apparent gloss (0–100)")
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=9)
    paths = _save(fig, outdir, stem)
    plt.close(fig)
    return paths
