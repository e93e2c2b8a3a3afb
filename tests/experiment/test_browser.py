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

from conftest import MAGNITUDE, N, OUT, PAIRS, TOKEN, pgloss_cli

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
        self.seed = seed
        self.noise = noise
        self.index = {k: i for i, k in enumerate(stimuli)}
        self.seen: Dict[str, int] = {}  # magnitude: how often each stimulus was rated in main trials
        # (c, d) from the manifest's physical parameters by eqs. 3–4, independently of pgloss.
        self.cd = {k: (float(np.cbrt(s["rho_s"] + s["rho_d"] / 2) - np.cbrt(s["rho_d"] / 2)), 1 - s["alpha"])
                   for k, s in stimuli.items()}
        self.answers: Dict[Tuple[str, int], int] = {}  # (procedure, trial) → rating given
        self.shown: Dict[str, List[str]] = {"pairs": [], "magnitude": []}
        self.page: Page = None  # type: ignore[assignment]
        self.checked = False

    def rating(self, stimuli: List[str], practice: bool = False) -> int:
        """The model's answer plus noise. The noise is a function of the pair (or of the stimulus and
        its repetition), not of the order, so that the ratings — and so the MDS — do not depend on
        the random trial order: the test is deterministic."""
        key = sorted(self.index[s] for s in stimuli)
        if len(stimuli) == 1:
            if practice:
                key.append(99)
            else:
                key.append(self.seen.get(stimuli[0], 0))
                self.seen[stimuli[0]] = key[-1] + 1
        noise = np.random.default_rng([self.seed, *key]).normal(0.0, self.noise)
        if len(stimuli) == 2:
            (c1, d1), (c2, d2) = self.cd[stimuli[0]], self.cd[stimuli[1]]
            value = 500.0 * np.hypot(c1 - c2, D_WEIGHT * (d1 - d2))  # the grid's largest ΔD ≈ 0.14 → 70
        else:
            c, d = self.cd[stimuli[0]]
            value = 100.0 * (0.5 * (c - 0.02) / 0.12 + 0.5 * (d - 0.87) / 0.12)
        return int(np.clip(round(value + noise), 0, 100))

    def open(self, browser: Browser, url: str, procedure: str) -> None:
        # bypass_csp: Playwright's wait_for_function evaluates strings, which the page's CSP forbids.
        self.page = browser.new_page(viewport={"width": 1000, "height": 700}, bypass_csp=True)
        self.checked = False
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

    def answer(self, procedure: str, submit: bool = True, practice: bool = False) -> Tuple[str, List[str], int]:
        """Answers the trial on screen; returns (label, stimuli, rating)."""
        page = self.page
        state = page.evaluate("""() => ({screen: document.body.dataset.screen, label: document.body.dataset.trialLabel,
            stimuli: [...document.querySelectorAll('#images img')].map(e => e.dataset.stimulus),
            disabled: document.getElementById('next').disabled,
            readout: document.getElementById('readout').textContent})""")
        assert state["screen"] == "trial"
        label, stimuli = state["label"], state["stimuli"]
        assert state["disabled"] and state["readout"] == "–", "Next must wait for a slider movement"
        if not self.checked:  # once per page: the paper's display, images at a fixed size on black
            sizes = page.eval_on_selector_all("#images img", "els => els.map(e => [e.width, e.height, e.naturalWidth])")
            assert sizes == [[48, 36, 48]] * (2 if procedure == "pairs" else 1)
            assert page.evaluate("getComputedStyle(document.body).backgroundColor") == "rgb(0, 0, 0)"
            low = "0, small difference" if procedure == "pairs" else "0, not glossy"
            assert page.inner_text("#label-low") == low
            visible = page.evaluate("""() => [...document.querySelectorAll('body *')].filter(e =>
                e.offsetParent !== null && !e.children.length && e.textContent.trim()).map(e => e.id)""")
            assert sorted(visible) == ["label-high", "label-low", "next", "progress", "readout"], visible
            self.checked = True
        rating = self.rating(stimuli, practice)
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
            label, _, _ = self.answer(procedure, practice=True)
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
    half = PAIRS // 2
    for _ in range(half):
        assert o1.main_trial("pairs", PAIRS)
    assert o1.page.evaluate("document.body.dataset.acked") == str(half)
    assert {t: r for t, (_, r) in db_rows(db, "obs1", "pairs").items()} == {
        t: o1.answers[("pairs", t)] for t in range(half)}
    label, shown, rating = o1.answer("pairs", submit=False)
    o1.page.screenshot(path=str(OUT / "trial-pairs.png"))
    srv.kill()
    o1.page.click("#next")  # the answer to trial `half` is now in flight to a dead server
    o1.page.wait_for_selector("#connection", state="visible")
    assert o1.page.evaluate("document.body.dataset.pending") == str(half)
    o1.record("pairs", shown, rating)
    before = db_rows(db, "obs1", "pairs")
    assert len(before) == half and all(before[t][1] == o1.answers[("pairs", t)] for t in range(half))
    srv.start()  # same port, same database
    o1.page.wait_for_function("n => document.body.dataset.acked === String(n)", arg=half + 1, timeout=30000)
    o1.page.wait_for_selector("#connection", state="hidden")
    after = db_rows(db, "obs1", "pairs")
    assert len(after) == half + 1 and all(after[t] == before[t] for t in before)
    assert after[half] == (",".join(shown), rating)
    # The subject's browser is closed; they come back in a new page and resume after the last one stored.
    o1.page.close()
    o1.open(browser, srv.url, "pairs")
    assert o1.page.is_visible("#instructions-resume") and o1.page.inner_text("#resume-done") == str(half + 1)
    o1.begin()
    assert o1.page.evaluate("document.body.dataset.trialLabel") == f"{half + 2} of {PAIRS}"
    while o1.main_trial("pairs", PAIRS):
        pass

    # Observers 2 and 3 at the same time, trial by trial.
    for o in obs[1:]:
        o.open(browser, srv.url, "pairs")
        o.begin()
        o.practice("pairs")
    while any([o.main_trial("pairs", PAIRS) for o in obs[1:]]):
        pass

    # --- magnitude estimation: all three at once.
    for o in obs:
        o.page.close()
        o.open(browser, srv.url, "magnitude")
        o.begin()
        o.practice("magnitude")
    while any([o.main_trial("magnitude", MAGNITUDE) for o in obs]):
        pass

    # Every answer is in the database, once, as given, in the order shown.
    for o in obs:
        for procedure, n in (("pairs", PAIRS), ("magnitude", MAGNITUDE)):
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
    view.screenshot(path=str(OUT / "experimenter.png"))
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
    assert len(mag) == 3 * MAGNITUDE
    for r in mag:
        o = obs[int(r["subject"][3:]) - 1]
        t = int(r["trial"])
        assert r["stimulus"] == o.shown["magnitude"][t] and int(r["rating"]) == o.answers[("magnitude", t)]
        assert int(r["repetition"]) == t // N + 1
    # --max-dims 3: 12 stimuli support at most a 2- or 3-D non-metric solution (Kruskal & Wish: about
    # 4 stimuli per dimension); a 4-D fit is near-degenerate (with 9 stimuli its drop measured 30–56 %).
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
