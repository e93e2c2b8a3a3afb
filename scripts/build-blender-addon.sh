#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Builds the Blender extension blender/pgloss_paint into out/blender/pgloss_paint-<version>.zip:
# the add-on, the self-contained shader osl/standalone/pgloss_material.osl and a wheel of the
# pgloss Python package (built with .venv-py, CPython 3.11 as Blender 4.2–5.x). Quick when re-run.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh >/dev/null
py=$PWD/.venv-py/bin/python
build=build-blender
sources=$(find pyproject.toml CMakeLists.txt libpgloss bindings/python -type f -not -path '*/__pycache__/*' -print0 |
          sort -z | xargs -0 sha256sum | sha256sum | cut -c1-16)
if [[ "$(cat "$build/.wheel-sources" 2>/dev/null)" != "$sources" ]] || ! ls "$build"/wheels/pgloss-*.whl >/dev/null 2>&1; then
  echo "== building the pgloss wheel"
  rm -rf "$build/wheels"
  mkdir -p "$build/wheels"
  CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
    step "pip wheel ." "$py" -m pip wheel -v --disable-pip-version-check --no-deps --no-build-isolation -w "$build/wheels" .
  echo "$sources" >"$build/.wheel-sources"
fi
wheel=$(basename "$(ls "$build"/wheels/pgloss-*.whl | head -1)")
stage=$build/pgloss_paint
rm -rf "$stage"
mkdir -p "$stage/wheels"
cp blender/pgloss_paint/*.py "$stage/"
sed "s/@WHEEL@/$wheel/" blender/pgloss_paint/blender_manifest.toml >"$stage/blender_manifest.toml"
cp osl/standalone/pgloss_material.osl "$stage/"
cp "$build/wheels/$wheel" "$stage/wheels/"
version=$(sed -n 's/^version = "\(.*\)"/\1/p' blender/pgloss_paint/blender_manifest.toml)
mkdir -p out/blender
zip_path=$PWD/out/blender/pgloss_paint-$version.zip
rm -f "$zip_path"
(cd "$stage" && "$py" -c "
import sys, zipfile, os
with zipfile.ZipFile(sys.argv[1], 'w', zipfile.ZIP_DEFLATED) as z:
    for root, _, files in os.walk('.'):
        for f in sorted(files):
            p = os.path.join(root, f)
            z.write(p, os.path.relpath(p, '.'))
" "$zip_path")
echo "$zip_path"
