#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The Blender extension blender/pgloss_paint: build its zip (scripts/build-blender-addon.sh),
# then, with the bpy 5.0.1 module of scripts/test-osl.sh (.venv-bpy, set up there), install it
# as an extension into a fresh user folder, create a material, set the sliders, check the
# derived values and render a small image. Nothing is skipped under PGLOSS_REQUIRE_ALL=1.
set -euo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
PGLOSS_OSL_SETUP_ONLY=1 bash scripts/test-osl.sh
bash scripts/build-blender-addon.sh
user=$(mktemp -d)
trap 'rm -rf "$user"' EXIT
echo "== Blender extension: install, material, sliders, derived values, render"
set +e
BLENDER_USER_RESOURCES=$user .venv-bpy/bin/python -m pytest -q -s -p no:cacheprovider -rs \
  -c tests/blender/pytest.ini tests/blender 2>&1 | grep -v -e 'DeprecationWarning' -e '| Saved:' -e '^Fra:'
rc=${PIPESTATUS[0]}
set -e
[[ $rc == 0 ]] && echo "== Blender tests passed"
exit "$rc"
