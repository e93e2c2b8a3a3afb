#!/usr/bin/env bash
# The main job: set up, build the core and the pgloss tool, and run the paper's worked
# examples (Experiment 1's stimuli in gloss space, Fig. 12's gloss matching, Fig. 11's
# isogloss contour, Fig. 10's envelope, a Fig. 13 colour/gloss paint and its BRDF).
# Extra arguments are passed to the tool instead of "demo", e.g. scripts/run.sh to-physical 50 0 0 0.08 0.95
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh core
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPGLOSS_BUILD_TESTS=OFF >/dev/null
cmake --build build >/dev/null
if (($#)); then
  exec ./build/tools/pgloss "$@"
fi
exec ./build/tools/pgloss demo
