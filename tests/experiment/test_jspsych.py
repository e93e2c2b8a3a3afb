# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The jsPsych study end to end in a real browser (Debian's Chromium, headless, Playwright): the
study exported for both procedures and served as plain files; three scripted observers (eq. 5
plus noise, observers.py) go through consent, full screen, the virtual chinrest (the card dragged
to 342 px, i.e. 4.0 px/mm; the blind spot answered when the ball is 300 mm·tan 13.5° away), the
screen check, practice, breaks and every trial. Observer 1 saves JSON, observer 2 (device pixel
ratio 2) CSV, observer 3 runs under a stand-in of jatos.js whose appended rows are packed as a
JATOS results archive (.jrzip). Then `experiment import` of the three (once more: nothing added),
`experiment export` (the store holds exactly the answers given, trial by trial), `python -m
pgloss mds` (2 dimensions, the d/c weight within 0.3 of the planted 1.78, the 2-D configuration
the planted (c, 1.78 d): Procrustes r² ≥ 0.995, Spearman's ρ of the distances ≥ 0.95) and
`python -m pgloss magnitude` (c + d the best pair). On the way: the stimuli are on screen in
device pixels exactly as an independent box filter (numpy, below) reduces the rendered image, at
the visual angle the chinrest's numbers give; the slider has no thumb before the first touch.

The test's study is reduced to be quick (12 stimuli, 66 pairs, 1° images, 30 ms between trials,
2 blind-spot sweeps, 2 practice trials); `scripts/test-experiment.sh --full` runs the same
observers on the paper's defaults (3.2°, 500 ms, 5 sweeps, 3 practice trials)."""
from __future__ import annotations

import csv
import functools
import http.server
import json
import math
import os
import re
import shutil
import subprocess
import threading
import time
from fractions import Fraction
from pathlib import Path
from typing import Dict, Iterator, List, Optional

import numpy as np
import pytest
from playwright.sync_api import Browser, Page

from conftest import MAGNITUDE, OUT, PAIRS, PY, ROOT, jrzip, pgloss_cli
from observers import D_WEIGHT, Model, set_slider, thumb_hidden
from pngio import read_png
from recovery import distances, procrustes_r2, spearman

FULL = os.environ.get("PGLOSS_JSPSYCH_FULL") == "1"
OPTIONS = [] if FULL else ["--visual-angle", "1", "--iti-ms", "30", "--chinrest-reps", "2", "--practice", "2",
                           "--break-every", "30"]
#: The 2-D configuration against the planted (c, 1.78 d). In 30 simulated runs of these observers
#: (tests/experiment/elbow_simulation.py) Procrustes r² was 0.9984–0.9997 and Spearman's ρ of the
#: 66 distances 0.981–0.993 (ρ < 1: pairs whose planted distances differ by less than the noise,
#: e.g. 2Δc = 0.060 against hypot(Δc, 1.78Δd) = 0.061, swap ranks); the planted points with their
#: labels shuffled gave at most r² 0.34 and ρ 0.25. This test's observers (their noise is fixed
#: per pair, so the figures repeat) give r² 0.9992 and ρ 0.974. The limits sit below all of these
#: and far above the nulls: a configuration that passes has the planted shape.
R2_MIN, RHO_MIN = 0.995, 0.95
CARD_PX, PX_PER_MM, DISTANCE_MM = 342, 4.0, 300.0  # 342 / 85.6 mm = 3.995, which the chinrest rounds to 4.0
GAMMA_CODE, BLACK_CODE = 186, 4


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:
        pass


@pytest.fixture(scope="module")
def site(manifest: Path, tmp_path_factory) -> Iterator[tuple]:
    """Both studies exported, served as static files: /static/P/ as exported, /jatos/P/ with the
    jatos.js stand-in beside index.html (where JATOS serves its own)."""
    root = tmp_path_factory.mktemp("site")
    for procedure in ("pairs", "magnitude"):
        pgloss_cli("experiment", "export-jspsych", str(manifest), "--procedure", procedure, "--out",
                   str(root / "static" / procedure), "--completion-code", "C0DE-42", *OPTIONS)
        shutil.copytree(root / "static" / procedure, root / "jatos" / procedure)
        shutil.copyfile(Path(__file__).with_name("fake_jatos.js"), root / "jatos" / procedure / "jatos.js")
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(root)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    yield root, f"http://127.0.0.1:{server.server_address[1]}"
    server.shutdown()
    server.server_close()


