#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Regenerates BENCHMARKS.md (and out/bench/pareto.png): builds the core's benchmark in a
# default Release build (no -march: the batched loops pick the ISA at run time), runs it,
# sets up the Python layer (the package in .venv-py, as scripts/test-python.sh does, plus
# pinned Mitsuba 3 and moderngl) and runs the peers, then writes the report.
#   bash bench/run.sh [--quick]
set -euo pipefail
cd "$(dirname "$0")/.."
quick=()
[[ ${1:-} == --quick ]] && quick=(--quick)
bash scripts/bootstrap.sh apt libllvm19 libegl-mesa0 libgl1-mesa-dri
mkdir -p out/bench

echo "== build (Release, default flags)"
cmake --preset bench >/dev/null
cmake --build --preset bench --target pgloss_bench_core pgloss_bench_inline_v3 pgloss_bench_inline_plain \
  pgloss_bench_texture >/dev/null
echo "== bench_core"
./build-bench/bench/pgloss_bench_core "${quick[@]}" --csv out/bench/core.csv | tee out/bench/core.md
echo "== bench_texture"
./build-bench/bench/pgloss_bench_texture "${quick[@]}" | tee out/bench/texture.md
echo "== bench_inline (-O2 -march=x86-64-v3, then -O2)"
./build-bench/bench/pgloss_bench_inline_v3 "${quick[@]}" | tee out/bench/inline_v3.md
./build-bench/bench/pgloss_bench_inline_plain "${quick[@]}" | tee out/bench/inline_plain.md

echo "== Python layer + peers"
PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh >/dev/null
py=.venv-py/bin/python
peer_pins=(mitsuba==3.9.1 drjit==1.5.0 moderngl==5.13.0)
if [[ "$(cat .venv-py/.pgloss-bench-pins 2>/dev/null)" != "${peer_pins[*]}" ]]; then
  "$py" -m pip install -q --disable-pip-version-check "${peer_pins[@]}"
  echo "${peer_pins[*]}" >.venv-py/.pgloss-bench-pins
fi
n=$((1 << 20)); [[ ${#quick[@]} -gt 0 ]] && n=$((1 << 16))
"$py" bench/peers.py --n "$n" --csv out/bench/peers.csv | tee out/bench/peers.md
side=4096; [[ ${#quick[@]} -gt 0 ]] && side=512
"$py" bindings/python/bench/bench_textures.py --size "$side" --csv out/bench/python_textures.csv | tee out/bench/python_textures.md

echo "== BENCHMARKS.md"
MPLBACKEND=Agg MPLCONFIGDIR="$PWD/out/bench/mpl" "$py" bench/report.py out/bench BENCHMARKS.md
