#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The libFuzzer harnesses (tests/fuzz): builds them with clang under ASan + UBSan in build-fuzz/,
# then runs each for SECONDS (default 60), as many at once as there are cores, and prints per
# harness the executions, execs/s, coverage and corpus size. Exits non-zero on any finding
# (the crashing input is kept in build-fuzz/findings/). The corpora grow in build-fuzz/corpus/
# from the seeds in tests/fuzz/corpus/ (and the shipped scenes), so later runs start further on.
#   scripts/fuzz.sh [SECONDS] [HARNESS…]      harnesses: brdf perceptual scene cli tool
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
secs=${1:-60}
shift || true
harnesses=("$@")
((${#harnesses[@]})) || harnesses=(brdf perceptual scene cli tool)
bash scripts/bootstrap.sh apt clang libclang-rt-14-dev libglm-dev
echo "== fuzz: build (clang, libFuzzer, ASan + UBSan)"
step "configure (fuzz)" cmake --preset fuzz
step "build the fuzzers" cmake --build --preset fuzz --target $(printf 'fuzz_%s ' "${harnesses[@]}")
mkdir -p build-fuzz/findings build-fuzz/logs
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=abort_on_error=1:detect_leaks=1

run_one() {
  local h=$1 seeds=(tests/fuzz/corpus/$1)
  [[ $h == scene ]] && seeds+=(examples/tracer/scenes)
  mkdir -p "build-fuzz/corpus/$h"
  build-fuzz/tests/fuzz/fuzz_"$h" -max_total_time="$secs" -print_final_stats=1 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/findings/$h-" "build-fuzz/corpus/$h" "${seeds[@]}" >"build-fuzz/logs/$h.log" 2>&1
}

echo "== fuzz: ${harnesses[*]}, ${secs} s each, $(nproc) at a time"
declare -A rc
running=()
for h in "${harnesses[@]}"; do
  run_one "$h" & running+=("$h:$!")
  if ((${#running[@]} >= $(nproc))); then
    for r in "${running[@]}"; do wait "${r#*:}" && rc[${r%%:*}]=0 || rc[${r%%:*}]=$?; done
    running=()
  fi
done
for r in "${running[@]}"; do wait "${r#*:}" && rc[${r%%:*}]=0 || rc[${r%%:*}]=$?; done

failed=0
printf '%-11s %12s %10s %8s %8s %7s  %s\n' harness execs execs/s cov ft corpus result
for h in "${harnesses[@]}"; do
  log=build-fuzz/logs/$h.log
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  eps=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\).*/\1/p' <<<"$last")
  result=ok
  if ((rc[$h] != 0)); then result="FINDING (exit ${rc[$h]}; log $log)"; failed=1; fi
  printf '%-11s %12s %10s %8s %8s %7s  %s\n' "$h" "${execs:-?}" "${eps:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result"
done
if ((failed)); then
  for h in "${harnesses[@]}"; do
    ((rc[$h] != 0)) && { echo "---- $h"; grep -E -B2 -A25 'ERROR|contract violated|runtime error|deadly signal' "build-fuzz/logs/$h.log" | head -60; }
  done
  echo "== fuzz: FINDINGS"
  exit 1
fi
echo "== fuzz: no finding"
