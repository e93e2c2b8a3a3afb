#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The pinned venv .venv-web (Playwright for Python, pytest, numpy) that the browser tests share
# (scripts/test-web.sh, scripts/test-experiment.sh). Playwright drives the system Chromium: no
# browser download. Kept while the pins are unchanged.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
venv=.venv-web
pins=(playwright==1.49.1 pytest==8.3.4 numpy==2.2.1)
if [[ ! -x $venv/bin/python ]] || [[ "$(cat "$venv/.pgloss-pins" 2>/dev/null)" != "${pins[*]}" ]]; then
  echo "== creating $venv (${pins[*]})"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 step "pip install (pins)" pip_pins "$venv/bin/python" "${pins[@]}"
  echo "${pins[*]}" >"$venv/.pgloss-pins"
fi
