#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Peers of the pgloss core, measured in the same run on the same directions.

Prints a Markdown table: ns per evaluation and max / mean relative error against a float64
transcription of eq. 2 (whose own error, ~1e-16, is far below every row's), with the ratio
to the straightforward numpy implementation measured in the same run (timings on a shared
machine drift; ratios within one run do not).

Rows: numpy float64 and float32 transcriptions of eq. 2; pgloss.eval through the Python
binding (float32: the vectorised C batch; float64: the vectorised double batch) and the C batch
it calls; Mitsuba 3 (llvm_ad_rgb) evaluating its closest built-in BSDF, `roughplastic`
with a Beckmann distribution (a different model: time only); and, informational, the GLSL
port on Mesa llvmpipe (time per evaluation of a compute dispatch).

    python bench/peers.py [--n 1048576] [--repeat 7] [--csv FILE] [--no-mitsuba] [--no-glsl]
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import pgloss
from pgloss import _core

ROOT = Path(__file__).resolve().parent.parent
RHO_D, RHO_S, ALPHA = 0.193, 0.066, 0.07  # Experiment 1's middle stimulus


def timed(fn, repeat: int) -> float:
    fn()
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def make_inputs(n: int):
    """wo uniform over the hemisphere (cosθo ≥ 0.05); wi drawn by pgloss.sample (float64
    scalar reference), so the lobe is exercised where it matters; rejected draws replaced."""
    rng = np.random.default_rng(2000)
    z = 0.05 + 0.95 * rng.random(n)
    phi = 2 * np.pi * rng.random(n)
    s = np.sqrt(1 - z * z)
    wo = np.stack([s * np.cos(phi), s * np.sin(phi), z], axis=1).astype(np.float32)
    mat = pgloss.Physical(RHO_D, RHO_S, ALPHA).material()
    wi = np.zeros_like(wo)
    todo = np.arange(n)
    for _ in range(50):
        rec = pgloss.sample(mat, wo[todo], rng.random((todo.size, 3)).astype(np.float32))
        good = rec.pdf > 0
        wi[todo[good]] = rec.wi[good]
        todo = todo[~good]
        if todo.size == 0:
            break
    wi[todo] = (0, 0, 1)
    return wo, wi, mat


def eq2_numpy(wo: np.ndarray, wi: np.ndarray, dtype) -> np.ndarray:
    """Eq. 2 (isotropic Ward), straightforwardly in numpy, in dtype."""
    o = wo.astype(dtype)
    i = wi.astype(dtype)
    o = o / np.linalg.norm(o, axis=1, keepdims=True)
    i = i / np.linalg.norm(i, axis=1, keepdims=True)
    h = o + i
    h = h / np.linalg.norm(h, axis=1, keepdims=True)
    tan2 = (h[:, 0] ** 2 + h[:, 1] ** 2) / h[:, 2] ** 2
    a = dtype(ALPHA)
    spec = dtype(RHO_S) * np.exp(-tan2 / (a * a)) / (dtype(4 * np.pi) * a * a * np.sqrt(o[:, 2] * i[:, 2]))
    return dtype(RHO_D / np.pi) + spec, tan2 / (a * a)


def errors(got: np.ndarray, want: np.ndarray, x: np.ndarray):
    keep = x <= 10.0  # the regular range of bench_core: exponent tan²δ/α² ≤ 10
    e = np.abs(got[keep].astype(np.float64) - want[keep]) / np.abs(want[keep])
    return float(e.max()), float(e.mean())


def mitsuba_row(wo: np.ndarray, wi: np.ndarray, repeat: int):
    import mitsuba as mi  # noqa: PLC0415

    mi.set_variant("llvm_ad_rgb")
    import drjit as dr  # noqa: PLC0415

    dr.set_thread_count(1)  # one core, like every other row

    bsdf = mi.load_dict({"type": "roughplastic", "distribution": "beckmann", "alpha": ALPHA,
                         "diffuse_reflectance": {"type": "rgb", "value": [RHO_D] * 3}})
    n = wo.shape[0]
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = mi.Vector3f(wo[:, 0], wo[:, 1], wo[:, 2])
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    wo_m = mi.Vector3f(wi[:, 0], wi[:, 1], wi[:, 2])
    ctx = mi.BSDFContext()

    def run():
        v = bsdf.eval(ctx, si, wo_m)
        dr.eval(v)
        dr.sync_thread()

    return timed(run, repeat) / n * 1e9


def glsl_row(n: int, repeat: int):
    sys.path.insert(0, str(ROOT / "tests" / "glsl"))
    import moderngl  # noqa: PLC0415

    ctx = moderngl.create_context(standalone=True, backend="egl", require=430)
    src = (ROOT / "glsl" / "pgloss.glsl").read_text()
    shader = """#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer A { float d[]; } inp;
layout(std430, binding = 1) writeonly buffer B { float f[]; } outp;
""" + src + """
uniform uint n;
void main() {
    uint j = gl_GlobalInvocationID.x;
    if (j >= n) return;
    pgloss_physical p;
    p.rho_d = vec3(%r); p.rho_s = %r; p.alpha_x = %r; p.alpha_y = %r; p.normalization = 0;
    pgloss_material m;
    pgloss_material_init(m, p);
    vec3 wo = vec3(inp.d[6u*j], inp.d[6u*j+1u], inp.d[6u*j+2u]);
    vec3 wi = vec3(inp.d[6u*j+3u], inp.d[6u*j+4u], inp.d[6u*j+5u]);
    vec3 f;
    pgloss_eval(m, wo, wi, 3u, f);
    outp.f[j] = f.r;
}
""" % (RHO_D, RHO_S, ALPHA, ALPHA)
    prog = ctx.compute_shader(shader)
    return prog, ctx


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1 << 20)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--csv")
    ap.add_argument("--no-mitsuba", action="store_true")
    ap.add_argument("--no-glsl", action="store_true")
    a = ap.parse_args(argv)
    n = a.n
    wo, wi, mat = make_inputs(n)
    want, x = eq2_numpy(wo, wi, np.float64)
    rows = []

    t = timed(lambda: eq2_numpy(wo, wi, np.float64), a.repeat) / n * 1e9
    rows.append(("numpy float64 (eq. 2)", t, 0.0, 0.0))
    base = t
    t = timed(lambda: eq2_numpy(wo, wi, np.float32), a.repeat) / n * 1e9
    rows.append(("numpy float32 (eq. 2)", t, *errors(eq2_numpy(wo, wi, np.float32)[0], want, x)))
    t = timed(lambda: pgloss.eval(mat, wo, wi), a.repeat) / n * 1e9
    rows.append(("pgloss.eval, float32 arrays (C float batch)", t, *errors(pgloss.eval(mat, wo, wi)[:, 0], want, x)))
    wo64, wi64 = wo.astype(np.float64), wi.astype(np.float64)
    t = timed(lambda: pgloss.eval(mat, wo64, wi64), max(3, a.repeat // 2)) / n * 1e9
    rows.append(("pgloss.eval, float64 arrays (C double batch)", t, *errors(pgloss.eval(mat, wo64, wi64)[:, 0], want, x)))
    if hasattr(_core, "time_eval_batch"):
        wo_soa, wi_soa = np.ascontiguousarray(wo.T), np.ascontiguousarray(wi.T)
        ts = list(_core.time_eval_batch(mat, int(pgloss.Lobe.ALL), wo_soa, wi_soa, a.repeat))
        rows.append(("C pgloss_eval_batch alone (the binding's callee)", statistics.median(ts) / n * 1e9, float("nan"), float("nan")))
    if not a.no_mitsuba:
        try:
            rows.append(("Mitsuba 3 llvm_ad_rgb roughplastic (Beckmann; other model), 1 thread", mitsuba_row(wo, wi, a.repeat), float("nan"), float("nan")))
        except Exception as e:  # noqa: BLE001
            print(f"peers.py: Mitsuba 3 unavailable: {type(e).__name__}: {e}", file=sys.stderr)
            rows.append(("Mitsuba 3: unavailable", float("nan"), float("nan"), float("nan")))
    if not a.no_glsl:
        try:
            import moderngl  # noqa: F401, PLC0415
            prog, ctx = glsl_row(n, a.repeat)
            data = np.concatenate([wo, wi], axis=1).astype(np.float32).ravel()
            bi = ctx.buffer(data.tobytes())
            bo = ctx.buffer(reserve=n * 4)
            bi.bind_to_storage_buffer(0)
            bo.bind_to_storage_buffer(1)
            prog["n"].value = n

            def run():
                prog.run(group_x=(n + 63) // 64)
                ctx.finish()

            t = timed(run, a.repeat) / n * 1e9
            got = np.frombuffer(bo.read(), dtype=np.float32)
            rows.append(("GLSL pgloss_eval, llvmpipe compute (informational)", t, *errors(got, want, x)))
        except Exception as e:  # noqa: BLE001
            print(f"peers.py: GLSL unavailable: {type(e).__name__}: {e}", file=sys.stderr)
            rows.append(("GLSL: unavailable", float("nan"), float("nan"), float("nan")))

    # The perceptual conversions, batched: pgloss's array functions (the batched C functions of
    # pgloss/perceptual_batch.h, GIL released) against numpy transcriptions of eqs. 4 and 6–7.
    prng = np.random.default_rng(7)
    rd = 0.001 + 0.8 * prng.random(n)
    rs = 1e-4 + 0.15 * prng.random(n) * (1 - rd)
    al = 0.01 + 0.19 * prng.random(n)
    c_want = np.cbrt(rs + rd / 2) - np.cbrt(rd / 2)
    prow = []
    t = timed(lambda: np.cbrt(rs + rd / 2) - np.cbrt(rd / 2), a.repeat) / n * 1e9
    prow.append(("numpy float64, eq. 4 (c from ρd, ρs)", t, float("nan"), float("nan")))
    pbase = {"gloss": t}
    t = timed(lambda: pgloss.gloss_from_physical(rd, rs, al), a.repeat) / n * 1e9
    e = np.abs(pgloss.gloss_from_physical(rd, rs, al)[1] - c_want) / c_want
    prow.append(("pgloss.gloss_from_physical (L, c, d; eqs. 3–4), arrays", t, float(e.max()), float(e.mean())))
    Ls = 1 + 98 * prng.random(n)
    cs = 0.001 + 0.05 * prng.random(n)
    ds = 1 - al

    def np_phys():
        Y = np.where(Ls <= 8, Ls * 27 / 24389, ((Ls + 16) / 116) ** 3)
        return Y, (cs + np.cbrt(Y / 2)) ** 3 - Y / 2

    t = timed(np_phys, a.repeat) / n * 1e9
    prow.append(("numpy float64, eqs. 6–7 (ρd, ρs from L, c)", t, float("nan"), float("nan")))
    pbase["physical"] = t
    # Some (L, c) pairs lie beyond gloss space's envelope: a status per paint, not an exception.
    t = timed(lambda: pgloss.physical_from_gloss(Ls, cs, ds, errors="status"), a.repeat) / n * 1e9
    prow.append(("pgloss.physical_from_gloss (ρd, ρs, α; eqs. 6–8), arrays, errors=\"status\"", t, float("nan"),
                 float("nan")))

    print(f"Peers: eval of eq. 2 on {n} direction pairs (rho_d {RHO_D}, rho_s {RHO_S}, alpha {ALPHA}); "
          f"median of {a.repeat} runs (the float64 binding row: of {max(3, a.repeat // 2)}); errors on the regular range (tan²δ/α² ≤ 10) against numpy float64\n")
    print("| implementation | ns/eval | × numpy float64 | max rel err | mean rel err |")
    print("|---|---:|---:|---:|---:|")
    fmt = lambda v, f: "–" if v != v else format(v, f)  # noqa: E731
    for name, t, emax, emean in rows:
        print(f"| {name} | {fmt(t, '.2f')} | {fmt(t / base, '.3f')} | {fmt(emax, '.2e')} | {fmt(emean, '.2e')} |")
    print(f"\nPerceptual conversions on {n} paints (double), median of {a.repeat} runs. The error column is c's relative difference from numpy's direct ∛(ρs+ρd/2) − ∛(ρd/2), which cancels for small ρs: pgloss's own error against long double is ≤ 1e-15 (C table above); numpy also skips L* and every check:\n")
    print("| implementation | ns/paint | × the numpy row above it | max rel err | mean rel err |")
    print("|---|---:|---:|---:|---:|")
    for k, (name, t, emax, emean) in enumerate(prow):
        base = pbase["gloss" if k < 2 else "physical"]
        print(f"| {name} | {fmt(t, '.2f')} | {fmt(t / base, '.2f')} | {fmt(emax, '.2e')} | {fmt(emean, '.2e')} |")
    if a.csv:
        with open(a.csv, "w") as fh:
            fh.write("implementation,ns,ratio,max_rel_err,mean_rel_err\n")
            for name, t, emax, emean in rows:
                fh.write(f"\"{name}\",{t},{t / base},{emax},{emean}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
