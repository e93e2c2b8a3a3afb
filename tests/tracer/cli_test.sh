#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# The pgloss-tracer command line under bad arguments, signals and a thread limit: each case
# states the exit status and the message a user must see. Usage: cli_test.sh TRACER SCENE WORKDIR
set -u
tracer=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
pass=0 fail=0
check() { # name, expected status, expected message (grep -F), command…
  local name=$1 want=$2 msg=$3; shift 3
  local out rc
  out=$("$@" 2>&1); rc=$?
  if [[ $rc == "$want" ]] && grep -qF -- "$msg" <<<"$out"; then pass=$((pass + 1)); echo "ok   $name"
  else fail=$((fail + 1)); echo "FAIL $name: status $rc (want $want), output: $out"; fi
}
r=("$tracer" render "$scene" --size 16x12 --quiet)
check "--spp abc" 2 "--spp wants a whole number, not 'abc'"      "${r[@]}" --spp abc
check "--spp 3x" 2 "--spp wants a whole number, not '3x'"       "${r[@]}" --spp 3x
check "--spp -3" 2 "--spp must be in [1, 16777216], not -3"     "${r[@]}" --spp -3
check "--spp 0" 2 "--spp must be in [1, 16777216], not 0"      "${r[@]}" --spp 0
check "--threads 0" 2 "--threads must be in [1, 1024], not 0"     "${r[@]}" --threads 0
check "--seed 1e3" 2 "--seed wants a whole number, not '1e3'"     "${r[@]}" --seed 1e3
check "--time nan" 2 "--time wants seconds, not 'nan'"            "${r[@]}" --time nan
check "--time -1" 2 "--time must be in (0, 1e7] seconds, not -1" "${r[@]}" --time -1
check "--size 3x4junk" 2 "--size height wants a whole number, not '4junk'" "${r[@]}" --size 3x4junk
check "--size 0x4" 2 "--size width must be in [1, 32768], not 0"  "${r[@]}" --size 0x4
check "--out s.jpg" 2 "--out is a prefix (OUT.exr and OUT.png are written), so 's.jpg' would make 's.jpg.exr'; give it without '.jpg'" \
  "${r[@]}" --spp 1 --out s.jpg
check "--out s.exr" 0 "s.exr s.png: 16x12, 1 spp"                 "${r[@]}" --spp 1 --out s.exr
check "--out s.exr writes s.exr" 0 "" test -s s.exr -a -s s.png -a ! -e s.exr.exr
check "--version"  0 "pgloss-tracer "                             "$tracer" --version
check "--help"     0 "usage: pgloss-tracer"                       "$tracer" --help
check "no scene"   1 "nope.scene: cannot open scene file (no such file)" "$tracer" render nope.scene
# Arguments are echoed escaped: an ANSI sequence in one does not reach the terminal.
check "--spp ESC[2J" 2 "--spp wants a whole number, not '\x1b[2J'" "${r[@]}" --spp $'\e[2J'
check "--mode ESC" 2 "--mode must be mis, brdf or light, not '\x1b]0;x\x07'" "${r[@]}" --mode $'\e]0;x\a'
check "scene ESC" 1 "\x1b[31m.scene: cannot open scene file (no such file)" "$tracer" render $'\e[31m.scene'

# SIGINT in the middle of a long render: what was rendered is written whole, exit 130.
"${r[@]}" --size 64x48 --spp 10000000 --out int >int.log 2>&1 &
pid=$!
# A background job of a script starts with SIGINT ignored, until the tracer installs its handler
# (after loading the scene): a SIGINT sent before that is lost and the render runs on. Wait until
# the process catches SIGINT (bit 2 of SigCgt in /proc), up to 60 s on a loaded machine.
for _ in $(seq 600); do
  cgt=$(awk '/^SigCgt:/ {print $2}' /proc/$pid/status 2>/dev/null) || break
  [[ -n $cgt ]] && (((16#$cgt >> 1) & 1)) && break
  sleep 0.1
done
sleep 1
kill -INT $pid
wait $pid
check "SIGINT: exit 130 and a message" 130 "pgloss-tracer: interrupted; wrote the" bash -c "cat int.log; exit $?"
check "SIGINT: the image is whole" 0 "" test -s int.exr -a -s int.png
check "SIGINT: no temporary left" 0 "" bash -c '! ls -a | grep -q "\.tmp"'

# Threads that cannot be created: the render goes on with those it has (was std::terminate).
check "thread limit" 0 "rendering with" bash -c "ulimit -v 1500000; exec ${r[*]} --spp 2 --threads 1000 --out thr"

echo "cli: $pass passed, $fail failed"
((fail == 0))
