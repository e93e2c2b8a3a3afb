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
py="$PWD/.venv-tools/bin/python"
jobs=$(nproc)

run_suite() { # dir, extra cmake args...
  local dir=$1; shift
  echo "== configure + build $dir"
  cmake -S . -B "$dir" -G Ninja -DPGLOSS_BUILD_TESTS=ON -DPython3_EXECUTABLE="$py" "$@" >/dev/null
  cmake --build "$dir"
  echo "== ctest $dir"
  ctest --test-dir "$dir" --output-on-failure -j "$jobs"
  # Which batched-kernel ISAs ran (an ISA the CPU lacks is a skip with its reason: test_isa.cpp).
  "$dir/tests/test_isa" --gtest_filter=Isa.NamesAndSupport | grep -E '^(best ISA|ISAs tested)'
}

run_suite build-test -DCMAKE_BUILD_TYPE=Release
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  PGLOSS_SANITIZED=1 run_suite build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPGLOSS_SANITIZE=ON
echo "== core test suites passed"
