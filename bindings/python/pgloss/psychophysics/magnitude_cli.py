# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss magnitude``: the paper's Experiment 2 analysis (§3.3.4) on magnitude estimates.

    python -m pgloss magnitude out/exp2/magnitude.csv --out out/exp2/magnitude

Reads a CSV with one rating per row and the columns stimulus, rho_d, rho_s, alpha, rating (and,
optionally, subject and repetition: ``experiment export`` writes such a ``magnitude.csv``). The
points are the mean rating per stimulus (Figs. 7, 8); each hypothesis is a function of the
physical parameters, fitted by least squares (:mod:`.magnitude`) and ranked by r²:

* DOI gloss (α varies): d = 1 − α (eq. 3), −log α, 1/α;
* contrast gloss (ρd, ρs vary): c (eq. 4), the luminance ratio (ρs + ρd/2)/(ρd/2) of the
  reflected white and black patches (the paper's first hypothesis, r² 0.76), the CIELAB
  lightness difference L*(ρs + ρd/2) − L*(ρd/2) (its second, r² 0.87) and ρs alone.

Where both vary (a grid in c and d), each pair of a contrast and a DOI hypothesis is fitted
together (rating ≈ a + b·x_c + e·x_d) and the pairs are ranked; the figures then show the
ratings with the other dimension's share taken out (component-plus-residual plots, whose slope is
the pair's coefficient). Writes report.txt, ranking.csv and Figs. 7 (fig07_doi_fit) and 8
(fig08_contrast_fit) as PNG and SVG.
"""

from __future__ import annotations

import argparse
import csv
from pathlib import Path
from typing import Dict, List, Tuple

import numpy as np

from . import figures as figs
from .magnitude import fit_hypothesis


class MagnitudeError(ValueError):
    """A ratings file that cannot be analysed; the message names the reason."""


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("csv", type=Path, help="ratings: columns stimulus, rho_d, rho_s, alpha, rating [, subject, repetition]")
    p.add_argument("--out", type=Path, default=Path("out/magnitude"), help="output folder (default out/magnitude)")


def read_ratings(path: Path) -> Tuple[List[str], Dict[str, np.ndarray], np.ndarray]:
    """Stimulus names, their parameters (rho_d, rho_s, alpha) and the ratings (observations ×
    stimuli, NaN where an observation has no rating of a stimulus)."""
    try:
        with Path(path).open(newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise MagnitudeError(f"{path}: cannot read ({e})") from None
    need = {"stimulus", "rho_d", "rho_s", "alpha", "rating"}
    if not rows or not need <= set(rows[0]):
        raise MagnitudeError(f"{path}: want columns {sorted(need)} and at least one row")
    names: List[str] = []
    params: Dict[str, Tuple[float, float, float]] = {}
    obs: Dict[Tuple[str, str], Dict[str, float]] = {}
    for k, r in enumerate(rows, 2):
        try:
            p = (float(r["rho_d"]), float(r["rho_s"]), float(r["alpha"]))
            rating = float(r["rating"])
        except (TypeError, ValueError):
            raise MagnitudeError(f"{path} row {k}: a parameter or the rating is not a number") from None
        if not np.all(np.isfinite([*p, rating])):
            raise MagnitudeError(f"{path} row {k}: not finite")
        s = r["stimulus"]
        if s not in params:
            names.append(s)
            params[s] = p
        elif params[s] != p:
            raise MagnitudeError(f"{path} row {k}: stimulus {s} with other parameters than before")
        key = (r.get("subject") or "", r.get("repetition") or str(k))
        obs.setdefault(key, {})[s] = rating
    ratings = np.full((len(obs), len(names)), np.nan)
    for i, o in enumerate(obs.values()):
        for j, s in enumerate(names):
            ratings[i, j] = o.get(s, np.nan)
    p = np.array([params[s] for s in names])
    return names, {"rho_d": p[:, 0], "rho_s": p[:, 1], "alpha": p[:, 2]}, ratings


def _lightness(y: np.ndarray) -> np.ndarray:
    """CIE 1976 L* of relative luminance Y (the reflectance of a reflected patch)."""
    e, k = 216 / 24389, 24389 / 27
    return np.where(y > e, 116 * np.cbrt(y) - 16, k * y)


def hypotheses(p: Dict[str, np.ndarray]) -> Tuple[Dict[str, np.ndarray], Dict[str, np.ndarray]]:
    """(DOI hypotheses, contrast hypotheses), each name → value per stimulus; a family is empty
    where its parameters do not vary, a hypothesis is left out where it is not finite."""
    import pgloss

    rd, rs, al = p["rho_d"], p["rho_s"], p["alpha"]
    doi, contrast = {}, {}
    if np.ptp(al) > 0:
        doi = {"d = 1 − α (eq. 3)": 1 - al, "−log α": -np.log(al), "1/α": 1 / al}
    if np.ptp(rd) > 0 or np.ptp(rs) > 0:
        with np.errstate(divide="ignore", invalid="ignore"):
            contrast = {"c (eq. 4)": np.asarray(pgloss.contrast_gloss(rd, rs), dtype=np.float64),
                        "luminance ratio (ρs + ρd/2)/(ρd/2)": (rs + rd / 2) / (rd / 2),
                        "lightness difference L*(ρs + ρd/2) − L*(ρd/2)": _lightness(rs + rd / 2) - _lightness(rd / 2),
                        "specular energy ρs": rs.copy()}
    keep = lambda fam: {k: v for k, v in fam.items() if np.all(np.isfinite(v)) and np.ptp(v) > 0}  # noqa: E731
    return keep(doi), keep(contrast)


def _pair_fit(xc: np.ndarray, xd: np.ndarray, y: np.ndarray) -> Tuple[float, np.ndarray]:
    a = np.column_stack([np.ones_like(xc), xc, xd])
    beta = np.linalg.lstsq(a, y, rcond=None)[0]
    res = y - a @ beta
    return 1.0 - float(res @ res) / float(np.sum((y - y.mean()) ** 2)), beta


def run(args: argparse.Namespace) -> int:
    try:
        names, p, ratings = read_ratings(args.csv)
        doi, contrast = hypotheses(p)
        if not doi and not contrast:
            raise MagnitudeError(f"{args.csv}: neither α nor ρd, ρs vary over the stimuli: nothing to fit")
        if len(names) < 3:
            raise MagnitudeError(f"{args.csv}: {len(names)} stimuli; a fit needs at least 3")
        y = np.nanmean(ratings, axis=0)
    except MagnitudeError as e:
        raise SystemExit(f"pgloss magnitude: {e}") from None
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    log = [f"{len(names)} stimuli, {ratings.shape[0]} observations, {int(np.isfinite(ratings).sum())} ratings "
           f"({args.csv})"]
    ranking: List[Tuple[str, float, str]] = []
    paths: List[Path] = []
    singles = {**doi, **contrast}
    for name, x in singles.items():
        ranking.append((name, fit_hypothesis(x, y, name).r2, "single"))
    best_c = best_d = None
    if doi and contrast:
        pairs = []
        for cn, xc in contrast.items():
            for dn, xd in doi.items():
                r2, beta = _pair_fit(xc, xd, y)
                pairs.append((r2, cn, dn, beta))
                ranking.append((f"{cn} + {dn}", r2, "pair"))
        r2, best_c, best_d, beta = max(pairs, key=lambda t: t[0])
        log.append(f"both dimensions vary: best pair {best_c} + {best_d} (r² {r2:.3f}; rating ≈ {beta[0]:.3g} "
                   f"{beta[1]:+.4g}·x_c {beta[2]:+.4g}·x_d)")
        parts = {"d": (doi[best_d], y - beta[1] * contrast[best_c], best_d, "c"),
                 "c": (contrast[best_c], y - beta[2] * doi[best_d], best_c, "d")}
    else:
        fam = doi or contrast
        best = max(fam, key=lambda n: fit_hypothesis(fam[n], y, n).r2)
        parts = {("d" if doi else "c"): (fam[best], y, best, None)}
    ranking.sort(key=lambda t: -t[1])
    log.append("hypotheses ranked by r² (least squares on the mean rating per stimulus):")
    log += [f"  {r2:.4f}  {name}" for name, r2, _ in ranking]
    for key, (x, yy, name, other) in parts.items():
        fit = fit_hypothesis(x, yy, name)
        adj = f" (adjusted for {other})" if other else ""
        log.append(f"Fig. {'7' if key == 'd' else '8'}: {name}{adj}: slope {fit.slope:.4g}, r² {fit.r2:.3f}, "
                   f"a cubic adds {fit.polynomial_gain:+.3f} (the paper's linearity check: < 0.01)")
        stem, num = ("fig07_doi_fit", "7") if key == "d" else ("fig08_contrast_fit", "8")
        obs = ratings - (yy - y)[None] if other else ratings
        paths += figs.magnitude_figure(fit, out, stem, xlabel=name, ratings=obs,
                                       title=f"Fig. {num} — magnitude estimates{adj} and fit for {name}")
    with (out / "ranking.csv").open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["hypothesis", "kind", "r2"])
        w.writerows([(n, kind, f"{r2:.6f}") for n, r2, kind in ranking])
    (out / "report.txt").write_text("\n".join(log) + "\n", encoding="utf-8")
    print("\n".join(log))
    for path in [out / "report.txt", out / "ranking.csv", *paths]:
        print(path)
    return 0
