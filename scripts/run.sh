#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The main job: set up, build the core, the pgloss tool and the Embree path tracer
# (examples/tracer), run the paper's worked examples (`pgloss demo`: Experiment 1's stimuli in
# gloss space, Fig. 12's gloss matching, Fig. 11's isogloss contour, Fig. 10's envelope, a
# Fig. 13 paint), then render Figs. 4 and 12 at preview quality into out/ (about a minute of
# rendering on 2 cores; more samples: examples/tracer/README or `pgloss-tracer --help`).
# Extra arguments are passed to the pgloss tool instead, e.g. scripts/run.sh to-physical 50 0 0 0.08 0.95
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh apt g++ pkg-config libembree-dev libopenimageio-dev libopencolorio-dev \
  libglm-dev fonts-dejavu-core
cmake --preset release -DPGLOSS_BUILD_TESTS=OFF -DPGLOSS_BUILD_EXAMPLES=ON >/dev/null
cmake --build --preset release >/dev/null
if (($#)); then
  exec ./build/tools/pgloss "$@"
fi
./build/tools/pgloss demo
tracer=./build/examples/tracer/pgloss-tracer
$tracer fig4 --size 128x96 --time 30 --out out
$tracer fig12 --size 160x120 --time 12 --out out
echo "== out/fig4.png (Experiment 1's 27 stimuli), out/fig12.png (gloss matching); linear EXRs in out/fig4/, out/fig12/"
