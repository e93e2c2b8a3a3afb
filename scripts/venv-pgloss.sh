#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# A pinned venv with the pgloss package in it: bash scripts/venv-pgloss.sh VENV PIN…
# (scripts/test-python.sh: .venv-py; scripts/test-bridge.sh: .venv-bridge). The venv is made
# anew only when the pins change; `pip install .` (the README's install command, with the venv's
# pinned build tools) runs only when the package's sources changed, and CMake's build folder
# (build-VENV-TAG/ for .VENV, one per venv so that two can build at once, one level below the
# tree as pyproject's build-py-TAG/, so that the compiler cache serves it) is kept, so a
# reinstall recompiles only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
root=$PWD
venv=$1
shift
pins=("$@")
py=$venv/bin/python
name=${venv##*/}
if [[ ! -x $py ]] || [[ "$(cat "$venv/.pgloss-pins" 2>/dev/null)" != "${pins[*]}" ]]; then
  echo "== creating $venv (${pins[*]})"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  step "pip install (pins)" pip_pins "$py" "${pins[@]}"
  echo "${pins[*]}" >"$venv/.pgloss-pins"
fi
sources=$(find pyproject.toml CMakeLists.txt libpgloss tools bindings/python -type f \
            -not -path '*/__pycache__/*' -print0 | sort -z | xargs -0 sha256sum | sha256sum | cut -c1-16)
if [[ "$(cat "$venv/.pgloss-installed" 2>/dev/null)" != "$sources" ]] || ! (cd / && "$root/$py" -c "import pgloss._core") 2>/dev/null; then
  echo "== pip install . into $venv (sources changed; a first build takes a few minutes)"
  export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
  # -v: scikit-build-core's CMake and Ninja output ([n/N]), which step shows as progress
  step "pip install ." "$py" -m pip install -v --disable-pip-version-check --no-build-isolation --force-reinstall --no-deps \
    --config-settings="build-dir=$root/build-${name#.}-{wheel_tag}" .
  echo "$sources" >"$venv/.pgloss-installed"
fi
