#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The tracer's correctness tests (tests/tracer): white furnace, MIS vs BRDF-only vs light-only,
# determinism across thread counts, scene-file errors, and the POV-Ray 3.7 reference
# comparison. Sets up its own Debian packages, builds examples/tracer, runs ctest. Nothing is
# skipped: with PGLOSS_REQUIRE_ALL=1 (CI, scripts/test.sh) a missing dependency is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
# openimageio-tools: Debian's OpenImageIOTargets.cmake names its tools (/usr/bin/iconvert, …)
# and find_package(OpenImageIO) fails without them.
bash scripts/bootstrap.sh apt g++ pkg-config libembree-dev libopenimageio-dev openimageio-tools \
  libopencolorio-dev libglm-dev fonts-dejavu-core libgtest-dev povray
echo "== configure + build build-tracer-test"
cmake --preset tracer-test >/dev/null
cmake --build --preset tracer-test
echo "== ctest build-tracer-test (tracer; measured values below, full log in build-tracer-test/ctest.log)"
status=0
ctest --test-dir build-tracer-test/tests-tracer --no-tests=error --output-on-failure -V >build-tracer-test/ctest.log 2>&1 || status=$?
grep -E "^[0-9]+: (furnace|alpha|povray|direct|mis,|light,|.* chi-square|.*Van Oosterom)|Test +#|tests passed|tests failed" build-tracer-test/ctest.log || true
if ((status != 0)); then
  grep -E "Failure|Expected|actual|Which is" -A2 build-tracer-test/ctest.log | head -80
  echo "== tracer tests FAILED"; exit "$status"
fi
echo "== tracer tests passed"
