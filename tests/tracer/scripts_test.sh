#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# scripts/run.sh (the main job, which builds this tracer) and the layer scripts: a failing build
# or install shows its error (a compile error was a silent exit 1: the output went to
# /dev/null), and a long step shows progress. Usage: scripts_test.sh REPOSITORY WORKDIR
set -u
root=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok   $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; }

# 1. No build or install of the scripts hides its output: builds and pip installs go through
#    `step` (scripts/step.sh), not to /dev/null or pip -q.
hidden=$(grep -nE '(cmake --build|pip"? (install|wheel)|apt-get .*install)' "$root"/scripts/*.sh |
  grep -vE '^[^:]*:[0-9]*:\s*#|\bstep "' | grep -E '>/dev/null|\s-qq?\s')
[[ -z $hidden ]] && ok "no build or install output sent to /dev/null" || bad "hidden output: $hidden"
grep -qE '^step "build \(build/\)" cmake --build --preset release$' "$root/scripts/run.sh" \
  && ok "run.sh builds through step" || bad "run.sh does not build through step"

# 2. A compile error: the compiler's message is printed and the status is not 0.
[[ -f $root/scripts/step.sh ]] && source "$root/scripts/step.sh"
printf 'int main(void) { return undeclared_name; }\n' >broken.c
out=$(step "build" cc -c broken.c -o broken.o 2>&1); rc=$?
if ((rc != 0)) && grep -q "broken.c:1:.*undeclared_name" <<<"$out" && grep -q "== build FAILED" <<<"$out"; then
  ok "a compile error is shown"
else bad "compile error: status $rc, output: $out"; fi
out=$(step "quiet" bash -c 'echo chatter; exit 0' 2>&1); rc=$?
((rc == 0)) && [[ -z $out ]] && ok "a step that succeeds quickly prints nothing" || bad "quick step: $rc '$out'"

# 3. Progress: a line every PGLOSS_STEP_INTERVAL seconds with Ninja's [n/N].
out=$(PGLOSS_STEP_INTERVAL=1 step "slow" bash -c 'echo "[3/40] Building C object a.o"; sleep 2.5; echo done' 2>&1); rc=$?
((rc == 0)) && grep -qE '^   … slow: [0-9]+ s — \[3/40\] Building C object a.o$' <<<"$out" \
  && ok "a long step shows progress" || bad "progress: status $rc, output: $out"

echo "scripts: $pass passed, $fail failed"
((fail == 0))
