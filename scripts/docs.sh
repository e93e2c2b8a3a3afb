#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The docs site (docs/: Sphinx + MyST-Parser, docs/conf.py says why) into out/docs, with every
# example executed:
#   1. the venv .venv-docs with pinned Sphinx and the pgloss package installed from the tree
#      (scripts/venv-pgloss.sh: autodoc reads the installed package's docstrings);
#   2. the C examples: the core library alone is built (build-docs/), then every
#      docs/examples/*.c is compiled against it with -Wall -Wextra -Werror and run; a nonzero exit
#      fails, and where docs/examples/NAME.out exists the program's stdout must equal it;
#   3. sphinx-build -W --keep-going -b html docs out/docs: any warning fails (among them a C
#      declaration that the C API reference cannot read, docs/_ext/pgloss_capi.py);
#   4. sphinx-build -W -b doctest: every ```{doctest} block of the pages and every >>> example of
#      the docstrings is run, and a wrong example fails.
# Nothing is skipped: with PGLOSS_REQUIRE_ALL=1 (the default here, and CI) a missing dependency
# fails. Quick when run again: the venv is kept while the pins are unchanged, the package is
# reinstalled only when its sources changed, and build-docs/ is kept.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh apt python3 python3-venv python3-dev g++ cmake ninja-build

venv=.venv-docs
pins=(scikit-build-core==1.1.2 pybind11==3.1.0 numpy==2.4.6 sphinx==8.2.3 myst-parser==4.0.1 docutils==0.21.2)
bash scripts/venv-pgloss.sh "$venv" "${pins[@]}"

run() {  # prints the command, then runs it
  echo "+ $*"
  "$@"
}

echo "== the C examples (docs/examples/*.c) against the core library (build-docs)"
# The library as users get it (every ISA the dispatcher picks from); in scripts/test.sh its
# objects come from the compiler cache that build-test/ filled.
step "configure (build-docs)" cmake -S . -B build-docs -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPGLOSS_BUILD_TESTS=OFF -DPGLOSS_BUILD_PYTHON=OFF -DPGLOSS_BUILD_CLI=OFF -DPGLOSS_INSTALL=OFF
step "build (build-docs)" cmake --build build-docs --target pgloss -j2
lib=build-docs/libpgloss/libpgloss.a
[[ -f $lib ]] || { echo "docs: no $lib after the build" >&2; exit 1; }
mkdir -p build-docs/examples
cc=${CC:-cc}
n=0
for src in docs/examples/*.c; do
  [[ -e $src ]] || continue
  name=$(basename "$src" .c)
  exe=build-docs/examples/$name
  run "$cc" -std=c11 -O2 -Wall -Wextra -Werror -DPGLOSS_STATIC -I libpgloss/include "$src" "$lib" -lm -o "$exe"
  echo "+ $exe"
  rc=0
  "$exe" >"$exe.stdout" || rc=$?
  if ((rc != 0)); then
    cat "$exe.stdout"
    echo "docs: $src exited with status $rc" >&2
    exit 1
  fi
  cat "$exe.stdout"
  expected=docs/examples/$name.out
  if [[ -f $expected ]]; then
    echo "+ diff -u $expected $exe.stdout"
    diff -u "$expected" "$exe.stdout" || { echo "docs: $src printed something other than $expected" >&2; exit 1; }
  fi
  echo "PASS $src"
  n=$((n + 1))
done
echo "== $n C examples compiled, run and checked"

# A fresh environment (-E) each time, so that a warning of an unchanged page is reported again.
echo "== the site, warnings as errors"
run "$venv/bin/sphinx-build" -E -W --keep-going -q -d build-docs/doctrees -b html docs out/docs
echo "== the Python examples (doctest builder)"
run "$venv/bin/sphinx-build" -W --keep-going -q -d build-docs/doctrees -b doctest docs build-docs/doctest
sed -n '/^Doctest summary/,$p' build-docs/doctest/output.txt
echo "== docs built: out/docs/index.html"
