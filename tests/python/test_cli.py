# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""``python -m pgloss`` has the C tool's subcommands (issue 18): for each command and a set of
arguments (ok, warnings, each kind of error, bad numbers, wrong counts), the standard output and
the exit code are the C tool's (tools/pgloss_cli.c, built by scripts/test-python.sh into
build-py/cli; its path in PGLOSS_CLI)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path
from typing import List

import pytest

from pgloss import cli

C_TOOL = os.environ.get("PGLOSS_CLI", "")

CASES: List[List[str]] = [
    ["to-physical", "35", "45", "25", "0.06", "0.95"],
    ["to-physical", "50", "0", "0", "0.08", "0.95", "bounded"],
    ["to-physical", "50", "0", "0", "0.08", "0.95", "ward-dur"],
    ["to-physical", "50", "120", "0", "0.05", "0.95"],        # GAMUT: values printed, exit 1
    ["to-physical", "95", "0", "0", "0.5", "0.95"],           # ENVELOPE (from the check)
    ["to-physical", "50", "0", "0", "0.05", "0.7"],           # WARN_ALPHA_UNTRUSTED
    ["to-physical", "120", "0", "0", "0.05", "0.95"],         # LIGHTNESS
    ["to-physical", "50", "0", "0", "0.05", "0.95", "phong"],  # bad normalisation: 2
    ["to-physical", "50", "0", "0", "0.05"],                  # too few: 2
    ["to-perceptual", "0.193", "0.066", "0.07"],
    ["to-perceptual", "0.9", "0.3", "0.07"],                  # ENERGY (from the check)
    ["to-perceptual", "0.2", "0.05", "0.3"],
    ["to-perceptual", "-0.2", "0.05", "0.1"],                 # NEGATIVE
    ["to-perceptual", "0.2", "nan", "0.1"],                   # NONFINITE
    ["to-perceptual-rgb", "0.3", "0.1", "0.05", "0.04", "0.05"],
    ["check", "0.767", "0.3", "0.04"],
    ["check", "0.193", "0.066", "0.07"],
    ["check", "0.193", "0.066", "0.07", "bounded"],
    ["check", "0.193", "0.066", "0"],                         # ALPHA
    ["check", "0.2", "x", "0.1"],                             # not a number: 2
    ["check", "0.2", "1e999", "0.1"],                         # overflow: 2
    ["match", "0.767", "0.099", "20"],
    ["match", "0.03", "0.5", "99"],                           # ENVELOPE: values printed
    ["distance", "0.087", "0.93", "0.1", "0.9"],
    ["distance", "0.087", "inf", "0.1", "0.9"],
    ["distance", "-1e-1", "0.93", "-.1", "-0.9"],             # negative numbers are numbers, not options
    ["distance", "0.1", "0.9", "-inf", "0.9"],
    ["distance", "0.1", "0.9", "0x1p-3", "0.9"],              # strtod's hexadecimal floats
    ["distance", "0.1", "0.9", "1_0", "0.9"],                 # not strtod's: 2
    ["distance", "0.1", "0.9", "0.2"],                        # too few: 2
    ["distance", "0.1", "0.9", "0.2", "0.9", "0.1"],          # too many: 2
    ["envelope", "50"],
    ["envelope", "0"],
    ["envelope", "-5"],
    ["eval", "0.193", "0.066", "0.07", "30", "0", "30", "180"],
    ["eval", "0.193", "0.066", "0.07", "60", "45", "20", "200", "ward-dur"],
    ["eval", "0.5", "0.2", "0.05", "10", "0", "80", "90", "bounded"],
    ["eval", "0.193", "0.066", "0.07", "95", "0", "30", "180"],  # below the horizon: 0
    ["eval", "0.193", "-0.066", "0.07", "30", "0", "30", "180"],  # material error
    ["eval", "0.2", "0.05", "x", "0", "0", "0", "0"],
    ["demo"],
]


def _run(argv: List[str]) -> subprocess.CompletedProcess:
    return subprocess.run(argv, capture_output=True, text=True, timeout=120)


def _c_tool() -> str:
    if not C_TOOL or not Path(C_TOOL).is_file():
        pytest.skip("the C tool is not built (PGLOSS_CLI; scripts/test-python.sh builds it)")
    return C_TOOL


@pytest.mark.parametrize("args", CASES, ids=[" ".join(a) for a in CASES])
def test_same_output_and_exit_code_as_the_c_tool(args: List[str]) -> None:
    c = _run([_c_tool(), *args])
    p = _run([sys.executable, "-m", "pgloss", *args])
    assert p.returncode == c.returncode, (p.stdout, p.stderr, c.stdout, c.stderr)
    assert p.stdout == c.stdout
    if c.returncode == 2 and c.stderr.startswith("pgloss: "):  # the reason line is the same
        assert p.stderr.splitlines()[0] == c.stderr.splitlines()[0]


def test_every_c_command_has_its_python_twin() -> None:
    usage = _run([_c_tool(), "--help"]).stdout
    c_cmds = {m.group(1) for m in re.finditer(r"^  ([a-z][a-z-]+)\b", usage, re.M)}
    assert c_cmds >= {"to-physical", "check", "match", "demo"}
    assert c_cmds == {t.name for t in cli.TOOL_COMMANDS}
    for t in cli.TOOL_COMMANDS:  # the same argument names
        line = next(ln for ln in usage.splitlines() if ln.startswith(f"  {t.name} ") or ln.strip() == t.name)
        for name in t.numbers:
            assert re.search(rf"\b{re.escape(name)}\b", line), (t.name, name, line)
        assert ("[norm]" in line) == t.norm
    assert _run([sys.executable, "-m", "pgloss", "--version"]).stdout == _run([_c_tool(), "--version"]).stdout


def test_package_commands_are_kept() -> None:
    out = _run([sys.executable, "-m", "pgloss", "--help"]).stdout
    for name in ("to-physical", "check", "figures", "mds", "experiment"):
        assert name in out
