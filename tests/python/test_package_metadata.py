# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The built wheel's metadata: licence, project URLs, classifiers and a README for
Python users, read from the METADATA of the wheel that scripts/check-python-dist.sh built
(PGLOSS_WHEEL) and from the installed distribution (importlib.metadata)."""

from __future__ import annotations

import os
import zipfile
from email.parser import Parser
from importlib.metadata import metadata as installed_metadata
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
WHEEL = os.environ.get("PGLOSS_WHEEL", "")


def _wheel() -> zipfile.ZipFile:
    if not WHEEL or not Path(WHEEL).is_file():
        pytest.skip("no built wheel (PGLOSS_WHEEL; scripts/check-python-dist.sh builds it)")
    return zipfile.ZipFile(WHEEL)


def _check(meta) -> None:
    assert meta["Name"] == "pgloss"
    assert meta["License-Expression"] == "Apache-2.0"
    assert "LICENSE" in meta.get_all("License-File")
    urls = dict(u.split(", ", 1) for u in meta.get_all("Project-URL"))
    assert {"Homepage", "Source", "Documentation", "Issues", "Changelog"} <= set(urls)
    assert all(u.startswith("https://") for u in urls.values())
    classifiers = meta.get_all("Classifier")
    for c in ("Programming Language :: Python :: 3", "Programming Language :: C",
              "Topic :: Multimedia :: Graphics :: 3D Rendering", "Topic :: Scientific/Engineering",
              "Typing :: Typed"):
        assert c in classifiers
    assert not any(c.startswith("License ::") for c in classifiers)  # PEP 639: the expression says it
    assert "BRDF" in meta["Keywords"] and "gloss" in meta["Keywords"]
    assert any(r.startswith("numpy") for r in meta.get_all("Requires-Dist"))
    assert meta["Requires-Python"] == ">=3.9"
    assert meta["Description-Content-Type"] == "text/markdown"


def test_wheel_metadata() -> None:
    w = _wheel()
    name = next(n for n in w.namelist() if n.endswith(".dist-info/METADATA"))
    text = w.read(name).decode("utf-8")
    meta = Parser().parsestr(text)
    _check(meta)
    body = meta.get_payload()
    readme = (ROOT / "bindings" / "python" / "README.md").read_text(encoding="utf-8")
    assert body.strip() == readme.strip()  # the package README, not the C library's
    assert "as root" not in body and "pip install pgloss" in body
    # The licence text travels in the wheel (PEP 639: .dist-info/licenses/).
    lic = next(n for n in w.namelist() if n.endswith(".dist-info/licenses/LICENSE"))
    assert w.read(lic) == (ROOT / "LICENSE").read_bytes()
    # Only the package: the pure-Python modules (typed inline), the extension's stub, py.typed and
    # the extension.
    files = [n for n in w.namelist() if ".dist-info/" not in n]
    assert all(n.startswith("pgloss/") for n in files), files
    for f in ("pgloss/__init__.py", "pgloss/_paints.py", "pgloss/_core.pyi", "pgloss/py.typed", "pgloss/cli.py"):
        assert f in files
    assert any(n.startswith("pgloss/_core.") and n.endswith(".so") for n in files)


def test_installed_metadata() -> None:
    _check(installed_metadata("pgloss"))


def test_wheel_qualifies_as_manylinux() -> None:
    _wheel()
    tag = Path(WHEEL).parent / "manylinux-tag"
    assert tag.is_file() and tag.read_text().startswith("manylinux_")
