# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Magnitude estimation (paper §3.3, Experiment 2): ratings of single stimuli regressed on
hypothesis functions of their physical parameters.

The paper fits a line to the ratings against each hypothesis (Fig. 7: d = 1 − α, r² = 0.96;
Fig. 8: eq. 4's c, r² = 0.94, against 0.76 for the luminance-ratio and 0.87 for the
lightness-difference hypotheses) and checks linearity by noting that polynomial fits raise r²
by less than 0.01. :func:`fit_hypothesis` does exactly that: ordinary least squares on the mean
rating per stimulus (the points of Figs. 7 and 8), r², residuals, the slope's F-test p-value,
and the r² of quadratic and cubic fits. :func:`compare_hypotheses` ranks several hypotheses.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Mapping

import numpy as np


@dataclass(frozen=True)
class LinearFit:
    """rating ≈ intercept + slope · x on the per-stimulus mean ratings ``y``."""

    name: str
    x: np.ndarray
    y: np.ndarray
    slope: float
    intercept: float
    r2: float
    residuals: np.ndarray
    p_value: float
    r2_quadratic: float
    r2_cubic: float

    @property
    def polynomial_gain(self) -> float:
        """How much a cubic raises r² over the line (the paper's linearity check: < 0.01)."""
        return self.r2_cubic - self.r2


def _r2_poly(x: np.ndarray, y: np.ndarray, deg: int) -> float:
    u = (x - x.mean()) / (x.std() if x.std() > 0 else 1.0)  # conditioning
    a = np.vander(u, deg + 1)
    beta = np.linalg.lstsq(a, y, rcond=None)[0]
    res = y - a @ beta
    tot = float(np.sum((y - y.mean()) ** 2))
    return 1.0 - float(res @ res) / tot if tot > 0 else 0.0


def mean_ratings(ratings) -> np.ndarray:
    """Per-stimulus mean of ratings (n_stim,) or (n_obs, n_stim) — NaN marks a missing rating."""
    r = np.asarray(ratings, dtype=np.float64)
    if r.ndim == 1:
        r = r[None]
    if r.ndim != 2:
        raise ValueError(f"ratings must be (n_stimuli,) or (n_observations, n_stimuli); got shape {r.shape}")
    if np.any(np.isinf(r)):
        raise ValueError("ratings must be finite (NaN marks a missing rating)")
    ok = np.isfinite(r)
    if not np.all(ok.any(axis=0)):
        raise ValueError(f"stimulus {int(np.flatnonzero(~ok.any(axis=0))[0])} has no rating")
    return np.nanmean(r, axis=0)


def fit_hypothesis(x, ratings, name: str = "") -> LinearFit:
    """Linear regression of the mean ratings on the hypothesis values x (n_stim,)."""
    try:
        from scipy import stats  # imported lazily: only this function needs it
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError("magnitude estimation needs scipy: pip install 'pgloss[psychophysics]'") from None

    x = np.asarray(x, dtype=np.float64).ravel()
    y = mean_ratings(ratings)
    if x.size != y.size:
        raise ValueError(f"{x.size} hypothesis values for {y.size} rated stimuli")
    if not np.all(np.isfinite(x)):
        raise ValueError(f"hypothesis {name!r} is not finite for every stimulus")
    if x.size < 3:
        raise ValueError(f"too few stimuli ({x.size}) for a regression with an r²; need at least 3")
    if np.ptp(x) == 0:
        raise ValueError(f"hypothesis {name!r} is constant over the stimuli")
    res = stats.linregress(x, y)
    resid = y - (res.intercept + res.slope * x)
    return LinearFit(name=name, x=x, y=y, slope=float(res.slope), intercept=float(res.intercept),
                     r2=float(res.rvalue**2), residuals=resid, p_value=float(res.pvalue),
                     r2_quadratic=_r2_poly(x, y, 2), r2_cubic=_r2_poly(x, y, 3))


@dataclass(frozen=True)
class HypothesisComparison:
    """Fits sorted by r², best first; ``report`` says which hypothesis wins and by how much."""

    fits: List[LinearFit]

    @property
    def best(self) -> LinearFit:
        return self.fits[0]

    def report(self) -> str:
        lines = [f"  {f.name:<32s} r² = {f.r2:.3f}  slope {f.slope:+.4g}  p = {f.p_value:.2g}  "
                 f"(cubic adds {f.polynomial_gain:+.3f})" for f in self.fits]
        b = self.fits[0]
        if len(self.fits) > 1:
            lines.append(f"  best: {b.name} (r² {b.r2:.3f}, {b.r2 - self.fits[1].r2:+.3f} over {self.fits[1].name})")
        return "\n".join(lines)


def compare_hypotheses(hypotheses: Mapping[str, object], ratings) -> HypothesisComparison:
    """Fits each hypothesis (name → values per stimulus) to the same ratings; sorted by r²."""
    if not hypotheses:
        raise ValueError("no hypotheses given")
    fits = [fit_hypothesis(x, ratings, name) for name, x in hypotheses.items()]
    return HypothesisComparison(sorted(fits, key=lambda f: -f.r2))
