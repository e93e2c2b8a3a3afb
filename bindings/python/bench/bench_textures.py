#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Benchmark: whole textures through the Python package, against numpy's bare
formulas, all in one run. Not a test: it prints a Markdown table.

Rows (median of --repeat runs after a warm-up, time.perf_counter around the public call):

* ``physical_from_perceptual`` on N² texels (default 4096²) with every element's validity
  (``Perceptual.to_physical(errors="status", check=False)``: LIGHTNESS, NEGATIVE, ALPHA, GAMUT…
  per texel), and with the full model check (the default, ``check=True``: envelope and energy
  too), against numpy's bare eqs. 6–7 (Y = f⁻¹(L*), ρs = (c + ∛(Y/2))³ − Y/2, α = 1 − d) plus Lab → linear
  Rec. 709 RGB, without any check. Target: pgloss (with validity) ≤ numpy bare.
* ``gloss_from_physical`` on N² paints (``check=False``; and the default, with the core's check of
  each paint) against numpy's bare eq. 4 (c = ∛(ρs + ρd/2) − ∛(ρd/2), c alone). Target: ≤ numpy.
* ``eval`` on N²/16 direction pairs: one material for all (the uniform batch) and one material per
  pair (an array ``Physical``), float32. Target: per-element ≤ 2× uniform. Both sides are
  compiled once and kept (one paint's ``Material``; an array's float block): the first call on
  a new texture, which rounds it to float, is a row of its own.
* float64 against float32, uniform and per-element materials. Target: float64 ≤ 2× float32.
* The eval ratios again on the first 65,536 pairs, whose arrays stay in the caches: the cost of
  the arithmetic, where the N²/16 rows are also bound by memory.

The eval and sample rows are paired: the two sides run alternately, call by call, and each
side's median is reported, so that a loaded host slows both alike.

Threads: the rows above run pgloss on **one thread** (``pgloss.set_num_threads(1)``, set
explicitly), like for like with numpy, whose element-wise functions run on one thread. Then, with
``--threads`` (default: every CPU this process may run on; 0 leaves them out), the same calls on
that many threads: against numpy's same formula, and against the same call on one thread (the
speed-up; paired, alternately, call by call), with the threaded call's CPU time over its wall
time (the cores it got: on a host shared with other jobs, about 1 when they hold the other cores).

    python bindings/python/bench/bench_textures.py [--size 4096] [--repeat 5] [--only perceptual|brdf]
                                                   [--threads N] [--csv FILE]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from typing import Callable, List, Tuple

import numpy as np

import pgloss


def timed(fn: Callable[[], object], repeat: int) -> float:
    fn()
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


# numpy's bare formulas (CIE 1976 with the exact ε, κ; D65 of Rec. 709; the XYZ → linear
# Rec. 709 matrix of IEC 61966-2-1).
_D65 = (0.95047, 1.0, 1.08883)
_XYZ_TO_RGB = np.array([[3.2404542, -1.5371385, -0.4985314],
                        [-0.9692660, 1.8760108, 0.0415560],
                        [0.0556434, -0.2040259, 1.0572252]])
_EPS_CBRT = 6.0 / 29.0


def alternate(fa: Callable[[], object], fb: Callable[[], object], repeat: int) -> Tuple[List[float], List[float]]:
    """Wall times of ``fa`` and ``fb`` run alternately ``repeat`` times each, after a warm-up call each."""
    fa()
    fb()
    ta, tb = [], []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fa()
        t1 = time.perf_counter()
        fb()
        t2 = time.perf_counter()
        ta.append(t1 - t0)
        tb.append(t2 - t1)
    return ta, tb


def paired(fa: Callable[[], object], fb: Callable[[], object], repeat: int) -> Tuple[float, float]:
    """Medians of ``fa`` and ``fb`` run alternately ``repeat`` times each (:func:`alternate`)."""
    ta, tb = alternate(fa, fb, repeat)
    return statistics.median(ta), statistics.median(tb)


