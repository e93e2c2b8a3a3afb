# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest set-up for tests/web: with PGLOSS_REQUIRE_ALL=1 (the test scripts' default, and CI)
a skipped test is a failure (tests/require_all.py). The session's one static server of the built
site and one headless Chromium (Playwright's sync API allows one per process), shared by the
test files."""
import os
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Iterator

import pytest
from playwright.sync_api import Browser, sync_playwright

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from require_all import pytest_sessionfinish, pytest_terminal_summary  # noqa: E402,F401

ROOT = Path(__file__).resolve().parents[2]
SITE = Path(os.environ.get("PGLOSS_WEB_SITE", ROOT / "build-web/site"))
CHROMIUM = os.environ.get("PGLOSS_CHROMIUM", "/usr/bin/chromium")
FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
         "--disable-background-networking", "--disable-component-update"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture(scope="session")
def base_url() -> Iterator[str]:
    if not (SITE / "pgloss.wasm").is_file():
        pytest.fail(f"{SITE} has no pgloss.wasm: run scripts/picker.sh --build (scripts/test-web.sh does)")
    port = _free_port()
    srv = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                            "--directory", str(SITE)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}"
    for _ in range(100):
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.1).close()
            break
        except OSError:
            time.sleep(0.05)
    yield url
    srv.terminate()
    srv.wait(5)


@pytest.fixture(scope="session")
def browser() -> Iterator[Browser]:
    if not Path(CHROMIUM).is_file():
        pytest.fail(f"no Chromium at {CHROMIUM} (Debian package chromium; scripts/test-web.sh installs it)")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS, headless=True)
        yield b
        b.close()
