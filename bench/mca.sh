#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Static throughput of the FAST tier's AVX-512 eval block on AMD Zen 4 (llvm-mca 19): the
# operation count and FP-pipe bound quoted in BENCHMARKS.md. Informational; not part of
# bench/run.sh or the tests (it installs Debian's llvm-19 for llvm-mca).
#   bash bench/mca.sh [CPU]      (default znver4)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh apt llvm-19
cpu=${1:-znver4}
mkdir -p out/bench
cc -O3 -S -o out/bench/fast_block_mca.s -Ilibpgloss/include -Ilibpgloss/src \
  -mavx2 -mfma -mavx512f -mavx512vl -mavx512dq -mavx512bw -mprefer-vector-width=512 \
  -fno-math-errno -fno-trapping-math -ffp-contract=off bench/fast_block_mca.c
llvm-mca-19 -mcpu="$cpu" -iterations=300 out/bench/fast_block_mca.s >out/bench/fast_block_mca.txt
it=300
awk -v it=$it '/^Instructions:/ {printf "instructions per block of 16: %.0f\n", $2 / it}
               /^Total Cycles:/ {printf "cycles per block of 16: %.1f (%.2f per evaluation)\n", $3 / it, $3 / it / 16}' \
  out/bench/fast_block_mca.txt
grep -A2 'Resource pressure per iteration' out/bench/fast_block_mca.txt | tail -1 |
  awk '{printf "pressure per block: FP0 %s, FP1 %s (multiply/FMA), FP2 %s, FP3 %s (add)\n", $9, $10, $11, $12}'
echo "instruction mix per block:"
awk '/Instruction Info:/ {f = 1; next} /Resources:/ {f = 0} f && /^ *[0-9]/' out/bench/fast_block_mca.txt |
  grep -oE '\b(v[a-z0-9]+|k[a-z]+)\b' | sort | uniq -c | sort -rn | awk '{printf "  %3d %s\n", $1, $2}'
echo "full report: out/bench/fast_block_mca.txt"
