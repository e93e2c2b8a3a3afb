#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The colour/gloss picker (web/picker): builds libpgloss to WebAssembly (clang --target=wasm32-wasi,
# CMake toolchain cmake/wasm32-wasi.cmake) into build-web/wasm, assembles the static site in
# build-web/site (the page, glsl/pgloss.glsl and the tracer's stimulus scene, copied verbatim),
# and serves it on http://127.0.0.1:PORT/ (PORT=8765 unless set).
#   bash scripts/picker.sh            build + serve (Ctrl-C stops)
#   bash scripts/picker.sh --build    build only (what scripts/test-web.sh uses)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
bash scripts/bootstrap.sh apt clang lld llvm wasi-libc libclang-rt-14-dev-wasm32 python3
step "configure (build-web/wasm)" cmake -S web/picker/wasm -B build-web/wasm -G Ninja \
  -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/wasm32-wasi.cmake"
step "build pgloss.wasm" cmake --build build-web/wasm -j "${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
site=build-web/site
rm -rf "$site"
mkdir -p "$site"
cp web/picker/*.html web/picker/*.js web/picker/*.css web/picker/*.glsl "$site"/
cp glsl/pgloss.glsl examples/tracer/scenes/stimulus.scene build-web/wasm/pgloss.wasm "$site"/
echo "picker: built $site ($(stat -c %s "$site/pgloss.wasm") bytes of wasm)"
[[ ${1:-} == --build ]] && exit 0
port=${PORT:-8765}
echo "picker: open http://127.0.0.1:$port/   (Ctrl-C to stop)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
