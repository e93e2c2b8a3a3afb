# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Proximity matrices: validation, missing cells and CSV input/output.

A *proximity matrix* holds one subject's dissimilarity judgements δ_ij of n stimuli (paper
§3.2.2: Table 1's city distances, or Experiment 1's 27 × 27 gloss-difference ratings).
Every fitting function of :mod:`pgloss.psychophysics` validates its input here, so that bad
data gets one clear error naming the reason and the offending cell:

* the matrix must be square and n ≥ 3 (:data:`MIN_STIMULI`);
* it must be symmetric (``|δ_ij − δ_ji| ≤ 1e-9·max|δ|``): MDS models a distance, and silently
  averaging order effects away would hide them — symmetrise yourself with ``(D + D.T) / 2``;
* proximities must be finite and ≥ 0;
* the diagonal is ignored (a stimulus is not compared with itself).

**Missing cells.** A pair that was not judged gets the *weight* 0 (``weights[k, i, j] = 0``);
its value is then ignored and may be NaN. Stress (eq. 1) sums over weighted pairs only, so
SMACOF, the non-metric fits and the individual-differences model all accept missing cells, as
long as the pairs that are present still connect every stimulus (else the configuration is
not determined, and that is an error). NaN with a non-zero weight is an error, not a silent
"missing". In CSV files an empty cell or ``NA``/``NaN`` is a missing cell.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional, Sequence, Tuple, Union

import numpy as np

#: The fewest stimuli a proximity matrix may have (3 points are the smallest non-trivial MDS).
MIN_STIMULI = 3

ArrayLike = Union[np.ndarray, Sequence]


class ProximityError(ValueError):
    """A proximity matrix (or its weights) is unusable; the message names the reason and cell."""


@dataclass(frozen=True)
class Proximities:
    """Validated proximities of K subjects: ``delta`` and ``weights`` are (K, n, n), symmetric,
    zero on the diagonal; missing cells have weight 0 and delta 0."""

    delta: np.ndarray
    weights: np.ndarray

    @property
    def n_subjects(self) -> int:
        return int(self.delta.shape[0])

    @property
    def n_stimuli(self) -> int:
        return int(self.delta.shape[1])

    @property
    def complete(self) -> bool:
        """Every off-diagonal pair of every subject is present with weight 1."""
        off = ~np.eye(self.n_stimuli, dtype=bool)
        return bool(np.all(self.weights[:, off] == 1.0))


def _connected(mask: np.ndarray) -> bool:
    """Whether the graph of pairs with positive weight connects all stimuli."""
    n = mask.shape[0]
    seen = np.zeros(n, dtype=bool)
    seen[0] = True
    frontier = np.array([0])
    while frontier.size:
        nxt = np.flatnonzero(mask[frontier].any(axis=0) & ~seen)
        seen[nxt] = True
        frontier = nxt
    return bool(seen.all())


