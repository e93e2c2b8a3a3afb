# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The C tool ``pgloss`` (tools/ in the repository), which the wheel ships as ``pgloss/bin/pgloss``.

``python -m pgloss`` and the wheel's ``pgloss`` command hand every command that is not the
package's own (:mod:`pgloss.__main__`) to it: ``to-physical``, ``to-perceptual``,
``to-perceptual-rgb``, ``check``, ``match``, ``distance``, ``envelope``, ``eval``,
``glossmeter``, ``from-gloss-units``, ``finish``, ``bridge``, ``demo``, ``--version``. There is one implementation of them, so one grammar, one set of messages and one
set of exit codes: 0 the result is ok or a warning, 1 the core's verdict is an error, 2 wrong
arguments, 3 the output could not be written.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path
from typing import NoReturn, Sequence


def tool() -> Path:
    """The C tool of this installation of the package (SystemExit with the reason if it is
    missing)."""
    path = Path(__file__).resolve().parent / "bin" / ("pgloss.exe" if os.name == "nt" else "pgloss")
    if not path.is_file():
        raise SystemExit(f"pgloss: the C tool is missing from this installation ({path}); reinstall the package")
    return path


def _flush() -> None:
    for stream in (sys.stdout, sys.stderr):
        if stream is not None:
            try:
                stream.flush()
            except OSError:
                pass


def run(args: Sequence[str]) -> int:
    """Runs the C tool on these arguments in a child process with this process's standard
    streams; returns its exit code (128 + N when signal N ended it)."""
    path = tool()
    _flush()
    rc = subprocess.run([str(path), *args], check=False).returncode
    return rc if rc >= 0 else 128 - rc


def exec_tool(args: Sequence[str]) -> NoReturn:
    """Becomes the C tool (POSIX ``execv``): its output, exit code and signals are the tool's own."""
    path = tool()
    if os.name != "posix":
        sys.exit(run(args))
    _flush()
    # Python ignores SIGPIPE and SIGXFSZ, and an exec'd program inherits that: give the tool
    # the defaults it has when a shell starts it (so `| head` ends it as it ends any tool).
    for name in ("SIGPIPE", "SIGXFSZ"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_DFL)
    os.execv(path, [str(path), *args])


def main() -> NoReturn:
    """The wheel's ``pgloss`` command: ``python -m pgloss``."""
    from .__main__ import main as package_main

    sys.exit(package_main())
