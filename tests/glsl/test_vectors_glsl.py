# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Every shared test vector executed through glsl/pgloss.glsl on a real OpenGL driver
(Mesa llvmpipe through EGL by default; PGLOSS_GLSL_DEVICE=gpu for a GPU), full build and
feature-switch builds (on the cases whose result a switch does not change)."""
from __future__ import annotations

import numpy as np
import pytest

import glsl_vectors as gv


def _report(rep: gv.pv.Report, title: str, full: bool = True) -> None:
    print("\n== " + rep.summary(title, full))
    for f in rep.failures[:40]:
        print("FAIL", f)
    assert not rep.failures, f"{len(rep.failures)} failures, first: {rep.failures[0]}"


def test_all_vectors_full_build(gl_ctx) -> None:
    rep = gv.run_all(gl_ctx)
    _report(rep, "GLSL full build, compute stage: every vector file")
    # Every function of every file was checked (no silent gaps).
    for key in ["eval f", "pdf pdf", "eval_pdf f", "eval_pdf pdf", "sample wi", "sample pdf",
                "sample weight", "sample lobe", "material_init spec_scale", "specular_probability P",
                "lightness_from_luminance L", "luminance_from_lightness Y", "contrast_gloss c",
                "specular_from_contrast rho_s", "gloss_from_physical c", "physical_from_gloss rho_s",
                "gloss_distance D", "envelope_contrast c_max", "match_gloss rho_s_out",
                "isogloss_contour c", "rgb_from_lab rgb", "lab_from_rgb lab", "luminance Y",
                "check_physical status", "check_perceptual status", "physical_from_perceptual rho_d",
                "perceptual_from_physical c"]:
        assert rep.stats.get(key) and rep.stats[key].checks > 0, f"no checks of {key}"


@pytest.mark.parametrize("stage", ["frag", "frag_es"])
def test_all_vectors_fragment(gl_ctx, stage: str) -> None:
    """The same vectors through a fragment shader — GLSL 3.30 core, and GLSL ES 3.00 (the
    language of WebGL2, run by the desktop context through ARB_ES3_compatibility) — with an
    RGBA32UI texture in and an RGBA32UI render target out (float bits travel exactly)."""
    rep = gv.run_all(gl_ctx, stage=stage)
    _report(rep, f"GLSL {gv.STAGES[stage]} fragment stage: every vector file")


def _job(fn: str, fin: list[float], uin1: int = 0, uin2: int = 0) -> gv.Job:
    return gv.Job({"id": "switch"}, fn, fin, [gv.FN[fn], uin1 & 0xFFFFFFFF, uin2, 0])


@pytest.mark.parametrize("defines,physical,norm,status,lobes", [
    # a compiled-out normalisation is an unknown one; anisotropy without its code is an error
    (["PGLOSS_NO_NORM_WARD_DUR"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 1, -10, 0),
    (["PGLOSS_NO_NORM_BOUNDED"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 2, -10, 0),
    (["PGLOSS_NO_NORM_BOUNDED"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 1, 0, 3),
    (["PGLOSS_NO_ANISOTROPY"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.2], 0, -11, 0),
    (["PGLOSS_NO_ANISOTROPY"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 0, 0, 3),
    # a compiled-out lobe is absent from the material
    (["PGLOSS_NO_DIFFUSE"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 0, 0, 2),
    (["PGLOSS_NO_SPECULAR"], [0.5, 0.5, 0.5, 0.1, 0.1, 0.1], 0, 0, 1),
])
def test_switch_semantics(gl_ctx, defines, physical, norm, status, lobes) -> None:
    """What pgloss.glsl's header says the switches do to pgloss_material_init."""
    fout, iout = gv.run_jobs(gl_ctx, [_job("material_init", physical, norm)], defines)
    assert int(iout[0, 0]) == status and int(iout[0, 1]) == lobes, (iout[0], fout[0])
    if status < 0:
        assert np.all(fout[0, 12:15] == 0), "a failed init must give a black material"


def _material_lobes(j: gv.Job) -> int:
    rd, rs = j.fin[0:3], j.fin[3]
    return (1 if any(x > 0 for x in rd) else 0) | (2 if rs > 0 else 0)


def _active(j: gv.Job) -> int:
    return j.uin[2] & _material_lobes(j) & 3


BRDF = ["material.json", "brdf_eval.json", "brdf_sample.json"]

# (defines, files, which cases keep their expected result under the switch)
FEATURE_BUILDS = {
    "NO_DIFFUSE": (["PGLOSS_NO_DIFFUSE"], ["brdf_eval.json", "brdf_sample.json"],
                   lambda j: not (_active(j) & 1)),
    "NO_SPECULAR": (["PGLOSS_NO_SPECULAR"], ["brdf_eval.json", "brdf_sample.json"],
                    lambda j: not (_active(j) & 2)),
    "NO_ANISOTROPY": (["PGLOSS_NO_ANISOTROPY"], BRDF, lambda j: j.fin[4] == j.fin[5]),
    "NO_NORM_WARD_DUR": (["PGLOSS_NO_NORM_WARD_DUR"], BRDF, lambda j: j.uin[1] != 1),
    "NO_NORM_BOUNDED": (["PGLOSS_NO_NORM_BOUNDED"], BRDF, lambda j: j.uin[1] != 2),
    "NO_PERCEPTUAL+NO_SAMPLING": (["PGLOSS_NO_PERCEPTUAL", "PGLOSS_NO_SAMPLING"],
                                  ["material.json", "brdf_eval.json"], lambda j: True),
    "minimal (isotropic eq. 2 only, no conversions)": (
        ["PGLOSS_NO_ANISOTROPY", "PGLOSS_NO_NORM_WARD_DUR", "PGLOSS_NO_NORM_BOUNDED",
         "PGLOSS_NO_CONVERSIONS"],
        ["brdf_eval.json", "brdf_sample.json"], lambda j: j.fin[4] == j.fin[5] and j.uin[1] == 0),
}


@pytest.mark.parametrize("name", list(FEATURE_BUILDS))
def test_feature_build(gl_ctx, name: str) -> None:
    defines, files, select = FEATURE_BUILDS[name]
    rep = gv.run_all(gl_ctx, files, defines, select)
    _report(rep, f"feature build {name}: {' '.join(defines)}", full=False)
    assert rep.n_cases > 100
