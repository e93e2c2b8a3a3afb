#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Every test of every layer (the README's test command), or the layers named:
#   bash scripts/test.sh                 every layer
#   bash scripts/test.sh core python     those layers only (names as in the table below)
# Each layer's script does its own set-up and is quick when run again. Nothing is skipped: with
# PGLOSS_REQUIRE_ALL=1 (the default here, and what CI sets) a missing dependency is a failure.
# A failing layer does not stop the others; the exit status is 1 if any failed.
#
# Two lanes run at once (PGLOSS_TEST_JOBS=1: one after the other): the C builds under the
# sanitizers and the docs in one, the Python, renderer and browser layers in the other. No two
# layers in different lanes share a build folder or a venv, so they cannot race; the browser
# and render tests wait on round trips more than on the CPU, and fill the other lane's gaps.
# The layers' builds of the same sources with the same flags compile once (scripts/ccache.sh).
# Each layer's output goes to out/test-logs/NAME.log and is printed whole when the layer ends;
# the last lines are a table: layer, result, tests passed / failed / skipped (counted from the
# output by scripts/test-counts.awk), seconds.
set -uo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS

# name, then the command. The second lane starts with layers that compile nothing of the core,
# so that the first lane's build-test/ fills the compiler cache before the second lane needs it.
declare -A cmd=(
  [core]="scripts/test-core.sh"
  [package]="scripts/test-package.sh"
  [tsan]="scripts/test-tsan.sh"
  [fuzz]="scripts/fuzz.sh ${PGLOSS_FUZZ_SECONDS:-10}"
  [glsl]="scripts/test-glsl.sh"
  [docs]="scripts/docs.sh"
  [python]="scripts/test-python.sh"
  [materialx]="scripts/test-materialx.sh"
  [osl]="scripts/test-osl.sh"
  [blender]="scripts/test-blender.sh"
  [tracer]="scripts/test-tracer.sh"
  [bridge]="scripts/test-bridge.sh"
  [web]="scripts/test-web.sh"
  [experiment]="scripts/test-experiment.sh"
)
lane1=(core package tsan fuzz glsl docs)
lane2=(materialx osl python experiment web blender tracer bridge)
order=("${lane1[@]}" "${lane2[@]}")
if (($#)); then
  for name in "$@"; do
    [[ -n ${cmd[$name]:-} ]] || { echo "test.sh: unknown layer '$name' (${order[*]})" >&2; exit 2; }
  done
  keep() { local n w out=(); for n in "$@"; do for w in "${want[@]}"; do [[ $n == "$w" ]] && out+=("$n"); done; done; echo "${out[@]}"; }
  want=("$@")
  read -ra lane1 <<<"$(keep "${lane1[@]}")"
  read -ra lane2 <<<"$(keep "${lane2[@]}")"
  order=("${lane1[@]}" "${lane2[@]}")
fi

jobs=${PGLOSS_TEST_JOBS:-2}
source scripts/ccache.sh || exit 1
[[ ${PGLOSS_CCACHE:-1} != 0 ]] && ccache --zero-stats >/dev/null
logs=out/test-logs
rm -rf "$logs" && mkdir -p "$logs"
printf '== %s, %d lane(s), %d cores, load %s\n' "$(date -u '+%F %T UTC')" "$jobs" "$(nproc)" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"

layer() { # NAME: runs it, keeps its log, writes NAME.result: rc seconds passed failed skipped
  local name=$1 log=$logs/$1.log t=$SECONDS rc=0
  printf '[test %(%H:%M:%S)T] ==== %s: bash %s\n' -1 "$name" "${cmd[$name]}"
  if ((jobs == 1)); then
    # shellcheck disable=SC2086
    bash ${cmd[$name]} 2>&1 | tee "$log"; rc=${PIPESTATUS[0]}
  else
    # shellcheck disable=SC2086
    bash ${cmd[$name]} >"$log" 2>&1 || rc=$?
  fi
  echo "$rc $((SECONDS - t)) $(awk -f scripts/test-counts.awk "$log")" >"$logs/$name.result"
  local verdict; verdict=$( ((rc == 0)) && echo passed || echo "FAILED (exit $rc)")
  if ((jobs == 1)); then
    printf '[test %(%H:%M:%S)T] ==== %s %s in %d s\n' -1 "$name" "$verdict" $((SECONDS - t))
  else  # the whole log at once, not interleaved with the other lane's
    flock "$logs" bash -c 'printf "[test %(%H:%M:%S)T] ==== %s %s in %d s; its output:\n" -1 "$1" "$2" "$3"
      cat "$4"; printf "[test %(%H:%M:%S)T] ==== end of %s\n" -1 "$1"' _ "$name" "$verdict" $((SECONDS - t)) "$log"
  fi
}
lane() { local name; for name in "$@"; do layer "$name"; done; }

if ((jobs == 1)); then
  lane "${order[@]}"
else
  lane "${lane1[@]}" & pid1=$!
  lane "${lane2[@]}" & pid2=$!
  wait "$pid1" "$pid2"
fi

failed=0 sum=0 tp=0 tf=0 ts=0
echo "== layers ($(nproc) cores, ${jobs} lane(s); logs in $logs/)"
printf '%-11s %-18s %7s %7s %8s %8s\n' layer result passed failed skipped seconds
for name in "${order[@]}"; do
  if [[ -f $logs/$name.result ]]; then
    read -r rc secs p f s <"$logs/$name.result"
  else
    rc=1 secs=0 p=0 f=0 s=0
  fi
  ((rc == 0)) && verdict=passed || { verdict="FAILED (exit $rc)"; failed=1; }
  # A layer that passed with a failing count, or failed with none counted, still shows it failed.
  ((rc != 0 && f == 0)) && f=1
  printf '%-11s %-18s %7d %7d %8d %8d\n' "$name" "$verdict" "$p" "$f" "$s" "$secs"
  sum=$((sum + secs)) tp=$((tp + p)) tf=$((tf + f)) ts=$((ts + s))
done
printf '%-11s %-18s %7d %7d %8d %8d\n' total "wall $((SECONDS - start)) s" "$tp" "$tf" "$ts" "$sum"
[[ ${PGLOSS_CCACHE:-1} != 0 ]] && echo "== ccache: $(ccache --print-stats 2>/dev/null | awk -F'\t' '$1=="direct_cache_hit"||$1=="preprocessed_cache_hit"{h+=$2} $1=="cache_miss"{m=$2} END{printf "%d hits, %d misses", h, m}')"
if ((failed)); then
  echo "== some tests FAILED ($((SECONDS - start)) s)"
  exit 1
fi
echo "== every test passed ($((SECONDS - start)) s)"
