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

    python bindings/python/bench/bench_threads.py [--threads N] [--repeat 50]
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


def best_pair(fa: Callable[[], object], fb: Callable[[], object], repeat: int):
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
    return min(ta), min(tb)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--threads", type=int, default=None, help="threads of the threaded side (default: all CPUs)")
    ap.add_argument("--repeat", type=int, default=50)
    args = ap.parse_args(argv)
    pgloss.set_num_threads(args.threads)
    T = pgloss.get_num_threads()
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
            "gloss_from_physical": lambda: pgloss.gloss_from_physical(rd, rs, al, errors="status"),
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


if __name__ == "__main__":
    sys.exit(main())
