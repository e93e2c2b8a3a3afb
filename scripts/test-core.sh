#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The C core's tests: set up, then build and run the suite twice — a Release build, and a
# build under AddressSanitizer + UndefinedBehaviorSanitizer. Nothing is skipped: with
# PGLOSS_REQUIRE_ALL=1 (CI sets it) a missing dependency is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh test
jobs=$(nproc)

# The presets (CMakePresets.json) hold the build folders and options: build-test, build-asan.
source scripts/step.sh
run_suite() { # preset
  local t=$SECONDS
  step "configure build-$1 (cmake --preset $1)" cmake --preset "$1"
  step "build build-$1" cmake --build --preset "$1"
  echo "== build-$1 configured and built in $((SECONDS - t)) s; ctest build-$1"
  ctest --preset "$1" -j "$jobs"
  # Which batched-kernel ISAs ran (an ISA the CPU lacks is a skip with its reason: test_isa.cpp).
  "build-$1/tests/test_isa" --gtest_filter=Isa.NamesAndSupport | grep -E '^(best ISA|ISAs tested)'
}

run_suite test
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  PGLOSS_SANITIZED=1 run_suite asan
echo "== core test suites passed"
