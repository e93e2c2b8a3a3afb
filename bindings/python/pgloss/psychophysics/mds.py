# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Multidimensional scaling (paper §3.2.2), after Borg & Groenen, *Modern Multidimensional
Scaling* (Springer 1997; "B&G" below):

* :func:`torgerson` — classical scaling (B&G ch. 12): double-centred squared proximities,
  top eigenvectors. Exact for Euclidean distances; the usual start for the iterative methods.
* :func:`smacof` — stress majorization (de Leeuw 1977; B&G ch. 8): the Guttman transform
  X⁺ = V⁺ B(X) X never increases raw stress (eq. 1). ``metric=True`` fits the proximities
  themselves (ratio MDS); ``metric=False`` is Kruskal's non-metric MDS (B&G ch. 9): each
  iteration replaces the proximities by *disparities*, the weighted least-squares monotone
  (isotonic) regression of the distances on the proximities' order, normalised to
  Σ w d̂² = n(n−1)/2 so the solution cannot shrink to a point. Ties among proximities:
  ``ties='primary'`` lets tied proximities get unequal disparities (order free inside a tie
  block), ``'secondary'`` forces them equal.
* :func:`weighted_euclidean_mds` — the individual-differences model the paper ran in PROXSCAL
  (Busing, Commandeur & Heiser 1997; "weighted Euclidean", INDSCAL-like; B&G ch. 21): one
  common space Z (n × p) and per-subject diagonal dimension weights W_k, X_k = Z W_k, fitted by
  majorization — a Guttman transform per subject, then the least-squares projection of the
  K updates onto the model (alternating Z and W_k), metric or non-metric per subject
  (matrix-conditional disparities). Its axes are not rotatable: the weights identify them.
* :func:`stress_curve`, :func:`choose_dimensionality` — Figs. 3 and 5 and the elbow rule.

