#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Installs what pgloss needs on Debian 12, and nothing twice: each package set is installed
# only if one of its packages is missing, so a second run costs a dpkg query.
#   bootstrap.sh core    C compiler, CMake, Ninja (all the core needs)
#   bootstrap.sh test    + GoogleTest, nlohmann-json, Python venv with pinned mpmath
#   bootstrap.sh apt P…  + the Debian packages P… (what a layer's own script needs)
#   bootstrap.sh fresh-root   only what scripts/fresh-debian.sh needs on the host (mmdebstrap,
#                        git; no compiler: the project's own needs are installed in the root)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/step.sh

want=(build-essential cmake ninja-build)
mode=${1:-core}
case $mode in
  core) ;;
  test) want+=(g++ libgtest-dev nlohmann-json3-dev python3 python3-venv) ;;
  apt) shift; want+=("$@") ;;
  fresh-root) want=(mmdebstrap git ca-certificates) ;;
  *) echo "bootstrap: unknown mode '$mode' (core | test | apt PACKAGE… | fresh-root)" >&2; exit 2 ;;
esac

# One bootstrap at a time (scripts/test.sh runs two lanes of layers): apt and the venv below
# are not safe to set up twice at once.
exec 9>"${TMPDIR:-/tmp}/pgloss-bootstrap.lock"
flock 9

missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "bootstrap: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  # Wait for another apt (a second script, unattended-upgrades) instead of failing on its lock.
  lock=(-o DPkg::Lock::Timeout=600)
  "${sudo_cmd[@]}" apt-get "${lock[@]}" update -qq
  step "apt-get install" "${sudo_cmd[@]}" apt-get "${lock[@]}" install -y -q --no-install-recommends "${missing[@]}"
fi

if [[ $mode == test ]]; then
  # The reference-vector generator runs in its own venv with a pinned mpmath, so that
  # regenerated vectors are byte-identical on every machine.
  venv=.venv-tools
  if [[ ! -x $venv/bin/python ]] || ! $venv/bin/python -c "import mpmath; assert mpmath.__version__ == '1.3.0'" 2>/dev/null; then
    echo "bootstrap: creating $venv (mpmath 1.3.0)"
    rm -rf "$venv"
    /usr/bin/python3 -m venv "$venv"
    step "pip install mpmath" pip_pins "$venv/bin/python" mpmath==1.3.0
  fi
fi