def paired_cpu(fa: Callable[[], object], fb: Callable[[], object], repeat: int) -> Tuple[float, float, float]:
    """As :func:`paired`, plus the median of ``fa``'s process CPU time over its wall time: the
    cores it got (about the thread count on an idle machine, about 1 when the other cores are
    busy with other jobs)."""
    fa()
    fb()
    ta, tb, ca = [], [], []
    for _ in range(repeat):
        c0 = time.process_time()
        t0 = time.perf_counter()
        fa()
        t1 = time.perf_counter()
        ca.append((time.process_time() - c0) / (t1 - t0))
        fb()
        t2 = time.perf_counter()
        ta.append(t1 - t0)
        tb.append(t2 - t1)
    return statistics.median(ta), statistics.median(tb), statistics.median(ca)


def numpy_physical_from_perceptual(L, a, b, c, d):
    fy = (L + 16.0) / 116.0
    fx = fy + a / 500.0
    fz = fy - b / 200.0

    def finv(t):
        return np.where(t > _EPS_CBRT, t * t * t, 3.0 * _EPS_CBRT ** 2 * (t - 4.0 / 29.0))

    X, Y, Z = _D65[0] * finv(fx), finv(fy), _D65[2] * finv(fz)
    M = _XYZ_TO_RGB
    r = M[0, 0] * X + M[0, 1] * Y + M[0, 2] * Z
    g = M[1, 0] * X + M[1, 1] * Y + M[1, 2] * Z
    bb = M[2, 0] * X + M[2, 1] * Y + M[2, 2] * Z
    h = 0.5 * Y
    rho_s = (c + np.cbrt(h)) ** 3 - h  # eq. 7
    alpha = 1.0 - d  # eq. 8
    return r, g, bb, rho_s, alpha


def numpy_contrast_gloss(rho_d, rho_s):
    h = 0.5 * rho_d
    return np.cbrt(rho_s + h) - np.cbrt(h)  # eq. 4


