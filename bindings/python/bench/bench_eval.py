#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Benchmark: vectorised ``pgloss.eval`` on 10⁶ direction pairs against the C batch it calls
(``pgloss_eval_pdf_batch``).

Not a test: it prints a table. The C figure is the batch on the same (n, 3) arrays through
``pgloss._core.eval_pdf`` (the binding hands numpy's pointers and strides to the C call, with
the GIL released; no argument checks, no allocation: the outputs are allocated once), timed with
``time.perf_counter``. The Python figure is the whole public call ``pgloss.eval(material, wo,
wi)`` on ``(n, 3)`` float32 arrays: argument checks, broadcasting, the output's allocation and
the same batch. The target is Python ≤ 1.5 × C. The float64 call (the double batch)
is shown for information. Both run on one thread (``pgloss.set_num_threads(1)``).

    python bindings/python/bench/bench_eval.py [--n 1000000] [--repeat 15]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

import numpy as np

import pgloss
from pgloss import _core

TARGET = 1.5


def directions(rng: np.random.Generator, n: int) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    v[:, 2] = np.abs(v[:, 2])
    return (v / np.linalg.norm(v, axis=1, keepdims=True)).astype(np.float32)


def timed(fn, repeat: int):
    fn()  # warm-up (page faults, caches)
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return times


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000, help="direction pairs (default 10^6)")
    ap.add_argument("--repeat", type=int, default=31, help="timed repetitions (best and median reported)")
    ap.add_argument("--check", action="store_true", help=f"exit 1 if Python/C (best) exceeds {TARGET}")
    args = ap.parse_args(argv)

    rng = np.random.default_rng(2000)
    n = args.n
    wo, wi = directions(rng, n), directions(rng, n)
    material = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1).material()  # both lobes, WARD (eq. 2)
    pgloss.set_num_threads(1)
    f_c, status = np.empty((n, 3), np.float32), np.empty(n, np.int8)

    def c_batch() -> None:
        _core.eval_pdf(material, None, lobes, wo.T, wi.T, f_c.T, None, status)

    # Both paths compute the same numbers (the same batch).
    lobes = int(pgloss.Lobe.ALL)
    f_py = pgloss.eval(material, wo, wi)
    assert f_py.dtype == np.float32 and f_py.shape == (n, 3)

    # C and Python alternate, so that both see the same machine load (other processes, turbo).
    c_batch()  # warm-up
    np.testing.assert_array_equal(f_c, f_py)
    pgloss.eval(material, wo, wi)
    c_times, py_times = [], []
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        c_batch()
        t1 = time.perf_counter()
        pgloss.eval(material, wo, wi)
        c_times.append(t1 - t0)
        py_times.append(time.perf_counter() - t1)
    wo64, wi64 = wo.astype(np.float64), wi.astype(np.float64)
    py64_times = timed(lambda: pgloss.eval(material, wo64, wi64), max(3, args.repeat // 3))

    c_best = min(c_times)
    rows = [
        ("C pgloss_eval_pdf_batch, (n, 3) float32", c_times),
        ("Python pgloss.eval, (n, 3) float32", py_times),
        ("Python pgloss.eval, (n, 3) float64", py64_times),
    ]
    print(f"pgloss {pgloss.__version__}: eval of n = {n:,} direction pairs, material rho_d=(0.5, 0.3, 0.1), "
          f"rho_s=0.05, alpha=0.1, lobes=ALL; best and median of {args.repeat} alternating runs")
    print(f"{'path':<50} {'best ms':>9} {'median ms':>10} {'ns/pair':>8} {'x C best':>9}")
    for name, t in rows:
        b, m = min(t), statistics.median(t)
        print(f"{name:<50} {b * 1e3:>9.2f} {m * 1e3:>10.2f} {b / n * 1e9:>8.2f} {b / c_best:>9.2f}")
    ratio = min(py_times) / c_best
    paired = statistics.median(p / c for p, c in zip(py_times, c_times))
    verdict = "meets" if ratio <= TARGET else "MISSES"
    print(f"Python float32 / C batched (best): {ratio:.2f}  -> {verdict} the target <= {TARGET}  "
          f"(median of the paired ratios: {paired:.2f})")
    return 1 if args.check and ratio > TARGET else 0


if __name__ == "__main__":
    sys.exit(main())
