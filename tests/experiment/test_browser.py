# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The whole loop in a real browser (Debian's Chromium, headless, driven by Playwright): three
scripted observers answer from the model — the eq. 5 distance between the stimuli's (c, d) plus
noise for pairs, a glossiness that grows with c and d for magnitude estimation — by moving the
slider as a person would (a mouse click on the track, then arrow keys until the read-out shows
their answer, then Next). The server is SIGKILLed mid-session with an answer in flight and
restarted: no acknowledged response is lost, the answer in flight arrives, and the subject
resumes where they stopped in a new browser page. Then export, and `python -m pgloss mds` on
the export finds 2 dimensions, and confirmatory MDS with c, d the observers' d/c weight 1.78."""
from __future__ import annotations

import csv
import json
import os
import re
import sqlite3
import time
from pathlib import Path
from typing import Dict, Iterator, List, Tuple

import numpy as np
import pytest
from playwright.sync_api import Browser, Page, sync_playwright

from conftest import OUT, TOKEN, pgloss_cli

CHROMIUM = os.environ.get("PGLOSS_CHROMIUM", "/usr/bin/chromium")
FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
         "--disable-background-networking", "--disable-component-update"]
D_WEIGHT = 1.78  # eq. 5: ΔD = sqrt(Δc² + (1.78 Δd)²)


@pytest.fixture(scope="module")
def browser() -> Iterator[Browser]:
    if not Path(CHROMIUM).is_file():
        pytest.fail(f"no Chromium at {CHROMIUM} (Debian package chromium; scripts/test-experiment.sh installs it)")
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS, headless=True)
        yield b
        b.close()


class Observer:
    """A scripted subject: answers from the model with its own noise, through the page's slider."""

    def __init__(self, name: str, stimuli: Dict[str, dict], seed: int, noise: float):
        self.name = name
        self.rng = np.random.default_rng(seed)
        self.noise = noise
        # (c, d) from the manifest's physical parameters by eqs. 3–4, independently of pgloss.
        self.cd = {k: (float(np.cbrt(s["rho_s"] + s["rho_d"] / 2) - np.cbrt(s["rho_d"] / 2)), 1 - s["alpha"])
                   for k, s in stimuli.items()}
        self.answers: Dict[Tuple[str, int], int] = {}  # (procedure, trial) → rating given
        self.shown: Dict[str, List[str]] = {"pairs": [], "magnitude": []}
        self.page: Page = None  # type: ignore[assignment]

    def rating(self, stimuli: List[str]) -> int:
        if len(stimuli) == 2:
            (c1, d1), (c2, d2) = self.cd[stimuli[0]], self.cd[stimuli[1]]
            value = 500.0 * np.hypot(c1 - c2, D_WEIGHT * (d1 - d2))  # the grid's largest ΔD ≈ 0.13 → 65
        else:
            c, d = self.cd[stimuli[0]]
            value = 100.0 * (0.5 * (c - 0.02) / 0.12 + 0.5 * (d - 0.87) / 0.12)
        return int(np.clip(round(value + self.rng.normal(0.0, self.noise)), 0, 100))

    def open(self, browser: Browser, url: str, procedure: str) -> None:
        # bypass_csp: Playwright's wait_for_function evaluates strings, which the page's CSP forbids.
        self.page = browser.new_page(viewport={"width": 1000, "height": 700}, bypass_csp=True)
        self.page.goto(f"{url}/?procedure={procedure}")
        self.page.wait_for_function("document.body.dataset.ready === '1'")
        self.page.fill("#subject", self.name)
        self.page.click("#start-button")
        self.page.wait_for_function("document.body.dataset.screen === 'instructions'")

    def begin(self) -> None:
        self.page.click("#instructions-button")
        self.page.wait_for_function("['trial', 'done'].includes(document.body.dataset.screen)")

    def screen(self) -> str:
        return self.page.evaluate("document.body.dataset.screen")

    def set_slider(self, value: int) -> None:
        """A click on the track near the value, then arrow keys until the read-out says it."""
        page = self.page
        box = page.locator("#slider").bounding_box()
        page.mouse.click(box["x"] + box["width"] * value / 100.0, box["y"] + box["height"] / 2)
        for _ in range(40):
            text = page.inner_text("#readout")
            if not text.isdigit():  # the click landed on the slider's current value: no input event yet
                page.keyboard.press("ArrowRight")
                continue
            shown = int(text)
            if shown == value:
                return
            page.keyboard.press("ArrowRight" if shown < value else "ArrowLeft")
        raise AssertionError(f"the slider did not reach {value}")

    def answer(self, procedure: str, submit: bool = True) -> Tuple[str, List[str], int]:
        """Answers the trial on screen; returns (label, stimuli, rating)."""
        page = self.page
        assert self.screen() == "trial"
        label = page.evaluate("document.body.dataset.trialLabel")
        stimuli = page.eval_on_selector_all("#images img", "els => els.map(e => e.dataset.stimulus)")
        assert page.is_disabled("#next"), "Next must wait for a slider movement"
        assert page.inner_text("#readout") == "–"
        # The paper's display: the images at their fixed size, on black, nothing else but the scale.
        sizes = page.eval_on_selector_all("#images img", "els => els.map(e => [e.width, e.height, e.naturalWidth])")
        assert all(s == [48, 36, 48] for s in sizes)
        assert page.evaluate("getComputedStyle(document.body).backgroundColor") == "rgb(0, 0, 0)"
        low = "0, small difference" if procedure == "pairs" else "0, not glossy"
        assert page.inner_text("#label-low") == low
        rating = self.rating(stimuli)
        self.set_slider(rating)
        if submit:
            self.next(label)
        return label, stimuli, rating

    def next(self, label: str) -> None:
        self.page.click("#next")
        self.page.wait_for_function(
            "l => document.body.dataset.screen !== 'trial' || document.body.dataset.trialLabel !== l", arg=label)

    def practice(self, procedure: str) -> None:
        for k in range(3):
            label, _, _ = self.answer(procedure)
            assert label == f"practice {k + 1} of 3"
        assert self.screen() == "interlude"
        self.page.click("#interlude-button")
        self.page.wait_for_function("document.body.dataset.screen === 'trial'")

    def main_trial(self, procedure: str, total: int) -> bool:
        """Answers one main trial; False when the procedure is finished."""
        if self.screen() == "done":
            return False
        label, stimuli, rating = self.answer(procedure)
        k = int(label.split(" of ")[0])
        assert label == f"{k} of {total}"
        self.record(procedure, stimuli, rating)
        return True

    def record(self, procedure: str, stimuli: List[str], rating: int) -> None:
        trial = len(self.shown[procedure])
        self.shown[procedure].append(",".join(stimuli))
        self.answers[(procedure, trial)] = rating


