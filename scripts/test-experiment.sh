#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The browser experiment's tests (bindings/python/pgloss/experiment, tests/experiment): three
# scripted observers in Debian's headless Chromium (Playwright for Python) run both procedures on
# 12 rendered stimuli, on the local server (SIGKILLed and restarted mid-session) and as the
# exported jsPsych study (JSON, CSV and a JATOS results archive imported back); the export goes
# through `python -m pgloss mds` and `magnitude`; bad requests, concurrent subjects, the seed
# reproducing the order. Sets up its own packages, the binding (.venv-py), pgloss-tracer
# (build-tracer-test, the configuration of scripts/test-tracer.sh), the venv .venv-web and the
# pinned jsPsych (scripts/jspsych.sh). Quick when run again. `--full`: the jsPsych study at the
# paper's settings (3.2°, 500 ms between trials, 5 blind-spot sweeps, 3 practice trials).
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (CI, scripts/test.sh) a skipped test is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
start=$SECONDS
bash scripts/bootstrap.sh apt chromium python3 python3-venv g++ pkg-config libembree-dev libopenimageio-dev openimageio-tools \
  libopencolorio-dev libglm-dev fonts-dejavu-core libgtest-dev

echo "== Python binding (.venv-py), pgloss-tracer (stimuli)"
PGLOSS_PY_SETUP_ONLY=1 bash scripts/test-python.sh
step "configure (build-tracer-test)" cmake -S . -B build-tracer-test -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPGLOSS_BUILD_CLI=OFF -DPGLOSS_BUILD_EXAMPLES=ON -DPGLOSS_BUILD_TRACER_TESTS=ON
step "build pgloss-tracer" cmake --build build-tracer-test --target pgloss-tracer
bash scripts/venv-web.sh
bash scripts/jspsych.sh
[[ ${1:-} == --full ]] && export PGLOSS_JSPSYCH_FULL=1

echo "== pytest tests/experiment (headless Chromium $(chromium --version 2>/dev/null | awk '{print $2}'))"
export PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1
export PGLOSS_EXPERIMENT_PY="$PWD/.venv-py/bin/python" PGLOSS_CHROMIUM=/usr/bin/chromium \
  PGLOSS_TRACER="$PWD/build-tracer-test/examples/tracer/pgloss-tracer" MPLBACKEND=Agg \
  MPLCONFIGDIR="$PWD/build-py/mplconfig"
status=0
.venv-web/bin/python -m pytest -q -p no:cacheprovider -rs -s tests/experiment || status=$?
if ((status != 0)); then echo "== experiment tests FAILED"; exit "$status"; fi
echo "== experiment tests passed ($((SECONDS - start)) s)"
