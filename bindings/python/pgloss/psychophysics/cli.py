# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss mds``: the paper's Experiment 1 analysis on proximity matrices in CSV.

    python -m pgloss mds --example cities --out out/mds          # Table 1 → Figs. 2 and 3
    python -m pgloss mds --example synthetic --out out/synth     # simulated observers → Figs. 5–8
    python -m pgloss mds subj1.csv … subj9.csv --stimuli stim.csv --out out/exp1

With one CSV the fit is SMACOF (metric unless ``--level ordinal``); with several (one file per
subject, same stimuli in the same order) it is the paper's weighted Euclidean model
(non-metric unless ``--level ratio``). It fits 1 to ``--max-dims`` dimensions, prints the stress
curve and the choice of dimensionality with its reasoning, and writes the curve, the chosen
configuration (CSV) and the figures. With ``--stimuli`` (a CSV with columns name, rho_d, rho_s,
alpha) it also runs confirmatory MDS with c and d from pgloss (eqs. 3–4): the fitted d/c weight
ratio (the paper's 1.78) with its bootstrap interval over subjects and a permutation test.
"""

from __future__ import annotations

import argparse
import csv
from pathlib import Path
from typing import List, Optional

import numpy as np

from . import cities, confirmatory, magnitude, synthetic
from . import figures as figs
from .mds import choose_dimensionality, stress_curve
from .procrustes import axis_r2, procrustes, property_fit
from .proximity import ProximityError, check_proximities, read_csv, read_csv_rows


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``mds`` subcommand's arguments."""
    p.add_argument("csv", nargs="*", type=Path, help="proximity matrices, one CSV per subject (header row of "
                   "stimulus names, one row per stimulus; empty / NA cell = missing; a lower triangle is mirrored)")
    p.add_argument("--example", choices=("cities", "synthetic"),
                   help="cities: the paper's Table 1 (Figs. 2, 3); synthetic: 9 simulated observers of the 27 "
                   "Fig. 4 stimuli with a planted truth (Figs. 5–8)")
    p.add_argument("--out", type=Path, default=Path("out/mds"), help="output folder (default out/mds)")
    p.add_argument("--stimuli", type=Path, help="CSV with columns name, rho_d, rho_s, alpha for the stimuli: "
                   "Fig. 6 symbols and confirmatory MDS with c, d of eqs. 3–4")
    p.add_argument("--level", choices=("auto", "ratio", "ordinal"), default="auto",
                   help="ratio = metric MDS, ordinal = non-metric (default: ratio for one matrix, ordinal for several)")
    p.add_argument("--ties", choices=("primary", "secondary"), default="primary", help="non-metric ties approach")
    p.add_argument("--max-dims", type=int, help="stress curve from 1 to this many dimensions (default 5, or the most "
                   "the stimuli allow: n − 2 for n stimuli)")
    p.add_argument("--ndim", type=int, help="use this dimensionality instead of the elbow of the stress curve")
    p.add_argument("--stress", choices=("stress1", "normalized", "raw"), default="stress1",
                   help="the stress plotted and used for the elbow (default Kruskal's stress-1)")
    p.add_argument("--starts", type=int, help="random starts besides the Torgerson start (default: automatic, 4 "
                   "or more until the lowest stress is reached twice, up to 32; 1-D up to 64)")
    p.add_argument("--seed", type=int, default=0, help="seed of the random starts, bootstrap and simulation")


def _say(lines: List[str], text: str) -> None:
    print(text)
    lines.append(text)


def _write_config(path: Path, x: np.ndarray, names) -> None:
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["stimulus"] + [f"dim{a + 1}" for a in range(x.shape[1])])
        for name, row in zip(names, x):
            w.writerow([name] + [f"{v:.8g}" for v in row])


def _write_curve(path: Path, curve) -> None:
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["dims", "raw_stress", "normalized_raw_stress", "stress1"])
        for k, s in zip(curve.dims, curve.stress):
            w.writerow([k, f"{s.raw:.8g}", f"{s.normalized:.8g}", f"{s.stress1:.8g}"])


def _read_stimuli(path: Path, names) -> dict:
    """The --stimuli table's rho_d, rho_s, alpha for the stimuli `names`, in that order; any
    problem is a ProximityError naming the file, row and column."""
    rows = read_csv_rows(path)
    header = [c.strip() for c in rows[0]] if rows else []
    missing = [k for k in ("name", "rho_d", "rho_s", "alpha") if k not in header]
    if missing:
        raise ProximityError(f"{path}: no column {', '.join(missing)} (needs columns name, rho_d, rho_s, alpha)")
    col = {k: header.index(k) for k in ("name", "rho_d", "rho_s", "alpha")}
    table = {}
    for line, r in enumerate(rows[1:], start=2):
        if any(c.strip() for c in r):
            if len(r) < len(header):
                raise ProximityError(f"{path}: row {line} has {len(r)} cells for {len(header)} columns")
            table[r[col["name"]].strip()] = (line, r)
    out = {}
    for k in ("rho_d", "rho_s", "alpha"):
        values = []
        for n in names:
            if n not in table:
                raise ProximityError(f"{path}: no row for stimulus '{n}' (the proximity matrices' names)")
            line, r = table[n]
            try:
                v = float(r[col[k]])
            except ValueError:
                v = float("nan")
            if not np.isfinite(v):
                raise ProximityError(f"{path}: row {line}, column {k}: {r[col[k]].strip()!r} is not a finite number")
            values.append(v)
        out[k] = np.array(values)
    return out


