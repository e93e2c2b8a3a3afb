#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The GLSL layer's tests (glsl/pgloss.glsl): sets up what it needs, then runs
#   1. the glslangValidator compile matrix (GLSL 3.30 / 4.50 core, ESSL 3.00 / 3.10, Vulkan
#      GLSL 4.50 and 4.60 ray tracing → SPIR-V; every stage x feature build) and the SPIR-V
#      size of the feature builds;
#   2. every shared test vector executed on Mesa llvmpipe through EGL, headless (a compute
#      shader; PGLOSS_GLSL_DEVICE=gpu runs it on the default EGL device, a GPU, instead);
#   3. the example chart render (examples/glsl) as a smoke test.
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the default here, and CI) a missing
# glslangValidator, EGL or llvmpipe is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"

bash scripts/bootstrap.sh apt python3 python3-venv glslang-tools spirv-tools \
  libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri

venv=.venv-glsl
req=tests/glsl/requirements.txt
if [[ ! -x $venv/bin/python ]] || ! cmp -s "$req" "$venv/.requirements"; then
  echo "test-glsl: creating $venv from $req"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  step "pip install -r $req" pip_pins "$venv/bin/python" -r "$req"
  cp "$req" "$venv/.requirements"
fi

echo "== GLSL: compile matrix, vectors on ${PGLOSS_GLSL_DEVICE:-llvmpipe}, example"
"$venv/bin/python" -m pytest -q -p no:cacheprovider -s tests/glsl
echo "== GLSL example: gloss chart (smoke render, 16 samples/pixel)"
"$venv/bin/python" examples/glsl/gloss_chart.py --spp 16 --cell 48 --out out/glsl/gloss_chart_smoke.png
"$venv/bin/python" -c "
from PIL import Image; import numpy as np, sys
a = np.asarray(Image.open(sys.argv[1]).convert('L'), float)
assert a.shape == (330, 880) and a.std() > 10, (a.shape, a.std())
print('example rendered', sys.argv[1], a.shape)" out/glsl/gloss_chart_smoke.png
echo "== GLSL tests passed"
