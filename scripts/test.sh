#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Every test of every layer (the README's test command). Each layer's script does its own
# set-up and is quick when run again. Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the
# default here, and what CI sets) a missing dependency is a failure. A failing layer does not
# stop the others (one run shows every failure); the summary names each layer's result and
# time, and the exit status is 1 if any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS
summary=() failed=0
layer() { # SCRIPT [ARGS…]
  local t=$SECONDS rc=0
  echo "==== $*"
  bash "$@" || rc=$?
  summary+=("$(printf '%-28s %s in %d s' "$1" "$( ((rc == 0)) && echo passed || echo "FAILED (exit $rc)")" $((SECONDS - t)))")
  ((rc == 0)) || failed=1
}
layer scripts/test-core.sh
layer scripts/test-package.sh
layer scripts/test-python.sh
layer scripts/test-glsl.sh
layer scripts/test-materialx.sh
layer scripts/test-osl.sh
layer scripts/test-blender.sh
layer scripts/test-tracer.sh
layer scripts/test-bridge.sh
layer scripts/test-web.sh
layer scripts/test-experiment.sh
layer scripts/test-tsan.sh
layer scripts/fuzz.sh "${PGLOSS_FUZZ_SECONDS:-30}"
printf '%s\n' "== layers:" "${summary[@]}"
if ((failed)); then
  echo "== some tests FAILED ($((SECONDS - start)) s)"
  exit 1
fi
echo "== every test passed ($((SECONDS - start)) s)"
