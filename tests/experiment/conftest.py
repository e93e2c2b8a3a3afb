# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pytest set-up for tests/experiment: tests/require_all.py's hooks (with PGLOSS_REQUIRE_ALL=1 a skipped test
is a failure), and the fixtures the experiment's tests share: the rendered stimuli and servers."""
from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
import zipfile
from pathlib import Path
from typing import Any, Dict, Iterator, List, Optional, Tuple

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
from require_all import pytest_sessionfinish, pytest_terminal_summary  # noqa: E402,F401

PY = os.environ.get("PGLOSS_EXPERIMENT_PY", str(ROOT / ".venv-py/bin/python"))
TRACER = os.environ.get("PGLOSS_TRACER", str(ROOT / "build-tracer-test/examples/tracer/pgloss-tracer"))
OUT = ROOT / "out/experiment-test"
#: 12 stimuli on a 4 × 3 grid of the (c, d) plane at the grey stimuli's lightness: a configuration
#: that is two-dimensional by construction, so that the stress curve has something to find. Not
#: 3 × 3: with 9 stimuli the 3-D fit of noise drops the stress by 26–48 % and the elbow rule
#: (a 2-D drop ≥ 2× every later one) failed in 2 of 10 simulated runs; with 12, 14–22 % (10 of 10).
LEVELS_C = (0.03, 0.06, 0.09, 0.12)
LEVELS_D = (0.90, 0.93, 0.96)
SPEC = f"L=51 c={','.join(map(str, LEVELS_C))} d={','.join(map(str, LEVELS_D))}"
N = len(LEVELS_C) * len(LEVELS_D)
PAIRS = N * (N - 1) // 2  # 66 pair trials per subject
MAGNITUDE = 3 * N  # 36 magnitude trials per subject
TOKEN = "test-token"
#: Debian's Chromium, headless with WebGL2 (SwiftShader), for the browser tests (Playwright).
CHROMIUM = os.environ.get("PGLOSS_CHROMIUM", "/usr/bin/chromium")
FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
         "--disable-background-networking", "--disable-component-update"]


def pgloss_cli(*args: str, check: bool = True, timeout: float = 300) -> subprocess.CompletedProcess:
    """`python -m pgloss …` in the Python that has the binding."""
    run = subprocess.run([PY, "-m", "pgloss", *args], capture_output=True, text=True, timeout=timeout)
    if check and run.returncode != 0:
        raise AssertionError(f"pgloss {' '.join(args)} exited {run.returncode}:\n{run.stdout}\n{run.stderr}")
    return run


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def jrzip(path: Path, runs: List[tuple], compression: int = zipfile.ZIP_DEFLATED) -> Path:
    """A JATOS results archive as JATOS 3.x writes it (ResultStreamer, IOUtils.getResultsPathForZip,
    JsonUtils.studyResultMetadata): metadata.json and study_result_N/comp-result_M/data.txt; runs are
    (study title, data.txt file)."""
    meta = {"data": []}
    with zipfile.ZipFile(path, "w", compression) as z:
        for k, (title, data) in enumerate(runs, 1):
            sr, cr = 100 + k, 200 + k
            z.writestr(f"study_result_{sr}/comp-result_{cr}/data.txt", data.read_text(encoding="utf-8"))
            meta["data"].append({"studyId": k, "studyUuid": f"uuid-{k}", "studyTitle": title, "studyResults": [{
                "id": sr, "uuid": f"sr-{k}", "studyState": "FINISHED", "workerId": 77, "workerType": "GeneralSingle",
                "componentResults": [{"id": cr, "componentState": "FINISHED", "path": f"/study_result_{sr}/comp-result_{cr}",
                                      "data": {"size": data.stat().st_size}, "files": []}]}]})
        z.writestr("metadata.json", json.dumps(meta))
    return path


@pytest.fixture(scope="session")
def manifest() -> Path:
    """The 12 stimuli, rendered once per run (48 × 36 px, 16 spp: seconds)."""
    if not Path(PY).is_file():
        pytest.fail(f"no Python with pgloss at {PY} (scripts/test-experiment.sh sets it up)")
    if not Path(TRACER).is_file():
        pytest.fail(f"no pgloss-tracer at {TRACER} (scripts/test-experiment.sh builds it)")
    out = OUT / "stimuli"
    run = pgloss_cli("experiment", "stimuli", SPEC, "--out", str(out), "--tracer", TRACER, "--size", "48x36",
                     "--spp", "16", "--scene", str(ROOT / "examples/tracer/scenes/stimulus.scene"))
    assert "manifest:" in run.stdout
    return out / "manifest.json"


class Server:
    """`python -m pgloss experiment serve` in a subprocess, on a fixed port so that it can be restarted."""

    def __init__(self, manifest: Path, db: Path, port: Optional[int] = None, token: str = TOKEN, log: bool = False):
        self.manifest, self.db, self.port = manifest, db, port or free_port()
        self.token, self.log = token, log  # log: the request log on stderr (else --quiet)
        self.proc: Optional[subprocess.Popen] = None
        self.url = f"http://127.0.0.1:{self.port}"
        self.output = ("", "")  # stdout, stderr, once stopped

    def start(self) -> "Server":
        self.proc = subprocess.Popen([PY, "-m", "pgloss", "experiment", "serve", str(self.manifest), "--db",
                                      str(self.db), "--port", str(self.port), "--token", self.token]
                                     + ([] if self.log else ["--quiet"]),
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise AssertionError(f"server exited {self.proc.returncode}: {self.proc.stderr.read()}")
            try:
                socket.create_connection(("127.0.0.1", self.port), timeout=0.2).close()
                return self
            except OSError:
                time.sleep(0.05)
        raise AssertionError("server did not start in 60 s")

    def kill(self) -> None:
        """SIGKILL: no clean-up, no flush — what a crash or a pulled plug does to the process."""
        assert self.proc is not None
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(10)
        self.proc.stdout.close()
        self.proc.stderr.close()

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.output = self.proc.communicate(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.output = self.proc.communicate(timeout=5)

    def request(self, path: str, body: Any = None, *, raw: Optional[bytes] = None,
                headers: Optional[Dict[str, str]] = None) -> Tuple[int, Any]:
        """(status, decoded JSON or text) of one request."""
        data = raw if raw is not None else (None if body is None else json.dumps(body).encode())
        hdr = {"Content-Type": "application/json"} if data is not None else {}
        hdr.update(headers or {})
        req = urllib.request.Request(self.url + path, data=data, headers=hdr, method="POST" if data is not None else "GET")
        try:
            with urllib.request.urlopen(req, timeout=30) as r:
                status, text = r.status, r.read().decode()
        except urllib.error.HTTPError as e:
            status, text = e.code, e.read().decode()
        try:
            return status, json.loads(text)
        except ValueError:
            return status, text


@pytest.fixture
def server_factory(tmp_path: Path) -> Iterator:
    servers = []

    def make(manifest: Path, db: Optional[Path] = None, port: Optional[int] = None) -> Server:
        s = Server(manifest, db or tmp_path / "responses.sqlite", port)
        servers.append(s)
        return s

    yield make
    for s in servers:
        s.stop()


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    """One headless Chromium per test module (Playwright, imported here so that the tests without
    a browser do not need it)."""
    from playwright.sync_api import sync_playwright

    if not Path(CHROMIUM).is_file():
        pytest.fail(f"no Chromium at {CHROMIUM} (Debian package chromium; scripts/test-experiment.sh installs it)")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS, headless=True)
        yield b
        b.close()