def _analyse(delta: np.ndarray, weights: np.ndarray, names, args, out: Path, log: List[str], *,
             curve_title: str, metric: bool):
    prox = check_proximities(delta, weights)
    delta, weights = prox.delta, prox.weights
    model = "smacof" if delta.shape[0] == 1 else "weighted_euclidean"
    # n stimuli support at most n − 2 dimensions (n − 1 always fit exactly).
    allowed = prox.n_stimuli - 2
    if args.ndim is not None and args.ndim > allowed:
        raise ProximityError(f"--ndim {args.ndim}: {prox.n_stimuli} stimuli allow at most {allowed} dimensions")
    max_dims = min(args.max_dims or 5, allowed)
    kw = dict(n_random=args.starts, seed=args.seed)
    if model == "weighted_euclidean":
        kw.update(max_iter=1000, eps=1e-6)
    curve = stress_curve(delta, range(1, max_dims + 1), weights=weights, model=model, metric=metric,
                         ties=args.ties, **kw)
    _say(log, f"{model} ({'metric' if metric else 'non-metric, ' + args.ties + ' ties'}), "
              f"{delta.shape[0]} subject(s), {delta.shape[1]} stimuli")
    if max_dims < (args.max_dims or 5):
        _say(log, f"{prox.n_stimuli} stimuli allow at most {allowed} dimensions (n − 2): the stress curve goes "
                  f"from 1 to {max_dims}{'' if args.max_dims else ', not the default 5'}")
    _say(log, "starts per dimensionality (Torgerson, the previous solution, random): " +
         ", ".join(f"{k}D {len(f.start_stress)}" for k, f in zip(curve.dims, curve.fits)) +
         ("" if args.starts is not None else " (automatic: more where the lowest stress was reached only once)"))
    choice = choose_dimensionality(curve, kind=args.stress)
    _say(log, choice.reasoning)
    ndim = args.ndim or choice.ndim
    if ndim is None:
        ndim = min(2, max_dims)
        _say(log, f"no elbow: showing the {ndim}-D solution anyway (choose with --ndim)")
    elif args.ndim:
        _say(log, f"--ndim {ndim}: using {ndim} dimensions")
    if ndim not in curve.dims:
        raise SystemExit(f"--ndim {ndim} is outside the stress curve's 1–{max_dims}")
    _write_curve(out / "stress_curve.csv", curve)
    fit = curve.fit(ndim)
    # The weighted model's common space has unit-variance axes; scaled by the subjects' root mean
    # square weights it is the average subject's space, whose proportions mean something.
    x = fit.config if model == "smacof" else fit.common * np.sqrt(np.mean(fit.subject_weights**2, axis=0))
    _write_config(out / "configuration.csv", x, names)
    paths = figs.stress_curve_figure(curve, out, "stress_curve", kind=args.stress, title=curve_title,
                                     chosen=choice.ndim)
    if model == "weighted_euclidean":
        _say(log, "subject dimension weights (rows: subjects): " +
             "; ".join(" ".join(f"{v:.3f}" for v in row) for row in fit.subject_weights))
    return curve, fit, x, ndim, paths


def _confirm(delta, weights, stim, names, args, log, *, planted: Optional[float] = None):
    import pgloss

    _, c, d = pgloss.gloss_from_physical(stim["rho_d"], stim["rho_s"], stim["alpha"])
    res = confirmatory.confirmatory_mds(delta, np.column_stack([c, d]), names=("c", "d"), weights=weights,
                                        ties=args.ties, seed=args.seed, n_perm=39)
    _say(log, res.summary())
    if planted is not None:
        lo, hi = res.ci[1]
        _say(log, f"  planted ratio {planted:.3f}: {'inside' if lo <= planted <= hi else 'OUTSIDE'} the interval")
    return res, np.asarray(c), np.asarray(d)


def _cities(args, out: Path, log: List[str]) -> List[Path]:
    delta, names = cities.table1()
    ll, _ = cities.latlon()
    truth = cities.azimuthal_equidistant(ll)
    metric = args.level != "ordinal"
    curve, fit, x, ndim, paths = _analyse(delta, None, names, args, out, log, metric=metric,
                                          curve_title="Fig. 3 — stress vs. dimensionality, Table 1 (U.S. cities)")
    fit2 = curve.fit(2)
    al = procrustes(fit2.config, truth)
    _say(log, f"2-D solution: stress-1 {fit2.stress.stress1:.5f}; after Procrustes to the projected true positions "
              f"RMS error {al.rms:.1f} mi, largest {np.max(np.linalg.norm(al.aligned - truth, axis=1)):.1f} mi, "
              f"scale {al.scale:.4f}")
    paths += figs.cities_map(fit2.config, names, truth, out)
    return paths


