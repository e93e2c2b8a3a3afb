#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The Python package's tests (bindings/python): set up, `pip install .` at the
# repository root into the venv .venv-py, then pytest tests/python — the shared vectors,
# the binding's behaviour, the figures command, a smoke run of the benchmark and pgloss.psychophysics
# (scipy: its runtime dependency; scikit-learn: the peer of its tests only; colour-science: the peer of the working-colour-space tests only).
# Also: the C tool `pgloss` built from tools/ (build-cli), which tests/python/test_cli.py
# runs beside `python -m pgloss` (the wheel's copy of it); and the distributions (scripts/check-python-dist.sh:
# the wheel, `auditwheel show` (manylinux), the sdist and a wheel built from it), whose metadata
# tests/python/test_package_metadata.py reads.
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the default here, and what CI sets) a skipped
# test is a failure. Quick when run again: the venv is kept while the pins are unchanged, the
# package is reinstalled only when its sources changed, and CMake's build folder
# (build-venv-py-TAG/, scripts/venv-pgloss.sh) is kept, so a reinstall recompiles only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh apt g++ cmake python3 python3-venv python3-dev

root=$PWD
venv=.venv-py
py=$venv/bin/python
pins=(scikit-build-core==1.1.2 pybind11==3.1.0 numpy==2.4.6 scipy==1.17.1 matplotlib==3.11.2 scikit-learn==1.9.1 pytest==9.2.0 colour-science==0.4.7 pybind11-stubgen==3.0.0)
# The venv with the pins, and `pip install .` when the sources changed (scripts/venv-pgloss.sh).
bash scripts/venv-pgloss.sh "$venv" "${pins[@]}"

# bench/run.sh needs the installed package only.
[[ ${PGLOSS_PY_SETUP_ONLY:-0} == 1 ]] && exit 0

# (build-cli/: Ninja, as deep as build-test/, so that the compiler cache serves the core layer's
# objects; scripts/ccache.sh)
echo "== the C tool (build-cli), beside python -m pgloss in tests/python/test_cli.py"
step "configure (build-cli)" cmake -S . -B build-cli -G Ninja -DCMAKE_BUILD_TYPE=Release -DPGLOSS_BUILD_PYTHON=OFF \
  -DPGLOSS_BUILD_TESTS=OFF -DPGLOSS_INSTALL=OFF
step "build (build-cli)" cmake --build build-cli --target pgloss_cli -j2
export PGLOSS_CLI="$PWD/build-cli/tools/pgloss"

bash scripts/check-python-dist.sh
export PGLOSS_WHEEL="$(ls "$PWD"/build-py/dist/pgloss-*.whl)"

echo "== pytest tests/python"
export MPLBACKEND=Agg MPLCONFIGDIR="$PWD/build-py/mplconfig"
"$py" -m pytest -q -p no:cacheprovider -rs tests/python
echo "== Python tests passed"
