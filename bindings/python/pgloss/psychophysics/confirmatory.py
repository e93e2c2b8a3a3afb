# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Confirmatory MDS (paper §3.3.4; B&G ch. 10): the configuration is not free but a hypothesis,
coordinates given as functions of the stimulus parameters, and the data only fit how much each
dimension counts.

Model, for subject k with predictor columns f_a (e.g. f_1 = c of eq. 4, f_2 = d = 1 − α of
eq. 3), centred:  X_k = F diag(v_k),  distances d_ij(X_k) = √Σ_a v_ka² (f_ia − f_ja)².
This is the weighted Euclidean model of :func:`.mds.weighted_euclidean_mds` with the common
space fixed to F up to per-dimension scale, so every subject's weights v_k are fitted by
majorization on its own: a Guttman transform X̄_k = V⁺B(X_k)X_k, then the least-squares
projection v_ka = f_aᵀ V x̄_ka / f_aᵀ V f_a (the V-metric regression of B&G §10.3) — stress
never increases. Non-metric (the paper's choice) alternates this with the subject's disparities.

The paper's 1.78 (eq. 5) is a *ratio* of dimension weights. The group ratio of dimension a
to dimension 1 is the geometric mean over subjects of v_ka / v_k1 — scale-free per subject,
which matters because a non-metric subject's overall scale is arbitrary. Its confidence
interval is a percentile bootstrap over subjects (resampling whole subjects, so between-
subject differences count). :func:`permutation_test` asks whether the hypothesis fits better
than the same functions attached to shuffled stimuli; :func:`compare_hypotheses` ranks
competing functional forms by stress, as the paper compared its three contrast hypotheses.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from .mds import _converged, _Disparities, _guttman, _vmat, _vplus
from .proximity import ArrayLike, Proximities, ProximityError, check_proximities
from .stress import Stress, distances, stress_of


@dataclass(frozen=True)
class ConfirmatoryResult:
    """A confirmatory fit.

    ``subject_weights`` (K, p): each subject's v_k; ``ratios`` (K, p): v_ka / v_k1;
    ``group_ratio`` (p,): geometric mean of ``ratios`` over subjects (1 for the first dimension);
    ``ci`` (p, 2): its percentile bootstrap interval over subjects at level ``level``;
    ``stress``: over all subjects; ``configs`` (K, n, p) = F diag(v_k).
    """

    names: Tuple[str, ...]
    predictors: np.ndarray
    subject_weights: np.ndarray
    ratios: np.ndarray
    group_ratio: np.ndarray
    ci: np.ndarray
    level: float
    stress: Stress
    subject_stress: Tuple[Stress, ...]
    configs: np.ndarray
    disparities: np.ndarray
    n_iter: int
    converged: bool
    permutation: Optional["PermutationTest"] = None

    @property
    def recovered(self) -> Optional[bool]:
        """Whether the hypothesis explains the data: it fits better than shuffled stimuli
        (permutation p < 0.05) *and* by a margin — its stress at most half the shuffles' median,
        so that the 1-in-20 chance win of a significance test on structureless data does not
        count. None when no permutation test was run. Without it a tight interval proves
        nothing: on pure noise the fitted ratio is set by the predictors' geometry and barely
        varies between subjects."""
        if self.permutation is None:
            return None
        pt = self.permutation
        return bool(pt.p_value < 0.05 and pt.observed <= 0.5 * float(np.median(pt.null)))

    @property
    def weight_ratio(self) -> float:
        """The group weight of the second dimension relative to the first (the paper's 1.78)."""
        if len(self.names) < 2:
            raise ValueError("a weight ratio needs two dimensions")
        return float(self.group_ratio[1])

    def summary(self) -> str:
        lines = [f"confirmatory MDS, dimensions {', '.join(self.names)}: stress-1 {self.stress.stress1:.4f}, "
                 f"normalised raw stress {self.stress.normalized:.5f}"]
        for a in range(1, len(self.names)):
            lo, hi = self.ci[a]
            lines.append(f"  weight of {self.names[a]} / weight of {self.names[0]} = {self.group_ratio[a]:.3f} "
                         f"({100 * self.level:.0f}% bootstrap interval over subjects {lo:.3f} – {hi:.3f})")
        if self.permutation is not None:
            pt = self.permutation
            verdict = ("the hypothesis explains the data" if self.recovered else
                       "NOT clearly better than chance: the weights mean nothing")
            lines.append(f"  permutation test: stress {pt.observed:.5f} vs shuffled stimuli {np.min(pt.null):.5f} – "
                         f"{np.max(pt.null):.5f} ({len(pt.null)} shuffles), p = {pt.p_value:.3f}: {verdict}")
        return "\n".join(lines)


def _check_predictors(f: ArrayLike, n: int, names: Optional[Sequence[str]]) -> Tuple[np.ndarray, Tuple[str, ...]]:
    f = np.array(f, dtype=np.float64)
    if f.ndim == 1:
        f = f[:, None]
    if f.ndim != 2 or f.shape[0] != n:
        raise ValueError(f"predictors must be (n_stimuli={n}, p); got shape {f.shape}")
    if not np.all(np.isfinite(f)):
        raise ValueError("predictors must be finite")
    f = f - f.mean(axis=0)
    if np.any(np.sqrt(np.sum(f * f, axis=0)) <= 1e-12 * max(1.0, float(np.max(np.abs(f))))):
        raise ValueError("a predictor is constant over the stimuli: it cannot carry a dimension")
    names = tuple(names) if names is not None else tuple(f"f{a + 1}" for a in range(f.shape[1]))
    if len(names) != f.shape[1]:
        raise ValueError(f"{len(names)} names for {f.shape[1]} predictors")
    return f, names


def _fit_subject(d: np.ndarray, w: np.ndarray, f: np.ndarray, metric: bool, ties: str, max_iter: int,
                 eps: float) -> Tuple[np.ndarray, np.ndarray, int, bool]:
    n = d.shape[0]
    off = ~np.eye(n, dtype=bool)
    complete = bool(np.all(w[off] == 1.0))
    vplus = None if complete else _vplus(w)
    vm = None if complete else _vmat(w)
    fn = None if metric else _Disparities(d, w, ties)
    target = d if metric else fn.initial()
    d0 = distances(f)
    v = np.full(f.shape[1], np.sqrt(np.sum(w * target**2) / max(np.sum(w * d0**2), 1e-300)))
    fvf = np.sum(f * f, axis=0) * n if complete else np.einsum("ia,ij,ja->a", f, vm, f)
    old = None
    converged = False
    it = 0
    for it in range(1, max_iter + 1):
        x = f * v
        dist = distances(x)
        disp = d if metric else (target if it == 1 else fn(dist))
        s = stress_of(disp, dist, w).normalized
        if _converged(old, s, eps):
            converged = True
            break
        old = s
        xbar = _guttman(x, dist, disp, w, vplus)
        num = n * np.sum(f * xbar, axis=0) if complete else np.einsum("ia,ij,ja->a", f, vm, xbar)
        v = np.abs(num / fvf)
    dist = distances(f * v)
    if not metric:
        disp = fn(dist)
    return v, disp, it, converged


def confirmatory_mds(delta: ArrayLike, predictors: ArrayLike, *, names: Optional[Sequence[str]] = None,
                     weights: Optional[ArrayLike] = None, metric: bool = False, ties: str = "primary",
                     n_boot: int = 2000, level: float = 0.95, seed: int = 0, max_iter: int = 1000,
                     eps: float = 1e-8, n_perm: int = 0) -> ConfirmatoryResult:
    """Fits X_k = F diag(v_k) to K proximity matrices (K, n, n) with F = ``predictors`` (n, p).

    Returns the subject weights, the group weight ratios with a bootstrap interval over subjects
    (``n_boot`` resamples, ``seed``; with one subject the interval is that subject's ratio), and
    the stress, so competing hypotheses can be compared.
    ``n_perm`` > 0 also runs :func:`permutation_test` (see :attr:`ConfirmatoryResult.recovered`).
    """
    p = check_proximities(delta, weights)
    f, names = _check_predictors(predictors, p.n_stimuli, names)
    if not (0.0 < level < 1.0) or n_boot < 1:
        raise ValueError("level must be in (0, 1) and n_boot ≥ 1")
    k = p.n_subjects
    vs, disps, iters, conv = [], [], [], []
    for s in range(k):
        v, disp, it, c = _fit_subject(p.delta[s], p.weights[s], f, metric, ties, max_iter, eps)
        vs.append(v)
        disps.append(disp)
        iters.append(it)
        conv.append(c)
    v = np.array(vs)
    disp = np.array(disps)
    configs = f[None] * v[:, None, :]
    dist = distances(configs)
    tiny = 1e-300
    ratios = np.maximum(v, tiny) / np.maximum(v[:, :1], tiny)
    logr = np.log(ratios)
    group = np.exp(logr.mean(axis=0))
    rng = np.random.default_rng(seed)
    idx = rng.integers(0, k, size=(n_boot, k))
    boot = np.exp(logr[idx].mean(axis=1))
    a = (1.0 - level) / 2.0
    ci = np.quantile(boot, [a, 1.0 - a], axis=0).T
    return ConfirmatoryResult(names=names, predictors=f, subject_weights=v, ratios=ratios, group_ratio=group, ci=ci,
                              level=level, stress=stress_of(disp, dist, p.weights),
                              subject_stress=tuple(stress_of(disp[s], dist[s], p.weights[s]) for s in range(k)),
                              configs=configs, disparities=disp, n_iter=max(iters), converged=all(conv),
                              permutation=None if n_perm <= 0 else permutation_test(
                                  p.delta, f, n_perm=n_perm, seed=seed, weights=p.weights, metric=metric, ties=ties))


@dataclass(frozen=True)
class PermutationTest:
    """``p_value`` = (1 + #null stresses ≤ observed) / (1 + n_perm): the chance that functions
    attached to randomly relabelled stimuli fit as well as the hypothesis."""

    observed: float
    null: np.ndarray
    p_value: float


def permutation_test(delta: ArrayLike, predictors: ArrayLike, *, n_perm: int = 39, seed: int = 0,
                     weights: Optional[ArrayLike] = None, metric: bool = False, ties: str = "primary",
                     max_iter: int = 300, eps: float = 1e-6) -> PermutationTest:
    """Does the hypothesis explain the proximities better than chance? Refits with the rows of
    ``predictors`` permuted (the same permutation for every column and subject) ``n_perm``
    times and compares normalised raw stress."""
    p = check_proximities(delta, weights)
    f, _ = _check_predictors(predictors, p.n_stimuli, None)
    kw = dict(weights=p.weights, metric=metric, ties=ties, n_boot=1, max_iter=max_iter, eps=eps)
    obs = confirmatory_mds(p.delta, f, **kw).stress.normalized
    rng = np.random.default_rng(seed)
    null = np.array([confirmatory_mds(p.delta, f[rng.permutation(p.n_stimuli)], **kw).stress.normalized
                     for _ in range(n_perm)])
    return PermutationTest(observed=obs, null=null, p_value=float((1 + np.sum(null <= obs)) / (1 + n_perm)))


def compare_hypotheses(delta: ArrayLike, hypotheses: Mapping[str, ArrayLike], **kwargs
                       ) -> List[Tuple[str, ConfirmatoryResult]]:
    """Fits every hypothesis (name → predictors (n, p)) and returns (name, fit) sorted by
    normalised raw stress, best first. Keywords go to :func:`confirmatory_mds`."""
    if not hypotheses:
        raise ValueError("no hypotheses given")
    fits = [(name, confirmatory_mds(delta, f, **kwargs)) for name, f in hypotheses.items()]
    return sorted(fits, key=lambda t: t[1].stress.normalized)
