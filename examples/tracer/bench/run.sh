#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# pgloss-tracer against Mitsuba 3 (llvm_ad_rgb), side by side on a tracer scene (a benchmark
# that prints Markdown tables; with --write, its own generated section of
# bench/results/tracer.md, which BENCHMARKS.md links; see mitsuba_compare.py).
# Builds the tracer and the pgloss tool in Release for this CPU (build-tracer-bench/,
# -march=native: Mitsuba's LLVM back end compiles its kernels for the host too), sets up
# Mitsuba from PyPI in its own venv (.venv-mitsuba, pinned below) and runs the comparison.
#   bash examples/tracer/bench/run.sh [--quick] [mitsuba_compare.py options…]
#   bash examples/tracer/bench/run.sh --scene mug --scale 1,10,32 --write bench/results/tracer.md
set -euo pipefail
cd "$(dirname "$0")/../../.."
bash scripts/bootstrap.sh apt g++ pkg-config libembree-dev libopenimageio-dev openimageio-tools \
  libopencolorio-dev libglm-dev fonts-dejavu-core libllvm19 python3-venv
echo "== build build-tracer-bench (Release)" >&2
cmake -S . -B build-tracer-bench -DCMAKE_BUILD_TYPE=Release -DPGLOSS_BUILD_EXAMPLES=ON \
  -DPGLOSS_BUILD_CLI=ON -DPGLOSS_TRACER_NATIVE=ON >/dev/null
cmake --build build-tracer-bench --target pgloss_tracer_cli pgloss_cli -j2 >/dev/null
pins=(mitsuba==3.9.1 drjit==1.5.0 numpy==2.4.6)
venv=.venv-mitsuba
if [[ "$(cat "$venv/.pgloss-pins" 2>/dev/null)" != "${pins[*]}" ]]; then
  echo "== venv $venv: ${pins[*]}" >&2
  python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "${pins[@]}"
  echo "${pins[*]}" >"$venv/.pgloss-pins"
fi
# Dr.Jit's LLVM back end needs LLVM >= 15 (Debian's libllvm19); where clang's LLVM 14 is also
# installed it would otherwise load that one and abort ("Cannot select: fminimum").
export DRJIT_LIBLLVM_PATH=${DRJIT_LIBLLVM_PATH:-$(dpkg -L libllvm19 | grep -m1 '/libLLVM-19\.so$')}
echo "== uptime: $(uptime)" >&2
exec "$venv/bin/python" examples/tracer/bench/mitsuba_compare.py \
  --tracer build-tracer-bench/examples/tracer/pgloss-tracer --pgloss build-tracer-bench/tools/pgloss "$@"
