#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The colour/gloss picker's tests (web/picker, tests/web):
#   1. the WebAssembly build of libpgloss against the shared vectors, under Node (tests/web/vectors.mjs);
#   2. the page in Debian's headless Chromium (WebGL2 on SwiftShader) driven by Playwright for
#      Python (tests/web/test_picker.py): read-outs equal the Python binding, the render agrees
#      with pgloss-tracer per region within its measured noise, URL-hash state, export, screenshots
#      in out/web/.
# Sets up its own packages and the venv .venv-web (pinned; Playwright uses the system Chromium,
# no browser download). Quick when run again. Nothing is skipped: with PGLOSS_REQUIRE_ALL=1
# (CI, scripts/test.sh) a skipped test is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS
bash scripts/bootstrap.sh apt clang lld llvm wasi-libc libclang-rt-14-dev-wasm32 nodejs chromium \
  python3 python3-venv openimageio-tools
# What the reference render and the expected values need: the tracer's packages and the binding.
bash scripts/bootstrap.sh apt g++ pkg-config libembree-dev libopenimageio-dev libopencolorio-dev \
  libglm-dev fonts-dejavu-core libgtest-dev

echo "== build the picker (wasm + site)"
bash scripts/picker.sh --build

echo "== WebAssembly core against the shared vectors (node $(node --version))"
node tests/web/vectors.mjs build-web/wasm/pgloss.wasm

echo "== Python binding (expected values), pgloss-tracer (reference render)"
PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh
# The same configuration as scripts/test-tracer.sh, so that the two share one build folder.
step "configure (build-tracer-test)" cmake -S . -B build-tracer-test -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPGLOSS_BUILD_CLI=OFF -DPGLOSS_BUILD_EXAMPLES=ON -DPGLOSS_BUILD_TRACER_TESTS=ON
step "build pgloss-tracer" cmake --build build-tracer-test --target pgloss-tracer

venv=.venv-web
bash scripts/venv-web.sh

echo "== pytest tests/web (headless Chromium $(chromium --version 2>/dev/null | awk '{print $2}'), SwiftShader)"
export PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
export PGLOSS_WEB_SITE="$PWD/build-web/site" PGLOSS_WEB_PY="$PWD/.venv-py/bin/python" \
  PGLOSS_TRACER="$PWD/build-tracer-test/examples/tracer/pgloss-tracer" PGLOSS_CHROMIUM=/usr/bin/chromium
args=(-q -p no:cacheprovider -rs -s tests/web)
status=0
"$venv/bin/python" -m pytest "${args[@]}" || status=$?
if ((status != 0)); then echo "== web tests FAILED"; exit "$status"; fi
echo "== web tests passed ($((SECONDS - start)) s)"
