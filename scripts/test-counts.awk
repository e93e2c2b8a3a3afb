# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# Counts a layer's tests from its output: pytest's summary lines, CTest's summary (minus the
# tests it lists as skipped), GoogleTest run directly ("[  PASSED  ] N tests"), Sphinx's doctest
# summary, and the PASS/FAIL lines of the package checks and the docs' C examples.
function add(p, f, s) { P += p; F += f; S += s }
{ sub(/\r$/, "") }
# pytest -q: "460 passed, 2 skipped, 3 warnings in 30.12s" (also inside "===== … =====")
/^(=+ )?[0-9]+ (passed|failed|skipped|errors?|deselected|xfailed|xpassed)(, [0-9]+ [a-z]+)* in [0-9.]+s/ {
  n = split($0, parts, /, /)
  for (i = 1; i <= n; i++) {
    if (match(parts[i], /[0-9]+ (passed|failed|skipped|errors?)/)) {
      split(substr(parts[i], RSTART, RLENGTH), kv, " ")
      if (kv[2] == "passed") add(kv[1], 0, 0)
      else if (kv[2] == "skipped") add(0, 0, kv[1])
      else add(0, kv[1], 0)
    }
  }
  next
}
# CTest: "100% tests passed, 0 tests failed out of 230"; skipped tests are listed as "(Skipped)"
/^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+/ { add($NF - $4, $4, 0); next }
/^[ \t]+[0-9]+ - .* \(Skipped\)$/ { add(-1, 0, 1); next }
# GoogleTest run directly (not under ctest -V, whose lines start with "N: ")
/^\[  PASSED  \] [0-9]+ tests?\./ { add($4, 0, 0); next }
/^\[  FAILED  \] [0-9]+ tests?, listed below/ { add(0, $4, 0); next }
/^\[  SKIPPED \] [0-9]+ tests?, listed below/ { add(-$4, 0, $4); next }
# Sphinx doctest summary: "   12 tests" / "    1 failure in tests"
/^ +[0-9]+ tests?$/ { add($1, 0, 0); next }
/^ +[0-9]+ failures? in (tests|setup code|cleanup code)$/ { add(-$1, $1, 0); next }
# the package layer's checks, the docs' C examples, the fuzzers' harness rows
/^PASS / { add(1, 0, 0); next }
/^FAIL / { add(0, 1, 0); next }
/^(brdf|perceptual|scene|cli|tool) +[0-9?]+ +[0-9?]+ +[0-9?]+ +[0-9?]+ +[0-9?]+  (ok|FINDING)/ {
  if ($7 == "ok") add(1, 0, 0); else add(0, 1, 0); next
}
END { printf "%d %d %d\n", P, F, S }
