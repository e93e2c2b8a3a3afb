# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Type information of the package (PEP 561): the Python modules carry their annotations inline
(no hand-written .pyi beside them), and the extension's stub ``_core.pyi`` is what
pybind11-stubgen (pinned in scripts/test-python.sh) generates from the built module:
``bash scripts/python-stubs.sh`` writes it, ``--check`` (run here) fails when it is stale.
"""

from __future__ import annotations

import inspect
import os
import subprocess
import sys
from pathlib import Path

import pgloss

ROOT = Path(pgloss.__file__).parent
SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "python-stubs.sh"


def test_core_stub_is_the_generated_one() -> None:
    r = subprocess.run(["bash", str(SCRIPT), "--check"], capture_output=True, text=True, timeout=120,
                       env={**os.environ, "PGLOSS_PYTHON": sys.executable})
    assert r.returncode == 0, r.stdout + r.stderr
    # The installed stub is the checked-in one.
    assert (ROOT / "_core.pyi").read_bytes() == (SCRIPT.parents[1] / "bindings/python/pgloss/_core.pyi").read_bytes()


def test_the_python_modules_are_typed_inline() -> None:
    assert (ROOT / "py.typed").is_file()
    assert not (ROOT / "__init__.pyi").exists(), "a hand-written stub would hide the modules' own annotations"
    for name in pgloss.__all__:
        obj = getattr(pgloss, name)
        if inspect.isfunction(obj):
            sig = inspect.signature(obj)
            assert sig.return_annotation is not inspect.Signature.empty, f"{name} has no return annotation"
            for p in sig.parameters.values():
                assert p.annotation is not inspect.Parameter.empty, f"{name}({p.name}) has no annotation"
