#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Our Fig. 14 (examples/bridge/fig14.py): the dark red and the light blue mug matched in gloss,
# in Blender Cycles through the pgloss paint add-on's Principled mode and in pgloss-tracer as
# Ward, side by side in out/fig14.png with the (c, d) the image gloss meter reads from each.
# Needs pgloss-tracer (build/, scripts/run.sh builds it); sets up the bpy venv
# (scripts/test-osl.sh) and the add-on's zip (scripts/build-blender-addon.sh).
# PGLOSS_RUN_QUICK=1: fewer samples (a smoke run).
set -euo pipefail
cd "$(dirname "$0")/.."
tracer=${PGLOSS_TRACER:-$PWD/build/examples/tracer/pgloss-tracer}
[[ -x $tracer ]] || { echo "fig14: $tracer not built (scripts/run.sh builds it)" >&2; exit 1; }
PGLOSS_OSL_SETUP_ONLY=1 bash scripts/test-osl.sh
zip=$(bash scripts/build-blender-addon.sh | tail -1)
user=$(mktemp -d)
trap 'rm -rf "$user"' EXIT
quick=()
[[ ${PGLOSS_RUN_QUICK:-0} == 1 ]] && quick=(--spp 16 --meter-spp 64 --basis-spp 128)
echo "== Fig. 14: mugs matched in gloss, Blender Principled (gloss bridge) | pgloss-tracer Ward"
BLENDER_USER_RESOURCES=$user .venv-bpy/bin/python examples/bridge/fig14.py --tracer "$tracer" --addon "$zip" \
  --out out "${quick[@]}" 2>&1 | grep -v -e '| Saved:' -e '^Fra:' -e 'use_nodes' -e 'DeprecationWarning'
exit "${PIPESTATUS[0]}"
