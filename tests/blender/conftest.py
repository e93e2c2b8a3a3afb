# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""With PGLOSS_REQUIRE_ALL=1 (scripts/test-materialx.sh's default, and CI) a skipped test is a failure."""
import os


def pytest_terminal_summary(terminalreporter, exitstatus, config):  # noqa: D103
    if os.environ.get("PGLOSS_REQUIRE_ALL") == "1" and terminalreporter.stats.get("skipped"):
        n = len(terminalreporter.stats["skipped"])
        terminalreporter.write_line(f"PGLOSS_REQUIRE_ALL=1: {n} skipped tests count as failures")


def pytest_sessionfinish(session, exitstatus):  # noqa: D103
    if os.environ.get("PGLOSS_REQUIRE_ALL") == "1":
        reporter = session.config.pluginmanager.get_plugin("terminalreporter")
        if reporter is not None and reporter.stats.get("skipped") and session.exitstatus == 0:
            session.exitstatus = 1
