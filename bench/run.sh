#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Regenerates BENCHMARKS.md whole, in one run on this machine (and out/bench/pareto.png): builds
# the benchmark programs in a default Release build (build-bench/; no -march: the batched loops
# pick the ISA at run time), sets up the Python layer (the package in .venv-py, as
# scripts/test-python.sh does, plus pinned Mitsuba 3 and moderngl for the peers), runs every
# program below, each writing out/bench/NAME.md (and NAME.cmd, the command), and then
# bench/report.py writes BENCHMARKS.md from them. --quick: the same programs and the same
# tables, with smaller inputs and fewer repetitions (a smoke run; the header says so).
# The long benchmarks are separate commands with their own generated files (BENCHMARKS.md links
# them): examples/tracer/bench/run.sh (bench/results/tracer.md), examples/bridge/validate.py
# (docs/bridge-validation.md, docs/bridge-harnesses.md).
#   bash bench/run.sh [--quick]
# bench/check_stable.py OLD NEW checks that two runs' files differ only in numbers.
set -euo pipefail
cd "$(dirname "$0")/.."
quick=()
case ${1:-} in
  --quick) quick=(--quick) ;;
  "") ;;
  *) echo "usage: bash bench/run.sh [--quick]" >&2; exit 2 ;;
esac
q=${#quick[@]}
bash scripts/bootstrap.sh apt libllvm19 libegl-mesa0 libgl1-mesa-dri
out=out/bench
rm -rf "$out"
mkdir -p "$out"
date -u +%s >"$out/started"
cut -d' ' -f1-3 /proc/loadavg >"$out/load_before"
echo "bash bench/run.sh${quick:+ ${quick[*]}}" >"$out/command"

# run NAME COMMAND…: runs COMMAND, its stdout to out/bench/NAME.md (and the terminal), the
# command itself to out/bench/NAME.cmd (BENCHMARKS.md quotes it above the table).
run() {
  local name=$1
  shift
  echo "== $name: $*"
  echo "$*" >"$out/$name.cmd"
  "$@" | tee "$out/$name.md"
}

echo "== build (build-bench: Release, default flags)"
cmake --preset bench >/dev/null
cmake --build --preset bench -j2 --target pgloss_bench_core pgloss_bench_inline_v3 pgloss_bench_inline_plain \
  pgloss_bench_texture pgloss_bench_rows >/dev/null
b=build-bench/bench
run core "$b/pgloss_bench_core" "${quick[@]}" --csv "$out/core.csv"
run inline_v3 "$b/pgloss_bench_inline_v3" "${quick[@]}"
run inline_plain "$b/pgloss_bench_inline_plain" "${quick[@]}"
run texture "$b/pgloss_bench_texture" "${quick[@]}"
run rows "$b/pgloss_bench_rows" "${quick[@]}"

echo "== Python layer + peers"
PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh >/dev/null
py=.venv-py/bin/python
peer_pins=(mitsuba==3.9.1 drjit==1.5.0 moderngl==5.13.0)
if [[ "$(cat .venv-py/.pgloss-bench-pins 2>/dev/null)" != "${peer_pins[*]}" ]]; then
  "$py" -m pip install -q --disable-pip-version-check "${peer_pins[@]}"
  echo "${peer_pins[*]}" >.venv-py/.pgloss-bench-pins
fi
pb=bindings/python/bench
# --quick keeps every row: bench_textures.py's in-cache rows need more than 2^16 pairs (size 2048: 2^18).
if ((q)); then
  run peers "$py" bench/peers.py --n $((1 << 16)) --csv "$out/peers.csv"
  run python_textures "$py" $pb/bench_textures.py --size 2048 --repeat 3 --csv "$out/python_textures.csv"
  run python_calls "$py" $pb/bench_calls.py --n $((1 << 16)) --repeat 5
  run python_threads "$py" $pb/bench_threads.py --repeat 5
else
  run peers "$py" bench/peers.py --n $((1 << 20)) --csv "$out/peers.csv"
  run python_textures "$py" $pb/bench_textures.py --size 4096 --csv "$out/python_textures.csv"
  run python_calls "$py" $pb/bench_calls.py --n $((1 << 20)) --repeat 15
  run python_threads "$py" $pb/bench_threads.py --repeat 50
fi

echo "== BENCHMARKS.md"
MPLBACKEND=Agg MPLCONFIGDIR="$PWD/$out/mpl" "$py" bench/report.py "$out" BENCHMARKS.md