def db_rows(db: Path, subject: str, procedure: str) -> Dict[int, Tuple[str, int]]:
    with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as con:
        return {t: (s, r) for t, s, r in con.execute(
            "SELECT trial, stimuli, rating FROM responses WHERE subject=? AND procedure=?", (subject, procedure))}


def test_full_loop(manifest: Path, server_factory, browser: Browser, tmp_path: Path):
    t_start = time.monotonic()
    m = json.loads(manifest.read_text())
    stimuli = {s["id"]: s for s in m["stimuli"]}
    db = tmp_path / "exp.sqlite"
    srv = server_factory(manifest, db).start()
    obs = [Observer(f"obs{k + 1}", stimuli, seed=k, noise=3.0) for k in range(3)]

    # --- pairs. Observer 1 alone, half-way; the server is killed with an answer in flight.
    o1 = obs[0]
    o1.open(browser, srv.url, "pairs")
    o1.begin()
    o1.practice("pairs")
    for _ in range(18):
        assert o1.main_trial("pairs", 36)
    assert o1.page.evaluate("document.body.dataset.acked") == "18"
    assert {t: r for t, (_, r) in db_rows(db, "obs1", "pairs").items()} == {
        t: o1.answers[("pairs", t)] for t in range(18)}
    label, shown, rating = o1.answer("pairs", submit=False)
    srv.kill()
    o1.page.click("#next")  # the answer to trial 18 is now in flight to a dead server
    o1.page.wait_for_selector("#connection", state="visible")
    assert o1.page.evaluate("document.body.dataset.pending") == "18"
    o1.record("pairs", shown, rating)
    before = db_rows(db, "obs1", "pairs")
    assert len(before) == 18 and all(before[t][1] == o1.answers[("pairs", t)] for t in range(18))
    srv.start()  # same port, same database
    o1.page.wait_for_function("document.body.dataset.acked === '19'", timeout=30000)
    o1.page.wait_for_selector("#connection", state="hidden")
    after = db_rows(db, "obs1", "pairs")
    assert len(after) == 19 and all(after[t] == before[t] for t in before) and after[18] == (",".join(shown), rating)
    # The subject's browser is closed; they come back in a new page and resume at trial 20.
    o1.page.close()
    o1.open(browser, srv.url, "pairs")
    assert o1.page.is_visible("#instructions-resume") and o1.page.inner_text("#resume-done") == "19"
    o1.begin()
    assert o1.page.evaluate("document.body.dataset.trialLabel") == "20 of 36"
    while o1.main_trial("pairs", 36):
        pass

    # Observers 2 and 3 at the same time, trial by trial.
    for o in obs[1:]:
        o.open(browser, srv.url, "pairs")
        o.begin()
        o.practice("pairs")
    while any([o.main_trial("pairs", 36) for o in obs[1:]]):
        pass

    # --- magnitude estimation: all three at once.
    for o in obs:
        o.page.close()
        o.open(browser, srv.url, "magnitude")
        o.begin()
        o.practice("magnitude")
    while any([o.main_trial("magnitude", 27) for o in obs]):
        pass

    # Every answer is in the database, once, as given, in the order shown.
    for o in obs:
        for procedure, n in (("pairs", 36), ("magnitude", 27)):
            rows = db_rows(db, o.name, procedure)
            assert len(rows) == n
            assert rows == {t: (o.shown[procedure][t], o.answers[(procedure, t)]) for t in range(n)}

    # The seed recorded for observer 2 reconstructs the order they saw, in a fresh process.
    with sqlite3.connect(f"file:{db}?mode=ro", uri=True) as con:
        seed = con.execute("SELECT seed FROM subjects WHERE subject='obs2' AND procedure='pairs'").fetchone()[0]
    code = ("import json, sys; from pgloss.experiment import design; "
            f"print(json.dumps([','.join(t) for t in design.trials({list(stimuli)!r}, 'pairs', {seed})]))")
    import subprocess

    from conftest import PY
    assert json.loads(subprocess.run([PY, "-c", code], capture_output=True, text=True, check=True).stdout) == \
        obs[1].shown["pairs"]

    # The experimenter's view lists everyone as complete.
    view = browser.new_page(bypass_csp=True)
    view.goto(f"{srv.url}/experimenter?token={TOKEN}")
    view.wait_for_function("document.body.dataset.loaded === '1'")
    assert view.locator("#progress tbody tr.complete").count() == 6
    http_csv = view.request.get(f"{srv.url}/export/pairs/obs1.csv?token={TOKEN}").text()
    view.close()
    for o in obs:
        o.page.close()
    srv.stop()

    # --- export, then the analysis.
    out = OUT / "export"
    pgloss_cli("experiment", "export", str(manifest), "--db", str(db), "--out", str(out))
    ids = list(stimuli)
    assert (out / "pairs/obs1.csv").read_text().replace("\r\n", "\n") == http_csv.replace("\r\n", "\n")
    for o in obs:
        with (out / "pairs" / f"{o.name}.csv").open() as f:
            rows = list(csv.reader(f))
        assert rows[0] == [""] + ids and [r[0] for r in rows[1:]] == ids
        mat = np.array([[float(v) for v in r[1:]] for r in rows[1:]])
        assert np.array_equal(mat, mat.T) and np.all(np.diag(mat) == 0)
        for t, pair in enumerate(o.shown["pairs"]):
            a, b = (ids.index(s) for s in pair.split(","))
            assert mat[a, b] == o.answers[("pairs", t)]
    with (out / "magnitude.csv").open() as f:
        mag = list(csv.DictReader(f))
    assert len(mag) == 81
    for r in mag:
        o = obs[int(r["subject"][3:]) - 1]
        t = int(r["trial"])
        assert r["stimulus"] == o.shown["magnitude"][t] and int(r["rating"]) == o.answers[("magnitude", t)]
        assert int(r["repetition"]) == t // 9 + 1
    # --max-dims 3: 9 stimuli cannot support a non-metric 4-D solution (Kruskal & Wish: more than 4
    # stimuli per dimension); with 4 the last drop measured 30–56 %, noise fitted by a near-degenerate
    # configuration, and no elbow could ever be "confirmed" by it.
    run = pgloss_cli("mds", *(str(out / "pairs" / f"{o.name}.csv") for o in obs), "--max-dims", "3",
                     "--stimuli", str(out / "stimuli.csv"), "--out", str(OUT / "mds"))
    print(run.stdout)
    assert "the elbow is at 2 dimensions" in run.stdout, run.stdout
    # Confirmatory MDS with c, d (eqs. 3–4) finds the observers' eq. 5 weight 1.78 of d against c.
    ratio = re.search(r"weight of d / weight of c = ([0-9.]+) \(95% bootstrap interval over subjects "
                      r"([0-9.]+) – ([0-9.]+)\)", run.stdout)
    assert ratio, run.stdout
    # Within 0.3 (17 %), not "inside the bootstrap interval": resampling 3 subjects gives intervals
    # too narrow to cover reliably (measured: 1.749 [1.476, 2.317] and 1.610 [1.512, 1.768]).
    assert abs(float(ratio[1]) - D_WEIGHT) < 0.3, ratio[0]
    with (OUT / "mds/stress_curve.csv").open() as f:
        curve = {int(r["dims"]): float(r["stress1"]) for r in csv.DictReader(f)}
    assert curve[2] < 0.5 * curve[1]
    print(f"full loop: {time.monotonic() - t_start:.1f} s; stress-1 by dimensionality {curve}")
