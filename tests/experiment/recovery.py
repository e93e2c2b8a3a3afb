# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""How well an MDS configuration recovers a planted one, in numpy alone (independent of
pgloss.psychophysics, whose output it judges).

* :func:`procrustes_r2` — Gower's Procrustes statistic 1 − m² for a similarity transform
  (translation, rotation/reflection, one scale): (tr Σ)² / (‖X‖² ‖Y‖²) with X, Y centred and Σ the
  singular values of XᵀY (Schönemann 1966; Borg & Groenen ch. 20). 1 = the same shape.
* :func:`spearman` — Spearman's rank correlation (ties get their mean rank): what non-metric MDS
  promises to keep is the order of the distances, so this is its natural score.
* :func:`distances` — the n(n−1)/2 inter-point distances, pair by pair."""
from __future__ import annotations

import numpy as np


def procrustes_r2(x: np.ndarray, y: np.ndarray) -> float:
    x = np.asarray(x, float) - np.mean(x, axis=0)
    y = np.asarray(y, float) - np.mean(y, axis=0)
    s = np.linalg.svd(x.T @ y, compute_uv=False)
    return float(s.sum() ** 2 / (np.sum(x * x) * np.sum(y * y)))


def _ranks(a: np.ndarray) -> np.ndarray:
    values, inverse = np.unique(a, return_inverse=True)
    first = np.cumsum(np.bincount(inverse, minlength=len(values))) - np.bincount(inverse)
    return first[inverse] + (np.bincount(inverse)[inverse] - 1) / 2.0


def spearman(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.corrcoef(_ranks(np.asarray(a)), _ranks(np.asarray(b)))[0, 1])


def distances(x: np.ndarray) -> np.ndarray:
    x = np.asarray(x, float)
    i, j = np.triu_indices(len(x), 1)
    return np.linalg.norm(x[i] - x[j], axis=1)
