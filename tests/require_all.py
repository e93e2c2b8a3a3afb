# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The pytest hooks every test folder shares: with PGLOSS_REQUIRE_ALL=1 (the test scripts'
default, and CI) a skipped test is a failure, so that no test skips silently.

A conftest takes them with ``from require_all import pytest_terminal_summary,
pytest_sessionfinish`` (tests/ on sys.path), or calls ``summary`` and ``finish`` from hooks of
its own."""
from __future__ import annotations

import os


def required() -> bool:
    """True when PGLOSS_REQUIRE_ALL=1: every dependency must be present, nothing may skip."""
    return os.environ.get("PGLOSS_REQUIRE_ALL") == "1"


def summary(terminalreporter) -> None:
    """Names the skips that count as failures (call from pytest_terminal_summary)."""
    skipped = terminalreporter.stats.get("skipped", [])
    if required() and skipped:
        terminalreporter.write_line(f"PGLOSS_REQUIRE_ALL=1: {len(skipped)} skipped tests count as failures")
        for r in skipped[:10]:
            terminalreporter.write_line(f"  skipped: {getattr(r, 'nodeid', r)}")


def finish(session) -> None:
    """Fails a run that passed but skipped something (call from pytest_sessionfinish)."""
    if required():
        reporter = session.config.pluginmanager.get_plugin("terminalreporter")
        if reporter is not None and reporter.stats.get("skipped") and session.exitstatus == 0:
            session.exitstatus = 1


def pytest_terminal_summary(terminalreporter, exitstatus, config):  # noqa: D103
    summary(terminalreporter)


def pytest_sessionfinish(session, exitstatus):  # noqa: D103
    finish(session)
