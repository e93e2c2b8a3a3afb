# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Sourced by scripts/run.sh and scripts/test.sh: builds of the same sources with the same flags
# compile once (ccache, installed here), in whichever build folder comes first — the test
# layers' build-test/, build-package/, build-tracer-test/ and each venv's `pip install .` share
# the library's objects. Paths below the tree are hashed relative to the build folder
# (CCACHE_BASEDIR). The cache is ccache's own (~/.cache/ccache), which a fresh root
# (scripts/fresh-debian.sh) starts empty. PGLOSS_CCACHE=0 leaves the compilers as they are; a
# launcher already set in the environment is kept.
if [[ ${PGLOSS_CCACHE:-1} != 0 ]]; then
  bash scripts/bootstrap.sh apt ccache
  export CMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER:-ccache}
  export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
fi
