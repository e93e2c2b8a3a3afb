#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The gloss bridge's instruments (tests/bridge): the image gloss meter (pgloss.image_meter) on
# pgloss-tracer Ward renders of known paints, and one low-spp batch per real-renderer harness
# (examples/bridge): Mitsuba 3 from PyPI (llvm_ad_rgb, LLVM 19), Cycles from PyPI bpy 5.0.1
# (.venv-bpy of scripts/test-osl.sh: Principled, glTF through Blender's importer, MaterialX
# open_pbr_surface through genosl). Sets up .venv-bridge (Mitsuba, OpenImageIO, MaterialX, the
# pgloss package) and pgloss-tracer (build-tracer-test, as scripts/test-tracer.sh).
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the default here, and what CI sets) a skipped
# test is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
# libllvm19: Dr.Jit's LLVM back end (Mitsuba's llvm_ad_rgb); the tracer's packages as test-tracer.sh.
bash scripts/bootstrap.sh apt g++ cmake python3 python3-venv python3-dev libllvm19 pkg-config libembree-dev \
  libopenimageio-dev openimageio-tools libopencolorio-dev libglm-dev fonts-dejavu-core libgtest-dev
bash scripts/bootstrap.sh test  # .venv-tools, which the test preset (the pgloss tool's build) names
PGLOSS_OSL_SETUP_ONLY=1 bash scripts/test-osl.sh

root=$PWD
py=.venv-bridge/bin/python
mapfile -t pins < <(grep -vE '^[[:space:]]*(#|$)' tests/bridge/requirements.txt)
bash scripts/venv-pgloss.sh .venv-bridge "${pins[@]}"

echo "== pgloss-tracer (build-tracer-test) and the pgloss tool (build-test; its bridge command maps the paints)"
step "configure (build-tracer-test)" cmake --preset tracer-test
step "build pgloss-tracer (build-tracer-test)" cmake --build --preset tracer-test --target pgloss-tracer
step "configure (build-test)" cmake --preset test
step "build pgloss_cli, pgloss_bridge_tables (build-test)" cmake --build --preset test --target pgloss_cli pgloss_bridge_tables

# Dr.Jit loads the first libLLVM it finds; clang's LLVM 14 aborts it ("Cannot select: fminimum").
llvm=$(ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so /usr/lib/llvm-19/lib/libLLVM-19.so 2>/dev/null | head -1 || true)
[[ -n $llvm ]] || { echo "test-bridge: libLLVM-19.so not found (libllvm19)"; exit 1; }
export DRJIT_LIBLLVM_PATH=$llvm
start=$SECONDS
set +e
PGLOSS_TRACER=$root/build-tracer-test/examples/tracer/pgloss-tracer PGLOSS_TOOL=$root/build-test/tools/pgloss \
  PGLOSS_BRIDGE_TABLES=$root/build-test/tools/pgloss_bridge_tables \
  "$py" -m pytest -q -s -p no:cacheprovider -rs tests/bridge 2>&1 | grep -v -e 'DeprecationWarning' -e 'use_nodes'
rc=${PIPESTATUS[0]}
set -e
echo "== bridge tests: exit $rc ($((SECONDS - start)) s)"
exit "$rc"
