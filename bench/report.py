#!/usr/bin/env python3
"""Writes BENCHMARKS.md from the outputs of bench/run.sh (core.md/.csv, peers.md/.csv in
DIR) and draws the time-against-error plot DIR/pareto.png.

    python bench/report.py DIR BENCHMARKS.md
"""
from __future__ import annotations

import csv
import datetime
import platform
import subprocess
import sys
from pathlib import Path


def machine() -> str:
    model = "unknown CPU"
    flags = ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name") and model == "unknown CPU":
                model = line.split(":", 1)[1].strip()
            if line.startswith("flags") and not flags:
                f = line.split(":", 1)[1].split()
                flags = ", ".join(x for x in ("avx2", "fma", "avx512f") if x in f)
    except OSError:
        pass
    cc = subprocess.run(["cc", "--version"], capture_output=True, text=True).stdout.splitlines()
    import os
    return (f"{model} ({os.cpu_count()} logical cores; {flags or 'no AVX2'}), "
            f"{platform.system()} {platform.release()}, {cc[0] if cc else 'cc'}; one core used")


def pareto(d: Path) -> str:
    import matplotlib.pyplot as plt  # noqa: PLC0415

    rows = list(csv.DictReader(open(d / "core.csv")))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    marks = {"double": "o", "float": "s", "fast": "^"}
    for r in rows:
        if r["path"] not in ("scalar", "batch") or r["function"] not in ("eval", "pdf", "eval_pdf", "sample"):
            continue
        if r["material"] != "both" or not r["max_rel_err"]:
            continue
        t, e = float(r["ns"]), max(float(r["max_rel_err"]), 1e-9)
        label = f"{r['function']} {r['path']} {r['tier']} {r['isa']}"
        ax.scatter(t, e, marker=marks.get(r["tier"], "x"), s=30)
        ax.annotate(label, (t, e), fontsize=5, xytext=(3, 2), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ns per call (median)")
    ax.set_ylabel("max relative error (regular range)")
    ax.set_title("pgloss: run time against error")
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    out = d / "pareto.png"
    fig.savefig(out, dpi=150)
    return str(out)


def main() -> int:
    d, dst = Path(sys.argv[1]), Path(sys.argv[2])
    core = (d / "core.md").read_text()
    peers = (d / "peers.md").read_text() if (d / "peers.md").exists() else "(peers not run)\n"
    plot = pareto(d)
    rows = list(csv.DictReader(open(d / "core.csv")))
    def ns(fn, path, tier, isa):
        for r in rows:
            if (r["function"], r["path"], r["tier"], r["isa"], r["material"]) == (fn, path, tier, isa, "both"):
                return float(r["ns"]), float(r["max_rel_err"] or "nan"), float(r["mean_rel_err"] or "nan")
        return float("nan"), float("nan"), float("nan")
    best = min((ns("eval", "batch", "float", i) for i in ("baseline", "avx2", "avx512")), key=lambda v: v[0] if v[0] == v[0] else 1e9)
    bestfast = min((ns("eval", "batch", "fast", i) for i in ("baseline", "avx2", "avx512")), key=lambda v: v[0] if v[0] == v[0] else 1e9)
    scalar = ns("eval", "scalar", "double", "-")
    targets = f"""## Against the targets (issue 7)

| target | measured here | met? |
|---|---|---|
| batched float `eval` ≤ 1 ns/eval | FLOAT tier {best[0]:.2f} ns; FAST tier {bestfast[0]:.2f} ns (max {bestfast[1]:.1e}, mean {bestfast[2]:.1e}) (best ISA) | no (FAST is closest) |
| … with max rel. error ≤ 2e-6 (regular range) | max {best[1]:.1e} / mean {best[2]:.1e} (see Errors above: the max is the conditioning of float input directions; the shared vectors' conditioning-aware tolerance is met: max 3.1e-7 on the vectors) | max: no; arithmetic: yes |
| scalar `eval` ≤ 10 ns | {scalar[0]:.1f} ns (double arithmetic, libm exp) | no |

**Operation count** of one batched `eval_pdf` (both lobes, eq. 2), counted in
`libpgloss/src/batch_isa.c` and `kernel_float.h`: normalising wo and wi ≈ 2 × 18 operations
(abs, max, exact power-of-two scale, squares, one sqrt and one division each); the lobe
kernel ≈ 71 (half vector 3, exponent 8 with one division, exp 24, normalisation factor 4 with
sqrt and division, pdf 8 with one division, sums, clamps and selects 24): about **107 float
operations, of which 5 divisions and 3 square roots**. This CPU's AVX-512 is two 256-bit
halves: about 32 single-precision operations per cycle at best, so the arithmetic alone bounds
an evaluation at ≈ 3.3 cycles; the divider/square-root unit (16 lanes,
several cycles each per vector; 8 per evaluation) bounds it at ≈ 4–5 cycles, ≈ 1.5 ns at 3 GHz. The FLOAT
tier measures {best[0]:.2f} ns. The FAST tier on AVX-512 (`batch_avx512_fast.h`, intrinsics; `batch_avx2_fast.h` on AVX2)
replaces every division and square root by vrcp14ps/vrsqrt14ps plus one Newton step, uses FMA
and vscalefps: about 90 vector operations per 16 evaluations, and measures {bestfast[0]:.2f} ns
with the same mean error. (A portable FAST variant with bit-level guesses and Newton steps was
*slower* than IEEE division, 3.1 against 2.6 ns, and was dropped.) The scalar functions are the double-precision reference
(two normalisations, libm exp, five divisions, one rounding); their latency chain is ≈ 120
cycles. For single evaluations at float speed, call the batch with n ≥ 16 (see the size table:
per-call overhead dominates below that).

"""
    text = f"""# pgloss benchmarks

Regenerate with `bash bench/run.sh` (about 3 minutes; `--quick` for a smoke run). The plot of
time against error is written to `{plot}` (generated, not committed).

Machine: {machine()}. Generated {datetime.date.today().isoformat()}.
Timings are medians of repeated runs on a shared machine: compare rows of one run, and use
the ratios to the numpy baseline measured in the same run.

**Errors** are relative errors against an independent long-double (C) or float64 (peers)
transcription of eq. 2 and Walter's pdf, on the same inputs: wo uniform over the hemisphere
(cosθo ≥ 0.05), wi drawn by pgloss_sample (so the specular lobe is exercised where it
matters), on the *regular range* — specular exponent tan²δ/α² ≤ 10, where 99.995 % of the
lobe's energy lies (beyond it every float exp loses accuracy in proportion to the exponent).
The float tiers' max error there (~2e-5 for α = 0.07) is the conditioning of eq. 2 in float
inputs: a unit direction rounded to float moves tan²δ/α² by about 2√x·6e-8/α; the mean error
and the shared vectors' tolerance model (rel + kappa·conditioning) show the arithmetic error.

{targets}## The C core (`build-bench/bench/pgloss_bench_core`)

{core}
## Peers (`bench/peers.py`)

{peers}"""
    dst.write_text(text)
    print(f"wrote {dst} and {plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
