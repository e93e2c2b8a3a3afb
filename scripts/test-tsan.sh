#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# ThreadSanitizer: the core and the tracer built with -fsanitize=thread (clang) in build-tsan/,
# then (1) tests/test_threads: 8 threads hammering eval, sample and every batch tier and ISA on
# shared materials, and (2) the tracer rendering the stimulus scene with 8 threads on this
# machine's cores. Any report fails the run (halt_on_error). Quick when run again.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh test
bash scripts/bootstrap.sh apt clang libclang-rt-14-dev pkg-config libembree-dev libopenimageio-dev \
  openimageio-tools libopencolorio-dev libglm-dev fonts-dejavu-core
echo "== TSan: configure + build build-tsan (clang -fsanitize=thread)"
step "configure (tsan)" cmake --preset tsan
step "build (tsan)" cmake --build --preset tsan --target test_threads pgloss_tracer_cli
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
echo "== TSan: test_threads"
build-tsan/tests/test_threads
echo "== TSan: pgloss-tracer, 8 threads on $(nproc) cores"
build-tsan/examples/tracer/pgloss-tracer render examples/tracer/scenes/stimulus.scene --threads 8 --spp 4 \
  --size 64x48 --quiet --out build-tsan/tsan-stimulus
echo "== TSan: no data race reported"
