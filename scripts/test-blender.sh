#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The Blender extension blender/pgloss_paint: build its zip (scripts/build-blender-addon.sh) and
# pgloss-tracer (build-tracer-test, as scripts/test-tracer.sh: it renders the image gloss meter's
# Ward basis), then, with the bpy 5.0.1 module of scripts/test-osl.sh (.venv-bpy, set up there),
# install it as an extension into a fresh user folder, make materials in both modes (Ward OSL,
# Principled), check the derived values and statuses, render them in the stimulus scene and read
# (c, d) back with the meter. Nothing is skipped under PGLOSS_REQUIRE_ALL=1.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh apt g++ cmake pkg-config libembree-dev libopenimageio-dev openimageio-tools \
  libopencolorio-dev libglm-dev fonts-dejavu-core
PGLOSS_OSL_SETUP_ONLY=1 bash scripts/test-osl.sh
bash scripts/build-blender-addon.sh
step "configure (build-tracer-test)" cmake --preset tracer-test
step "build pgloss-tracer (build-tracer-test)" cmake --build --preset tracer-test --target pgloss-tracer
user=$(mktemp -d)
trap 'rm -rf "$user"' EXIT
echo "== Blender extension: install, both modes, derived values, statuses, renders read back"
start=$SECONDS
set +e
PGLOSS_TRACER=$PWD/build-tracer-test/examples/tracer/pgloss-tracer BLENDER_USER_RESOURCES=$user \
  .venv-bpy/bin/python -m pytest -q -s -p no:cacheprovider -rs -c tests/blender/pytest.ini tests/blender 2>&1 |
  grep -v -e 'DeprecationWarning' -e '| Saved:' -e '^Fra:' -e 'use_nodes'
rc=${PIPESTATUS[0]}
set -e
echo "== Blender tests: exit $rc ($((SECONDS - start)) s)"
exit "$rc"
