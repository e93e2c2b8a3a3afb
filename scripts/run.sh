#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The main job: set up, build the core, the pgloss tool and the Embree path tracer
# (examples/tracer), run the paper's worked examples (`pgloss demo`: Experiment 1's stimuli in
# gloss space, Fig. 12's gloss matching, Fig. 11's isogloss contour, Fig. 10's envelope, a
# Fig. 13 paint), then render Figs. 4 and 12 at preview quality into out/ (about a minute of
# rendering on 2 cores; more samples: examples/tracer/README or `pgloss-tracer --help`).
# Extra arguments are passed to the pgloss tool instead, e.g. scripts/run.sh to-physical 50 0 0 0.08 0.95
# PGLOSS_RUN_QUICK=1 renders the same two figures smaller and for a few seconds each (a smoke
# run of the whole job, as CI's .ci/run does in a fresh root).
set -euo pipefail
cd "$(dirname "$0")/.."
# openimageio-tools: Debian's OpenImageIOTargets.cmake names its tools (/usr/bin/iconvert, …)
# and find_package(OpenImageIO) fails without them.
bash scripts/bootstrap.sh apt g++ pkg-config libembree-dev libopenimageio-dev openimageio-tools \
  libopencolorio-dev libglm-dev fonts-dejavu-core
source scripts/step.sh  # progress every 10 s; a failing step prints its output (a compile error)
source scripts/ccache.sh  # the core compiled once for build/ and the Blender add-on's wheel
[[ -f build/build.ninja ]] || echo "== first build of the core, the pgloss tool and pgloss-tracer (a few minutes on 2 cores)"
step "configure (build/)" cmake --preset release -DPGLOSS_BUILD_TESTS=OFF -DPGLOSS_BUILD_EXAMPLES=ON
step "build (build/)" cmake --build --preset release
if (($#)); then
  exec ./build/tools/pgloss "$@"
fi
./build/tools/pgloss demo
tracer=./build/examples/tracer/pgloss-tracer
if [[ ${PGLOSS_RUN_QUICK:-0} == 1 ]]; then
  echo "== PGLOSS_RUN_QUICK=1: smoke renders (small, a few seconds each)"
  $tracer fig4 --size 64x48 --time 4 --out out
  $tracer fig12 --size 80x60 --time 2 --out out
else
  $tracer fig4 --size 128x96 --time 30 --out out
  $tracer fig12 --size 160x120 --time 12 --out out
fi
for f in out/fig4.png out/fig12.png; do
  [[ -s $f ]] || { echo "run.sh: $f was not written" >&2; exit 1; }
done
bash scripts/fig14.sh  # out/fig14.png: Fig. 14's mugs matched in gloss, Blender Principled (gloss bridge) | Ward
echo "== out/fig4.png (Experiment 1's 27 stimuli), out/fig12.png (gloss matching); linear EXRs in out/fig4/, out/fig12/"
