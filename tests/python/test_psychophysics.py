# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss.psychophysics against independent truth: the paper's Table 1 and the cities' public
coordinates (Fig. 2), scikit-learn's SMACOF (the peer), synthetic observers with a planted truth
(the paper's Experiment 1 and 2 analysis replayed), a pure-noise control, and bad input.

Seeded throughout: every number here is deterministic.
"""

from __future__ import annotations

import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import pgloss
from pgloss import psychophysics as pp
from pgloss.psychophysics import cities, confirmatory, magnitude, synthetic
from pgloss.psychophysics.mds import stress_curve
from pgloss.psychophysics.stress import distances

sklearn_manifold = pytest.importorskip("sklearn.manifold", reason="scikit-learn is the peer of the SMACOF tests")

# --------------------------------------------------------------------------------------------
# Table 1 → Fig. 2 and Fig. 3
# --------------------------------------------------------------------------------------------


def test_table1_is_great_circle_mileage() -> None:
    """Two independent sources agree: the paper's Table 1 and the haversine distances of the
    cities' public coordinates (within 1 %: Table 1 rounds to miles and its city points are not
    exactly the city-centre coordinates)."""
    d, names = cities.table1()
    ll, names2 = cities.latlon()
    assert names == names2 and d.shape == (10, 10)
    iu = np.triu_indices(10, 1)
    assert np.allclose(d, d.T) and d[0, 1] == 587 and d[6, 9] == 205  # Atlanta–Chicago, NYC–DC as printed
    rel = np.abs(cities.great_circle(ll)[iu] / d[iu] - 1)
    assert rel.max() < 0.01


def test_table1_fig2_map() -> None:
    """The 2-D metric solution of Table 1 has stress near 0 and, after Procrustes, lies on the
    cities' true positions.

    Tolerance: Table 1 holds distances on a sphere, which no plane reproduces; the reference map
    (azimuthal equidistant projection about the cities' mean) itself misstates Table 1's
    distances by up to ``proj_err`` miles (≈ 17 mi, 2.3 %). The MDS map may differ from the
    reference by no more than that anywhere, and by at most 1 % of the map's radius in RMS; its
    scale (both are in miles) must be within 1 % of 1.
    """
    d, names = cities.table1()
    truth = cities.azimuthal_equidistant(cities.latlon()[0])
    iu = np.triu_indices(10, 1)
    proj_err = float(np.max(np.abs(distances(truth)[iu] - d[iu])))
    assert 5.0 < proj_err < 30.0
    fit = pp.smacof(d, 2)
    assert fit.converged and fit.stress.stress1 < 0.01
    al = pp.procrustes(fit.config, truth)
    radius = float(np.sqrt(np.mean(np.sum((truth - truth.mean(0)) ** 2, axis=1))))
    worst = float(np.max(np.linalg.norm(al.aligned - truth, axis=1)))
    print(f"\nFig. 2: stress-1 {fit.stress.stress1:.5f}, Procrustes RMS {al.rms:.2f} mi, worst {worst:.2f} mi "
          f"(reference map's own distance error up to {proj_err:.1f} mi), scale {al.scale:.5f}")
    assert worst <= proj_err
    assert al.rms <= 0.01 * radius
    assert abs(al.scale - 1.0) < 0.01
    assert al.r2 > 0.9999


def test_table1_stress_curve_fig3() -> None:
    d, _ = cities.table1()
    curve = stress_curve(d, range(1, 6), n_random=2)
    s = curve.values("stress1")
    assert s[0] > 0.1 and s[1] < 0.01 and s[0] / s[1] > 50  # the sharp drop at 2 of Fig. 3
    assert np.all(s[2:] <= s[1] * 1.01)  # flat after it
    choice = pp.choose_dimensionality(curve)
    assert choice.ndim == 2, choice.reasoning
    assert "elbow is at 2" in choice.reasoning


def test_cli_mds_cities(tmp_path: Path) -> None:
    """`python -m pgloss mds --example cities` reproduces Fig. 2 and the stress curve (Fig. 3)."""
    out = tmp_path / "mds"
    proc = subprocess.run([sys.executable, "-m", "pgloss", "mds", "--example", "cities", "--starts", "0",
                           "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "the elbow is at 2 dimensions" in proc.stdout
    for name in ("fig02_us_cities.png", "stress_curve.png", "fig02_us_cities.svg"):
        data = (out / name).read_bytes()
        assert len(data) > 10_000
    assert (out / "fig02_us_cities.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    curve = np.genfromtxt(out / "stress_curve.csv", delimiter=",", names=True)
    assert list(curve["dims"]) == [1, 2, 3, 4, 5] and curve["stress1"][1] < 0.01
    x = np.genfromtxt(out / "configuration.csv", delimiter=",", skip_header=1)[:, 1:]
    assert x.shape == (10, 2)


def test_cli_mds_csv_files(tmp_path: Path) -> None:
    """Per-subject CSV files, one with a missing cell (empty), through the weighted model."""
    rng = np.random.default_rng(3)
    z = rng.standard_normal((8, 2))
    names = [f"x{i}" for i in range(8)]
    files = []
    for k in range(3):
        dk = distances(z * np.array([1.0, 0.5 + 0.4 * k]))
        path = tmp_path / f"s{k}.csv"
        pp.write_csv(path, dk, names)
        files.append(str(path))
    text = Path(files[1]).read_text().splitlines()
    cells = text[2].split(",")
    cells[4] = ""  # one missing cell
    text[2] = ",".join(cells)
    Path(files[1]).write_text("\n".join(text) + "\n")
    out = tmp_path / "out"
    proc = subprocess.run([sys.executable, "-m", "pgloss", "mds", *files, "--level", "ratio", "--max-dims", "3",
                           "--starts", "1", "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "weighted_euclidean (metric), 3 subject(s), 8 stimuli" in proc.stdout
    bad = tmp_path / "bad.csv"
    bad.write_text(",a,b,c\na,0,1,2\nb,1,0,x\nc,2,3,0\n")
    proc = subprocess.run([sys.executable, "-m", "pgloss", "mds", str(bad), "--out", str(out)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode != 0 and "'x' is not a number" in proc.stderr


def test_cli_mds_subject_files_with_stimuli(tmp_path: Path) -> None:
    """The researcher's path: subjects' CSV files plus a stimulus table → weighted Euclidean
    non-metric fit, confirmatory MDS on pgloss's c, d, and Fig. 6 (five subjects, for time)."""
    stim = synthetic.experiment1_stimuli()
    obs = synthetic.simulate_experiment1(stim["c"], stim["d"], n_subjects=5, seed=2)
    names = [f"p{i:02d}" for i in range(27)]
    files = []
    for k, m in enumerate(obs.ratings):
        path = tmp_path / f"subject{k + 1}.csv"
        pp.write_csv(path, m, names)
        files.append(str(path))
    table = ["name,rho_d,rho_s,alpha"] + [f"{n},{a},{b},{c}" for n, a, b, c in
                                         zip(names, stim["rho_d"], stim["rho_s"], stim["alpha"])]
    (tmp_path / "stimuli.csv").write_text("\n".join(table) + "\n")
    out = tmp_path / "exp1"
    proc = subprocess.run([sys.executable, "-m", "pgloss", "mds", *files, "--stimuli", str(tmp_path / "stimuli.csv"),
                           "--max-dims", "3", "--starts", "0", "--out", str(out)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "non-metric, primary ties), 5 subject(s), 27 stimuli" in proc.stdout
    assert "the elbow is at 2 dimensions" in proc.stdout
    assert "the hypothesis explains the data" in proc.stdout
    assert (out / "fig06_configuration.png").stat().st_size > 10_000


def test_scipy_is_needed_only_by_the_fits_that_use_it() -> None:
    """scipy is imported lazily: without it `import pgloss` and metric SMACOF work, and a
    non-metric fit says what to install."""
    code = (
        "import sys; sys.modules['scipy'] = None\n"
        "import pgloss\n"
        "from pgloss import psychophysics as pp\n"
        "from pgloss.psychophysics import cities\n"
        "d = cities.table1()[0]\n"
        "assert pp.smacof(d, 2, n_random=0).stress.stress1 < 0.01\n"
        "try:\n"
        "    pp.smacof(d, 2, metric=False, n_random=0)\n"
        "except ImportError as e:\n"
        "    print(e)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "pip install 'pgloss[psychophysics]'" in proc.stdout


def test_cli_dispatcher() -> None:
    from pgloss import __main__ as cli

    names = [c.name for c in cli.COMMANDS]
    assert names.index("mds") == names.index("figures") + 1  # after the C tool's commands (test_cli.py)
    with pytest.raises(SystemExit) as e:
        cli.main(["mds", "--help"])
    assert e.value.code == 0
    with pytest.raises(SystemExit) as e:
        cli.main(["mds"])  # neither CSV nor --example
    assert "give either CSV files or --example" in str(e.value.code)


# --------------------------------------------------------------------------------------------
# The peer: scikit-learn's SMACOF (sklearn.manifold.MDS)
# --------------------------------------------------------------------------------------------
#
# scikit-learn 1.9 (pinned in scripts/test-python.sh): `stress_` is raw stress Σ_{i<j}(d̂ − d)²
# with normalized_stress=False and Kruskal's stress-1 √(raw / Σ_{i<j} d²) with True — pgloss's
# Stress.raw and Stress.stress1. Non-metric: its disparities are normalised to Σ d̂² = n(n−1)/2,
# as pgloss's, and its isotonic regression averages tied proximities (the secondary approach);
# its stress is that of the last update against the previous disparities, equal to pgloss's at
# convergence. Both run from the same start to convergence (eps 1e-15).


def _sklearn(delta, init, metric: bool, normalized: bool):
    mds = sklearn_manifold.MDS(n_components=init.shape[1], metric_mds=metric, metric="precomputed", n_init=1,
                               init="random", max_iter=100_000, eps=1e-15, normalized_stress=normalized)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FutureWarning)
        mds.fit(delta, init=init.copy())
    return mds


def _noisy(n: int, seed: int, decimals=None) -> np.ndarray:
    rng = np.random.default_rng(seed)
    x = rng.standard_normal((n, 3))
    d = np.exp(distances(x) / 2) * np.exp(0.2 * rng.standard_normal((n, n)))
    d = np.triu(d, 1)
    d = d + d.T
    return np.round(d, decimals) if decimals is not None else d


@pytest.mark.parametrize("case", ["table1-metric", "noisy-metric", "noisy-nonmetric", "tied-nonmetric"])
def test_smacof_matches_sklearn(case: str) -> None:
    metric = case.endswith("-metric")
    if case.startswith("table1"):
        delta = cities.table1()[0]
    else:
        delta = _noisy(15, 7, decimals=0 if case.startswith("tied") else None)
    n = delta.shape[0]
    if case.startswith("tied"):
        assert len(np.unique(delta[np.triu_indices(n, 1)])) < n * (n - 1) / 2  # there are ties
    init = np.random.default_rng(1).standard_normal((n, 2)) * float(np.mean(delta))
    ours = pp.smacof(delta, 2, metric=metric, ties="secondary", init=init, max_iter=100_000, eps=1e-15)
    for normalized, mine in ((False, ours.stress.raw), (True, ours.stress.stress1)):
        peer = _sklearn(delta, init, metric, normalized)
        print(f"\n{case}: sklearn stress_ (normalized_stress={normalized}) {peer.stress_:.12g}, pgloss "
              f"{mine:.12g}, relative difference {abs(mine - peer.stress_) / peer.stress_:.2e}")
        assert mine == pytest.approx(peer.stress_, rel=1e-6)
        al = pp.procrustes(ours.config, peer.embedding_)  # the same solution, not just the same stress
        assert al.rms < 1e-4 * np.sqrt(np.mean(ours.config**2))


def test_torgerson_exact_for_euclidean() -> None:
    x = np.random.default_rng(5).standard_normal((12, 3))
    y = pp.torgerson(distances(x), 3)
    assert pp.procrustes(y, x, scaling=False).rms < 1e-10


def test_nonmetric_ties_primary_not_worse_than_secondary() -> None:
    """The primary approach is the secondary one with fewer constraints: from the same start its
    optimal stress can only be lower or equal."""
    delta = _noisy(12, 11, decimals=0)
    init = np.random.default_rng(2).standard_normal((12, 2))
    prim = pp.smacof(delta, 2, metric=False, ties="primary", init=init)
    sec = pp.smacof(delta, 2, metric=False, ties="secondary", init=init)
    assert prim.stress.stress1 <= sec.stress.stress1 + 1e-9
    # secondary: tied proximities have equal disparities
    iu = np.triu_indices(12, 1)
    dl, dh = delta[iu], sec.disparities[iu]
    for v in np.unique(dl):
        assert np.ptp(dh[dl == v]) < 1e-12


@pytest.mark.parametrize("ties", ["primary", "secondary"])
def test_disparities_are_monotone_least_squares(ties: str) -> None:
    """The non-metric disparities of all subjects at once (one shifted PAVA run) equal the
    per-subject ones, are monotone in the proximities (equal for ties under 'secondary') and
    keep the normalisation Σ d̂² = n(n−1)/2."""
    from pgloss.psychophysics.mds import _BatchDisparities, _Disparities

    rng = np.random.default_rng(8)
    delta = np.stack([_noisy(9, s, decimals=0) for s in range(4)])
    dist = distances(rng.standard_normal((4, 9, 2)))
    batch = _BatchDisparities(delta, np.ones_like(delta), ties)(dist)
    iu = np.triu_indices(9, 1)
    for k in range(4):
        single = _Disparities(delta[k], np.ones((9, 9)), ties)(dist[k])
        np.testing.assert_allclose(batch[k], single, atol=1e-12)
        dl, dh = delta[k][iu], batch[k][iu]
        o = np.lexsort((dh, dl))
        assert np.all(np.diff(dh[o]) >= -1e-12)
        assert np.sum(dh**2) == pytest.approx(36.0)
        if ties == "secondary":
            for v in np.unique(dl):
                assert np.ptp(dh[dl == v]) < 1e-12


def test_missing_cells_weight_zero() -> None:
    """Table 1 with four pairs missing (weight 0, value NaN) still gives the map."""
    d, _ = cities.table1()
    w = np.ones_like(d)
    d = d.copy()
    for i, j in ((0, 1), (2, 7), (4, 8), (6, 9)):
        w[i, j] = w[j, i] = 0.0
        d[i, j] = d[j, i] = np.nan
    truth = cities.azimuthal_equidistant(cities.latlon()[0])
    fit = pp.smacof(d, 2, weights=w)
    assert fit.stress.stress1 < 0.01
    assert pp.procrustes(fit.config, truth).rms < 15.0
    # and the weighted Euclidean model with a missing cell in one subject only
    stack = np.stack([cities.table1()[0]] * 3)
    ws = np.ones_like(stack)
    ws[1, 0, 1] = ws[1, 1, 0] = 0.0
    res = pp.weighted_euclidean_mds(stack, 2, weights=ws, metric=True, n_random=0)
    assert res.stress.stress1 < 0.01


def test_weighted_euclidean_metric_recovers_exact_weights() -> None:
    """Exact distances of X_k = Z W_k: the metric weighted model finds Z's axes and the weights."""
    rng = np.random.default_rng(4)
    z = rng.standard_normal((15, 2)) * np.array([1.0, 0.6])
    w = np.exp(rng.normal(0, 0.4, size=(6, 2)))
    delta = np.stack([distances(z * wk) for wk in w])
    res = pp.weighted_euclidean_mds(delta, 2, metric=True, n_random=2, max_iter=5000, eps=1e-14)
    assert res.stress.stress1 < 1e-4
    r2 = pp.axis_r2(res.common, z)
    perm = [int(np.argmax(r2[a])) for a in range(2)]
    assert sorted(perm) == [0, 1] and r2[0, perm[0]] > 0.9999 and r2[1, perm[1]] > 0.9999
    ratio_fit = res.subject_weights[:, 1] / res.subject_weights[:, 0]
    ratio_true = w[:, perm[1]] / w[:, perm[0]]
    ratio_fit = ratio_fit * (ratio_true[0] / ratio_fit[0])  # axis scales are free; ratios between subjects are not
    np.testing.assert_allclose(ratio_fit, ratio_true, rtol=1e-3)


# --------------------------------------------------------------------------------------------
# Synthetic observers: the paper's analysis replayed on a known truth
# --------------------------------------------------------------------------------------------

PLANTED = pgloss.D_WEIGHT  # 1.78, eq. 5
CURVE_KW = dict(n_random=0, max_iter=300, eps=1e-7, seed=0)  # Torgerson + the previous dimensionality's solution


@pytest.fixture(scope="module")
def stimuli():
    s = synthetic.experiment1_stimuli()
    # c, d are pgloss's own (eqs. 3, 4) — the model is the input of this simulation
    np.testing.assert_allclose(s["d"], 1 - s["alpha"])
    return s


@pytest.fixture(scope="module")
def observers(stimuli):
    return synthetic.simulate_experiment1(stimuli["c"], stimuli["d"], n_subjects=9, ratio=PLANTED, seed=0)


@pytest.fixture(scope="module")
def observers_curve(observers):
    return stress_curve(observers.ratings, range(1, 6), **CURVE_KW)


def test_synthetic_planted_truth(observers) -> None:
    r = observers.ratings
    assert r.shape == (9, 27, 27) and np.all(r == np.swapaxes(r, 1, 2)) and r.min() >= 0 and r.max() <= 100
    s = observers.subject_weights
    assert np.exp(np.mean(np.log(s[:, 1] / s[:, 0]))) == pytest.approx(1.0, rel=1e-12)  # group ratio = PLANTED


def test_synthetic_picks_two_dimensions(observers_curve) -> None:
    choice = pp.choose_dimensionality(observers_curve)
    print("\nsynthetic observers:", choice.reasoning)
    assert choice.ndim == 2, choice.reasoning


def test_synthetic_axes_are_c_and_d(observers_curve, stimuli) -> None:
    """The weighted model's axes are identified by the subject weights: one is c, the other d."""
    fit = observers_curve.fit(2)
    r2 = pp.axis_r2(fit.common, np.column_stack([stimuli["c"], stimuli["d"]]))
    print(f"\naxis r² (rows: axes; columns: c, d):\n{np.round(r2, 4)}")
    best = max(r2[0, 0] + r2[1, 1], r2[0, 1] + r2[1, 0])
    pairing = (r2[0, 0], r2[1, 1]) if r2[0, 0] + r2[1, 1] == best else (r2[0, 1], r2[1, 0])
    assert min(pairing) >= 0.9
    for prop in ("c", "d"):
        assert pp.property_fit(fit.common, stimuli[prop]).r2 >= 0.9


def test_synthetic_confirmatory_recovers_ratio(observers, stimuli) -> None:
    f = np.column_stack([stimuli["c"], stimuli["d"]])
    res = pp.confirmatory_mds(observers.ratings, f, names=("c", "d"), n_perm=39, seed=0)
    lo, hi = res.ci[1]
    planted_subject = PLANTED * observers.subject_weights[:, 1] / observers.subject_weights[:, 0]
    print(f"\nconfirmatory: planted group ratio {PLANTED:.3f}, recovered {res.weight_ratio:.3f} "
          f"(95% bootstrap over subjects {lo:.3f} – {hi:.3f}); permutation p = {res.permutation.p_value:.3f}")
    print("per subject planted  ", np.round(planted_subject, 3))
    print("per subject recovered", np.round(res.ratios[:, 1], 3))
    assert lo <= PLANTED <= hi
    assert res.recovered
    np.testing.assert_allclose(res.ratios[:, 1], planted_subject, rtol=0.1)
    assert res.stress.stress1 < 0.1


def test_synthetic_confirmatory_prefers_true_functions(observers, stimuli) -> None:
    """Confirmatory MDS ranks the true (c, d) below (in stress) two decoy functional forms."""
    rd, rs, d = stimuli["rho_d"], stimuli["rho_s"], stimuli["d"]
    ranked = confirmatory.compare_hypotheses(observers.ratings, {
        "c (eq. 4), d": np.column_stack([stimuli["c"], d]),
        "luminance ratio, d": np.column_stack([(rs + rd / 2) / (rd / 2), d]),
        "rho_s, d": np.column_stack([rs, d]),
    }, n_boot=10)
    print("\nconfirmatory hypotheses:", [(n, round(r.stress.stress1, 4)) for n, r in ranked])
    assert ranked[0][0] == "c (eq. 4), d"
    assert ranked[0][1].stress.normalized < 0.5 * ranked[1][1].stress.normalized


@pytest.mark.parametrize("study,true", [("doi", "d = 1 − α (eq. 3)"), ("contrast", "c (eq. 4)")])
def test_synthetic_magnitude_prefers_true_hypothesis(study: str, true: str) -> None:
    s = synthetic.doi_study() if study == "doi" else synthetic.contrast_study()
    hyp = {k: v for k, v in s.items() if k not in ("rho_d", "rho_s", "alpha")}
    assert len(hyp) == 3 and true in hyp
    ratings = synthetic.simulate_magnitude(s[true], noise=8.0, seed=1)
    cmp = pp.compare_magnitude_hypotheses(hyp, ratings)
    print(f"\nmagnitude estimation ({study}):\n{cmp.report()}")
    assert cmp.best.name == true
    assert cmp.best.r2 >= 0.9 and cmp.best.r2 - cmp.fits[1].r2 >= 0.05
    assert abs(cmp.best.polynomial_gain) < 0.01  # the paper's linearity check
    np.testing.assert_allclose(cmp.best.residuals, cmp.best.y - cmp.best.intercept - cmp.best.slope * cmp.best.x)


def test_magnitude_regression_is_least_squares() -> None:
    """Against numpy's polyfit (an independent least-squares solver)."""
    rng = np.random.default_rng(0)
    x = rng.uniform(0, 1, 20)
    ratings = 10 + 50 * x + rng.normal(0, 3, (4, 20))
    fit = pp.fit_hypothesis(x, ratings, "x")
    slope, icept = np.polyfit(x, ratings.mean(0), 1)
    assert fit.slope == pytest.approx(slope, rel=1e-10) and fit.intercept == pytest.approx(icept, rel=1e-10)
    y = ratings.mean(0)
    assert fit.r2 == pytest.approx(np.corrcoef(x, y)[0, 1] ** 2, rel=1e-10)


# --------------------------------------------------------------------------------------------
# Pure noise: nothing may be "recovered"
# --------------------------------------------------------------------------------------------
#
# "Recovered" means what the synthetic tests assert: an elbow in the stress curve, axes or
# directions matching c and d (r² ≥ 0.9), a confirmatory fit clearly better than shuffled
# stimuli (ConfirmatoryResult.recovered: permutation p < 0.05 and stress at most half the
# shuffles' median — a bare p < 0.05 would "recover" one noise data set in 20), a magnitude
# hypothesis with r² ≥ 0.9. On uniform random ratings none of these may happen. (A bootstrap interval alone proves nothing: on noise the fitted ratio is
# fixed by the predictors' geometry, and the interval is tight around a meaningless value.)


@pytest.fixture(scope="module")
def noise():
    return synthetic.simulate_noise(27, n_subjects=9, seed=0)


def test_noise_has_no_elbow(noise) -> None:
    curve = stress_curve(noise, range(1, 6), **CURVE_KW)
    choice = pp.choose_dimensionality(curve)
    print("\nnoise:", choice.reasoning)
    assert choice.ndim is None, choice.reasoning
    fit = curve.fit(2)
    stim = synthetic.experiment1_stimuli()
    assert np.max(pp.axis_r2(fit.common, np.column_stack([stim["c"], stim["d"]]))) < 0.5
    for prop in ("c", "d"):
        assert pp.property_fit(fit.common, stim[prop]).r2 < 0.5


def test_noise_confirmatory_not_recovered(noise) -> None:
    stim = synthetic.experiment1_stimuli()
    res = pp.confirmatory_mds(noise, np.column_stack([stim["c"], stim["d"]]), names=("c", "d"), n_perm=39, seed=0)
    print(f"\nnoise confirmatory: ratio {res.weight_ratio:.3f} ({res.ci[1][0]:.3f} – {res.ci[1][1]:.3f}), "
          f"permutation p = {res.permutation.p_value:.3f}, stress-1 {res.stress.stress1:.3f}")
    assert res.recovered is False
    assert res.permutation.observed > 0.9 * np.median(res.permutation.null)  # no better than shuffled stimuli
    assert "NOT clearly better than chance" in res.summary()
    assert res.stress.stress1 > 0.3


def test_noise_magnitude_not_recovered() -> None:
    s = synthetic.contrast_study()
    hyp = {k: v for k, v in s.items() if k not in ("rho_d", "rho_s", "alpha")}
    ratings = np.random.default_rng(0).uniform(0, 100, size=(27, s["rho_d"].size))
    cmp = pp.compare_magnitude_hypotheses(hyp, ratings)
    assert cmp.best.r2 < 0.5


# --------------------------------------------------------------------------------------------
# Bad input
# --------------------------------------------------------------------------------------------

GOOD = distances(np.random.default_rng(0).standard_normal((6, 2)))


def _with(i, j, v):
    d = GOOD.copy()
    d[i, j] = v
    return d


def _sym(i, j, v):
    d = _with(i, j, v)
    d[j, i] = v
    return d


@pytest.mark.parametrize("delta,weights,message", [
    (np.ones((4, 5)), None, "must be square"),
    (np.ones(5), None, "one (n, n) matrix or a stack"),
    (_with(0, 1, GOOD[0, 1] + 1.0), None, "not symmetric"),
    (_sym(0, 1, -1.0), None, "is negative"),
    (_sym(0, 1, np.nan), None, "is NaN; a missing cell must have weight 0"),
    (_sym(0, 1, np.inf), None, "is infinite"),
    (GOOD[:2, :2], None, "too few stimuli"),
    (GOOD, -np.ones((6, 6)), "is negative"),
    (GOOD, np.ones((5, 5)), "weights must have the proximities' shape"),
    (GOOD, np.zeros((6, 6)), "no pair present"),
    (GOOD, np.kron(np.eye(2), np.ones((3, 3))), "do not connect all stimuli"),
    ([["a", "b"], ["c", "d"]], None, "must be numbers"),
])
def test_bad_input_raises(delta, weights, message) -> None:
    with pytest.raises(pp.ProximityError, match=None) as e:
        pp.smacof(delta, 1, weights=weights)
    assert message in str(e.value)
    assert isinstance(e.value, ValueError)


def test_bad_input_other() -> None:
    with pytest.raises(pp.ProximityError, match="too few stimuli: 4 for a 3-dimensional"):
        pp.smacof(GOOD[:4, :4], 3)
    with pytest.raises(ValueError, match="ties must be"):
        pp.smacof(GOOD, 2, metric=False, ties="tertiary")
    with pytest.raises(ValueError, match="init must be"):
        pp.smacof(GOOD, 2, init=np.ones((5, 2)))
    with pytest.raises(ValueError, match="a predictor is constant"):
        pp.confirmatory_mds(GOOD, np.column_stack([np.arange(6.0), np.ones(6)]))
    with pytest.raises(ValueError, match="predictors must be"):
        pp.confirmatory_mds(GOOD, np.ones((5, 2)))
    with pytest.raises(ValueError, match="constant over the stimuli"):
        pp.fit_hypothesis(np.ones(5), np.arange(5.0))
    with pytest.raises(ValueError, match="stimulus 1 has no rating"):
        pp.fit_hypothesis(np.arange(3.0), np.array([[1.0, np.nan, 2.0]]))
    # a NaN cell *with* weight 0 is a missing cell, accepted
    d = _sym(0, 1, np.nan)
    w = np.ones((6, 6))
    w[0, 1] = w[1, 0] = 0
    assert np.isfinite(pp.smacof(d, 2, weights=w).stress.stress1)


def test_csv_round_trip_and_lower_triangle(tmp_path: Path) -> None:
    names = [f"s{i}" for i in range(6)]
    pp.write_csv(tmp_path / "full.csv", GOOD, names)
    d, w, n2 = pp.read_csv(tmp_path / "full.csv")
    assert n2 == names and np.allclose(d, GOOD, rtol=1e-9) and np.all(w[~np.eye(6, dtype=bool)] == 1)
    lower = [",".join([""] + names)] + [",".join([names[i]] + [f"{GOOD[i, j]:.12g}" for j in range(i + 1)])
                                        for i in range(6)]
    lower[3] = lower[3].replace(lower[3].split(",")[1], "NA", 1)  # one missing cell: s2–s0
    (tmp_path / "lower.csv").write_text("\n".join(lower) + "\n")
    d, w, _ = pp.read_csv(tmp_path / "lower.csv")
    assert w[2, 0] == w[0, 2] == 0 and np.isnan(d[2, 0])
    mask = w > 0
    assert np.allclose(d[mask], GOOD[mask], rtol=1e-9)
    (tmp_path / "ragged.csv").write_text(",a,b\na,0,1\n")
    with pytest.raises(pp.ProximityError, match="must be square"):
        pp.read_csv(tmp_path / "ragged.csv")


# --------------------------------------------------------------------------------------------
# Convergence, starts and the command line's bad input
# --------------------------------------------------------------------------------------------

def _near_perfect(n: int, seed: int, noise: float = 1e-4, dim: int = 2) -> np.ndarray:
    rng = np.random.default_rng(seed)
    d = distances(rng.standard_normal((n, dim))) * np.exp(noise * rng.standard_normal((n, n)))
    d = np.triu(d, 1)
    return d + d.T


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_near_perfect_fit_converges_as_far_as_sklearn(seed: int) -> None:
    """Stress 1e-4: the relative stop rule reaches scikit-learn's minimum (run to eps 1e-15 from
    the same start) within 1e-5; the absolute 1e-10 stopped 0.4–1.1 % above it after 5–8
    iterations. So does the weighted model on three such subjects against the metric fit run to
    its end."""
    delta = _near_perfect(20, seed)
    init = pp.torgerson(delta, 2)
    ours = pp.smacof(delta, 2, init=init)
    peer = _sklearn(delta, init, True, True).stress_
    print(f"\nstress-1 1e-4 (seed {seed}): pgloss {ours.stress.stress1:.8e} in {ours.n_iter} iterations, "
          f"sklearn {peer:.8e}: {ours.stress.stress1 / peer - 1:+.1e}")
    assert ours.converged and ours.stress.stress1 == pytest.approx(peer, rel=1e-5)
    stack = np.stack([_near_perfect(12, seed + 10 * k) for k in range(3)])
    fit = pp.weighted_euclidean_mds(stack, 2, metric=True, n_random=0)
    long = pp.weighted_euclidean_mds(stack, 2, metric=True, n_random=0, eps=0.0, max_iter=20000)
    assert fit.converged and fit.stress.normalized == pytest.approx(long.stress.normalized, rel=1e-4)


def _sklearn_best(delta: np.ndarray, ndim: int, metric: bool, n_init: int) -> float:
    """scikit-learn's lowest stress-1 over n_init random starts (its non-metric isotonic regression
    averages tied proximities: pgloss's secondary approach)."""
    mds = sklearn_manifold.MDS(n_components=ndim, metric_mds=metric, metric="precomputed", n_init=n_init,
                               init="random", max_iter=3000, eps=1e-9, normalized_stress=True, random_state=5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FutureWarning)
        mds.fit(delta)
    return float(mds.stress_)


@pytest.mark.parametrize("ndim,metric", [(1, True), (1, False), (2, False)])
def test_default_starts_leave_local_minima(ndim: int, metric: bool) -> None:
    """Rounded (tied) proximities of 15 points in 3-D: fits below the data's dimensionality. The
    default starts reach scikit-learn's best of 16 random starts (or lower); Torgerson plus 4
    random starts, the former default, stayed in a local minimum 4–10 % above the default's.
    How many starts ran is in start_stress."""
    delta = _noisy(15, 7, decimals=0)
    fit = pp.smacof(delta, ndim, metric=metric, ties="secondary")
    four = pp.smacof(delta, ndim, metric=metric, ties="secondary", n_random=4)
    peer = _sklearn_best(delta, ndim, metric, 16)
    print(f"\n{ndim}-D {'metric' if metric else 'non-metric'}: default {fit.stress.stress1:.4f} "
          f"({len(fit.start_stress)} starts), 5 starts {four.stress.stress1:.4f}, sklearn best of 16 {peer:.4f}")
    assert fit.stress.stress1 <= peer * (1 + 1e-3)
    assert four.stress.stress1 > fit.stress.stress1 * 1.04
    assert len(fit.start_stress) > len(four.start_stress) == 5
    assert len(fit.start_stress) == (pp.mds.MAX_STARTS_1D if ndim == 1 else len(fit.start_stress))


def _mds_cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "pgloss", "mds", *args], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


def test_cli_bad_files_are_messages_not_tracebacks(tmp_path: Path) -> None:
    """A missing CSV, a CSV that is not UTF-8, and stimulus tables with a non-numeric value, a
    missing column or a missing stimulus: one line naming the file and the reason, exit 1."""
    names = [f"s{i}" for i in range(6)]
    pp.write_csv(tmp_path / "good.csv", GOOD, names)
    (tmp_path / "latin1.csv").write_bytes(",a,b,c\na,0,1,2\nb,1,0,3\nc,2,3,0\n".replace("a", "\xe9").encode("latin-1"))
    table = "name,rho_d,rho_s,alpha\n" + "".join(f"s{i},0.193,0.0{i + 3},0.07\n" for i in range(6))
    (tmp_path / "stim_text.csv").write_text(table.replace("0.05,0.07", "high,0.07"))
    (tmp_path / "stim_nocol.csv").write_text(table.replace("alpha", "alfa"))
    (tmp_path / "stim_short.csv").write_text(table.replace("s5,", "s9,"))
    (tmp_path / "stim_nan.csv").write_text(table.replace("0.05,0.07", "nan,0.07"))
    cases = [
        ((str(tmp_path / "missing.csv"),), f"{tmp_path / 'missing.csv'}: cannot read it (No such file or directory)"),
        ((str(tmp_path / "latin1.csv"),), f"{tmp_path / 'latin1.csv'}: not UTF-8 text (byte 0xe9 at offset 1)"),
        ((str(tmp_path / "good.csv"), "--stimuli", str(tmp_path / "stim_text.csv")),
         f"{tmp_path / 'stim_text.csv'}: row 4, column rho_s: 'high' is not a finite number"),
        ((str(tmp_path / "good.csv"), "--stimuli", str(tmp_path / "stim_nan.csv")),
         f"{tmp_path / 'stim_nan.csv'}: row 4, column rho_s: 'nan' is not a finite number"),
        ((str(tmp_path / "good.csv"), "--stimuli", str(tmp_path / "stim_nocol.csv")),
         f"{tmp_path / 'stim_nocol.csv'}: no column alpha (needs columns name, rho_d, rho_s, alpha)"),
        ((str(tmp_path / "good.csv"), "--stimuli", str(tmp_path / "stim_short.csv")),
         f"{tmp_path / 'stim_short.csv'}: no row for stimulus 's5'"),
        ((str(tmp_path / "good.csv"), "--stimuli", str(tmp_path / "missing.csv")),
         f"{tmp_path / 'missing.csv'}: cannot read it (No such file or directory)"),
    ]
    for args, message in cases:
        proc = _mds_cli(*args, "--max-dims", "2", "--starts", "0", "--out", str(tmp_path / "out"), cwd=tmp_path)
        assert proc.returncode == 1 and "Traceback" not in proc.stderr, (args, proc.stderr)
        assert message in proc.stderr, (args, proc.stderr)


def test_cli_dimensions_the_stimuli_allow(tmp_path: Path) -> None:
    """6 stimuli allow 4 dimensions (n − 2): by default the curve goes to 4, and says so (the
    default 5 failed with "too few stimuli"); --ndim beyond that is a message."""
    names = [f"s{i}" for i in range(6)]
    pp.write_csv(tmp_path / "six.csv", GOOD, names)
    proc = _mds_cli(str(tmp_path / "six.csv"), "--out", str(tmp_path / "out"), cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "6 stimuli allow at most 4 dimensions (n − 2): the stress curve goes from 1 to 4, not the default 5" \
        in proc.stdout
    assert "starts per dimensionality (Torgerson, the previous solution, random): 1D 64, 2D " in proc.stdout
    curve = np.genfromtxt(tmp_path / "out/stress_curve.csv", delimiter=",", names=True)
    assert list(curve["dims"]) == [1, 2, 3, 4]
    proc = _mds_cli(str(tmp_path / "six.csv"), "--ndim", "5", "--out", str(tmp_path / "out"), cwd=tmp_path)
    assert proc.returncode == 1 and "--ndim 5: 6 stimuli allow at most 4 dimensions" in proc.stderr, proc.stderr


def test_fig6_legend_lists_this_stimulus_set(tmp_path: Path) -> None:
    """Fig. 6's legend lists the levels of the stimuli drawn (it listed Fig. 4's whatever the set),
    each symbol in the figure is one of the legend's, and Fig. 4's set keeps its names."""
    import matplotlib

    from pgloss.psychophysics import figures

    matplotlib.rcParams["svg.fonttype"] = "none"  # text as text, to read the legend back
    rd = np.repeat([0.05, 0.3], 8)
    rs = np.tile(np.repeat([0.02, 0.05, 0.08, 0.11], 2), 2)
    al = np.tile([0.05, 0.15], 8)
    x = np.random.default_rng(0).standard_normal((16, 2))
    figures.configuration_figure(x, rd, rs, al, tmp_path, c=rs, d=1 - al)
    svg = (tmp_path / "fig06_configuration.svg").read_text(encoding="utf-8")
    import re

    labels = sorted(set(re.findall(r"(?:ρd|ρs|α) = [0-9.]+", svg)))
    assert labels == sorted(["ρd = 0.05", "ρd = 0.3", "ρs = 0.02", "ρs = 0.05", "ρs = 0.08", "ρs = 0.11",
                             "α = 0.05", "α = 0.15"]), labels
    entries = figures.symbol_legend(rd, rs, al)
    assert len({e["marker"] for e in entries if e["label"].startswith("ρs")}) == 4
    fig4 = synthetic.experiment1_stimuli()
    names = [e["label"] for e in figures.symbol_legend(fig4["rho_d"], fig4["rho_s"], fig4["alpha"])]
    assert names == ["ρd = 0.03 (black)", "ρd = 0.193 (grey)", "ρd = 0.767 (white)", "ρs = 0.033", "ρs = 0.066",
                     "ρs = 0.099", "α = 0.04", "α = 0.07", "α = 0.1"]


def test_guide_experiment1_stimuli_in_one_call() -> None:
    """docs/guide/python.md's "Experiment 1's 27 stimuli (3 ρd × 3 ρs × 3 α) in one call" gives 27
    (it once gave 9: α was one value), equal to the 27 stimuli of the psychophysics module, and c,
    d by eqs. 3–4 written out here."""
    guide = (Path(__file__).resolve().parents[2] / "docs" / "guide" / "python.md").read_text(encoding="utf-8")
    start = guide.index(">>> L, c, d = pgloss.gloss_from_physical(")
    lines = []
    for line in guide[start:].splitlines():  # the doctest's call: its >>> line and ... lines
        if lines and not line.startswith("... "):
            break
        lines.append(line[4:])
    call = "\n".join(lines)
    scope = {"np": np, "pgloss": pgloss}
    exec(call, scope)  # noqa: S102 - the guide's own lines
    L, c, d = (np.asarray(scope[k]) for k in ("L", "c", "d"))
    assert c.size == 27 and d.size == 27 and L.size == 27
    stim = synthetic.experiment1_stimuli()
    got = sorted(zip(np.round(c.ravel(), 12), np.round(d.ravel(), 12)))
    assert got == sorted(zip(np.round(stim["c"], 12), np.round(stim["d"], 12)))
    rd = np.broadcast_to(np.reshape([0.03, 0.193, 0.767], (3, 1, 1)), (3, 3, 3))
    rs = np.broadcast_to(np.reshape([0.033, 0.066, 0.099], (3, 1)), (3, 3, 3))
    al = np.broadcast_to([0.04, 0.07, 0.10], (3, 3, 3))
    np.testing.assert_allclose(np.reshape(c, (3, 3, 3)), np.cbrt(rs + rd / 2) - np.cbrt(rd / 2), rtol=1e-12)
    np.testing.assert_allclose(np.reshape(d, (3, 3, 3)), 1 - al, rtol=1e-12)
