#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Static throughput of the float lobe's FAST tier on AVX-512 (a block of 16) on AMD Zen 4 (llvm-mca 19): the
# operation count and FP-pipe bound (docs/kernels.md). Informational: a static model of a CPU,
# not a measurement, so not part of bench/run.sh or the tests (it installs Debian's llvm-19).
#   bash bench/mca.sh [CPU]            (default znver4)
#   bash bench/mca.sh --inline [CPU]   pgloss/inline.h's eval_pdf and sample (bench/inline_mca.c)
#                                      compiled -O2 -march=x86-64-v3 and -O2: throughput of
#                                      independent calls, and one call's critical path
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh apt llvm-19
mkdir -p out/bench
if [[ ${1:-} == --inline ]]; then
  cpu=${2:-znver4}
  echo "| compiled | function | instructions | cycles per call, independent calls | critical path of one call (cycles) |"
  echo "|---|---|---:|---:|---:|"
  for flags in "-O2 -march=x86-64-v3" "-O2"; do
    cc $flags -S -o out/bench/inline_mca.s -Ilibpgloss/include bench/inline_mca.c
    llvm-mca-19 -mcpu="$cpu" -iterations=200 out/bench/inline_mca.s >out/bench/inline_mca_thr.txt
    llvm-mca-19 -mcpu="$cpu" -iterations=1 out/bench/inline_mca.s >out/bench/inline_mca_lat.txt
    paste <(awk '/Code Region - /{r=$NF} /^Instructions:/{i=$2} /^Total Cycles:/{print r, i / 200, $3 / 200}' out/bench/inline_mca_thr.txt) \
          <(awk '/^Total Cycles:/{print $3}' out/bench/inline_mca_lat.txt) |
      awk -v f="$flags" '{printf "| %s | %s | %.0f | %.1f | %d |\n", f, $1, $2, $3, $4}'
  done
  exit 0
fi
cpu=${1:-znver4}
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
