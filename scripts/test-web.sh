#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The colour/gloss picker's tests (web/picker, tests/web):
#   1. the WebAssembly build of libpgloss against the shared vectors, under Node (tests/web/vectors.mjs);
#   2. the page in Debian's headless Chromium (WebGL2 on SwiftShader) driven by Playwright for
#      Python (tests/web/test_picker.py): read-outs equal the Python binding, the render agrees
#      with pgloss-tracer per region within its measured noise, URL-hash state, export, screenshots
#      in out/web/; the shared vectors again in Chromium, the gloss-bridge targets' read-outs and
#      glossmeter readings against the binding, paint entry by gloss units and finish, and the
#      targets' exports read by their own libraries: glTF by three.js's GLTFLoader (npm, tests/web),
#      MaterialX by MaterialX's validation and Mitsuba 3 by mitsuba.load_string (PyPI, .venv-bridge);
#   3. (c, d) read by the image gloss meter (pgloss.image_meter, .venv-bridge, a pgloss-tracer
#      basis) from the page's own renders of the stimulus scene (tests/web/test_picker_meter.py).
# Sets up its own packages and the venv .venv-web (pinned; Playwright uses the system Chromium,
# no browser download). Quick when run again. Nothing is skipped: with PGLOSS_REQUIRE_ALL=1
# (CI, scripts/test.sh) a skipped test is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS
bash scripts/bootstrap.sh apt clang lld llvm wasi-libc libclang-rt-14-dev-wasm32 nodejs chromium \
  python3 python3-venv openimageio-tools libllvm19
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

# three.js for the glTF export's test (tests/web/package-lock.json; npm ci: exactly the lockfile).
command -v npm >/dev/null || bash scripts/bootstrap.sh apt npm
stamp=$(sha256sum tests/web/package-lock.json | cut -c1-16)
if [[ "$(cat tests/web/node_modules/.pgloss-lock 2>/dev/null)" != "$stamp" ]]; then
  step "npm ci (tests/web: three.js)" npm ci --prefix tests/web --ignore-scripts --no-audit --no-fund
  echo "$stamp" >tests/web/node_modules/.pgloss-lock
fi
# MaterialX and Mitsuba 3 for the MaterialX and Mitsuba exports' tests, and pgloss with OpenImageIO
# for the image gloss meter on the page's renders (the versions test-bridge.sh pins).
xvenv=.venv-bridge  # the gloss bridge layer's venv, one list of pins (tests/bridge/requirements.txt)
mapfile -t pins < <(grep -vE '^[[:space:]]*(#|$)' tests/bridge/requirements.txt)
bash scripts/venv-pgloss.sh "$xvenv" "${pins[@]}"
# Dr.Jit loads the first libLLVM it finds; clang's LLVM 14 aborts it ("Cannot select: fminimum").
llvm=$(ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so /usr/lib/llvm-19/lib/libLLVM-19.so 2>/dev/null | head -1 || true)
[[ -n $llvm ]] || { echo "test-web: libLLVM-19.so not found (libllvm19)"; exit 1; }
export DRJIT_LIBLLVM_PATH=$llvm PGLOSS_WEB_EXPORT_PY="$PWD/$xvenv/bin/python"

echo "== pytest tests/web (headless Chromium $(chromium --version 2>/dev/null | awk '{print $2}'), SwiftShader)"
export PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
export PGLOSS_WEB_SITE="$PWD/build-web/site" PGLOSS_WEB_PY="$PWD/.venv-py/bin/python" \
  PGLOSS_TRACER="$PWD/build-tracer-test/examples/tracer/pgloss-tracer" PGLOSS_CHROMIUM=/usr/bin/chromium
args=(-q -p no:cacheprovider -rs -s tests/web)
status=0
"$venv/bin/python" -m pytest "${args[@]}" || status=$?
if ((status != 0)); then echo "== web tests FAILED"; exit "$status"; fi
echo "== web tests passed ($((SECONDS - start)) s)"
