#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The OSL layer's tests (osl/, tests/osl/) in a real OSL runtime: OSL 1.14 inside Cycles,
# from Blender's Python module on PyPI (bpy 5.0.1, CPython 3.11, numpy < 2) in its own venv
# .venv-bpy. Compiles every shader, executes every shared vector through osl/pgloss.h and
# checks it (tests/osl/test_osl.py). Quick when run again (the venv is kept if its pins match).
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (CI sets it) a missing dependency is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
# python3.11 + venv; a C compiler for the C core that decides float-boundary cases
# (tests/osl/cref.py); the X/GL client libraries that bpy's module loads at import.
bash scripts/bootstrap.sh apt python3 python3-venv libgl1 libx11-6 libxext6 libxfixes3 libxi6 \
  libxkbcommon0 libxrender1 libxxf86vm1 libsm6 libice6

venv=.venv-bpy
pins=(bpy==5.0.1 numpy==1.26.4 pytest==8.3.4)
check_pins='from importlib.metadata import version as v
assert (v("bpy"), v("numpy"), v("pytest")) == ("5.0.1", "1.26.4", "8.3.4")'
if [[ ! -x $venv/bin/python ]] || ! $venv/bin/python -c "$check_pins" 2>/dev/null; then
  echo "test-osl: creating $venv (${pins[*]}, about 400 MB download)"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  step "pip install (pins)" pip_pins "$venv/bin/python" "${pins[@]}"
fi
$venv/bin/python -c 'import sys; assert sys.version_info[:2] == (3, 11), "bpy 5.0.1 needs CPython 3.11"'
[[ ${PGLOSS_OSL_SETUP_ONLY:-0} == 1 ]] && exit 0

start=$SECONDS
cd tests/osl
set +e
../../$venv/bin/python -m pytest -q -s -p no:cacheprovider test_osl.py 2>&1 |
  grep -v -e 'DeprecationWarning' -e 'use_nodes' -e '| Saved:' -e '^Fra:'
rc=${PIPESTATUS[0]}
set -e
echo "== OSL tests: exit $rc ($((SECONDS - start)) s)"
exit "$rc"
