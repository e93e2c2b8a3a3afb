#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Installs the npm packages that `python -m pgloss experiment export-jspsych` bundles into a study
# (jsPsych 8 and three plugins, pinned by web/jspsych/package-lock.json) into web/jspsych/node_modules,
# with `npm ci` (exactly the lockfile, no install scripts). npm comes from Debian where no npm is
# on the machine (a Node.js that carries its own npm is used as it is). Quick when run again.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
command -v npm >/dev/null || bash scripts/bootstrap.sh apt npm
dir=web/jspsych
stamp=$(sha256sum "$dir/package-lock.json" | cut -c1-16)
if [[ "$(cat "$dir/node_modules/.pgloss-lock" 2>/dev/null)" != "$stamp" ]]; then
  step "npm ci ($dir)" npm ci --prefix "$dir" --ignore-scripts --no-audit --no-fund
  echo "$stamp" >"$dir/node_modules/.pgloss-lock"
fi
echo "jsPsych: $dir/node_modules ($(node -p "require('./$dir/node_modules/jspsych/package.json').version") )"
