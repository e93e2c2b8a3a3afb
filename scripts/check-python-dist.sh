#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The Python package's distributions, called by scripts/test-python.sh after the
# venv .venv-py exists:
#   1. the wheel (`python -m build --wheel`, the venv's pinned scikit-build-core and pybind11,
#      CMake's build folder build-py-TAG/ kept: only what changed recompiles);
#   2. `auditwheel show` on it: it must qualify for a manylinux tag (printed, and written to
#      build-py/dist/manylinux-tag);
#   3. the sdist, and a wheel built from the unpacked sdist alone (what a user's
#      `pip install pgloss-X.tar.gz` does), checked to hold the same files.
# The wheel's metadata is then checked by tests/python/test_package_metadata.py (PGLOSS_WHEEL).
# Quick when run again: the sdist round trip is skipped while the sources it is built from
# are unchanged.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
py=.venv-py/bin/python
dist=build-py/dist
pins=(build==1.6.1 pyproject-hooks==1.3.3 auditwheel==6.8.2 pyelftools==0.33)
if [[ "$(cat .venv-py/.pgloss-dist-pins 2>/dev/null)" != "${pins[*]}" ]]; then
  echo "== installing ${pins[*]} into .venv-py"
  step "pip install (pins)" pip_pins "$py" "${pins[@]}"
  echo "${pins[*]}" >.venv-py/.pgloss-dist-pins
fi
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
mkdir -p "$dist"

echo "== wheel"
rm -f "$dist"/pgloss-*.whl
"$py" -m build --wheel --no-isolation --outdir "$dist" . >"$dist/wheel.log" 2>&1 || { cat "$dist/wheel.log"; exit 1; }
wheel=$(ls "$dist"/pgloss-*.whl)
echo "$wheel"

echo "== auditwheel show"
"$py" -m auditwheel show "$wheel" | tee "$dist/auditwheel.txt"
tag=$(grep -o 'manylinux_[0-9]*_[0-9]*_[a-z0-9_]*' "$dist/auditwheel.txt" | head -n1 || true)
if [[ -z $tag ]]; then
  echo "auditwheel: the wheel does not qualify for any manylinux tag (see above)" >&2
  exit 1
fi
echo "$tag" >"$dist/manylinux-tag"
echo "manylinux tag: $tag"

echo "== sdist, and a wheel from it"
sources=$(find pyproject.toml CMakeLists.txt LICENSE cmake libpgloss tools bindings/python tests/python tests/vectors -type f \
            -not -path '*/__pycache__/*' -print0 | sort -z | xargs -0 sha256sum | sha256sum | cut -c1-16)
if [[ "$(cat "$dist/.sdist-checked" 2>/dev/null)" == "$sources" ]]; then
  echo "(sources unchanged since the last check: skipped)"
  exit 0
fi
rm -rf "$dist"/pgloss-*.tar.gz "$dist/sdist"
"$py" -m build --sdist --no-isolation --outdir "$dist" . >"$dist/sdist.log" 2>&1 || { cat "$dist/sdist.log"; exit 1; }
sdist=$(ls "$dist"/pgloss-*.tar.gz)
echo "$sdist ($(du -k "$sdist" | cut -f1) KiB)"
mkdir -p "$dist/sdist"
tar -xzf "$sdist" -C "$dist/sdist"
src=$(ls -d "$dist"/sdist/pgloss-*/)
for f in pyproject.toml CMakeLists.txt LICENSE bindings/python/README.md libpgloss/include/pgloss/pgloss.h \
         bindings/python/src/core.cpp tools/pgloss_cli.c tests/vectors/gloss.json; do
  [[ -f $src/$f ]] || { echo "sdist lacks $f" >&2; exit 1; }
done
for d in web blender glsl osl .ci; do
  [[ ! -e $src/$d ]] || { echo "sdist holds $d/, which the package does not need" >&2; exit 1; }
done
# CMake's build folder of the sdist's wheel is inside the unpacked tree, where pyproject puts it
# (build-py-TAG/): the compile commands are then those of the tree's own wheel above, relative
# to the build folder, and the compiler cache (scripts/ccache.sh) serves them.
(cd "$src" && "$OLDPWD/$py" -m build --wheel --no-isolation --outdir ../wheel . >../wheel.log 2>&1) ||
  { cat "$dist/sdist/wheel.log"; exit 1; }
from_sdist=$(ls "$dist"/sdist/wheel/pgloss-*.whl)
"$py" - "$wheel" "$from_sdist" <<'EOF'
import sys, zipfile
a, b = (sorted(n for n in zipfile.ZipFile(p).namelist() if not n.endswith("RECORD")) for p in sys.argv[1:3])
if a != b:
    sys.exit(f"the wheel built from the sdist differs in its files: {sorted(set(a) ^ set(b))}")
print(f"wheel from the sdist: the same {len(a)} files")
EOF
echo "$sources" >"$dist/.sdist-checked"
