# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Type information of the package (PEP 561): the Python modules carry their annotations inline
(no hand-written .pyi beside them), and the extension's stub ``_core.pyi`` is what
pybind11-stubgen (pinned in scripts/test-python.sh) generates from the built module, under a
three-line header. A stale stub fails here; ``bash scripts/python-stubs.sh`` regenerates it.
"""

from __future__ import annotations

import inspect
import subprocess
import sys
from pathlib import Path

import pgloss

ROOT = Path(pgloss.__file__).parent


def test_core_stub_is_the_generated_one(tmp_path: Path) -> None:
    r = subprocess.run([sys.executable, "-m", "pybind11_stubgen", "pgloss._core", "-o", str(tmp_path)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    generated = (tmp_path / "pgloss" / "_core.pyi").read_text(encoding="utf-8")
    *header, body = (ROOT / "_core.pyi").read_text(encoding="utf-8").split("\n", 3)
    assert header[0].startswith("# SPDX-FileCopyrightText") and "python-stubs.sh" in header[2]
    assert body == generated, "bindings/python/pgloss/_core.pyi is stale: run bash scripts/python-stubs.sh"


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
