# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Scripted observers shared by the browser tests (local server and jsPsych study): the planted
model and the way they move the slider.

Pairs: 500 × the eq. 5 distance between the stimuli's (c, d), with d weighted D_WEIGHT = 1.78 against
c, plus Gaussian noise. Magnitude: a glossiness linear in c and d, plus noise. (c, d) come from the
manifest's physical parameters by eqs. 3–4, computed here independently of pgloss. The noise is a
function of the pair (or of the stimulus and its repetition), not of the order, so the ratings and
the MDS do not depend on the random trial order: the tests are deterministic."""
from __future__ import annotations

from typing import Dict, List

import numpy as np
from playwright.sync_api import Page

D_WEIGHT = 1.78  # eq. 5: ΔD = sqrt(Δc² + (1.78 Δd)²)


class Model:
    def __init__(self, stimuli: Dict[str, dict], seed: int, noise: float):
        self.seed, self.noise = seed, noise
        self.index = {k: i for i, k in enumerate(stimuli)}
        self.cd = {k: (float(np.cbrt(s["rho_s"] + s["rho_d"] / 2) - np.cbrt(s["rho_d"] / 2)), 1 - s["alpha"])
                   for k, s in stimuli.items()}
        self.seen: Dict[str, int] = {}  # magnitude: how often each stimulus was rated in main trials

    def rating(self, stimuli: List[str], practice: bool = False) -> int:
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


def set_slider(page: Page, value: int) -> None:
    """As a person would: a click on the track near the value, then arrow keys until the read-out
    says it. The thumb is hidden until that first touch (display.js)."""
    box = page.locator("#pgloss-slider").bounding_box()
    thumb = 16  # Chromium's range thumb: the track's ends are half a thumb in from the box
    x = box["x"] + thumb / 2 + (box["width"] - thumb) * value / 100.0
    page.mouse.click(x, box["y"] + box["height"] / 2)
    page.wait_for_function("document.getElementById('pgloss-readout').textContent !== '–'")  # the touch is shown
    for _ in range(40):
        shown = int(page.inner_text("#pgloss-readout"))
        if shown == value:
            return
        page.keyboard.press("ArrowRight" if shown < value else "ArrowLeft")
    raise AssertionError(f"the slider did not reach {value}")


def thumb_hidden(page: Page) -> bool:
    """Whether the slider's thumb is hidden: it has the class that display.css's rule for the
    thumb pseudo-element (opacity 0) selects, and that rule is in the page's style sheets
    (getComputedStyle does not report a range thumb's pseudo-element)."""
    return page.evaluate("""() => document.getElementById('pgloss-slider').classList.contains('pgloss-untouched') &&
      [...document.styleSheets].some(s => [...s.cssRules].some(r => r.selectorText === '.pgloss-untouched::-webkit-slider-thumb'
        && r.style.opacity === '0'))""")
