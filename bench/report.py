#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Writes BENCHMARKS.md whole from the outputs of one run of bench/run.sh in DIR (NAME.md: a
program's tables, NAME.cmd: its command; core.csv; started, load_before, command) and draws the
time-against-error plot DIR/pareto.png. Every table in the file comes from that run.

    python bench/report.py DIR BENCHMARKS.md
"""
from __future__ import annotations

import csv
import datetime
import os
import platform
import re
import subprocess
import sys
from pathlib import Path
from typing import Dict, List, Tuple

ROOT = Path(__file__).resolve().parent.parent

# (file stem, heading, what the table measures and how: one paragraph), in the file's order.
SECTIONS: List[Tuple[str, str, str]] = [
    ("core", "The C core: time against error on every path",
     "Scalar and batched `eval`, `pdf`, `eval_pdf` and `sample` in each accuracy tier (double, FLOAT, "
     "FAST) on each instruction set this CPU has, one thread. Time: the median over repeated runs of "
     "ns per call (per element for batches). Error: max and mean relative error against an "
     "independent long-double transcription on the same inputs (see *Errors* above)."),
    ("inline_v3", "One shading point, compiled `-O2 -march=x86-64-v3`",
     "Renderer-style loops over `pgloss/inline.h`, the scalar library call, the batch at n = 1 and "
     "n = 16, and a plain float transcription of eq. 2 with libm, on the same inputs (the program's "
     "header describes the loops). thr.: independent calls; lat.: each call's input depends on the "
     "previous call's output. Time: the thread's CPU time, median of interleaved repetitions. Error: "
     "max relative error against long double on the regular range."),
    ("inline_plain", "One shading point, compiled `-O2`",
     "The same program as the previous table, compiled without `-march`."),
    ("texture", "Whole textures in C: per-element materials, float64, batched perceptual",
     "The C batches on SoA columns of n texels. The two sides of each row (A, B) run alternately, "
     "repetition by repetition; each side's median is reported, and the ratio of the two medians. "
     "The float64 / float32 ratios here are the C batches on SoA columns at this n; the Python "
     "tables below measure the same kind of ratio through the binding on (n, 3) rows at their own "
     "sizes, which adds the rows' copies, so the two need not agree."),
    ("rows", "The strided batch's front end in C: (n, 3) rows against SoA columns",
     "`pgloss_eval_pdf_batch` on the layout numpy's channel-last arrays pass and on columns, with and "
     "without a status array; the thread's CPU time, min of alternating calls; the last column "
     "divides by the columns without statuses, measured in the same run."),
    ("peers", "Peers of the core",
     "numpy, the Python binding, Mitsuba 3 and the GLSL port (Mesa llvmpipe) evaluating eq. 2 on the "
     "same directions, one thread where the peer allows; the ratio is to numpy float64 measured in "
     "the same run. Error: max and mean relative error against numpy float64 on the regular range."),
    ("python_textures", "Whole textures from Python",
     "Arrays through the Python package against numpy's bare formulas in the same run: time, the "
     "reference's time and their ratio (pgloss / reference). pgloss runs on one thread, as numpy, "
     "except the rows that name a thread count. The eval and sample rows are paired: the two sides "
     "alternate call by call. The target column is the bound a ratio is held to."),
    ("python_calls", "The Python binding's BRDF calls on (n, 3) rows",
     "The public API's `pgloss.eval` and `pgloss.sample` on (n, 3) float32 and float64 arrays, one "
     "thread, timed by the calling thread's CPU time (robust to descheduling on a shared host)."),
    ("python_threads", "Threads: where an array call gains from a second thread",
     "Each call on one thread and on all of this process's CPUs, alternately, with the split threshold "
     "lowered to one element per thread so that short arrays are split too; the best of the "
     "repetitions of each (at tens of µs, load adds noise only upwards)."),
]

LONG = """## Long benchmarks: separate commands, separate generated files

Not run by `bash bench/run.sh`; each writes its own file, whose header states its own date,
machine and command.

- The tracer against Mitsuba 3: [bench/results/tracer.md](bench/results/tracer.md), written by
  `bash examples/tracer/bench/run.sh --write bench/results/tracer.md [options]` (one section per
  command line).
- The gloss bridge in real renderers (Mitsuba 3, Cycles, MaterialX through OSL), read back by the
  image gloss meter: [docs/bridge-validation.md](docs/bridge-validation.md) and its instruments'
  checks [docs/bridge-harnesses.md](docs/bridge-harnesses.md), written by
  `nice .venv-bridge/bin/python examples/bridge/validate.py all` (after `bash scripts/test-bridge.sh`).