def directions(rng: np.random.Generator, n: int) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--size", type=int, default=4096, help="texture side N (N² texels; default 4096)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--only", choices=("perceptual", "brdf"), help="only the conversion rows, or only eval/sample")
    ap.add_argument("--threads", type=int, default=None,
                    help="threads of the threaded rows (default: all CPUs of this process; 0: no threaded rows)")
    ap.add_argument("--csv", help="also write the rows as CSV")
    args = ap.parse_args(argv)
    N, rep = args.size, args.repeat
    pgloss.set_num_threads(None)
    T = pgloss.get_num_threads() if args.threads is None else args.threads
    pgloss.set_num_threads(1)  # the like-for-like rows: one thread, as numpy

    def on(threads: int, fn: Callable[[], object]) -> Callable[[], object]:
        def call() -> object:
            old = pgloss.set_num_threads(threads)
            try:
                return fn()
            finally:
                pgloss.set_num_threads(old)
        return call

    # (what, call, the numpy reference's label and time or None): the threaded rows, run last
    threaded: List[Tuple[str, Callable[[], object], str, float]] = []
    n = N * N
    rng = np.random.default_rng(18)
    rows: List[Tuple[str, str, float, str, float, str]] = []

    def row(what: str, ours: str, t_ours: float, ref: str, t_ref: float, target: str) -> None:
        rows.append((what, ours, t_ours, ref, t_ref, target))

    if args.only != "brdf":
        # A texture of paints inside the gamut and envelope mostly; a few out on purpose.
        L = rng.uniform(20.0, 80.0, (N, N))
        a = rng.uniform(-20.0, 20.0, (N, N))
        b = rng.uniform(-20.0, 20.0, (N, N))
        c = rng.uniform(0.0, 0.08, (N, N))
        d = rng.uniform(0.85, 0.99, (N, N))
        a[::97, ::89] = 180.0  # out of gamut
        tex = pgloss.Perceptual(L, a, b, c, d)

        t_np = timed(lambda: numpy_physical_from_perceptual(L, a, b, c, d), rep)
        t_pg = timed(lambda: tex.to_physical(errors="status", check=False), rep)
        t_pg_check = timed(lambda: tex.to_physical(errors="status"), rep)
        row(f"physical_from_perceptual, {N}² texels", "to_physical(errors=\"status\", check=False) (validity per "
            "texel)", t_pg, "numpy eqs. 6–7 + Lab→RGB, no checks", t_np, "≤ 1")
        row(f"physical_from_perceptual + check, {N}² texels", "to_physical(errors=\"status\") (the default: the full "
            "model check too)", t_pg_check, "numpy eqs. 6–7 + Lab→RGB, no checks", t_np, "")
        threaded.append((f"physical_from_perceptual, {N}² texels",
                         lambda: tex.to_physical(errors="status", check=False), "numpy eqs. 6–7 + Lab→RGB, no checks",
                         t_np))

        rd = rng.uniform(0.0, 0.9, n)
        rs = rng.uniform(0.0, 0.1, n)
        al = rng.uniform(0.02, 0.2, n)
        t_np = timed(lambda: numpy_contrast_gloss(rd, rs), rep)
        t_pg = timed(lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status", check=False), rep)
        t_pg_check = timed(lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status"), rep)
        row(f"gloss_from_physical, {n:,} paints", "gloss_from_physical (L, c, d + statuses, check=False)", t_pg,
            "numpy eq. 4 (c only)", t_np, "≤ 1")
        row(f"gloss_from_physical + check, {n:,} paints", "gloss_from_physical (the default: check_physical too)",
            t_pg_check, "numpy eq. 4 (c only)", t_np, "")
        threaded.append((f"gloss_from_physical, {n:,} paints",
                         lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status", check=False),
                         "numpy eq. 4 (c only)", t_np))

    if args.only != "perceptual":
        rng = np.random.default_rng([18, 1])  # its own stream: the same data with or without --only
        m = max(n // 16, 1 << 16)
        wo64, wi64 = directions(rng, m), directions(rng, m)
        wo32, wi32 = wo64.astype(np.float32), wi64.astype(np.float32)
        uniform = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1)
        fields = (rng.uniform(0.0, 0.8, (m, 3)), rng.uniform(0.0, 0.1, m), rng.uniform(0.03, 0.2, m),
                  rng.uniform(0.03, 0.2, m))

        def texture() -> pgloss.Physical:
            return pgloss.Physical(fields[0], fields[1], alpha_x=fields[2], alpha_y=fields[3])

        per = texture()
        f32 = np.empty((m, 3), np.float32)
        f32b = np.empty((m, 3), np.float32)
        f64 = np.empty((m, 3), np.float64)
        def ev(mat: pgloss.Physical, wo: np.ndarray, wi: np.ndarray, out: np.ndarray) -> Callable[[], object]:
            return lambda: pgloss.eval(mat, wo, wi, out=out)

        t_p32, t_u32 = paired(ev(per, wo32, wi32, f32), ev(uniform, wo32, wi32, f32b), rep)
        t_u64, t_u32b = paired(ev(uniform, wo64, wi64, f64), ev(uniform, wo32, wi32, f32), rep)
        t_p64, t_p32b = paired(ev(per, wo64, wi64, f64), ev(per, wo32, wi32, f32), rep)
        # The first call on a new texture (it rounds the texture to float, then evaluates), against
        # the uniform batch; the texture's construction (a copy of its fields) is not timed.
        t_first, t_u32c = [], []
        for _ in range(rep):
            fresh = texture()
            t0 = time.perf_counter()
            pgloss.eval(fresh, wo32, wi32, out=f32)
            t1 = time.perf_counter()
            pgloss.eval(uniform, wo32, wi32, out=f32b)
            t_first.append(t1 - t0)
            t_u32c.append(time.perf_counter() - t1)
        row(f"eval, {m:,} pairs, float32", "one material per pair", t_p32, "one material for all", t_u32, "≤ 2")
        row(f"eval, {m:,} pairs, float32", "one material per pair, first call on a new texture",
            statistics.median(t_first), "one material for all", statistics.median(t_u32c), "")
        row(f"eval, {m:,} pairs, one material", "float64 (vectorised double)", t_u64, "float32", t_u32b, "≤ 2")
        row(f"eval, {m:,} pairs, per-pair materials", "float64 (vectorised double)", t_p64, "float32", t_p32b, "≤ 2")
        k = 1 << 16
        if m > k:
            # The same ratios on the first 65,536 pairs, whose arrays (4.5 MB in float64) stay in
            # the caches: the cost of the arithmetic, where the rows above are bound by memory too.
            wo32k, wi32k, wo64k, wi64k = wo32[:k], wi32[:k], wo64[:k], wi64[:k]
            per_k = pgloss.Physical(fields[0][:k], fields[1][:k], alpha_x=fields[2][:k], alpha_y=fields[3][:k])
            rk = 20 * rep
            a, b = paired(ev(per_k, wo32k, wi32k, f32[:k]), ev(uniform, wo32k, wi32k, f32b[:k]), rk)
            row(f"eval, {k:,} pairs (in cache), float32", "one material per pair", a, "one material for all", b, "≤ 2")
            a, b = paired(ev(uniform, wo64k, wi64k, f64[:k]), ev(uniform, wo32k, wi32k, f32[:k]), rk)
            row(f"eval, {k:,} pairs (in cache), one material", "float64 (vectorised double)", a, "float32", b, "≤ 2")
            a, b = paired(ev(per_k, wo64k, wi64k, f64[:k]), ev(per_k, wo32k, wi32k, f32[:k]), rk)
            row(f"eval, {k:,} pairs (in cache), per-pair materials", "float64 (vectorised double)", a, "float32", b,
                "≤ 2")
        u32, u64 = rng.random((m, 3), dtype=np.float32), rng.random((m, 3))
        t_s64, t_s32 = paired(lambda: pgloss.sample(uniform, wo64, u64), lambda: pgloss.sample(uniform, wo32, u32), rep)
        row(f"sample, {m:,} draws, one material", "float64 (vectorised double)", t_s64, "float32", t_s32, "≤ 2")
        threaded += [
            (f"eval, {m:,} pairs, one material, float32", ev(uniform, wo32, wi32, f32b), "", 0.0),
            (f"eval, {m:,} pairs, per-pair materials, float32", ev(per, wo32, wi32, f32), "", 0.0),
            (f"eval, {m:,} pairs, one material, float64", ev(uniform, wo64, wi64, f64), "", 0.0),
            (f"eval, {m:,} pairs, per-pair materials, float64", ev(per, wo64, wi64, f64), "", 0.0),
            (f"sample, {m:,} draws, one material, float64", lambda: pgloss.sample(uniform, wo64, u64), "", 0.0),
        ]

    if T > 1:
        for what, fn, ref, t_ref in threaded:
            t_many, t_one, cores = paired_cpu(on(T, fn), on(1, fn), rep)
            row(what, f"on {T} threads", t_many, "the same on 1 thread", t_one,
                f"speed-up ×{t_one / t_many:.2f} (CPU/wall {cores:.2f})")
            if ref:
                row(what, f"on {T} threads", t_many, ref + " (1 thread)", t_ref, "≤ 1")

    try:
        load = os.getloadavg()
        load_s = f"load average {load[0]:.2f}, {load[1]:.2f}, {load[2]:.2f}"
    except OSError:
        load_s = "load average unknown"
    print(f"pgloss {pgloss.__version__}, numpy {np.__version__}, {load_s}; median of {rep} runs; "
          f"pgloss on 1 thread but in the rows that say otherwise ({os.cpu_count()} CPUs)\n")
    print("| what | pgloss | time | reference | time | ratio | target |")
    print("|---|---|---:|---|---:|---:|---|")
    for what, ours, t1, ref, t2, target in rows:
        print(f"| {what} | {ours} | {t1 * 1e3:.1f} ms | {ref} | {t2 * 1e3:.1f} ms | {t1 / t2:.2f} | {target} |")
    if args.csv:
        with open(args.csv, "w", encoding="utf-8") as fh:
            fh.write("what,pgloss,seconds,reference,reference_seconds,ratio,target\n")
            for what, ours, t1, ref, t2, target in rows:
                fh.write(f"\"{what}\",\"{ours}\",{t1:.6g},\"{ref}\",{t2:.6g},{t1 / t2:.4g},\"{target}\"\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