def _synthetic(args, out: Path, log: List[str]) -> List[Path]:
    stim = synthetic.experiment1_stimuli()
    obs = synthetic.simulate_experiment1(stim["c"], stim["d"], seed=args.seed)
    names = [f"s{i + 1:02d}" for i in range(27)]
    _say(log, "9 simulated subjects rate the 378 pairs of the 27 Fig. 4 stimuli: eq. 5 distance with per-subject "
              f"weights, noise {obs.noise:g}×mean, response exponents {np.round(obs.gamma, 2).tolist()}")
    curve, fit, x, ndim, paths = _analyse(obs.ratings, None, names, args, out, log, metric=args.level == "ratio",
                                          curve_title="Fig. 5 — dimensionality vs. stress, simulated Experiment 1")
    if x.shape[1] == 2:
        r2 = axis_r2(x, np.column_stack([stim["c"], stim["d"]]))
        _say(log, f"axes vs (c, d), r²: axis 1 {np.round(r2[0], 3).tolist()}, axis 2 {np.round(r2[1], 3).tolist()}; "
                  f"property fits c {property_fit(x, stim['c']).r2:.3f}, d {property_fit(x, stim['d']).r2:.3f}")
        paths += figs.configuration_figure(x, stim["rho_d"], stim["rho_s"], stim["alpha"], out, c=stim["c"],
                                           d=stim["d"], title="Fig. 6 — 2-D weighted Euclidean non-metric solution "
                                           "(simulated)")
    _confirm(obs.ratings, None, stim, names, args, log, planted=obs.ratio)
    for study, key, fig, label in ((synthetic.doi_study(), "d = 1 − α (eq. 3)", "fig07_doi_fit", "d = 1 − α"),
                                   (synthetic.contrast_study(), "c (eq. 4)", "fig08_contrast_fit", "c (eq. 4)")):
        hyp = {k: v for k, v in study.items() if k not in ("rho_d", "rho_s", "alpha")}
        ratings = synthetic.simulate_magnitude(study[key], seed=args.seed)
        cmp = magnitude.compare_hypotheses(hyp, ratings)
        _say(log, f"magnitude estimation, true hypothesis {key}:\n" + cmp.report())
        best = next(f for f in cmp.fits if f.name == key)
        n = "7" if fig.startswith("fig07") else "8"
        paths += figs.magnitude_figure(best, out, fig, xlabel=label, ratings=ratings,
                                       title=f"Fig. {n} — magnitude estimates (simulated) and fit for {label}")
    return paths


def run(args: argparse.Namespace) -> int:
    """Runs the ``mds`` subcommand; returns the exit status."""
    out: Path = args.out
    if (args.max_dims is not None and args.max_dims < 1) or (args.ndim is not None and args.ndim < 1) or \
            (args.starts is not None and args.starts < 0):
        raise SystemExit("--max-dims and --ndim must be ≥ 1, --starts ≥ 0")
    if bool(args.example) == bool(args.csv):
        raise SystemExit("give either CSV files or --example (see --help)")
    out.mkdir(parents=True, exist_ok=True)
    log: List[str] = []
    try:
        if args.example == "cities":
            paths = _cities(args, out, log)
        elif args.example == "synthetic":
            paths = _synthetic(args, out, log)
        else:
            mats = [read_csv(p) for p in args.csv]
            names = mats[0][2]
            for p, m in zip(args.csv, mats):
                if m[2] != names:
                    raise ProximityError(f"{p}: stimuli {m[2]} differ from {args.csv[0]}'s {names}")
            delta = np.stack([m[0] for m in mats])
            weights = np.stack([m[1] for m in mats])
            metric = args.level == "ratio" or (args.level == "auto" and len(mats) == 1)
            curve, fit, x, ndim, paths = _analyse(delta, weights, names, args, out, log, metric=metric,
                                                  curve_title="stress vs. dimensionality")
            if args.stimuli:
                stim = _read_stimuli(args.stimuli, names)
                _, c, d = _confirm(delta, weights, stim, names, args, log)
                if x.shape[1] == 2:
                    paths += figs.configuration_figure(x, stim["rho_d"], stim["rho_s"], stim["alpha"], out, c=c, d=d)
    except ProximityError as e:
        raise SystemExit(f"pgloss mds: {e}") from None
    (out / "report.txt").write_text("\n".join(log) + "\n", encoding="utf-8")
    for p in [out / "report.txt", out / "stress_curve.csv", out / "configuration.csv"] + paths:
        print(p)
    return 0
