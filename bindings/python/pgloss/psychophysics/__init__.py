# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss.psychophysics — the paper's analysis (§3) as a library: the method that produced the
model, so it can be rerun on new materials and viewing conditions (§6).

* :mod:`.mds` — classical (Torgerson) scaling; SMACOF, metric and non-metric (isotonic
  regression, primary / secondary ties); the weighted Euclidean individual-differences model
  the paper ran in PROXSCAL; stress curves and the choice of dimensionality (Figs. 3, 5).
* :mod:`.stress` — raw stress (eq. 1), normalised raw stress and Kruskal's stress-1.
* :mod:`.procrustes` — Procrustes alignment, property fitting, axis correlations.
* :mod:`.confirmatory` — confirmatory MDS: coordinates fixed to functions of the stimulus
  parameters (c, d of eqs. 3–4 or any), fitted dimension weights (eq. 5's 1.78) with a
  bootstrap interval over subjects, permutation test, comparison of hypotheses.
* :mod:`.magnitude` — magnitude estimation: regressions on hypothesis functions, r²,
  residuals, comparison (Figs. 7, 8).
* :mod:`.proximity` — validation of proximity matrices (missing cells = weight 0), CSV I/O.
* :mod:`.cities` — Table 1 and the cities' true positions (Fig. 2);
  :mod:`.synthetic` — simulated observers with a planted truth; :mod:`.figures` — the plots.

Needs numpy and scipy (``pip install 'pgloss[psychophysics]'``); scipy is imported only when a
fit runs, so ``import pgloss`` never needs it. Figures need matplotlib.
Command line: ``python -m pgloss mds --help``.
"""

from __future__ import annotations

from .confirmatory import ConfirmatoryResult, PermutationTest, compare_hypotheses, confirmatory_mds, permutation_test
from .magnitude import HypothesisComparison, LinearFit, fit_hypothesis
from .magnitude import compare_hypotheses as compare_magnitude_hypotheses
from .mds import (Dimensionality, MDSResult, StressCurve, WeightedEuclideanResult, choose_dimensionality, smacof,
                  stress_curve, torgerson, weighted_euclidean_mds)
from .procrustes import ProcrustesResult, PropertyFit, axis_r2, procrustes, property_fit
from .proximity import Proximities, ProximityError, check_proximities, read_csv, write_csv
from .stress import Stress, distances, raw_stress, stress_of

__all__ = [
    "ConfirmatoryResult", "PermutationTest", "compare_hypotheses", "confirmatory_mds", "permutation_test",
    "HypothesisComparison", "LinearFit", "fit_hypothesis", "compare_magnitude_hypotheses",
    "Dimensionality", "MDSResult", "StressCurve", "WeightedEuclideanResult", "choose_dimensionality", "smacof",
    "stress_curve", "torgerson", "weighted_euclidean_mds",
    "ProcrustesResult", "PropertyFit", "axis_r2", "procrustes", "property_fit",
    "Proximities", "ProximityError", "check_proximities", "read_csv", "write_csv",
    "Stress", "distances", "raw_stress", "stress_of",
]
