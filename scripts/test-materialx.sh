#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The MaterialX library (materialx/pgloss): validation, ShaderGen (GLSL, OSL) with the PyPI
# MaterialX package pinned in tests/materialx/requirements.txt, glslangValidator on the generated
# GLSL, the generated GLSL on llvmpipe (moderngl) against the C core, and the generated OSL in
# Cycles (the bpy 5.0.1 venv of scripts/test-osl.sh) against osl/pgloss_material.osl; the gloss
# bridge's nodes (materialx/pgloss/pgloss_bridge.mtlx) as generated GLSL on llvmpipe and generated
# OSL in Cycles against the C bridge (docs/materialx.md). Nothing is skipped: with
# PGLOSS_REQUIRE_ALL=1 (the default here, and what CI sets) a skipped test is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh apt python3 python3-venv glslang-tools cmake ninja-build gcc \
  libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri

venv=.venv-materialx
req=tests/materialx/requirements.txt
if [[ ! -x $venv/bin/python ]] || ! cmp -s "$req" "$venv/.requirements"; then
  echo "test-materialx: creating $venv from $req"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  step "pip install -r $req" pip_pins "$venv/bin/python" -r "$req"
  cp "$req" "$venv/.requirements"
fi

echo "== MaterialX: library, sample document, ShaderGen GLSL + OSL, glslangValidator"
"$venv/bin/python" -m pytest -q -p no:cacheprovider -rs --ignore=tests/materialx/cycles tests/materialx

echo "== MaterialX: the generated OSL in Cycles (bpy 5.0.1, .venv-bpy of scripts/test-osl.sh)"
PGLOSS_OSL_SETUP_ONLY=1 bash scripts/test-osl.sh
inc=build-materialx/mx_include
rm -rf "$inc" && mkdir -p "$inc"
cp "$("$venv/bin/python" -c 'import MaterialX, os; print(os.path.dirname(MaterialX.__file__))')"/libraries/stdlib/genosl/include/*.h "$inc/"
set +e
.venv-bpy/bin/python -m pytest -q -s -p no:cacheprovider -rs tests/materialx/cycles 2>&1 |
  grep -v -e 'DeprecationWarning' -e '| Saved:' -e '^Fra:'
rc=${PIPESTATUS[0]}
set -e
[[ $rc == 0 ]] || exit "$rc"
echo "== MaterialX tests passed"
