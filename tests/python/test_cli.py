# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The pgloss tool from both ends: the C tool built from tools/ (scripts/test-python.sh builds it
into build-cli; its path in PGLOSS_CLI) and ``python -m pgloss``, which runs the copy that the
wheel ships. For a table of argument lists (every command; ok, warnings, each verdict; every
kind of bad number; wrong counts) both give the same stdout, stderr and exit code; the grammar,
messages and verdicts are those tools/cli_common.h documents; the installed wheel runs the tool
with no build tree; write errors are errors."""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import List

import pytest

import pgloss
from pgloss import __main__ as package_main
from pgloss import cli

C_TOOL = os.environ.get("PGLOSS_CLI", "")
WHEEL = os.environ.get("PGLOSS_WHEEL", "")
PY = [sys.executable, "-m", "pgloss"]
EVAL = ["0.193", "0.066", "0.07", "30", "0", "30", "180"]

CASES: List[List[str]] = [
    ["to-physical", "35", "45", "25", "0.06", "0.95"],
    ["to-physical", "50", "0", "0", "0.08", "0.95", "bounded"],
    ["to-physical", "50", "0", "0", "0.08", "0.95", "ward-dur"],
    ["to-physical", "50", "120", "0", "0.05", "0.95"],        # GAMUT: values printed, exit 1
    ["to-physical", "95", "0", "0", "0.5", "0.95"],           # ENVELOPE (from the check)
    ["to-physical", "50", "0", "0", "0.05", "0.7"],           # WARN_ALPHA_UNTRUSTED
    ["to-physical", "120", "0", "0", "0.05", "0.95"],         # LIGHTNESS
    ["to-physical", "50", "0", "0", "0.05", "1.5"],           # ALPHA
    ["to-physical", "50", "0", "0", "0.05", "0.95", "phong"],  # bad normalisation: 2
    ["to-physical", "50", "0", "0", "0.05"],                  # too few: 2
    ["to-perceptual", "0.193", "0.066", "0.07"],
    ["to-perceptual", "0.9", "0.3", "0.07"],                  # ENERGY (from the check)
    ["to-perceptual", "0.2", "0.05", "0.3"],
    ["to-perceptual", "-0.2", "0.05", "0.1"],                 # NEGATIVE
    ["to-perceptual", "0.2", "nan", "0.1"],                   # not a finite number: 2
    ["to-perceptual-rgb", "0.3", "0.1", "0.05", "0.04", "0.05"],
    ["check", "0.767", "0.3", "0.04"],
    ["check", "0.193", "0.066", "0.07"],
    ["check", "0.193", "0.066", "0.07", "bounded"],
    ["check", "0.193", "0.066", "0"],                         # ALPHA
    ["check", "0.2", "x", "0.1"],                             # not a number: 2
    ["check", "0.2", "1e999", "0.1"],                         # out of range: 2
    ["check", "0.2", "0.05", "1e-999"],                       # out of range (rounds to 0): 2
    ["check", "0.2", "0.05", "4.9e-324"],                     # subnormal: a number (ALPHA_MIN clamps it)
    ["check", "0.2", "0.05", "0.1", "Ward"],                  # normalisations are lower case: 2
    ["check", "0.2", "0.05", "0.1", "ward", "x"],             # too many: 2
    ["match", "0.767", "0.099", "20"],
    ["match", "0.03", "0.5", "99"],                           # ENVELOPE: values printed
    ["match", "0.9", "0.3", "50"],                            # the given paint: ENERGY
    ["match", "0.2", "0.05", "120"],                          # LIGHTNESS
    ["distance", "0.087", "0.93", "0.1", "0.9"],
    ["distance", "0.05", "1.5", "0.05", "0.95"],              # d > 1: ALPHA
    ["distance", "-0.05", "0.9", "0.05", "0.95"],             # c < 0: NEGATIVE
    ["distance", "1.2", "0.9", "0.05", "0.95"],               # c > 1: ENVELOPE
    ["distance", "0.1", "0.7", "0.1", "0.9"],                 # WARN_ALPHA_UNTRUSTED
    ["distance", "0.087", "inf", "0.1", "0.9"],
    ["distance", "-1e-1", "0.93", "-.1", "-0.9"],             # negative numbers are numbers, not options
    ["distance", "0.1", "0.9", "-inf", "0.9"],
    ["distance", "0.1", "0.9", "-Infinity", "0.9"],
    ["distance", "0.1", "0.9", "NaN", "0.9"],
    ["distance", "0.1", "0.9", "nan(1)", "0.9"],
    ["distance", "0.1", "0.9", "0x1p-3", "0.9"],              # hexadecimal
    ["distance", "0.1", "0.9", "0x23", "0.9"],
    ["distance", "0.1", "0.9", "1_0", "0.9"],
    ["distance", "0.1", "0.9", "\u0661", "0.9"],               # ARABIC-INDIC DIGIT ONE
    ["distance", "0.1", "0.9", "\uff11", "0.9"],               # FULLWIDTH DIGIT ONE
    ["distance", "0.1", "0.9", "0.\u0665", "0.9"],
    ["distance", "0.1", "0.9", "\u00bd", "0.9"],               # VULGAR FRACTION ONE HALF
    ["distance", "0.1", "0.9", " 0.1", "0.9"],
    ["distance", "0.1", "0.9", "0.1 ", "0.9"],
    ["distance", "0.1", "0.9", "", "0.9"],
    ["distance", "0.1", "0.9", "1e", "0.9"],
    ["distance", "0.1", "0.9", ".", "0.9"],
    ["distance", "0.1", "0.9", "\x1b[31m", "0.9"],             # a terminal escape, shown as bytes
    ["distance", "0.1", "0.9", "9" * 400, "0.9"],             # out of range, shown cut
    ["distance", "4.9e-324", "0.9", "2.2250738585072014e-308", "0.9"],  # subnormal, smallest normal
    ["distance", ".05", "9.E-1", "+5e-2", "0.90"],
    ["distance", "0.1", "0.9", "0.2"],                        # too few: 2
    ["distance", "0.1", "0.9", "0.2", "0.9", "0.1"],          # too many: 2
    ["envelope", "50"],
    ["envelope", "0"],
    ["envelope", "-5"],
    ["envelope", "1e300"],
    ["envelope"],
    ["eval", *EVAL],
    ["eval", "0.193", "0.066", "0.07", "60", "45", "20", "200", "ward-dur"],
    ["eval", "0.5", "0.2", "0.05", "10", "0", "80", "90", "bounded"],
    ["eval", "0.193", "0.066", "0.07", "95", "0", "30", "180"],  # below the horizon: 0
    ["eval", "0.193", "-0.066", "0.07", "30", "0", "30", "180"],  # material error
    ["eval", "0.9", "0.5", "0.07", "30", "0", "30", "180"],   # ENERGY, values printed
    ["eval", "0.2", "0.05", "0.3", "30", "0", "30", "180"],   # WARN_ALPHA_UNTRUSTED
    ["eval", "0.193", "0.066", "0.07", "inf", "0", "30", "180"],
    ["eval", "0.193", "0.066", "0.07", "1e300", "0", "30", "180"],
    ["eval", "0.2", "0.05", "x", "0", "0", "0", "0"],
    ["eval", *EVAL, "ward", "extra"],
    ["glossmeter", "0.5", "0", "0.1"],                       # a perfect diffuser
    ["glossmeter", "0.193", "0.066", "0.04", "bounded", "--azimuth", "-30", "--rgb", "0.3", "0.1", "0.05"],
    ["glossmeter", "0.5", "-0.1", "0.1"],                      # NEGATIVE
    ["glossmeter", "0.5", "0", "0.1", "--tol", "inf"],         # not a finite number: 2
    ["glossmeter", "0.5", "0", "0.1", "--rgb", "0.1", "0.2"],  # a missing value: 2
    ["glossmeter", "--fig4", "--markdown"],
    ["from-gloss-units", "--L", "50", "--g60", "17", "--g20", "12.2"],
    ["from-gloss-units", "--L", "50", "--g60", "20"],          # the family, d assumed
    ["from-gloss-units", "--L", "50", "--g60", "20", "--g20", "90"],  # NO_FIT
    ["from-gloss-units", "--L", "50", "--g60"],                # a missing value: 2
    ["from-gloss-units", "--L", "x", "--g60", "20"],           # not a number: 2
    ["finish", "satin", "--L", "90"],
    ["finish", "--list"],
    ["finish", "glosy"],                                       # unknown finish: 2
    ["bridge", "openpbr", "50", "0", "0", "0.057", "0.96"],
    ["bridge", "gltf_core", "20", "0", "0", "0.2", "0.95"],  # BRIDGE_SPECULAR: parameters, exit 1
    ["bridge", "vray", "50", "0", "0", "0.057", "0.96"],       # unknown target: 2
    ["bridge", "openpbr", "50", "0", "0", "0.057", "1e999"],   # out of range: 2
    ["demo"],
    ["demo", "extra"],
    ["demo", "--help"],
    ["distance", "-h"],
    ["--version"],
    ["fit", "1", "2"],                                        # unknown command
    ["--frobnicate"],
]


def _run(argv: List[str], stdout=subprocess.PIPE) -> subprocess.CompletedProcess:
    return subprocess.run(argv, stdout=stdout, stderr=subprocess.PIPE, timeout=120)


def _c_tool() -> str:
    if not C_TOOL or not Path(C_TOOL).is_file():
        pytest.skip("the C tool is not built (PGLOSS_CLI; scripts/test-python.sh builds it)")
    return C_TOOL


def _tool(which: str) -> List[str]:
    return [_c_tool()] if which == "c" else PY


@pytest.mark.parametrize("args", CASES, ids=[repr(" ".join(a))[1:-1][:60] for a in CASES])
def test_same_stdout_stderr_and_exit_code(args: List[str]) -> None:
    c = _run([_c_tool(), *args])
    p = _run([*PY, *args])
    assert (p.returncode, p.stdout, p.stderr) == (c.returncode, c.stdout, c.stderr)
    assert c.returncode in (0, 1, 2)
    assert not (c.returncode == 2 and c.stdout), c.stdout  # wrong arguments: nothing on stdout
    assert b"Traceback" not in p.stderr


def _usage_error(cmd: str, reason: str, usage: str) -> tuple:
    return 2, b"", f"pgloss {cmd}: {reason}\nusage: pgloss {cmd} {usage}\n".encode()


DISTANCE = "c1 d1 c2 d2"

#: The documented grammar, messages and verdicts (tools/cli_common.h), for each tool.
EXPECTED = [
    (["distance", "0.05", "1.5", "0.05", "0.95"],  # d >= 1 is α <= 0 (eq. 3)
     (1, b"status: PGLOSS_ERR_ALPHA (alpha <= 0 (d >= 1): the specular lobe has no spread)\n", b"")),
    (["distance", "-0.05", "0.9", "0.05", "0.95"],  # c < 0 is no contrast gloss (eq. 4)
     (1, b"status: PGLOSS_ERR_NEGATIVE (a reflectance or gloss value is negative)\n", b"")),
    (["distance", "0.087", "0.93", "0.1", "0.9"], (0, b"D = 0.054960\nstatus: ok\n", b"")),  # hypot(.013, 1.78 * .03)
    (["distance", "1e400", "0.9", "0.1", "0.9"], _usage_error("distance", "c1: '1e400' is out of range (|x| > 1.8e308)",
                                                              DISTANCE)),
    (["distance", "0.1", "1e-400", "0.1", "0.9"],
     _usage_error("distance", "d1: '1e-400' is out of range (0 < |x| < 4.9e-324)", DISTANCE)),
    (["distance", "4.9e-324", "0.9", "0.1", "0.9"], (0, b"D = 0.100000\nstatus: ok\n", b"")),
    (["distance", "0x23", "0.9", "0.1", "0.9"], _usage_error("distance", "c1: '0x23' is not a decimal number", DISTANCE)),
    (["distance", "0.1", "inf", "0.1", "0.9"], _usage_error("distance", "d1: 'inf' is not a finite number", DISTANCE)),
    (["distance", "\u0661", "0.9", "0.1", "0.9"],
     _usage_error("distance", "c1: '\\xd9\\xa1' is not a number (digits are ASCII 0-9)", DISTANCE)),
    (["distance", "\uff11", "0.9", "0.1", "0.9"],
     _usage_error("distance", "c1: '\\xef\\xbc\\x91' is not a number (digits are ASCII 0-9)", DISTANCE)),
    (["distance", "0.1", "0.9", "0.2"], _usage_error("distance", "expected 4 arguments, got 3", DISTANCE)),
    (["eval", "0.193", "0.066", "0.07", "inf", "0", "30", "180"],
     _usage_error("eval", "theta_o: 'inf' is not a finite number",
                  "rho_d rho_s alpha theta_o phi_o theta_i phi_i [norm]")),
    (["demo", "extra"], (2, b"", b"pgloss demo: expected no arguments, got 1\nusage: pgloss demo\n")),
    (["finish", "satin", "--L"], _usage_error("finish", "--L needs a number",
                                              "NAME [--L L] [--a A] [--b B] [--norm N] | --list")),
    (["bridge", "openpbr", "50", "0", "0", "x", "0.96"],
     _usage_error("bridge", "c: 'x' is not a number", "TARGET L a b c d | --from TARGET FILE.json")),
    (["fit"], (2, b"", b"pgloss: unknown command 'fit' (pgloss --help lists the commands)\n")),
]


@pytest.mark.parametrize("which", ["c", "python"])
@pytest.mark.parametrize("args,expected", EXPECTED, ids=[repr(" ".join(a))[1:-1] for a, _ in EXPECTED])
def test_grammar_messages_and_verdicts(which: str, args: List[str], expected: tuple) -> None:
    r = _run([*_tool(which), *args])
    assert (r.returncode, r.stdout, r.stderr) == expected


@pytest.mark.parametrize("which", ["c", "python"])
def test_demo_spells_grey(which: str) -> None:
    out = _run([*_tool(which), "demo"]).stdout.decode()
    assert "\n  grey    0.193  0.066  0.07 |" in out and "gray" not in out


@pytest.mark.parametrize("which", ["c", "python"])
@pytest.mark.parametrize("args", [["demo"], ["distance", "0.1", "0.9", "0.2", "0.9"], ["--help"], ["--version"]])
def test_write_errors_are_errors(which: str, args: List[str]) -> None:
    if not Path("/dev/full").exists():
        pytest.skip("no /dev/full on this system")
    with open("/dev/full", "wb") as full:
        r = _run([*_tool(which), *args], stdout=full)
    assert r.returncode == 3
    assert r.stderr == b"pgloss: cannot write the output: No space left on device\n"


@pytest.mark.parametrize("which", ["c", "python"])
@pytest.mark.parametrize("args", [["demo"], ["--help"]])
def test_a_closed_stdout_is_a_write_error(which: str, args: List[str]) -> None:
    r = subprocess.run([*_tool(which), *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=120,
                       preexec_fn=lambda: os.close(1))
    assert (r.returncode, r.stderr) == (3, b"pgloss: cannot write the output: Bad file descriptor\n")


def test_help_lists_the_tools_and_the_packages_commands() -> None:
    c = _run([_c_tool(), "--help"])
    p = _run([*PY, "--help"])
    assert p.returncode == 0 and p.stdout.startswith(c.stdout)
    for name in ("to-physical", "check", "distance", "demo", "figures", "mds", "experiment"):
        assert f"\n  {name} ".encode() in p.stdout
    none = _run(PY)
    assert none.returncode == 2 and none.stderr == p.stdout and none.stdout == b""


def test_package_commands_are_python_and_the_rest_is_the_tool() -> None:
    assert [c.name for c in package_main.COMMANDS] == ["figures", "mds", "magnitude", "experiment", "image-meter"]
    assert cli.tool().is_file() and os.access(cli.tool(), os.X_OK)
    # Called in-process, a tool command runs in a child and returns its exit code.
    assert package_main.main(["envelope", "50"]) == 0
    assert package_main.main(["envelope", "-5"]) == 1
    assert _run([*PY, "--version"]).stdout == f"pgloss {pgloss.__version__}\n".encode()


def _installed(tmp_path: Path) -> Path:
    """The wheel installed with pip into a folder of its own (no build tree, no repository)."""
    if not WHEEL or not Path(WHEEL).is_file():
        pytest.skip("no wheel (PGLOSS_WHEEL; scripts/test-python.sh builds it)")
    target = tmp_path / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "-q", "--disable-pip-version-check", "--no-deps",
                    "--no-index", "--target", str(target), WHEEL], check=True, timeout=300)
    return target


def test_the_wheel_ships_the_tool(tmp_path: Path) -> None:
    target = _installed(tmp_path)
    names = zipfile.ZipFile(WHEEL).namelist()
    assert "pgloss/bin/pgloss" in names
    entry = next(n for n in names if n.endswith(".dist-info/entry_points.txt"))
    assert "pgloss = pgloss.cli:main" in zipfile.ZipFile(WHEEL).read(entry).decode()
    # From a folder outside the repository, with only the installed files on the path.
    env = {k: v for k, v in os.environ.items() if k != "LD_LIBRARY_PATH"}
    env["PYTHONPATH"] = str(target)
    run = tmp_path / "elsewhere"
    run.mkdir()
    args = ["distance", "0.05", "1.5", "0.05", "0.95"]
    want = _run([_c_tool(), *args])
    for argv in ([sys.executable, "-m", "pgloss", *args], [str(target / "bin" / "pgloss"), *args]):
        r = subprocess.run(argv, capture_output=True, cwd=run, env=env, timeout=120)
        assert (r.returncode, r.stdout, r.stderr) == (want.returncode, want.stdout, want.stderr), argv
    # The tool itself needs no Python and no shared libpgloss.
    r = subprocess.run([str(target / "pgloss" / "bin" / "pgloss"), "envelope", "50"], capture_output=True, cwd=run,
                       env={"PATH": "/usr/bin:/bin"}, timeout=60)
    assert r.returncode == 0 and r.stdout.startswith(b"c_max = ")
    ldd = subprocess.run(["ldd", str(target / "pgloss" / "bin" / "pgloss")], capture_output=True, timeout=60)
    assert ldd.returncode == 0 and b"libpgloss" not in ldd.stdout