def check_proximities(delta: ArrayLike, weights: Optional[ArrayLike] = None, *,
                      min_stimuli: int = MIN_STIMULI) -> Proximities:
    """Validates one (n, n) matrix or K matrices (K, n, n) and optional weights of the same shape.

    Returns :class:`Proximities` with float64 (K, n, n) arrays. Raises :class:`ProximityError`
    (a ``ValueError``) for a non-square, asymmetric, negative or non-finite matrix, NaN in a
    cell whose weight is not 0, negative or non-finite weights, too few stimuli, a subject
    with no pair present, or present pairs that do not connect all stimuli.
    """
    try:
        d = np.array(delta, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ProximityError(f"proximities must be numbers: {e}") from None
    if d.ndim == 2:
        d = d[None]
    if d.ndim != 3:
        raise ProximityError(f"proximities must be one (n, n) matrix or a stack (K, n, n); got shape {d.shape}")
    if d.shape[1] != d.shape[2]:
        raise ProximityError(f"a proximity matrix must be square; got {d.shape[1]} rows and {d.shape[2]} columns")
    k, n, _ = d.shape
    if k == 0:
        raise ProximityError("no proximity matrix given")
    if n < min_stimuli:
        raise ProximityError(f"too few stimuli: {n}; MDS needs at least {min_stimuli}")
    if weights is None:
        w = np.ones_like(d)
    else:
        w = np.array(weights, dtype=np.float64)
        if w.ndim == 2 and w.shape == d.shape[1:]:
            w = np.broadcast_to(w, d.shape).copy()
        if w.shape != d.shape:
            raise ProximityError(f"weights must have the proximities' shape {d.shape}; got {w.shape}")
        if not np.all(np.isfinite(w)):
            bad = np.argwhere(~np.isfinite(w))[0]
            raise ProximityError(f"weight of subject {bad[0]}, cell ({bad[1]}, {bad[2]}) is not finite")
        if np.any(w < 0):
            bad = np.argwhere(w < 0)[0]
            raise ProximityError(f"weight of subject {bad[0]}, cell ({bad[1]}, {bad[2]}) is negative: {w[tuple(bad)]}")
    eye = np.eye(n, dtype=bool)
    w[:, eye] = 0.0
    d[:, eye] = 0.0
    missing = w == 0.0
    present = ~missing & ~eye
    if np.any(np.isnan(d) & present):
        bad = np.argwhere(np.isnan(d) & present)[0]
        raise ProximityError(
            f"proximity of subject {bad[0]}, cell ({bad[1]}, {bad[2]}) is NaN; a missing cell must have weight 0 "
            "(pass weights with 0 there, or leave the cell empty / NA in the CSV)")
    if np.any(np.isinf(d) & present):
        bad = np.argwhere(np.isinf(d) & present)[0]
        raise ProximityError(f"proximity of subject {bad[0]}, cell ({bad[1]}, {bad[2]}) is infinite")
    d[missing] = 0.0
    if np.any(d < 0):
        bad = np.argwhere(d < 0)[0]
        raise ProximityError(
            f"proximity of subject {bad[0]}, cell ({bad[1]}, {bad[2]}) is negative ({d[tuple(bad)]}); "
            "dissimilarities are ≥ 0 (convert similarities to dissimilarities first)")
    if not np.array_equal(w, np.swapaxes(w, 1, 2)):
        bad = np.argwhere(w != np.swapaxes(w, 1, 2))[0]
        raise ProximityError(f"weights of subject {bad[0]} are not symmetric at cell ({bad[1]}, {bad[2]})")
    scale = max(float(np.max(np.abs(d))), 1e-300)
    asym = np.abs(d - np.swapaxes(d, 1, 2)) > 1e-9 * scale
    if np.any(asym):
        s, i, j = np.argwhere(asym)[0]
        raise ProximityError(
            f"proximity matrix of subject {s} is not symmetric: δ[{i},{j}] = {d[s, i, j]:g} but δ[{j},{i}] = "
            f"{d[s, j, i]:g}; MDS models distances — average the two orders ((D + D.T) / 2) if that is what you mean")
    for s in range(k):
        if not np.any(w[s] > 0):
            raise ProximityError(f"subject {s} has no pair present (all weights 0)")
    if not _connected(np.any(w > 0, axis=0)):
        raise ProximityError("the pairs present do not connect all stimuli: the configuration is not determined")
    return Proximities(delta=d, weights=w)


def upper(a: np.ndarray) -> np.ndarray:
    """The strict upper triangle of (..., n, n) as (..., n(n-1)/2), row by row."""
    n = a.shape[-1]
    i, j = np.triu_indices(n, 1)
    return a[..., i, j]


def from_upper(v: np.ndarray, n: int) -> np.ndarray:
    """The symmetric (..., n, n) matrix with zero diagonal whose strict upper triangle is v."""
    out = np.zeros(v.shape[:-1] + (n, n))
    i, j = np.triu_indices(n, 1)
    out[..., i, j] = v
    out[..., j, i] = v
    return out


_MISSING = {"", "na", "nan", "n/a"}


def read_csv_rows(path: Union[str, Path]) -> List[List[str]]:
    """The rows of a UTF-8 CSV file; a file that cannot be read or is not UTF-8 (or CSV) raises
    :class:`ProximityError` naming the file and the reason, not a traceback."""
    try:
        with Path(path).open(newline="", encoding="utf-8-sig") as f:
            return list(csv.reader(f))
    except OSError as e:
        raise ProximityError(f"{path}: cannot read it ({e.strerror or e})") from None
    except UnicodeDecodeError as e:
        raise ProximityError(f"{path}: not UTF-8 text (byte 0x{e.object[e.start]:02x} at offset {e.start}); "
                             "save the file as UTF-8 CSV") from None
    except csv.Error as e:
        raise ProximityError(f"{path}: not a CSV file ({e})") from None


def read_csv(path: Union[str, Path]) -> Tuple[np.ndarray, np.ndarray, List[str]]:
    """Reads one proximity matrix from CSV: a header row of stimulus names (the first cell may
    be empty or a label) and one row per stimulus, its name first. A lower-triangular matrix
    (upper triangle empty, as Table 1 is printed) is mirrored, and so is any pair given in one
    order only. Empty / NA cells are missing.

    Returns (delta, weights, names); weights are 1 for present and 0 for missing cells.
    Structural problems raise :class:`ProximityError` naming the file and row.
    """
    path = Path(path)
    rows = [r for r in read_csv_rows(path) if r and any(c.strip() for c in r)]
    if len(rows) < 2:
        raise ProximityError(f"{path}: needs a header row and at least one data row")
    names = [c.strip() for c in rows[0][1:]]
    n = len(names)
    body = rows[1:]
    if len(body) != n:
        raise ProximityError(f"{path}: a proximity matrix must be square; {n} columns but {len(body)} rows")
    d = np.full((n, n), np.nan)
    for i, r in enumerate(body):
        if r[0].strip() != names[i]:
            raise ProximityError(f"{path}: row {i + 2} is '{r[0].strip()}' but column {i + 1} is '{names[i]}'")
        cells = r[1:] + [""] * (n - len(r) + 1)
        if len(r) - 1 > n:
            raise ProximityError(f"{path}: row {i + 2} has {len(r) - 1} values for {n} stimuli")
        for j, c in enumerate(cells[:n]):
            c = c.strip()
            if c.lower() in _MISSING:
                continue
            try:
                d[i, j] = float(c)
            except ValueError:
                raise ProximityError(f"{path}: row {i + 2}, column {j + 2}: '{c}' is not a number") from None
    d = np.where(np.isnan(d), d.T, d)  # a triangular matrix (or a cell given once) is mirrored
    np.fill_diagonal(d, 0.0)
    w = np.where(np.isnan(d), 0.0, 1.0)
    np.fill_diagonal(w, 0.0)
    return d, w, names


def write_csv(path: Union[str, Path], delta: np.ndarray, names: Sequence[str]) -> None:
    """Writes one proximity matrix (the layout :func:`read_csv` reads)."""
    with Path(path).open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow([""] + list(names))
        for name, row in zip(names, np.asarray(delta)):
            w.writerow([name] + [f"{x:.10g}" for x in row])