"""


def first_line(cmd: List[str]) -> str:
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, check=False).stdout.splitlines()
    except OSError:
        return "unknown"
    return out[0].strip() if out else "unknown"


def cpu() -> str:
    model, flags = "unknown CPU", ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name") and model == "unknown CPU":
                model = line.split(":", 1)[1].strip()
            if line.startswith("flags") and not flags:
                f = line.split(":", 1)[1].split()
                flags = ", ".join(x for x in ("avx2", "fma", "avx512f") if x in f)
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} logical cores ({flags or 'no AVX2'})"


def compilers() -> str:
    """The C and C++ compilers of build-bench (its CMake cache), or cc and c++."""
    found: Dict[str, str] = {"C": "cc", "CXX": "c++"}
    cache = ROOT / "build-bench" / "CMakeCache.txt"
    if cache.exists():
        for line in cache.read_text().splitlines():
            m = re.match(r"CMAKE_(C|CXX)_COMPILER:\w+=(.+)", line)
            if m:
                found[m.group(1)] = m.group(2)
    return f"C: {first_line([found['C'], '--version'])}; C++: {first_line([found['CXX'], '--version'])}"


def commit() -> str:
    """HEAD's short hash, and "dirty" when tracked files (other than BENCHMARKS.md) differ."""
    head = first_line(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"])
    st = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "--untracked-files=no", "--", ".",
                         ":!BENCHMARKS.md"], capture_output=True, text=True, check=False).stdout.strip()
    return f"{head} (dirty: uncommitted changes)" if st else head


def python_versions() -> str:
    from importlib import metadata  # noqa: PLC0415

    def v(p: str) -> str:
        try:
            return metadata.version(p)
        except metadata.PackageNotFoundError:
            return "not installed"
    return (f"Python {platform.python_version()}, pgloss {v('pgloss')}, numpy {v('numpy')}, "
            f"Mitsuba {v('mitsuba')}, moderngl {v('moderngl')}")


