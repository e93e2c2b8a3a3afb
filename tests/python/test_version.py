# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The version is written once, in libpgloss/include/pgloss/version.h: the installed
distribution's metadata (scikit-build-core reads the header) and pgloss.__version__ (the
linked C library's pgloss_version()) both carry it."""

from __future__ import annotations

import re
from importlib.metadata import version as dist_version
from pathlib import Path

import pgloss

VERSION_H = Path(__file__).resolve().parents[2] / "libpgloss" / "include" / "pgloss" / "version.h"


def header_version() -> str:
    text = VERSION_H.read_text(encoding="utf-8")
    parts = [re.search(rf"^#define PGLOSS_VERSION_{p} (\d+)$", text, re.M) for p in ("MAJOR", "MINOR", "PATCH")]
    assert all(parts), f"no PGLOSS_VERSION_MAJOR/MINOR/PATCH in {VERSION_H}"
    return ".".join(m.group(1) for m in parts if m)


def test_version_is_the_header_version() -> None:
    expected = header_version()
    assert pgloss.__version__ == expected
    assert pgloss.VERSION == expected
    assert dist_version("pgloss") == expected
