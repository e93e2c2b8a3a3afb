# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest set-up for tests/bridge: with PGLOSS_REQUIRE_ALL=1 (the test scripts' default, and CI)
a skipped test is a failure (tests/require_all.py)."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from require_all import pytest_sessionfinish, pytest_terminal_summary  # noqa: E402,F401
