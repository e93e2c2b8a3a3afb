# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Stress: how badly a configuration's distances reproduce the (transformed) proximities.

With disparities d̂_ij (the proximities δ_ij themselves in metric MDS, their best monotone
transformation in non-metric MDS), distances d_ij = ‖x_i − x_j‖ and pair weights w_ij (0 for
a missing cell), summing **each unordered pair once** (i < j):

* raw stress, the paper's eq. 1:      σ_r = Σ w_ij (d̂_ij − d_ij)²
  (eq. 1 writes Σ_{i,j}; over ordered pairs that is exactly 2 σ_r — PROXSCAL, SMACOF and
  scikit-learn all sum i < j, and so does pgloss);
* normalised raw stress (PROXSCAL's): σ_n = σ_r / Σ w_ij d̂_ij², scale-free, in [0, 1];
* Kruskal's stress-1:                σ_1 = √(σ_r / Σ w_ij d_ij²) (Borg & Groenen 1997, §3.2;
  scikit-learn's ``normalized_stress=True``). Kruskal's verbal guide: 0.2 poor, 0.1 fair,
  0.05 good, 0.025 excellent.

For several subjects the sums run over subjects too (the fit's total stress).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Stress:
    """The three stress measures of one fit (see the module docstring)."""

    raw: float
    normalized: float
    stress1: float

    def get(self, kind: str) -> float:
        """``kind``: 'raw', 'normalized' or 'stress1'."""
        if kind not in ("raw", "normalized", "stress1"):
            raise ValueError(f"stress kind must be 'raw', 'normalized' or 'stress1'; got {kind!r}")
        return float(getattr(self, kind))


def distances(x: np.ndarray) -> np.ndarray:
    """Euclidean distances (..., n, n) between the rows of configurations x (..., n, p)."""
    g = np.einsum("...ia,...ja->...ij", x, x)
    sq = np.einsum("...ii->...i", g)
    d2 = sq[..., :, None] + sq[..., None, :] - 2.0 * g
    d = np.sqrt(np.maximum(d2, 0.0))
    n = x.shape[-2]
    d[..., np.arange(n), np.arange(n)] = 0.0
    return d


def stress_of(disparities: np.ndarray, dist: np.ndarray, weights: np.ndarray) -> Stress:
    """Stress of distances ``dist`` against ``disparities`` with pair ``weights``; all three are
    (..., n, n) symmetric arrays (only the strict upper triangles are used)."""
    n = dist.shape[-1]
    iu = np.triu_indices(n, 1)
    dh, dd, w = disparities[..., iu[0], iu[1]], dist[..., iu[0], iu[1]], weights[..., iu[0], iu[1]]
    raw = float(np.sum(w * (dh - dd) ** 2))
    den_n = float(np.sum(w * dh**2))
    den_1 = float(np.sum(w * dd**2))
    return Stress(raw=raw, normalized=raw / den_n if den_n > 0 else 0.0,
                  stress1=float(np.sqrt(raw / den_1)) if den_1 > 0 else 0.0)


def raw_stress(delta: np.ndarray, x: np.ndarray, weights: np.ndarray | None = None) -> float:
    """The paper's eq. 1 for a configuration x (n, p) against proximities delta (n, n), each pair once."""
    delta = np.asarray(delta, dtype=np.float64)
    w = np.ones_like(delta) if weights is None else np.asarray(weights, dtype=np.float64)
    return stress_of(delta, distances(np.asarray(x, dtype=np.float64)), w).raw
