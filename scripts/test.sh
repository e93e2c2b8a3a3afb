#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Every test of every layer (the README's test command). Each layer's script does its own
# set-up and is quick when run again. Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the
# default here, and what CI sets) a missing dependency is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS
bash scripts/test-core.sh
bash scripts/test-package.sh
bash scripts/test-python.sh
bash scripts/test-glsl.sh
bash scripts/test-materialx.sh
bash scripts/test-osl.sh
bash scripts/test-blender.sh
bash scripts/test-tracer.sh
bash scripts/test-bridge.sh
bash scripts/test-web.sh
bash scripts/test-experiment.sh
bash scripts/test-tsan.sh
bash scripts/fuzz.sh "${PGLOSS_FUZZ_SECONDS:-30}"
echo "== every test passed ($((SECONDS - start)) s)"
