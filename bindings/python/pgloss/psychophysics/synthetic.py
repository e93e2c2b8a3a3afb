# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Synthetic observers: the paper's experiments replayed on a known truth.

The truth is the paper's own model, computed by pgloss: stimulus i has contrast gloss c_i
(eq. 4) and DOI gloss d_i = 1 − α_i (eq. 3) from :func:`pgloss.gloss_from_physical`, and the
perceived difference is eq. 5's distance with the dimension weight ``ratio`` (1.78).

:func:`simulate_experiment1` — K subjects rate every pair of Experiment 1's 27 stimuli on the
0–100 slider. Subject k sees D_ijk = √((s_kc Δc)² + (ratio · s_kd Δd)²) with its own dimension
weights s_k (log-normal, spread ``weight_spread``; the logs are centred over subjects so that the
geometric mean of s_kd / s_kc is exactly 1 and the planted group ratio is exactly ``ratio``),
adds Gaussian noise (sd ``noise`` × the subject's mean distance), and answers through its own
monotone response function 100·(D/D_max)^γ_k (γ_k uniform in [0.6, 1.5]), rounded to the slider's
integer readout (which makes ties). :func:`simulate_noise` is the same experiment without any
structure: independent uniform ratings. :func:`simulate_magnitude` rates single stimuli linearly in
a hypothesis value plus noise, per subject and repeat (Experiment 2).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Tuple

import numpy as np

#: Experiment 1's stimulus levels (§3.2.3.1).
RHO_D = (0.03, 0.193, 0.767)
RHO_S = (0.033, 0.066, 0.099)
ALPHA = (0.04, 0.07, 0.10)
#: Experiment 2's contrast-gloss study (§3.3.3.1; α fixed at 0.04) and DOI study levels.
CONTRAST_RHO_D = (0.03, 0.087, 0.193, 0.420, 0.767)
CONTRAST_RHO_S = (0.017, 0.033, 0.050, 0.066, 0.083, 0.099)
DOI_ALPHA = tuple(np.round(np.linspace(0.01, 0.19, 11), 3))


def experiment1_stimuli() -> Dict[str, np.ndarray]:
    """The 27 stimuli of Fig. 4 (ρd slowest, α fastest): arrays rho_d, rho_s, alpha, L, c, d."""
    import pgloss

    rd, rs, al = (a.ravel() for a in np.meshgrid(RHO_D, RHO_S, ALPHA, indexing="ij"))
    L, c, d = pgloss.gloss_from_physical(rd, rs, al)
    return {"rho_d": rd, "rho_s": rs, "alpha": al, "L": np.asarray(L), "c": np.asarray(c), "d": np.asarray(d)}


@dataclass(frozen=True)
class SyntheticObservers:
    """Ratings (K, n, n) and the planted truth: subject weights (K, 2) for (c, d), the group ratio,
    the response exponents γ_k and the noise level."""

    ratings: np.ndarray
    subject_weights: np.ndarray
    ratio: float
    gamma: np.ndarray
    noise: float


def simulate_experiment1(c, d, *, n_subjects: int = 9, ratio: float = 1.78, weight_spread: float = 0.2,
                         noise: float = 0.08, seed: int = 0) -> SyntheticObservers:
    """K subjects' 0–100 pair ratings of stimuli at (c, d) (see the module docstring)."""
    rng = np.random.default_rng(seed)
    c = np.asarray(c, dtype=np.float64).ravel()
    d = np.asarray(d, dtype=np.float64).ravel()
    n = c.size
    logs = rng.normal(0.0, weight_spread, size=(n_subjects, 2))
    s = np.exp(logs - logs.mean(axis=0))
    gamma = rng.uniform(0.6, 1.5, size=n_subjects)
    iu = np.triu_indices(n, 1)
    out = np.zeros((n_subjects, n, n))
    for k in range(n_subjects):
        dc = (c[:, None] - c[None]) * s[k, 0]
        dd = (d[:, None] - d[None]) * s[k, 1] * ratio
        dist = np.sqrt(dc * dc + dd * dd)[iu]
        noisy = np.maximum(dist + noise * dist.mean() * rng.standard_normal(dist.size), 0.0)
        r = np.round(100.0 * (noisy / noisy.max()) ** gamma[k])
        out[k][iu] = r
        out[k] = out[k] + out[k].T
    return SyntheticObservers(ratings=out, subject_weights=s, ratio=float(ratio), gamma=gamma, noise=float(noise))


def simulate_noise(n_stimuli: int = 27, *, n_subjects: int = 9, seed: int = 0) -> np.ndarray:
    """K matrices of independent uniform integer ratings 0–100: no structure at all."""
    rng = np.random.default_rng(seed)
    iu = np.triu_indices(n_stimuli, 1)
    out = np.zeros((n_subjects, n_stimuli, n_stimuli))
    for k in range(n_subjects):
        out[k][iu] = rng.integers(0, 101, size=iu[0].size)
        out[k] = out[k] + out[k].T
    return out


def contrast_study() -> Dict[str, np.ndarray]:
    """Experiment 2's contrast-gloss stimuli (every ρd × ρs level of §3.3.3.1 — 30, where the
    paper reports 24 images — at α = 0.04) with eq. 4's c and two decoys: the paper's first,
    rejected hypothesis, the luminance ratio (ρs + ρd/2)/(ρd/2) of the reflected white and black
    patches, and the specular energy ρs alone.

    The paper's second hypothesis, the CIELAB lightness difference of the two patches, is no
    decoy here: L* grows as the cube root of luminance, so without blur it *is* 116·c (eq. 4);
    the paper told them apart only through the image-plane contrast lost to blur at large α,
    which this model-level simulation does not render."""
    import pgloss

    rd, rs = (a.ravel() for a in np.meshgrid(CONTRAST_RHO_D, CONTRAST_RHO_S, indexing="ij"))
    c = np.asarray(pgloss.contrast_gloss(rd, rs))
    ratio = (rs + rd / 2) / (rd / 2)
    return {"rho_d": rd, "rho_s": rs, "c (eq. 4)": c, "luminance ratio": ratio, "specular energy ρs": rs.copy()}


def doi_study() -> Dict[str, np.ndarray]:
    """Experiment 2's DOI stimuli (α in 11 levels 0.01–0.19, ρd 0.03, ρs 0.099) with the
    hypothesis d = 1 − α (eq. 3) and two monotone decoys, −log α and 1/α."""
    al = np.array(DOI_ALPHA)
    return {"alpha": al, "d = 1 − α (eq. 3)": 1.0 - al, "−log α": -np.log(al), "1/α": 1.0 / al}


def simulate_magnitude(values, *, n_subjects: int = 9, repeats: int = 3, noise: float = 4.0,
                       seed: int = 0) -> np.ndarray:
    """Magnitude estimates (n_subjects·repeats, n): each subject maps the hypothesis value linearly
    onto its own part of the 0–100 scale, plus Gaussian noise of sd ``noise`` rating points."""
    rng = np.random.default_rng(seed)
    v = np.asarray(values, dtype=np.float64).ravel()
    u = (v - v.min()) / np.ptp(v)
    rows = []
    for _ in range(n_subjects):
        lo, span = rng.uniform(5, 20), rng.uniform(60, 80)
        for _ in range(repeats):
            rows.append(np.clip(lo + span * u + noise * rng.standard_normal(v.size), 0, 100))
    return np.array(rows)
