#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Benchmark: the BRDF calls on 2^20 direction pairs through the public API, one thread, timed
by the calling thread's CPU time (``time.thread_time``), so that a loaded, shared host — where
the wall clock counts the time the scheduler gives to other processes — still compares. Only the
public API: the same program runs against any installed version, so that two builds (the tree
before a change and after) can be run alternately and compared call by call. Not a test: it
prints a Markdown table (min and median of --repeat calls after a warm-up).

    python bindings/python/bench/bench_calls.py [--n 1048576] [--repeat 15]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import numpy as np

import pgloss


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1 << 20, help="direction pairs (default 2^20)")
    ap.add_argument("--repeat", type=int, default=15)
    args = ap.parse_args(argv)
    pgloss.set_num_threads(1)
    rng = np.random.default_rng(2026)
    m = args.n

    def dirs() -> np.ndarray:
        v = rng.normal(size=(m, 3))
        v[:, 2] = np.abs(v[:, 2]) + 0.05
        return v / np.linalg.norm(v, axis=1, keepdims=True)

    wo64, wi64 = dirs(), dirs()
    wo32, wi32 = wo64.astype(np.float32), wi64.astype(np.float32)
    one = pgloss.Physical((0.5, 0.3, 0.1), 0.05, 0.1)
    per = pgloss.Physical(rng.uniform(0, 0.8, (m, 3)), rng.uniform(0, 0.1, m), alpha_x=rng.uniform(0.03, 0.2, m),
                          alpha_y=rng.uniform(0.03, 0.2, m))
    u64 = rng.random((m, 3))
    u32 = u64.astype(np.float32)
    f32, f64 = np.empty((m, 3), np.float32), np.empty((m, 3))
    calls = {
        "eval, one material, float32": lambda: pgloss.eval(one, wo32, wi32, out=f32),
        "eval, one material, float64": lambda: pgloss.eval(one, wo64, wi64, out=f64),
        "eval, one material per pair, float32": lambda: pgloss.eval(per, wo32, wi32, out=f32),
        "eval, one material per pair, float64": lambda: pgloss.eval(per, wo64, wi64, out=f64),
        "sample, one material, float32": lambda: pgloss.sample(one, wo32, u32),
        "sample, one material, float64": lambda: pgloss.sample(one, wo64, u64),
    }
    times = {k: [] for k in calls}
    for c in calls.values():
        c()
    for _ in range(args.repeat):
        for k, c in calls.items():
            t0 = time.thread_time()
            c()
            times[k].append(time.thread_time() - t0)
    load = os.getloadavg()
    print(f"pgloss {pgloss.__version__}, {m:,} pairs, one thread, (n, 3) rows; CPU time of the calling thread, "
          f"min and median of {args.repeat} calls after a warm-up; load average {load[0]:.2f}, {load[1]:.2f}, "
          f"{load[2]:.2f}\n")
    print("| call | min ms | median ms |")
    print("|---|---:|---:|")
    for k, t in times.items():
        print(f"| {k} | {min(t) * 1e3:.2f} | {statistics.median(t) * 1e3:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
