# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The paints at which the bridge's MaterialX nodes are checked against the C bridge, shared by
the GLSL (llvmpipe) and OSL (Cycles) tests, and the stated errors (docs/materialx.md)."""
from __future__ import annotations

import numpy as np

# The paint that the graph's parameters read as, against the requested reachable paint: the
# measured maxima over random reachable paints (docs/materialx.md), rounded up.
TOL_L, TOL_AB, TOL_C, TOL_D, TOL_D_TRUSTED = 0.75, 0.5, 0.01, 0.035, 0.015
# Out of reach, the median distance of the paint read from the graph's parameters to the C
# bridge's nearest reachable paint (measured 0.10 / 0.004 / 0.007), with room for the sample.
OUT_L, OUT_C, OUT_D = 0.5, 0.015, 0.03
# The Fig. 14 red paint of materialx/examples/pgloss_bridge_paint.mtlx.
FIG14_RED = (35.0, 45.0, 25.0, 0.06, 0.95)


def paper_paints() -> list:
    """Fig. 4's 27 Ward paints and Fig. 12's triplet as (L*, 0, 0, c, d) (eqs. 3, 4, 6), the
    sample's Fig. 14 red paint and a light blue one of the same gloss."""
    def gloss(rd: float, rs: float, alpha: float) -> tuple:
        return (116 * rd ** (1 / 3) - 16, 0.0, 0.0, (rs + rd / 2) ** (1 / 3) - (rd / 2) ** (1 / 3), 1 - alpha)
    out = [gloss(rd, rs, a) for rd in (0.767, 0.193, 0.03) for rs in (0.033, 0.066, 0.099) for a in (0.04, 0.07, 0.1)]
    out += [(116 * rd ** (1 / 3) - 16, 0.0, 0.0, 0.057, 0.96) for rd in (0.767, 0.193, 0.03)]
    return out + [FIG14_RED, (70.0, -5.0, -30.0, 0.06, 0.95)]


def random_paints(n: int, seed: int) -> list:
    """Uniform over the graph's input box (L* 0-100, c 0-0.5, d 0.6-0.99), a*, b* in ±30."""
    rng = np.random.default_rng(seed)
    return list(np.stack([rng.uniform(0, 100, n), rng.uniform(-30, 30, n), rng.uniform(-30, 30, n),
                          rng.uniform(0, 0.5, n), rng.uniform(0.6, 0.99, n)], -1))


# Inputs a shader may receive that the C bridge refuses: out of every range, and at the edges.
INVALID = [(-10.0, 0.0, 0.0, 0.05, 0.95), (150.0, 0.0, 0.0, 0.05, 0.95), (50.0, 0.0, 0.0, 5.0, 0.95),
           (50.0, 0.0, 0.0, -1.0, 0.95), (50.0, 0.0, 0.0, 0.05, 1.0), (50.0, 0.0, 0.0, 0.05, 1.5),
           (50.0, 0.0, 0.0, 0.05, -3.0), (50.0, 300.0, -300.0, 0.05, 0.95), (0.0, 0.0, 0.0, 0.0, 0.6),
           (100.0, 0.0, 0.0, 0.5, 0.99)]


def check_against_c(bg, paints: np.ndarray, got: np.ndarray, min_reachable: int = 40) -> str:
    """Asserts the graph's parameters got (rows r, g, b, roughness, F0) at paints against the
    C bridge (bridge_graph's ctypes bindings ``bg``); returns a one-line summary."""
    lib = bg.bridge_lib()
    r_lo, r_hi = np.sqrt(bg.ALPHA_RANGE[0]), np.sqrt(bg.ALPHA_RANGE[1])
    # Every input: finite parameters inside the targets' box.
    assert np.all(np.isfinite(got))
    assert np.all((got[:, :3] >= 0) & (got[:, :3] <= 1 + 1e-6)), got[:, :3]
    assert np.all((got[:, 3] >= r_lo - 1e-6) & (got[:, 3] <= r_hi + 1e-6))
    assert np.all((got[:, 4] >= bg.F0_RANGE[0] - 1e-7) & (got[:, 4] <= bg.F0_RANGE[1] + 1e-7))
    reached_err, param_err = [], []
    for p, g in zip(paints, got):
        st, params, reached = bg.from_paint(lib, p)
        rst, read = bg.to_paint(lib, g[:3], g[3], 1.5, g[4] / 0.04)
        assert rst >= 0 or rst in bg.REACH_STATUSES, (p, g, rst)
        read_v = np.array([read.L, read.a, read.b, read.c, read.d])
        if st >= 0:  # reachable: the graph's parameters read back as the paint
            e = np.abs(read_v - p)
            assert e[0] <= TOL_L and e[3] <= TOL_C, (p, read_v)
            assert e[4] <= (TOL_D_TRUSTED if p[4] >= 0.8 else TOL_D), (p, read_v)
            if params.base_color[1] > 0.05 * bg.lightness_to_y(np.array(p[0])):  # a*, b* need a base colour
                assert max(e[1], e[2]) <= TOL_AB, (p, read_v)
            param_err.append((abs(g[4] / (params.specular * 0.04) - 1), abs(g[3] / params.roughness - 1)))
        elif st in bg.REACH_STATUSES:
            reached_err.append(np.abs(read_v - [reached.L, reached.a, reached.b, reached.c, reached.d]))
    assert len(param_err) >= min_reachable, len(param_err)
    pe, re_ = np.array(param_err), np.array(reached_err)
    # Out of reach: near the C bridge's nearest reachable paint (docs/materialx.md states the spread).
    med = np.median(re_, axis=0)
    assert med[0] <= OUT_L and med[3] <= OUT_C and med[4] <= OUT_D, med
    return (f"{len(pe)} reachable paints: max relative |dF0| {pe[:, 0].max():.3f}, |droughness| {pe[:, 1].max():.3f}; "
            f"{len(re_)} out of reach, against the C bridge's nearest reachable paint: median |dL*| "
            f"{np.median(re_[:, 0]):.2f}, |dc| {np.median(re_[:, 3]):.3f}, |dd| {np.median(re_[:, 4]):.3f}")


def all_paints() -> np.ndarray:
    return np.array(paper_paints() + random_paints(120, seed=7) + INVALID, dtype=float)
