# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Sourced by the scripts: `step LABEL COMMAND…` runs a long, chatty command (a build, a pip or
# apt install) with its output in a log instead of on the terminal, prints one progress line
# every 10 s while it runs (elapsed time and its latest line, e.g. Ninja's [n/N]), and when it
# fails prints the end of that log, so that a compile error is never a silent exit status.
# Returns the command's status. PGLOSS_STEP_INTERVAL sets the seconds between progress lines.

_pgloss_progress() {  # reads the command's output; a line of progress every $PGLOSS_STEP_INTERVAL s
  local label=$1 start=$SECONDS every=${PGLOSS_STEP_INTERVAL:-10} line last="" st
  local next=$every
  while :; do
    if IFS= read -r -t 1 line; then
      line=${line//$'\r'/}
      [[ -n ${line// /} ]] && last=$line
    else
      st=$?
      ((st > 128)) || break  # end of the output (a timeout is > 128)
    fi
    if ((SECONDS - start >= next)); then
      [[ $last =~ \[[0-9]+/[0-9]+\] ]] && last="${BASH_REMATCH[0]}${last#*"${BASH_REMATCH[0]}"}"
      echo "   … $label: $((SECONDS - start)) s${last:+ — ${last:0:110}}" >&2
      next=$((SECONDS - start + every))
    fi
  done
}

step() {
  local - label=$1 log rc
  shift
  set +e +o pipefail  # (local -: restored on return) the status is taken from PIPESTATUS
  log=$(mktemp "${TMPDIR:-/tmp}/pgloss-step.XXXXXX")
  "$@" 2>&1 | tee "$log" | _pgloss_progress "$label"
  rc=${PIPESTATUS[0]}
  if ((rc != 0)); then
    echo "== $label FAILED (exit status $rc); the end of its output:" >&2
    tail -n 80 "$log" >&2
  fi
  rm -f "$log"
  return "$rc"
}

# `pip_pins PYTHON ARG…` installs pinned packages (ARG: pins, or -r FILE) into PYTHON's venv.
# With PGLOSS_WHEELHOUSE set (scripts/fresh-debian.sh mounts its download cache there) they are
# first downloaded into that folder, where pip skips a file it already holds, then installed from
# it alone (--no-index): a cache of what the index serves, never a package built or installed
# here. One download at a time per folder (flock), as pip's writes into it are not atomic.
pip_pins() {
  local py=$1
  shift
  if [[ -z ${PGLOSS_WHEELHOUSE:-} ]]; then
    "$py" -m pip install --disable-pip-version-check "$@"
    return
  fi
  mkdir -p "$PGLOSS_WHEELHOUSE"
  (flock 9 && "$py" -m pip download --disable-pip-version-check -d "$PGLOSS_WHEELHOUSE" "$@") 9>"$PGLOSS_WHEELHOUSE/.lock" &&
    "$py" -m pip install --disable-pip-version-check --no-index --find-links "$PGLOSS_WHEELHOUSE" "$@"
}
