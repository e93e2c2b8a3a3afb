# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Export: what the analysis reads.

* ``pairs/SUBJECT.csv`` — one proximity matrix per subject in the layout ``python -m pgloss mds``
  reads (header row of stimulus ids, one row per stimulus, its id first; symmetric; a pair not
  yet judged is an empty cell, i.e. missing);
* ``stimuli.csv`` — columns name, rho_d, rho_s, alpha, L, c, d (``mds --stimuli`` reads it);
* ``magnitude.csv`` — the magnitude-estimation table, one row per rating: subject, trial,
  repetition, stimulus, its parameters, rating, response time;
* ``responses.csv`` — every response as stored, with seed, sitting and timestamp (the raw log);
* ``screens.csv`` — each sitting's screen: size, device pixel ratio, measured viewing distance and
  pixels per mm (jsPsych's virtual chinrest), the images' size in device pixels and the visual
  angle reached, the screen check (matched grey → gamma, darkest square seen), browser.
"""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Dict, List

from .store import Store


def _rating(v: float) -> str:
    return f"{v:g}"


def proximity_rows(responses: List[Dict], ids: List[str]) -> List[List[str]]:
    index = {s: i for i, s in enumerate(ids)}
    n = len(ids)
    cells = [[""] * n for _ in range(n)]
    for r in responses:
        a, b = r["stimuli"].split(",")
        i, j = index[a], index[b]
        cells[i][j] = cells[j][i] = _rating(r["rating"])
    for i in range(n):
        cells[i][i] = "0"
    return [[""] + ids] + [[ids[i]] + cells[i] for i in range(n)]


def export(store: Store, manifest: dict, outdir: Path) -> List[Path]:
    """Writes the files above into outdir; returns their paths."""
    outdir = Path(outdir)
    (outdir / "pairs").mkdir(parents=True, exist_ok=True)
    stim = {s["id"]: s for s in manifest["stimuli"]}
    ids = list(stim)
    # One read transaction for everything written below, so that the files agree with each
    # other while subjects keep answering.
    seeds, responses, screens = store.snapshot()
    written: List[Path] = []

    path = outdir / "stimuli.csv"
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["name", "rho_d", "rho_s", "alpha", "L", "c", "d", "file", "sha256"])
        for s in manifest["stimuli"]:
            w.writerow([s["id"], s["rho_d"], s["rho_s"], s["alpha"], s["L"], s["c"], s["d"], s["file"], s["sha256"]])
    written.append(path)

    pairs = [r for r in responses if r["procedure"] == "pairs"]
    for subject in sorted({r["subject"] for r in pairs}):
        path = outdir / "pairs" / f"{subject}.csv"
        with path.open("w", newline="", encoding="utf-8") as f:
            csv.writer(f).writerows(proximity_rows([r for r in pairs if r["subject"] == subject], ids))
        written.append(path)

    n = len(ids)
    path = outdir / "magnitude.csv"
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["subject", "trial", "repetition", "stimulus", "rho_d", "rho_s", "alpha", "L", "c", "d",
                    "rating", "rt_ms"])
        for r in (r for r in responses if r["procedure"] == "magnitude"):
            s = stim[r["stimuli"]]
            w.writerow([r["subject"], r["trial"], r["trial"] // n + 1, s["id"], s["rho_d"], s["rho_s"], s["alpha"],
                        s["L"], s["c"], s["d"], r["rating"], f"{r['rt_ms']:.0f}"])
    written.append(path)

    path = outdir / "responses.csv"
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["subject", "procedure", "seed", "trial", "stimuli", "rating", "rt_ms", "received_at", "sitting"])
        for r in responses:
            w.writerow([r["subject"], r["procedure"], seeds[(r["subject"], r["procedure"])], r["trial"],
                        r["stimuli"].replace(",", " "), r["rating"], f"{r['rt_ms']:.0f}", r["received_at"],
                        r["sitting"]])
    written.append(path)

    path = outdir / "screens.csv"
    first = ["subject", "procedure", "sitting", "screen_width", "screen_height", "window_width", "window_height", "dpr",
             "px_per_mm", "view_dist_mm", "image_device_width", "image_device_height", "visual_angle_deg",
             "visual_angle_stated", "image_size_limited", "gamma_code", "gamma_estimate", "display_gamma_stated",
             "black_code", "user_agent", "recorded_at"]
    keys = first + sorted({k for s in screens for k in s} - set(first))
    with path.open("w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(screens)
    written.append(path)
    return written
