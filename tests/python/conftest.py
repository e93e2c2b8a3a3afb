# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest set-up for the Python package's tests.

* ``tests/vectors`` is put on ``sys.path`` so that the shared vector module ``pgloss_vectors``
  (loading, tolerance model and report of the shared test vectors) imports.
* The package under test is the *installed* one (``pip install .``), never the source tree:
  the source folder has no compiled ``_core``.
* With PGLOSS_REQUIRE_ALL=1 (set by scripts/test.sh and CI) a skipped test is a failure.
* The largest error per function and output against the shared vectors is printed at the end.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "vectors"))

import pgloss_vectors as pv  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
import require_all  # noqa: E402  (tests/require_all.py: skips fail under PGLOSS_REQUIRE_ALL=1)

_session: Optional[pv.Report] = None


@pytest.fixture(scope="session")
def vector_report() -> pv.Report:
    """The session's report of the shared vectors; each test checks through a child of it."""
    global _session
    if _session is None:
        _session = pv.Report()
    return _session


def pytest_terminal_summary(terminalreporter, exitstatus, config):  # noqa: D103
    if _session is not None and _session.stats:
        terminalreporter.write_line("")
        for line in _session.summary_lines("pgloss vectors (Python)"):
            terminalreporter.write_line(line)
    require_all.summary(terminalreporter)


def pytest_sessionfinish(session, exitstatus):  # noqa: D103
    require_all.finish(session)
