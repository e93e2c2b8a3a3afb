# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Why the browser tests use a 4 × 3 grid: how often the toolkit's elbow rule picks 2 dimensions
for three simulated observers like the tests' (eq. 5 distance × 500 + Gaussian noise, rounded);
and how closely the 2-D configuration (the average subject's space, as `pgloss mds` writes it)
recovers the planted (c, 1.78 d): Procrustes r² and Spearman's ρ of the 66 distances (recovery.py),
with the same scores for the planted points with their labels shuffled (what no structure gives).

    .venv-py/bin/python tests/experiment/elbow_simulation.py 0.04,0.08,0.12 3 10      # 3 × 3: 8 / 10
    .venv-py/bin/python tests/experiment/elbow_simulation.py 0.03,0.06,0.09,0.12 3 30 # 4 × 3: 30 / 30

Arguments: the c levels (d is 0.90, 0.93, 0.96), the noise σ, the number of runs. Prints how many
runs chose 2 dimensions and each run's relative stress drop at 3-D (the rule needs the 2-D drop
to be at least twice it), then the range of the recovery scores and of their shuffled nulls.
"""
import itertools
import sys

import numpy as np

from pgloss.psychophysics.mds import choose_dimensionality, stress_curve
from recovery import distances, procrustes_r2, spearman

cs = [float(x) for x in sys.argv[1].split(",")]
noise, reps = float(sys.argv[2]), int(sys.argv[3])
pts = np.array(list(itertools.product(cs, (0.90, 0.93, 0.96))))
n = len(pts)
planted = pts * [1.0, 1.78]
ok, drops, r2, rho, null_r2, null_rho = 0, [], [], [], [], []
for r in range(reps):
    rng = np.random.default_rng(100 + r)
    delta = np.zeros((3, n, n))
    for k in range(3):
        for i, j in itertools.combinations(range(n), 2):
            v = 500 * np.hypot(pts[i, 0] - pts[j, 0], 1.78 * (pts[i, 1] - pts[j, 1]))
            delta[k, i, j] = delta[k, j, i] = np.clip(round(v + rng.normal(0, noise)), 0, 100)
    curve = stress_curve(delta, range(1, 4), model="weighted_euclidean", metric=False, ties="primary", n_random=4,
                         seed=0, max_iter=1000, eps=1e-8)
    choice = choose_dimensionality(curve)
    drops.append(round(choice.gains[1], 2))
    ok += choice.ndim == 2
    fit = curve.fit(2)
    x = fit.common * np.sqrt(np.mean(fit.subject_weights**2, axis=0))
    r2.append(procrustes_r2(x, planted))
    rho.append(spearman(distances(x), np.round(distances(planted), 12)))
    shuffled = planted[rng.permutation(n)]
    null_r2.append(procrustes_r2(x, shuffled))
    null_rho.append(spearman(distances(x), np.round(distances(shuffled), 12)))
print(f"{n} stimuli, noise {noise:g}: 2 dimensions chosen in {ok} of {reps} runs; 3-D drops {drops}")
print(f"2-D vs planted: Procrustes r² {min(r2):.4f}–{max(r2):.4f}, Spearman ρ {min(rho):.4f}–{max(rho):.4f}; "
      f"labels shuffled: r² {min(null_r2):.3f}–{max(null_r2):.3f}, ρ {min(null_rho):.3f}–{max(null_rho):.3f}")
