#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Benchmark (threads): where an array call starts to gain from a second thread. Not a test:
it prints a Markdown table.

For array lengths from 2^11 to 2^19 it times each call on one thread and on ``--threads``
threads (default: all CPUs of this process), alternately, call by call, and reports the best
of ``--repeat`` runs of each (the best, not the median: at tens of microseconds a loaded host
adds noise only upwards). The split threshold is lowered to one element per thread for the
run (``_core._set_min_elements_per_thread``), so that short arrays are split too; the
crossover is the shortest length from which the threaded call is faster.
``MIN_ELEMENTS_PER_THREAD`` (bindings/python/src/parallel.h) is set from it.

With ``--textures`` it times instead the calls of a whole texture (4096² paints, 2^20 direction
pairs, as bench_textures.py) on one thread and on ``--threads``, paired, the median of
``--repeat`` pairs, with the threaded call's CPU time over its wall time (the cores it got).

    python bindings/python/bench/bench_threads.py [--threads N] [--repeat 50]
    python bindings/python/bench/bench_threads.py --textures [--threads N] [--repeat 5]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from typing import Callable, Dict, List

import numpy as np

import pgloss
from pgloss import _core

from bench_textures import alternate, directions  # this folder: the same timing and data


def best_pair(fa: Callable[[], object], fb: Callable[[], object], repeat: int):
    ta, tb = alternate(fa, fb, repeat)
    return min(ta), min(tb)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--threads", type=int, default=None, help="threads of the threaded side (default: all CPUs)")
    ap.add_argument("--repeat", type=int, default=None, help="default 50, or 5 with --textures")
    ap.add_argument("--textures", action="store_true", help="the speed-up on whole textures instead")
    args = ap.parse_args(argv)
    pgloss.set_num_threads(args.threads)
    T = pgloss.get_num_threads()
    if args.textures:
        return textures(T, args.repeat or 5)
    args.repeat = args.repeat or 50
    rng = np.random.default_rng(7)
    sizes = [1 << k for k in range(11, 20)]
    uniform = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1)

    def calls(n: int) -> Dict[str, Callable[[], object]]:
        rd, rs, al = rng.uniform(0.0, 0.9, n), rng.uniform(0.0, 0.1, n), rng.uniform(0.02, 0.2, n)
        v = rng.normal(size=(2, n, 3))
        v[..., 2] = np.abs(v[..., 2]) + 0.05
        wo, wi = v[0].astype(np.float32), v[1].astype(np.float32)
        f = np.empty((n, 3), np.float32)
        per = pgloss.Physical(rng.uniform(0.0, 0.8, (n, 3)), rs, al)
        return {
            "gloss_from_physical": lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status", check=False),
            "contrast_gloss (scalar per element)": lambda: pgloss.contrast_gloss(rd, rs, errors="status"),
            "eval float32, one material": lambda: pgloss.eval(uniform, wo, wi, out=f),
            "eval float32, per-element": lambda: pgloss.eval(per, wo, wi, out=f),
        }

    old = _core._set_min_elements_per_thread(1)
    table: Dict[str, List[str]] = {}
    try:
        for n in sizes:
            for name, fn in calls(n).items():
                def one(fn=fn):
                    pgloss.set_num_threads(1)
                    fn()
                def many(fn=fn):
                    pgloss.set_num_threads(T)
                    fn()
                t1, tn = best_pair(one, many, args.repeat)
                table.setdefault(name, []).append(f"{t1 * 1e6:.0f} / {tn * 1e6:.0f} ({t1 / tn:.2f}×)")
    finally:
        _core._set_min_elements_per_thread(old)
        pgloss.set_num_threads(T)
    load = os.getloadavg()
    print(f"pgloss {pgloss.__version__}, {T} threads against 1, load average {load[0]:.2f}, {load[1]:.2f}, "
          f"{load[2]:.2f}; best of {args.repeat}; µs on 1 thread / on {T} (speed-up)\n")
    print("| call | " + " | ".join(f"{n:,}" for n in sizes) + " |")
    print("|---|" + "---:|" * len(sizes))
    for name, cells in table.items():
        print(f"| {name} | " + " | ".join(cells) + " |")
    return 0


def textures(T: int, rep: int) -> int:
    import statistics
    N = 4096
    n = N * N
    rng = np.random.default_rng(18)
    tex = pgloss.Perceptual(*(rng.uniform(lo, hi, (N, N)) for lo, hi in
                              ((20.0, 80.0), (-20.0, 20.0), (-20.0, 20.0), (0.0, 0.08), (0.85, 0.99))))
    rd, rs, al = rng.uniform(0.0, 0.9, n), rng.uniform(0.0, 0.1, n), rng.uniform(0.02, 0.2, n)
    m = 1 << 20

    wo64, wi64 = directions(rng, m), directions(rng, m)
    wo32, wi32 = wo64.astype(np.float32), wi64.astype(np.float32)
    uniform = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1)
    per = pgloss.Physical(rng.uniform(0.0, 0.8, (m, 3)), rng.uniform(0.0, 0.1, m), rng.uniform(0.03, 0.2, m))
    f32, f64 = np.empty((m, 3), np.float32), np.empty((m, 3))
    calls = {
        f"to_physical(errors=\"status\", check=False), {N}² texels":
            lambda: tex.to_physical(errors="status", check=False),
        f"gloss_from_physical, {n:,} paints":
            lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status", check=False),
        f"eval float32, one material, {m:,} pairs": lambda: pgloss.eval(uniform, wo32, wi32, out=f32),
        f"eval float32, per-pair materials, {m:,} pairs": lambda: pgloss.eval(per, wo32, wi32, out=f32),
        f"eval float64, one material, {m:,} pairs": lambda: pgloss.eval(uniform, wo64, wi64, out=f64),
        f"eval float64, per-pair materials, {m:,} pairs": lambda: pgloss.eval(per, wo64, wi64, out=f64),
    }
    rows = []
    for name, fn in calls.items():
        t1, tn, cores = [], [], []
        for k in (1, T):
            pgloss.set_num_threads(k)
            fn()
        for _ in range(rep):
            pgloss.set_num_threads(1)
            t0 = time.perf_counter()
            fn()
            t1.append(time.perf_counter() - t0)
            pgloss.set_num_threads(T)
            c0, t0 = time.process_time(), time.perf_counter()
            fn()
            w = time.perf_counter() - t0
            tn.append(w)
            cores.append((time.process_time() - c0) / w)
        a, b = statistics.median(t1), statistics.median(tn)
        rows.append(f"| {name} | {a * 1e3:.1f} ms | {b * 1e3:.1f} ms | {a / b:.2f}× | {statistics.median(cores):.2f} |")
    load = os.getloadavg()
    print(f"pgloss {pgloss.__version__}, {T} threads against 1, load average {load[0]:.2f}, {load[1]:.2f}, "
          f"{load[2]:.2f}; median of {rep} paired calls\n")
    print(f"| call | 1 thread | {T} threads | speed-up | CPU/wall on {T} |")
    print("|---|---:|---:|---:|---:|")
    print("\n".join(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
