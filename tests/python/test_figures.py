# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""`python -m pgloss figures OUTDIR` writes the paper's Figs. 9, 10, 11 as PNG and SVG, and the
numbers it draws are the paper's."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import pgloss
from pgloss import __main__ as cli

STEMS = ["fig09_gloss_space", "fig10_envelope", "fig11_isogloss"]


def test_figures_command(tmp_path: Path) -> None:
    out = tmp_path / "figs"
    proc = subprocess.run([sys.executable, "-m", "pgloss", "figures", str(out)], capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr
    for stem in STEMS:
        png, svg = out / f"{stem}.png", out / f"{stem}.svg"
        assert str(png) in proc.stdout and str(svg) in proc.stdout
        data = png.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000
        root = ET.parse(svg).getroot()
        assert root.tag.endswith("svg")
        assert f"Fig. {int(stem[3:5])}" in svg.read_text(encoding="utf-8")  # the title is text in the SVG


def test_cli_usage() -> None:
    with pytest.raises(SystemExit) as e:
        cli.main([])
    assert e.value.code == 2
    with pytest.raises(SystemExit) as e:
        cli.main(["--version"])
    assert e.value.code == 0


def test_figure_data_are_the_papers() -> None:
    rd, rs, al, L, c, d = cli.experiment1()
    assert L.shape == c.shape == d.shape == (3, 3, 3)
    # 27 distinct stimuli: ρd × ρs × α of §3.2.3.1
    assert len({(a, b, x) for a, b, x in zip(rd.ravel(), rs.ravel(), al.ravel())}) == 27
    np.testing.assert_allclose(d, 1 - al)  # eq. 3
    # the grey (0.193, 0.066, 0.07) stimulus is Fig. 11's reference c = 0.087, d = 0.93
    assert round(float(c[1, 1, 1]), 3) == cli.REFERENCE[0] and round(float(d[1, 1, 1]), 2) == cli.REFERENCE[1]
    # darker paints look glossier at the same physical gloss (Fig. 10, §5.2)
    assert (np.diff(c, axis=0) < 0).all()
    # the envelope decreases with lightness and bounds every stimulus
    env = pgloss.envelope_contrast(L)
    assert (c < env).all()
    assert pgloss.envelope_contrast(0.0) == pytest.approx(1.0) and pgloss.envelope_contrast(100.0) == pytest.approx(0.0, abs=1e-12)


def test_benchmark_script_runs() -> None:
    """The benchmark is a program, not a timed test: only check that it runs and reports both paths."""
    bench = Path(__file__).resolve().parents[2] / "bindings" / "python" / "bench" / "bench_eval.py"
    proc = subprocess.run([sys.executable, str(bench), "--n", "20000", "--repeat", "2"], capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "C pgloss_eval_pdf_batch" in proc.stdout and "Python float32 / C batched (best)" in proc.stdout