def rows_of(d: Path) -> List[Dict[str, str]]:
    with open(d / "core.csv", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def pareto(d: Path) -> str:
    import matplotlib.pyplot as plt  # noqa: PLC0415

    fig, ax = plt.subplots(figsize=(7, 4.5))
    marks = {"double": "o", "float": "s", "fast": "^"}
    for r in rows_of(d):
        if r["path"] not in ("scalar", "batch") or r["function"] not in ("eval", "pdf", "eval_pdf", "sample"):
            continue
        if r["material"] != "both" or not r["max_rel_err"]:
            continue
        t, e = float(r["ns"]), max(float(r["max_rel_err"]), 1e-9)
        ax.scatter(t, e, marker=marks.get(r["tier"], "x"), s=30)
        ax.annotate(f"{r['function']} {r['path']} {r['tier']} {r['isa']}", (t, e), fontsize=5, xytext=(3, 2),
                    textcoords="offset points")
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


def targets(d: Path) -> str:
    """The core's targets against this run's figures: numbers only (measured / bound)."""
    rows = rows_of(d)

    def get(fn: str, path: str, tier: str, isa: str, material: str, col: str) -> float:
        for r in rows:
            if (r["function"], r["path"], r["tier"], r["isa"], r["material"]) == (fn, path, tier, isa, material):
                return float(r[col] or "nan")
        raise SystemExit(f"report.py: core.csv has no row {fn} {path} {tier} {isa} {material}")

    floor = get("floor", "-", "-", "-", "specular", "max_rel_err")
    items = [
        ("batched float `eval`, FAST tier, the dispatcher's ISA: ns per evaluation", 1.0,
         get("eval", "batch", "fast", "auto", "both", "ns"), ".2f"),
        ("... its max relative error on the regular range (material of Experiment 1)", 2e-6,
         get("eval", "batch", "fast", "auto", "both", "max_rel_err"), ".2e"),
        ("... its max relative error, specular lobe alone", 2e-6,
         get("eval", "batch", "fast", "auto", "specular", "max_rel_err"), ".2e"),
        ("for comparison, the FLOAT tier (IEEE division and square root): ns per evaluation", 1.0,
         get("eval", "batch", "float", "auto", "both", "ns"), ".2f"),
        ("... the FLOAT tier's max relative error, specular lobe alone", 2e-6,
         get("eval", "batch", "float", "auto", "specular", "max_rel_err"), ".2e"),
        ("scalar `eval` (double inside): ns per call", 10.0, get("eval", "scalar", "double", "-", "both", "ns"), ".2f"),
    ]
    out = ["## The core's targets", "",
           "From the C core's tables below (this run). A target is met where measured / bound ≤ 1. "
           f"For scale: merely rounding the half vector and the exponent to float, every other step exact, "
           f"costs up to {floor:.2e} on the specular lobe's inputs (the *floor* row below).", "",
           "| target | bound | measured | measured / bound |", "|---|---:|---:|---:|"]
    for what, bound, got, f in items:
        out.append(f"| {what} | {bound:{'.0e' if bound < 1 else 'g'}} | {got:{f}} | {got / bound:.2f} |")
    return "\n".join(out) + "\n"


def isa_picked(core: str) -> str:
    m = re.search(r"Best ISA here: (\w+)", core)
    return m.group(1) if m else "unknown"


def main() -> int:
    d, dst = Path(sys.argv[1]), Path(sys.argv[2])
    texts: Dict[str, Tuple[str, str]] = {}
    for stem, _, _ in SECTIONS:
        md, cmd = d / f"{stem}.md", d / f"{stem}.cmd"
        if not md.exists() or not cmd.exists():
            raise SystemExit(f"report.py: {md} or {cmd} missing: run bash bench/run.sh, which runs every program")
        texts[stem] = (md.read_text(encoding="utf-8").strip(), cmd.read_text(encoding="utf-8").strip())
    command = (d / "command").read_text().strip()
    quick = "--quick" in command.split()
    started = datetime.datetime.fromtimestamp(int((d / "started").read_text()), datetime.timezone.utc)
    ended = datetime.datetime.now(datetime.timezone.utc)
    load0 = (d / "load_before").read_text().split()
    load1 = [f"{x:.2f}" for x in os.getloadavg()]
    plot = pareto(d)
    mode = ("quick mode (`--quick`: smaller inputs and fewer repetitions than the full run; a smoke run, "
            "not figures to quote)") if quick else "full run"
    head = [
        "<!-- SPDX-FileCopyrightText: 2026 The pgloss authors -->",
        "<!-- SPDX-License-Identifier: Apache-2.0 -->",
        "# pgloss benchmarks", "",
        f"Written whole by `{command}` (bench/report.py): every table below comes from that one run on one "
        "machine; do not edit by hand. `python bench/check_stable.py OLD NEW` checks that two runs differ "
        "only in their numbers. The plot of time against error is written to "
        f"`{plot}` (not committed).", "",
        "| run | |", "|---|---|",
        f"| mode | {mode} |",
        f"| date | {started:%Y-%m-%d %H:%M}–{ended:%H:%M} UTC ({(ended - started).total_seconds():.0f} s) |",
        f"| CPU | {cpu()} |",
        f"| ISA the dispatcher picked | {isa_picked(texts['core'][0])} |",
        f"| load average (1, 5, 15 min) | {', '.join(load0)} before; {', '.join(load1)} after |",
        f"| OS | {platform.system()} {platform.release()} |",
        f"| compilers | {compilers()} |",
        f"| Python | {python_versions()} |",
        f"| commit | {commit()} |",
        f"| command | `{command}` |", "",
        "Timings drift with the machine's load: compare rows within one table, and read peers through "
        "the ratios measured side by side in the same run. Each table gives its inputs, its repetitions "
        "and its statistic above it.", "",
        "**Errors** are relative errors against an independent long-double (C) or float64 (peers) "
        "transcription of eq. 2 and Walter's pdf, on the same inputs: wo uniform over the hemisphere "
        "(cosθo ≥ 0.05), wi drawn by pgloss_sample (so the specular lobe is exercised where it "
        "matters), on the *regular range*: specular exponent tan²δ/α² ≤ 10, where 99.995 % of the "
        "lobe's energy lies (beyond it every float exp loses accuracy in proportion to the exponent).", "",
    ]
    body = [targets(d)]
    for stem, heading, how in SECTIONS:
        text, cmd = texts[stem]
        body.append(f"## {heading}\n\n{how}\n\nCommand: `{cmd}`\n\n{text}\n")
    body.append(LONG)
    dst.write_text("\n".join(head) + "\n" + "\n".join(body), encoding="utf-8")
    print(f"wrote {dst} and {plot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