Every fit runs from the Torgerson start plus seeded random starts and keeps the lowest stress.
Local minima are common in non-metric MDS, in one dimension and below the data's own
dimensionality (a 2-D fit of 3-D data), so by default (``n_random=None``) the random starts
continue, in batches of :data:`AUTO_STARTS`, until the lowest stress has been reached from two
starts or two batches have not lowered it (:data:`STALLED`), up to :data:`MAX_STARTS`; a 1-D fit runs :data:`MAX_STARTS_1D` starts, most of them
projections of the data's Torgerson configuration (:func:`_projections`). ``start_stress``
lists every start's result. An integer ``n_random`` runs exactly that many random starts. Iterations stop on a relative
decrease of stress (:func:`_converged`). Missing cells are pairs with weight 0 (see :mod:`.proximity`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, List, Optional, Sequence, Tuple

import numpy as np

from .proximity import ArrayLike, Proximities, ProximityError, check_proximities
from .stress import Stress, distances, stress_of

TIES = ("primary", "secondary")
#: The automatic rule's batch of random starts (n_random=None), and the most random starts it runs.
AUTO_STARTS = 4
MAX_STARTS = 32
MAX_STARTS_1D = 64  # one dimension: a local minimum per order of the points along the line
#: Two starts whose stress differ by less than this (relative), or 100 × the stop rule's eps
#: where that is larger, reached the same minimum.
SAME_MINIMUM = 1e-5
#: ... or two batches of random starts have not lowered the best stress by this much (relative):
#: above the data's dimensionality the minima differ by a few tenths of a per cent and rarely repeat.
STALLED = 1e-3
#: Normalised raw stress (stress-1 about 1e-6) below which a fit counts as exact: nothing lower is
#: worth finding, and a fit with more dimensions than the data have converges slowly towards 0.
PERFECT_FIT = 1e-12


def _isotonic(y: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Weighted least-squares non-decreasing fit to y (pool-adjacent-violators, scipy's C code)."""
    try:
        from scipy.optimize import isotonic_regression  # scipy ≥ 1.12; imported here, only non-metric fits need it
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError("non-metric MDS needs scipy ≥ 1.12 (scipy.optimize.isotonic_regression): "
                          "pip install 'pgloss[psychophysics]'") from None
    return isotonic_regression(y, weights=w, increasing=True).x


class _Disparities:
    """The non-metric transformation of one subject's proximities (B&G §9.2): precomputes the
    order of the present pairs once; each call is one isotonic regression of the distances."""

    def __init__(self, delta: np.ndarray, weights: np.ndarray, ties: str) -> None:
        if ties not in TIES:
            raise ValueError(f"ties must be 'primary' or 'secondary'; got {ties!r}")
        n = delta.shape[0]
        self.n = n
        self.ties = ties
        iu = np.triu_indices(n, 1)
        keep = weights[iu] > 0
        self.i, self.j = iu[0][keep], iu[1][keep]
        self.delta = delta[self.i, self.j]
        self.w = weights[self.i, self.j]
        self.order = np.argsort(self.delta, kind="stable")
        ds = self.delta[self.order]
        self.block = np.concatenate(([0], np.cumsum(ds[1:] != ds[:-1])))  # tie block of each sorted pair
        self.block_w = np.bincount(self.block, weights=self.w[self.order])
        self.target = n * (n - 1) / 2.0  # Σ w d̂² after normalisation (B&G §9.4, as scikit-learn)

    def _matrix(self, v: np.ndarray) -> np.ndarray:
        s = float(np.sum(self.w * v * v))
        v = v * np.sqrt(self.target / s) if s > 0 else np.full_like(v, np.sqrt(self.target / np.sum(self.w)))
        out = np.zeros((self.n, self.n))
        out[self.i, self.j] = v
        out[self.j, self.i] = v
        return out

    def initial(self) -> np.ndarray:
        """The normalised proximities: the disparities of the first iteration."""
        return self._matrix(self.delta.astype(np.float64))

    def __call__(self, dist: np.ndarray) -> np.ndarray:
        d = dist[self.i, self.j]
        out = np.empty_like(d)
        if self.ties == "primary":  # inside a tie block the distances' own order is free
            o = np.lexsort((d, self.delta))
            out[o] = _isotonic(d[o], self.w[o])
        else:  # tied proximities share one disparity: fit the block means
            o = self.order
            means = np.bincount(self.block, weights=self.w[o] * d[o]) / self.block_w
            out[o] = _isotonic(means, self.block_w)[self.block]
        return self._matrix(out)


class _BatchDisparities:
    """:class:`_Disparities` for K subjects at once (matrix-conditional: each subject its own
    monotone regression). One sort and one PAVA run over all subjects: subject s's values are
    shifted by s·gap with gap above every distance, so no pool can cross from one subject to the
    next, and the shift is removed afterwards."""

    def __init__(self, delta: np.ndarray, weights: np.ndarray, ties: str) -> None:
        if ties not in TIES:
            raise ValueError(f"ties must be 'primary' or 'secondary'; got {ties!r}")
        k, n, _ = delta.shape
        self.k, self.n, self.ties = k, n, ties
        self.iu = np.triu_indices(n, 1)
        m = self.iu[0].size
        w = weights[:, self.iu[0], self.iu[1]].ravel()
        self.sel = np.flatnonzero(w > 0)
        self.subj = self.sel // m
        self.m = m
        self.delta = delta[:, self.iu[0], self.iu[1]].ravel()[self.sel]
        self.w = w[self.sel]
        self.order = np.lexsort((self.delta, self.subj))
        ds, ss = self.delta[self.order], self.subj[self.order]
        self.block = np.concatenate(([0], np.cumsum((ds[1:] != ds[:-1]) | (ss[1:] != ss[:-1]))))
        self.block_w = np.bincount(self.block, weights=self.w[self.order])
        self.block_subj = np.zeros(self.block_w.size, dtype=np.int64)
        self.block_subj[self.block] = ss
        self.block_of = np.empty_like(self.block)  # each present pair's (subject, proximity) block
        self.block_of[self.order] = self.block
        self.target = n * (n - 1) / 2.0

    def _matrix(self, v: np.ndarray) -> np.ndarray:
        ss = np.bincount(self.subj, weights=self.w * v * v, minlength=self.k)
        v = v * np.sqrt(self.target / np.where(ss > 0, ss, 1.0))[self.subj]
        flat = np.zeros(self.k * self.m)
        flat[self.sel] = v
        out = np.zeros((self.k, self.n, self.n))
        out[:, self.iu[0], self.iu[1]] = flat.reshape(self.k, self.m)
        return out + np.swapaxes(out, 1, 2)

    def initial(self) -> np.ndarray:
        return self._matrix(self.delta.astype(np.float64))

    def __call__(self, dist: np.ndarray) -> np.ndarray:
        d = dist[:, self.iu[0], self.iu[1]].ravel()[self.sel]
        gap = 2.0 * float(np.max(d)) + 1.0
        out = np.empty_like(d)
        if self.ties == "primary":
            # Sort by block, then by distance inside a block: one float key (block · gap + d) is
            # much faster than a three-key lexsort; the blocks follow subject, then proximity.
            key = self.block_of * gap + d
            o = np.argsort(key, kind="stable")
            shift = self.subj[o] * gap
            out[o] = _isotonic(d[o] + shift, self.w[o]) - shift
        else:
            o = self.order
            means = np.bincount(self.block, weights=self.w[o] * d[o]) / self.block_w
            shift = self.block_subj * gap
            out[o] = (_isotonic(means + shift, self.block_w) - shift)[self.block]
        return self._matrix(np.maximum(out, 0.0))


def _vplus(w: np.ndarray) -> Optional[np.ndarray]:
    """V⁺ of B&G eq. 8.19 for pair weights w; None for unit weights (then V⁺ B X = B X / n)."""
    n = w.shape[0]
    off = ~np.eye(n, dtype=bool)
    if np.all(w[off] == 1.0):
        return None
    v = -w.copy()
    np.fill_diagonal(v, 0.0)
    np.fill_diagonal(v, -v.sum(axis=1))
    return np.linalg.pinv(v + 1.0 / n) - 1.0 / n  # (V + 11ᵀ/n)⁻¹ − 11ᵀ/n (B&G eq. 8.21)


def _vmat(w: np.ndarray) -> np.ndarray:
    v = -w.copy()
    np.fill_diagonal(v, 0.0)
    np.fill_diagonal(v, -v.sum(axis=1))
    return v


def _guttman(x: np.ndarray, dist: np.ndarray, disp: np.ndarray, w: np.ndarray, vplus: Optional[np.ndarray]) -> np.ndarray:
    """The Guttman transform V⁺ B(X) X (B&G eq. 8.24); b_ij = −w_ij d̂_ij / d_ij, 0 where d_ij = 0."""
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(dist > 0, w * disp / dist, 0.0)
    b = -ratio
    np.fill_diagonal(b, ratio.sum(axis=1))
    bx = b @ x
    return bx / x.shape[0] if vplus is None else vplus @ bx


def torgerson(delta: ArrayLike, ndim: int = 2, weights: Optional[ArrayLike] = None) -> np.ndarray:
    """Classical (Torgerson–Gower) scaling of one proximity matrix: the n × ndim configuration
    whose inner products best match −½ J Δ⁽²⁾ J (B&G eq. 12.2). Missing cells (weight 0) are
    filled with the mean present proximity first — a start, not an estimate."""
    p = check_proximities(delta, weights)
    if p.n_subjects != 1:
        raise ProximityError("torgerson takes one proximity matrix; average the subjects first")
    return _torgerson(p.delta[0], p.weights[0], ndim)


def _torgerson(d: np.ndarray, w: np.ndarray, ndim: int) -> np.ndarray:
    n = d.shape[0]
    off = ~np.eye(n, dtype=bool)
    d = d.copy()
    fill = np.sum(w * d) / np.sum(w)
    d[(w == 0) & off] = fill
    j = np.eye(n) - 1.0 / n
    b = -0.5 * j @ (d * d) @ j
    vals, vecs = np.linalg.eigh(b)
    idx = np.argsort(vals)[::-1][:ndim]
    x = vecs[:, idx] * np.sqrt(np.maximum(vals[idx], 0.0))
    # A direction with zero eigenvalue gives a degenerate start; give it a small spread instead.
    scale = np.sqrt(max(float(np.mean(d[off] ** 2)), 1e-300))
    for a in range(x.shape[1]):
        if np.linalg.norm(x[:, a]) < 1e-9 * scale:
            x[:, a] = 1e-3 * scale * np.linspace(-1.0, 1.0, n)
    signs = np.sign(x[np.argmax(np.abs(x), axis=0), np.arange(x.shape[1])])  # deterministic orientation
    return x * np.where(signs == 0, 1.0, signs)


@dataclass(frozen=True)
class MDSResult:
    """One SMACOF fit: ``config`` (n, p), the ``disparities`` it fits (n, n; the proximities in
    metric MDS), its :class:`~.stress.Stress`, iterations, whether it converged, and the final
    stress-1 of every start tried (Torgerson first)."""

    config: np.ndarray
    disparities: np.ndarray
    stress: Stress
    n_iter: int
    converged: bool
    start_stress: Tuple[float, ...] = ()
    metric: bool = True


def _check_fit_args(p: Proximities, ndim: int, max_iter: int, eps: float) -> None:
    if int(ndim) != ndim or ndim < 1:
        raise ValueError(f"ndim must be a positive integer; got {ndim!r}")
    if p.n_stimuli < ndim + 2:
        raise ProximityError(f"too few stimuli: {p.n_stimuli} for a {ndim}-dimensional solution "
                             f"(needs at least {ndim + 2}; n − 1 dimensions always fit exactly)")
    if max_iter < 1 or not (eps >= 0):
        raise ValueError("max_iter must be ≥ 1 and eps ≥ 0")


def _check_start(x: ArrayLike, n: int, ndim: int) -> np.ndarray:
    x = np.array(x, dtype=np.float64)
    if x.shape != (n, ndim) or not np.all(np.isfinite(x)):
        raise ValueError(f"a start must be a finite ({n}, {ndim}) array; got shape {x.shape}")
    return x


def _converged(old: Optional[float], new: float, eps: float) -> bool:
    """The stop rule of every majorization loop here: stress fell by less than ``eps`` of its
    value in one iteration. Relative, so that a near-perfect fit (stress 1e-6) converges as far
    as a poor one: an absolute 1e-10 stopped such fits 0.4–1 % above the minimum that
    scikit-learn reaches (B&G §8.6 state the rule either way; R's smacof uses an absolute 1e-6).
    A fit below PERFECT_FIT is exact and stops (its stress falls towards 0 at a constant rate)."""
    return old is not None and (new <= PERFECT_FIT or old - new < eps * old)


def _random_start(rng: np.random.Generator, n: int, ndim: int, scale: float) -> np.ndarray:
    x = rng.standard_normal((n, ndim))
    return x * scale / max(float(np.sqrt(np.mean(np.sum((x - x.mean(0)) ** 2, axis=1)))), 1e-300)


def _projections(d: np.ndarray, w: np.ndarray, count: int) -> List[np.ndarray]:
    """One-dimensional starts: the Torgerson configuration in up to 3 dimensions projected on
    ``count`` directions spread over a half circle or hemisphere (Fibonacci lattice). A 1-D fit
    has a local minimum for every order of the points along the line; the orders of the data's
    own projections are likelier to be near the best one than random orders."""
    q = min(3, d.shape[0] - 1)
    z = _torgerson(d, w, q)
    i = np.arange(count) + 0.5
    if q == 1:
        return [z]
    if q == 2:
        t = np.pi * i / count
        dirs = np.column_stack([np.cos(t), np.sin(t)])
    else:
        polar, azimuth = np.arccos(1.0 - i / count), np.pi * (1.0 + 5.0**0.5) * i
        dirs = np.column_stack([np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)])
    return [(z @ u)[:, None] for u in dirs]


def _multistart(fit, fixed: Sequence[np.ndarray], random_start, n_random: Optional[int], ndim: int, stress,
                projections, eps: float) -> list:
    """The fits from the ``fixed`` starts and from random ones: ``n_random`` of them, or with
    None the automatic rule (module doc): in 1-D AUTO_STARTS random starts and the rest of
    MAX_STARTS_1D from ``projections(count)``; otherwise batches of AUTO_STARTS until the lowest
    ``stress`` (normalised raw stress) has been reached from two starts, or two batches have not
    lowered it by STALLED, or MAX_STARTS. An exact fit (below PERFECT_FIT) ends the search."""
    if n_random is not None and (int(n_random) != n_random or n_random < 0):
        raise ValueError(f"n_random must be None (automatic) or an integer ≥ 0; got {n_random!r}")
    fits = [fit(x) for x in fixed]
    if n_random is not None:
        return fits + [fit(random_start()) for _ in range(int(n_random))]
    if ndim == 1:
        fits += [fit(x) for x in projections(MAX_STARTS_1D - AUTO_STARTS - len(fixed))]
        return fits + [fit(random_start()) for _ in range(AUTO_STARTS)]
    done, best = 0, [min(stress(f) for f in fits)]  # the lowest stress after each batch
    while done < MAX_STARTS:
        values = np.array([stress(f) for f in fits])
        same = values <= values.min() * (1 + max(SAME_MINIMUM, 100 * eps))
        stalled = len(best) > 2 and best[-1] > best[-3] * (1 - STALLED)
        if values.min() <= PERFECT_FIT or (done and np.sum(same) >= 2) or stalled:
            break
        fits += [fit(random_start()) for _ in range(AUTO_STARTS)]
        done += AUTO_STARTS
        best.append(min(stress(f) for f in fits))
    return fits


def _smacof_once(d: np.ndarray, w: np.ndarray, x: np.ndarray, metric: bool, ties: str,
                 max_iter: int, eps: float) -> MDSResult:
    vplus = _vplus(w)
    disp_fn = None if metric else _Disparities(d, w, ties)
    old = None
    converged = False
    it = 0
    for it in range(1, max_iter + 1):
        dist = distances(x)
        if metric:
            disp = d
        else:
            disp = disp_fn.initial() if it == 1 else disp_fn(dist)
        s = stress_of(disp, dist, w).normalized
        if _converged(old, s, eps):
            converged = True
            break
        old = s
        x = _guttman(x, dist, disp, w, vplus)
    dist = distances(x)
    if not metric:
        disp = disp_fn(dist)
    x = x - x.mean(axis=0)
    return MDSResult(config=x, disparities=disp, stress=stress_of(disp, dist, w), n_iter=it,
                     converged=converged, metric=metric)


def smacof(delta: ArrayLike, ndim: int = 2, *, weights: Optional[ArrayLike] = None, metric: bool = True,
           ties: str = "primary", init: Optional[ArrayLike] = None, n_random: Optional[int] = None, seed: int = 0,
           max_iter: int = 3000, eps: float = 1e-8, starts: Sequence[ArrayLike] = ()) -> MDSResult:
    """SMACOF on one proximity matrix (B&G ch. 8; non-metric: ch. 9).

    ``init`` (n, ndim) runs one fit from that configuration; otherwise the Torgerson start, any
    further ``starts`` and random starts (``seed``; ``n_random`` of them, or by the automatic
    rule of the module doc when None) are run and the lowest stress-1 kept; ``start_stress``
    has one entry per start. Iterations stop when normalised raw stress decreases by less than
    ``eps`` of its value in one step, or at ``max_iter``.
    """
    p = check_proximities(delta, weights)
    if p.n_subjects != 1:
        raise ProximityError("smacof takes one proximity matrix; use weighted_euclidean_mds for several subjects")
    _check_fit_args(p, ndim, max_iter, eps)
    d, w = p.delta[0], p.weights[0]

    def fit(x: np.ndarray) -> MDSResult:
        return _smacof_once(d, w, x, metric, ties, max_iter, eps)

    if init is not None:
        x0 = np.array(init, dtype=np.float64)
        if x0.shape != (p.n_stimuli, ndim) or not np.all(np.isfinite(x0)):
            raise ValueError(f"init must be a finite ({p.n_stimuli}, {ndim}) array; got shape {x0.shape}")
        fits = [fit(x0)]
    else:
        x0 = _torgerson(d, w, ndim)
        scale = float(np.sqrt(np.mean(np.sum((x0 - x0.mean(0)) ** 2, axis=1))))
        rng = np.random.default_rng(seed)
        fixed = [x0] + [_check_start(x, p.n_stimuli, ndim) for x in starts]
        fits = _multistart(fit, fixed, lambda: _random_start(rng, p.n_stimuli, ndim, scale), n_random, ndim,
                           lambda f: f.stress.normalized, lambda count: _projections(d, w, count), eps)
    best = min(fits, key=lambda f: f.stress.stress1)
    return MDSResult(config=best.config, disparities=best.disparities, stress=best.stress, n_iter=best.n_iter,
                     converged=best.converged, start_stress=tuple(f.stress.stress1 for f in fits), metric=metric)


@dataclass(frozen=True)
class WeightedEuclideanResult:
    """The weighted Euclidean (individual differences) fit X_k = Z W_k.

    ``common`` Z (n, p) has centred columns of unit mean square (Σ_i z_ia² = n);
    ``subject_weights`` (K, p) are the diagonals of W_k (≥ 0); ``configs`` (K, n, p) = Z W_k;
    ``disparities`` (K, n, n); ``stress`` over all subjects, ``subject_stress`` per subject.
    """

    common: np.ndarray
    subject_weights: np.ndarray
    configs: np.ndarray
    disparities: np.ndarray
    stress: Stress
    subject_stress: Tuple[Stress, ...]
    n_iter: int
    converged: bool
    start_stress: Tuple[float, ...] = ()
    metric: bool = False


def _wemds_once(p: Proximities, z: np.ndarray, metric: bool, ties: str, max_iter: int, eps: float
                ) -> WeightedEuclideanResult:
    k, n = p.n_subjects, p.n_stimuli
    ndim = z.shape[1]
    complete = p.complete
    vplus = [None if complete else _vplus(p.weights[s]) for s in range(k)]
    vmats = None if complete else [_vmat(p.weights[s]) for s in range(k)]
    fns = None if metric else _BatchDisparities(p.delta, p.weights, ties)
    z = z - z.mean(axis=0)
    wts = np.ones((k, ndim))
    old = None
    converged = False
    it = 0
    den = None
    for it in range(1, max_iter + 1):
        xs = z[None] * wts[:, None, :]
        dist = distances(xs)
        if metric:
            disp = p.delta
        else:
            disp = fns.initial() if it == 1 else fns(dist)
        raw = float(np.sum(p.weights * (disp - dist) ** 2)) / 2.0
        den = float(np.sum(p.weights * disp**2)) / 2.0
        s = raw / den if den > 0 else 0.0
        if _converged(old, s, eps):
            converged = True
            break
        old = s
        # Guttman transform per subject: the unconstrained update X̄_k.
        if complete:  # V⁺ B(X_k) X_k = B(X_k) X_k / n for every subject at once
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = np.where(dist > 0, p.weights * disp / dist, 0.0)
            xbar = (np.sum(ratio, axis=2)[:, :, None] * xs - np.einsum("kij,kja->kia", ratio, xs)) / n
        else:
            xbar = np.stack([_guttman(xs[s], dist[s], disp[s], p.weights[s], vplus[s]) for s in range(k)])
        # Projection onto X_k = Z W_k in the metric of V_k (B&G §21.2): one sweep of Z, then W.
        if complete:
            num = np.einsum("ka,kia->ia", wts, xbar)
            wsq = np.sum(wts**2, axis=0)
            z = num / np.where(wsq > 0, wsq, 1.0)
            z -= z.mean(axis=0)
            zz = np.sum(z * z, axis=0)
            wts = np.einsum("ia,kia->ka", z, xbar) / np.where(zz > 0, zz, 1.0)
        else:
            for a in range(ndim):
                lhs = sum(wts[s, a] ** 2 * vmats[s] for s in range(k))
                rhs = sum(wts[s, a] * (vmats[s] @ xbar[s, :, a]) for s in range(k))
                z[:, a] = np.linalg.lstsq(lhs + 1.0 / n, rhs, rcond=None)[0]
                z[:, a] -= z[:, a].mean()
                for s in range(k):
                    vz = vmats[s] @ z[:, a]
                    zvz = float(z[:, a] @ vz)
                    wts[s, a] = float(vz @ xbar[s, :, a]) / zvz if zvz > 0 else 0.0
        # Identification: unit mean-square columns of Z, the scale carried by the weights.
        norm = np.sqrt(np.sum(z * z, axis=0) / n)
        norm = np.where(norm > 0, norm, 1.0)
        z = z / norm
        wts = np.abs(wts * norm)  # the sign of a weight is immaterial (distances use w²)
    xs = z[None] * wts[:, None, :]
    dist = distances(xs)
    if not metric:
        disp = fns(dist)
    per = tuple(stress_of(disp[s], dist[s], p.weights[s]) for s in range(k))
    return WeightedEuclideanResult(common=z, subject_weights=wts, configs=xs, disparities=disp,
                                   stress=stress_of(disp, dist, p.weights), subject_stress=per,
                                   n_iter=it, converged=converged, metric=metric)


def _mean_matrix(p: Proximities) -> Tuple[np.ndarray, np.ndarray]:
    """Subjects' proximities averaged cell by cell after scaling each to unit mean square."""
    ms = np.sqrt(np.sum(p.weights * p.delta**2, axis=(1, 2)) / np.sum(p.weights, axis=(1, 2)))
    dn = p.delta / np.where(ms > 0, ms, 1.0)[:, None, None]
    wsum = np.sum(p.weights, axis=0)
    mean = np.sum(p.weights * dn, axis=0) / np.where(wsum > 0, wsum, 1.0)
    return mean, (wsum > 0).astype(np.float64)


def weighted_euclidean_mds(delta: ArrayLike, ndim: int = 2, *, weights: Optional[ArrayLike] = None,
                           metric: bool = False, ties: str = "primary", init: Optional[ArrayLike] = None,
                           n_random: Optional[int] = None, seed: int = 0, max_iter: int = 2000, eps: float = 1e-7,
                           starts: Sequence[ArrayLike] = ()) -> WeightedEuclideanResult:
    """The weighted Euclidean model (PROXSCAL's, the paper's Experiment 1) on K proximity
    matrices (K, n, n): common space Z and subject weights W_k with X_k = Z W_k.

    ``metric=False`` (the paper's choice) fits each subject's own monotone transformation;
    ``init`` is a common-space start (n, ndim); otherwise the Torgerson start of the averaged
    matrices, any further common-space ``starts`` and random starts (``n_random``, or the
    automatic rule of the module doc when None), the lowest total stress kept. ``eps``: as
    :func:`smacof`'s.
    """
    p = check_proximities(delta, weights)
    _check_fit_args(p, ndim, max_iter, eps)

    def fit(z: np.ndarray) -> WeightedEuclideanResult:
        return _wemds_once(p, z, metric, ties, max_iter, eps)

    if init is not None:
        z0 = np.array(init, dtype=np.float64)
        if z0.shape != (p.n_stimuli, ndim) or not np.all(np.isfinite(z0)):
            raise ValueError(f"init must be a finite ({p.n_stimuli}, {ndim}) array; got shape {z0.shape}")
        fits = [fit(z0)]
    else:
        mean, mw = _mean_matrix(p)
        z0 = _torgerson(mean, mw, ndim)
        scale = float(np.sqrt(np.mean(np.sum(z0**2, axis=1))))
        rng = np.random.default_rng(seed)
        fixed = [z0] + [_check_start(z, p.n_stimuli, ndim) for z in starts]
        fits = _multistart(fit, fixed, lambda: _random_start(rng, p.n_stimuli, ndim, scale), n_random, ndim,
                           lambda f: f.stress.normalized, lambda count: _projections(mean, mw, count), eps)
    best = min(fits, key=lambda f: f.stress.normalized)
    return WeightedEuclideanResult(**{**best.__dict__, "start_stress": tuple(f.stress.normalized for f in fits)})


@dataclass(frozen=True)
class StressCurve:
    """Stress of the best solution in each dimensionality (Figs. 3 and 5)."""

    dims: Tuple[int, ...]
    stress: Tuple[Stress, ...]
    fits: Tuple[object, ...] = field(repr=False, default=())
    model: str = "smacof"

    def values(self, kind: str = "stress1") -> np.ndarray:
        return np.array([s.get(kind) for s in self.stress])

    def fit(self, ndim: int):
        """The fit of dimensionality ndim."""
        return self.fits[self.dims.index(ndim)]


def stress_curve(delta: ArrayLike, dims: Iterable[int] = range(1, 6), *, weights: Optional[ArrayLike] = None,
                 model: str = "auto", metric: Optional[bool] = None, **kwargs) -> StressCurve:
    """Fits every dimensionality in ``dims`` (default 1–5, as Figs. 3 and 5) and returns the
    stress curve. ``model``: 'smacof' (one matrix), 'weighted_euclidean' (K matrices), or
    'auto' (smacof for one matrix, weighted Euclidean for several). ``metric`` defaults to
    True for smacof (Table 1's distances are ratio data) and False for the weighted model (the
    paper's ratings are ordinal); other keywords go to the fitting function."""
    p = check_proximities(delta, weights)
    if model == "auto":
        model = "smacof" if p.n_subjects == 1 else "weighted_euclidean"
    if model not in ("smacof", "weighted_euclidean"):
        raise ValueError(f"model must be 'auto', 'smacof' or 'weighted_euclidean'; got {model!r}")
    dims = tuple(int(k) for k in dims)
    if not dims:
        raise ValueError("dims is empty")
    fits: list = []
    for k in dims:
        # The previous dimensionality's solution plus a small new axis is one more start, so that
        # the curve cannot rise where a local minimum was found (B&G §13.4).
        prev = fits[-1] if fits and dims[len(fits) - 1] == k - 1 else None
        if model == "smacof":
            extra = [] if prev is None else [_pad(prev.config, k)]
            fits.append(smacof(p.delta, k, weights=p.weights, metric=True if metric is None else metric,
                               starts=extra, **kwargs))
        else:
            extra = [] if prev is None else [_pad(prev.common * np.sqrt(np.mean(prev.subject_weights**2, 0)), k)]
            fits.append(weighted_euclidean_mds(p.delta, k, weights=p.weights,
                                               metric=False if metric is None else metric, starts=extra, **kwargs))
    return StressCurve(dims=dims, stress=tuple(f.stress for f in fits), fits=tuple(fits), model=model)


def _pad(x: np.ndarray, ndim: int) -> np.ndarray:
    """x (n, ndim − 1) with one more axis of small, deterministic spread."""
    n = x.shape[0]
    spread = 0.05 * float(np.sqrt(np.mean(np.sum(x**2, axis=1))))
    return np.column_stack([x, spread * np.cos(np.arange(n) * 2.399963)])  # golden-angle pattern


@dataclass(frozen=True)
class Dimensionality:
    """The dimensionality an elbow rule picks from a stress curve (None: no clear elbow), with
    the reasoning in words."""

    ndim: Optional[int]
    reasoning: str
    gains: Tuple[float, ...]


def choose_dimensionality(curve: StressCurve, *, kind: str = "stress1", good: float = 0.05,
                          min_gain: float = 0.5, flatten: float = 2.0) -> Dimensionality:
    """The elbow of the stress curve, as the paper reads Figs. 3 and 5 ("drops sharply …, then
    declines more slowly").

    With s_p the stress of p dimensions and the relative gain g_p = (s_{p−1} − s_p)/s_{p−1}:

    1. if s at the smallest dimensionality is already ≤ ``good`` (Kruskal's "good", stress-1
       0.05), that dimensionality is chosen;
    2. otherwise the candidate is the p with the largest gain; it is the elbow if the stress
       at least halves there (g_p ≥ ``min_gain``), the curve flattens after it (g_p ≥
       ``flatten`` × every later gain), and at least one later dimensionality shows that;
    3. otherwise there is no elbow (ndim None): stress falls gradually, as it does for data
       without low-dimensional structure (noise).
    """
    s = curve.values(kind)
    dims = curve.dims
    if list(dims) != list(range(dims[0], dims[0] + len(dims))):
        raise ValueError("the stress curve's dimensionalities must be consecutive")
    gains = tuple(float((s[i - 1] - s[i]) / s[i - 1]) if s[i - 1] > 0 else 0.0 for i in range(1, len(s)))
    table = ", ".join(f"{d}D {v:.4f}" for d, v in zip(dims, s))
    gtxt = ", ".join(f"{dims[i]}D {100 * g:.0f}%" for i, g in enumerate(gains, start=1))
    head = f"{kind} by dimensionality: {table}. Relative drop from the previous dimensionality: {gtxt}. "
    if s[0] <= good:
        return Dimensionality(dims[0], head + f"{dims[0]}D already fits well ({kind} {s[0]:.4f} ≤ {good}): "
                              f"choose {dims[0]}.", gains)
    if len(gains) < 2:
        return Dimensionality(None, head + "too few dimensionalities to see an elbow (need 3 or more).", gains)
    cand = int(np.argmax(gains[:-1]))  # the last gain cannot be confirmed by a later one
    g = gains[cand]
    later = max(gains[cand + 1:])
    p = dims[cand + 1]
    if g >= min_gain and g >= flatten * later:
        return Dimensionality(p, head + f"the stress drops by {100 * g:.0f}% at {p}D and by at most "
                              f"{100 * later:.0f}% per dimension after it: the elbow is at {p} dimensions.", gains)
    why = (f"the largest drop ({100 * g:.0f}% at {p}D) is under {100 * min_gain:.0f}%" if g < min_gain else
           f"the drop at {p}D ({100 * g:.0f}%) is not {flatten:g}× the later ones (up to {100 * later:.0f}%)")
    return Dimensionality(None, head + f"no clear elbow: {why}; the stress declines gradually, as for data "
                          "without low-dimensional structure.", gains)