STATE = """() => {
  const slider = document.getElementById('pgloss-slider');
  if (document.body.dataset.pglossTrial !== undefined && slider && !slider.disabled) return 'trial:' + document.body.dataset.pglossTrial;
  if (document.getElementById('pgloss-download-json') || (window.jatos && window.jatos.ended)) return 'end';
  const stim = document.getElementById('jspsych-html-button-response-stimulus');
  if (stim && document.querySelector('#jspsych-html-button-response-btngroup button')) return 'button:' + stim.textContent.slice(0, 60);
  return '';
}"""


def box_filter(image: np.ndarray, w: int, h: int, gamma: float) -> np.ndarray:
    """The image's area mean over each of w × h cells, in linear light: every source pixel repeated
    w (h) times, then block means of W (H) — exact, and another formulation than display.js's."""
    lin = (image.astype(np.float64) / 255.0) ** gamma
    H, W, _ = lin.shape
    a = np.repeat(lin, w, axis=1).reshape(H, w, W, 3).mean(axis=2)
    b = np.repeat(a, h, axis=0).reshape(h, H, w, 3).mean(axis=1)
    return np.rint(255.0 * b ** (1.0 / gamma))


def grid_size(want: float, dpr: float, width: int, height: int) -> tuple:
    """The stimulus size the display must choose: whole CSS pixels that are whole device pixels, so
    at a ratio p/q (Fraction.limit_denominator) multiples of p device pixels; the width the nearest
    such to the wanted device width, the height the nearest to the image's aspect (halves up), both
    within the rendered image."""
    r = Fraction(dpr).limit_denominator(16)
    assert abs(float(r) - dpr) < 1e-5, dpr  # float32 ratios as browsers give them (1.1 = 1.10000002384)
    p = r.numerator
    w = p * max(1, min(width // p, math.floor(Fraction(want) / p + Fraction(1, 2))))
    h = p * max(1, min(height // p, math.floor(Fraction(w * height, width * p) + Fraction(1, 2))))
    return w, h


class Observer:
    def __init__(self, name: str, model: Model, mode: str, dpr: float):
        self.name, self.model, self.mode, self.dpr = name, model, mode, dpr
        self.page: Optional[Page] = None
        self.state = ""
        self.answers: Dict[int, tuple] = {}
        self.given: Dict[str, Dict[int, tuple]] = {}  # procedure → the answers of its run
        self.checked = False

    def open(self, browser: Browser, url: str) -> None:
        self.page = browser.new_page(viewport={"width": 1100, "height": 760}, device_scale_factor=self.dpr)
        self.errors: List[str] = []
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.goto(url)
        self.model.seen.clear()
        self.answers, self.checked, self.checked_touch, self.state = {}, False, False, ""

    def setup(self) -> None:
        """Consent, full screen, the virtual chinrest, the screen check."""
        page = self.page
        page.click("button:has-text('I agree')")
        page.click("#jspsych-fullscreen-btn")
        handle = page.wait_for_selector("#jspsych-resize-handle").bounding_box()
        width = page.evaluate("document.querySelector('#item').getBoundingClientRect().width")
        x, y = handle["x"] + handle["width"] / 2, handle["y"] + handle["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + (CARD_PX - width) / 2, y, steps=4)  # the plugin grows the card by 2·dx
        page.mouse.up()
        page.click("#end_resize_phase")
        sweeps = 5 if FULL else 2
        for _ in range(sweeps):
            page.wait_for_selector("#virtual-chinrest-circle")
            page.keyboard.press(" ")
            page.wait_for_function("""d => { const b = document.querySelector('#virtual-chinrest-circle').getBoundingClientRect();
                const s = document.querySelector('#virtual-chinrest-square').getBoundingClientRect();
                return (s.left + s.width / 2) - (b.left + b.width / 2) >= d; }""",
                                   arg=PX_PER_MM * DISTANCE_MM * math.tan(math.radians(13.5)), polling="raf")
            page.keyboard.press(" ")
        page.click("#distance-report #proceed")
        page.wait_for_selector("#pgloss-gamma-slider")
        page.fill("#pgloss-gamma-slider", str(GAMMA_CODE))
        page.click("#pgloss-gamma-done")
        page.click(f".pgloss-black[data-code='{BLACK_CODE}']")

    def wait(self) -> str:
        handle = self.page.wait_for_function(f"prev => {{ const s = ({STATE})(); return s && s !== prev ? s : null; }}",
                                             arg=self.state, timeout=30000)
        self.state = handle.json_value()
        return self.state

    def act(self) -> bool:
        """Answers what is on screen; False once the study has ended."""
        page, state = self.page, self.state
        if state == "end":
            return False
        if state.startswith("button:"):
            page.click("#jspsych-html-button-response-btngroup button >> nth=0")
            return True
        label = state[len("trial:"):]
        stimuli = page.eval_on_selector_all("canvas.pgloss-stimulus", "els => els.map(e => e.dataset.stimulus)")
        if not self.checked and not label.startswith("practice"):
            self.check_display(stimuli)
        rating = self.model.rating(stimuli, practice=label.startswith("practice"))
        set_slider(page, rating)
        if not self.checked_touch:
            assert not thumb_hidden(page), "the thumb must show once the slider is touched"
            self.checked_touch = True
        page.click("#pgloss-next")
        if not label.startswith("practice"):
            k, n = (int(v) for v in label.split(" of "))
            self.answers[k - 1] = (tuple(stimuli), rating)
        return True

    def check_display(self, stimuli: List[str]) -> None:
        """Once per page: no thumb and no read-out before the first touch; the canvases in device
        pixels, of the size the chinrest gives, showing the box-filtered image."""
        page = self.page
        assert thumb_hidden(page) and page.inner_text("#pgloss-readout") == "–"
        assert page.is_disabled("#pgloss-next")
        sizes = page.eval_on_selector_all("canvas.pgloss-stimulus", "els => els.map(e => { const r = e.getBoundingClientRect(); "
                                          "return [e.width, e.height, r.width, r.height, r.left + scrollX, r.top + scrollY, e.dataset.deviceExact, "
                                          "r.left, r.top]; })")
        w, h = sizes[0][:2]
        # The browser's own check (devicePixelContentBoxSize); Chromium under an emulated device scale
        # factor reports it at the host's scale (1), so there the screenshot below is the check.
        assert self.dpr != 1 or all(s[6] == "true" for s in sizes), sizes
        # Size and corner on the page in whole CSS pixels that are whole device pixels (no edge between
        # device pixels); on screen (scrolled by whole device pixels) whole device pixels.
        assert all(s[2] * self.dpr == s[0] and s[3] * self.dpr == s[1] for s in sizes), sizes
        assert all(float(v).is_integer() and float(v * self.dpr).is_integer() for s in sizes for v in s[2:6]), sizes
        assert all(float(v * self.dpr).is_integer() for s in sizes for v in s[7:9]), sizes
        self.size = (w, h)
        shot = self.page.screenshot()
        path = OUT / f"jspsych-{self.name}-{self.model.seed}.png"
        path.write_bytes(shot)
        img, _ = read_png(path)
        for sid, (left, top) in zip(stimuli, (s[7:9] for s in sizes)):
            master, _ = read_png(self.folder / "stimuli" / f"{sid}.png")
            want = box_filter(master, w, h, self.gamma)
            x0, y0 = int(left * self.dpr), int(top * self.dpr)  # whole (asserted above)
            diff = np.abs(img[y0:y0 + h, x0:x0 + w].astype(float) - want).max()
            assert diff <= 1, (f"{self.name} (DPR {self.dpr}) {sid} at {x0},{y0} in a {img.shape} screenshot: the canvas "
                               f"differs from the box-filtered image by {diff} code values")
        page.mouse.move(5, 5)
        self.checked = True

    def data(self, out: Path, procedure: str) -> Path:
        page = self.page
        if self.mode == "jatos":
            assert page.evaluate("window.jatos.ended.successful") is True
            text = page.evaluate("window.jatos.data.join('')")
            path = out / f"{self.name}-{procedure}.data.txt"
            path.write_text(text, encoding="utf-8")
            return path
        button = "#pgloss-download-json" if self.mode == "json" else "#pgloss-download-csv"
        assert "C0DE-42" in page.inner_text("body")
        with page.expect_download() as dl:
            page.click(button)
        path = out / dl.value.suggested_filename
        dl.value.save_as(path)
        return path


def test_stimulus_size_on_the_pixel_grid(browser: Browser):
    """display.js's stimulusSize at integer and fractional device pixel ratios (system scales and
    browser zoom levels) against grid_size: whole CSS pixels that are whole device pixels."""
    page = browser.new_page()
    page.add_script_tag(path=str(ROOT / "bindings/python/pgloss/experiment/static/display.js"))
    cases = [(dpr, px_mm, mm, 48, 36) for dpr in (1, 2, 3, 1.25, 1.5, 1.75, 2.5, 1.1, 0.9, 2 / 3)
             for px_mm, mm in ((4.0, 300.0), (4.0, 315.0), (3.7, 287.0), (9.0, 900.0))]
    cases += [(1.25, 3.8, 600.0, 640, 481), (1.5, 4.2, 550.0, 333, 250)]
    for dpr, px_mm, mm, width, height in cases:
        dpr_js = page.evaluate("x => Math.fround(x)", dpr) if dpr in (1.1, 0.9, 2 / 3) else dpr  # as Chromium gives it
        got = page.evaluate("a => { const s = pglossDisplay.stimulusSize({angleDeg: 1, distanceMm: a[1], pxPerMm: a[2], "
                            "dpr: a[0], imageWidth: a[3], imageHeight: a[4]}); return [s.width, s.height, "
                            "pglossDisplay.cssLength(s.width, a[0]), pglossDisplay.cssLength(s.height, a[0])]; }",
                            [dpr_js, mm, px_mm, width, height])
        want = 2 * mm * math.tan(math.radians(0.5)) * px_mm * dpr_js
        size = grid_size(want, dpr_js, width, height)
        assert tuple(got[:2]) == size, (dpr, px_mm, mm, got, size)
        r = Fraction(dpr_js).limit_denominator(16)
        assert got[2:] == [size[0] // r.numerator * r.denominator, size[1] // r.numerator * r.denominator], got
    page.close()


def test_jspsych_study_end_to_end(manifest: Path, site, browser: Browser, tmp_path: Path):
    t0 = time.monotonic()
    root, url = site
    m = json.loads(manifest.read_text())
    stimuli = {s["id"]: s for s in m["stimuli"]}
    observers = [Observer("obs1", Model(stimuli, 0, 3.0), "json", 1), Observer("obs2", Model(stimuli, 1, 3.0), "csv", 2),
                 Observer("obs3", Model(stimuli, 2, 3.0), "jatos", 1)]
    files: Dict[str, List[Path]] = {}
    for procedure, total in (("pairs", PAIRS), ("magnitude", MAGNITUDE)):
        for o in observers:
            where = "jatos" if o.mode == "jatos" else "static"
            o.folder, o.gamma = root / where / procedure, m["display"]["gamma"]
            query = "" if o.mode == "jatos" else f"?subject={o.name}"
            o.open(browser, f"{url}/{where}/{procedure}/index.html{query}")
            o.setup()
        for o in observers:
            o.wait()
        active = list(observers)
        while active:  # trial by trial, all three at once
            active = [o for o in active if o.act()]
            for o in active:
                o.wait()
        for o in observers:
            assert not o.errors, o.errors
            assert sorted(o.answers) == list(range(total)), f"{o.name} answered {len(o.answers)} of {total}"
            files.setdefault(o.mode, []).append(o.data(tmp_path, procedure))
            # The trials follow the seed the study recorded (design.js = design.py).
            seed = int(o.page.evaluate("document.body.dataset.pglossSeed"))
            code = ("import json; from pgloss.experiment import design; "
                    f"print(json.dumps(design.trials({list(stimuli)!r}, {procedure!r}, {seed})))")
            order = json.loads(subprocess.run([PY, "-c", code], capture_output=True, text=True, check=True).stdout)
            assert [list(o.answers[t][0]) for t in range(total)] == order
            o.subject = o.page.evaluate("document.body.dataset.pglossSubject")
            o.given[procedure] = dict(o.answers)
            o.page.close()
    print(f"browser part: {time.monotonic() - t0:.1f} s")

    db = tmp_path / "online.sqlite"
    archive = jrzip(tmp_path / "jatos_results.jrzip", [("pairs", files["jatos"][0]), ("magnitude", files["jatos"][1])])
    run = pgloss_cli("experiment", "import", str(manifest), *map(str, files["json"] + files["csv"]), str(archive),
                     "--db", str(db))
    assert f"{3 * (PAIRS + MAGNITUDE)} responses in 6 sittings imported" in run.stdout, run.stdout
    again = pgloss_cli("experiment", "import", str(manifest), str(archive), "--db", str(db))
    assert "0 responses in 0 sittings imported" in again.stdout and f"({PAIRS + MAGNITUDE} already there)" in again.stdout

    out = OUT / "jspsych-export"
    pgloss_cli("experiment", "export", str(manifest), "--db", str(db), "--out", str(out))
    subjects = ["jatos-77", "obs1", "obs2"]
    # No answer lost or changed: the store holds exactly what each observer answered, trial by trial.
    with (out / "responses.csv").open() as f:
        stored = {(r["subject"], r["procedure"], int(r["trial"])): (tuple(r["stimuli"].split()), int(r["rating"]))
                  for r in csv.DictReader(f)}
    given = {(o.subject, procedure, t): answer for o in observers for procedure, answers in o.given.items()
             for t, answer in answers.items()}
    assert len(given) == 3 * (PAIRS + MAGNITUDE) and stored == given
    assert sorted(p.stem for p in (out / "pairs").glob("*.csv")) == subjects
    with (out / "screens.csv").open() as f:
        screens = list(csv.DictReader(f))
    assert len(screens) == 6
    for s in screens:
        dpr = float(s["dpr"])
        assert float(s["px_per_mm"]) == PX_PER_MM and abs(float(s["view_dist_mm"]) - DISTANCE_MM) < 0.05 * DISTANCE_MM
        angle = 3.2 if FULL else 1.0
        want = 2 * float(s["view_dist_mm"]) * math.tan(math.radians(angle / 2)) * PX_PER_MM * dpr
        size = grid_size(want, dpr, m["renderer"]["width"], m["renderer"]["height"])
        assert (int(s["image_device_width"]), int(s["image_device_height"])) == size, (s, size)
        assert int(s["gamma_code"]) == GAMMA_CODE and int(s["black_code"]) == BLACK_CODE
        assert abs(float(s["gamma_estimate"]) - math.log(0.5) / math.log(GAMMA_CODE / 255)) < 1e-3
        assert float(s["display_gamma_stated"]) == m["display"]["gamma"]

    run = pgloss_cli("mds", *(str(out / "pairs" / f"{s}.csv") for s in subjects), "--max-dims", "3",
                     "--stimuli", str(out / "stimuli.csv"), "--out", str(OUT / "jspsych-mds"))
    print(run.stdout)
    assert "the elbow is at 2 dimensions" in run.stdout, run.stdout
    ratio = re.search(r"weight of d / weight of c = ([0-9.]+)", run.stdout)
    assert ratio and abs(float(ratio[1]) - D_WEIGHT) < 0.3, run.stdout
    with (OUT / "jspsych-mds/configuration.csv").open() as f:
        rows = list(csv.DictReader(f))
    model = observers[0].model
    x = np.array([[float(r["dim1"]), float(r["dim2"])] for r in rows])
    planted = np.array([[model.cd[r["stimulus"]][0], D_WEIGHT * model.cd[r["stimulus"]][1]] for r in rows])
    r2 = procrustes_r2(x, planted)
    rho = spearman(distances(x), np.round(distances(planted), 12))
    print(f"2-D configuration vs planted (c, {D_WEIGHT} d): Procrustes r² {r2:.4f}, Spearman ρ {rho:.4f}")
    assert r2 >= R2_MIN and rho >= RHO_MIN, (r2, rho)
    run = pgloss_cli("magnitude", str(out / "magnitude.csv"), "--out", str(OUT / "jspsych-magnitude"))
    print(run.stdout)
    ranked = [line.split(None, 1)[1] for line in run.stdout.splitlines() if re.match(r"  [01]\.\d{4}  ", line)]
    assert ranked[0] == "c (eq. 4) + d = 1 − α (eq. 3)", ranked
    assert (OUT / "jspsych-magnitude/fig07_doi_fit.png").is_file() and (OUT / "jspsych-magnitude/fig08_contrast_fit.svg").is_file()
    print(f"jsPsych end to end: {time.monotonic() - t0:.1f} s; d/c weight {ratio[1]} (planted {D_WEIGHT}), "
          f"Procrustes r² {r2:.4f}, Spearman ρ {rho:.4f}")
