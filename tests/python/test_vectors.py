# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The shared test vectors (tests/vectors/*.json) through the Python package.

Every case of every file goes through the public Python function of the same name, one
call per case (a scalar call: Python floats in, Python floats out); the BRDF cases are also
run as arrays, grouped by (material, lobe mask) like the C runner's batches, in float32 (the
vectorised batched path) and in float64 (the scalar reference path). Loading, tolerances
(the file's c_precision column: the package computes in the core's precision) and the report
are the shared module tests/vectors/pgloss_vectors.py (the logic of the C runner). A core error is a PglossError whose status must be the
expected one; the outputs the core wrote (its documented fallback, or the computed values
for GAMUT / ENVELOPE) are on the exception's ``result`` and are checked too.
"""

from __future__ import annotations

import warnings
from collections import OrderedDict
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import pytest

import pgloss
import pgloss_vectors as pv
from pgloss_vectors import first_error, groups_of, load, num


def run(thunk: Callable[[], Any]) -> Tuple[str, Any]:
    """Calls thunk; returns (status name the Python API signalled, outputs)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            out = thunk()
        except pgloss.PglossError as e:
            assert isinstance(e, ValueError)
            assert e.reason == pgloss.status_string(e.status) and e.reason in str(e)
            return e.status.c_name, e.result
    untrusted = [w for w in caught if issubclass(w.category, pgloss.AlphaUntrustedWarning)]
    assert len(untrusted) <= 1, "one warning per call"
    return ("PGLOSS_WARN_ALPHA_UNTRUSTED" if untrusted else "PGLOSS_OK"), out


def physical(p: Dict[str, Any]) -> pgloss.Physical:
    return pgloss.Physical([num(x) for x in p["rho_d"]], num(p["rho_s"]), alpha_x=num(p["alpha_x"]),
                           alpha_y=num(p["alpha_y"]), normalization=int(p["normalization"]))


def perceptual(q: Dict[str, Any]) -> pgloss.Perceptual:
    return pgloss.Perceptual(num(q["L"]), num(q["a"]), num(q["b"]), num(q["c"]), num(q["d"]))


def test_files_present_and_covered() -> None:
    chk = pv.Report()
    pv.check_coverage(chk)
    chk.finish("vector files")
    for fns in pv.FUNCTIONS.values():
        for fn in fns:
            # Every C function of the vectors has its Python twin (one name across languages);
            # a C _ex function is its twin's keyword argument ``space``.
            assert callable(getattr(pgloss, fn.replace("_batch", "").removesuffix("_ex"))), fn


# ------------------------------------------------------------------------------------------------
# Double-precision functions: each maps a case's input to a thunk and its outputs to a dict. The
# vectors are the C functions' own verdicts: the conversions run without the model's check
# (check=False), which the C functions leave to check_perceptual / check_physical.

def _scalar_outputs(names):
    def outs(r):
        r = r if isinstance(r, tuple) else (r,)
        return dict(zip(names, r))
    return outs


DOUBLE_FUNCS: "OrderedDict[str, Tuple[str, Callable, Callable]]" = OrderedDict([
    ("lightness_from_luminance", ("lightness.json", lambda i: lambda: pgloss.lightness_from_luminance(num(i["Y"])),
                                  _scalar_outputs(["L"]))),
    ("luminance_from_lightness", ("lightness.json", lambda i: lambda: pgloss.luminance_from_lightness(num(i["L"])),
                                  _scalar_outputs(["Y"]))),
    ("contrast_gloss", ("gloss.json", lambda i: lambda: pgloss.contrast_gloss(num(i["rho_d"]), num(i["rho_s"])),
                        _scalar_outputs(["c"]))),
    ("specular_from_contrast", ("gloss.json", lambda i: lambda: pgloss.specular_from_contrast(num(i["rho_d"]), num(i["c"])),
                                _scalar_outputs(["rho_s"]))),
    ("gloss_from_physical", ("gloss.json", lambda i: lambda: pgloss.gloss_from_physical(
        num(i["rho_d"]), num(i["rho_s"]), num(i["alpha"]), check=False), _scalar_outputs(["L", "c", "d"]))),
    ("physical_from_gloss", ("gloss.json", lambda i: lambda: pgloss.physical_from_gloss(
        num(i["L"]), num(i["c"]), num(i["d"]), check=False), _scalar_outputs(["rho_d", "rho_s", "alpha"]))),
    ("gloss_distance", ("gloss.json", lambda i: lambda: pgloss.gloss_distance(
        num(i["c1"]), num(i["d1"]), num(i["c2"]), num(i["d2"])), _scalar_outputs(["D"]))),
    ("envelope_contrast", ("gloss.json", lambda i: lambda: pgloss.envelope_contrast(num(i["L"])),
                           _scalar_outputs(["c_max"]))),
    ("match_gloss", ("gloss.json", lambda i: lambda: pgloss.match_gloss(num(i["rho_d"]), num(i["rho_s"]), num(i["L_target"])),
                     _scalar_outputs(["rho_d_out", "rho_s_out"]))),
    ("isogloss_contour", ("gloss.json", lambda i: lambda: pgloss.isogloss_contour(
        num(i["c0"]), num(i["d0"]), num(i["D"]), int(i["n"])), lambda r: {"c": list(r[0]), "d": list(r[1])})),
    ("rgb_from_lab", ("color.json", lambda i: lambda: pgloss.rgb_from_lab([num(x) for x in i["lab"]]),
                      lambda r: {"rgb": list(r)})),
    ("lab_from_rgb", ("color.json", lambda i: lambda: pgloss.lab_from_rgb([num(x) for x in i["rgb"]]),
                      lambda r: {"lab": list(r)})),
    ("luminance", ("color.json", lambda i: lambda: pgloss.luminance([num(x) for x in i["rgb"]]),
                   _scalar_outputs(["Y"]))),
    ("physical_from_perceptual", ("perceptual_material.json", lambda i: lambda: pgloss.physical_from_perceptual(
        perceptual(i["q"]), int(i["normalization"]), check=False),
        lambda p: {"rho_d": list(p.rho_d), "rho_s": p.rho_s, "alpha_x": p.alpha_x, "alpha_y": p.alpha_y,
                   "normalization": int(p.normalization)})),
    ("perceptual_from_physical", ("perceptual_material.json", lambda i: lambda: pgloss.perceptual_from_physical(
        physical(i["p"]), check=False), lambda q: {"L": q.L, "a": q.a, "b": q.b, "c": q.c, "d": q.d})),
    # color_space.json: the C core's _ex functions are the keyword argument ``space``.
    ("rgb_from_lab_ex", ("color_space.json", lambda i: lambda: pgloss.rgb_from_lab(
        [num(x) for x in i["lab"]], space=int(i["space"])), lambda r: {"rgb": list(r)})),
    ("lab_from_rgb_ex", ("color_space.json", lambda i: lambda: pgloss.lab_from_rgb(
        [num(x) for x in i["rgb"]], space=int(i["space"])), lambda r: {"lab": list(r)})),
    ("luminance_ex", ("color_space.json", lambda i: lambda: pgloss.luminance(
        [num(x) for x in i["rgb"]], space=int(i["space"])), _scalar_outputs(["Y"]))),
    ("physical_from_perceptual_ex", ("color_space.json", lambda i: lambda: pgloss.physical_from_perceptual(
        perceptual(i["q"]), int(i["normalization"]), space=int(i["space"]), check=False),
        lambda p: {"rho_d": list(p.rho_d), "rho_s": p.rho_s, "alpha_x": p.alpha_x, "alpha_y": p.alpha_y,
                   "normalization": int(p.normalization)})),
    ("perceptual_from_physical_ex", ("color_space.json", lambda i: lambda: pgloss.perceptual_from_physical(
        physical(i["p"]), space=int(i["space"]), check=False), lambda q: {"L": q.L, "a": q.a, "b": q.b, "c": q.c, "d": q.d})),
])


def test_check_perceptual_ex(vector_report: pv.Report) -> None:
    """color_space.json's check_perceptual_ex through pgloss.check_perceptual(q, space=...)."""
    fn = "check_perceptual_ex"
    doc = load("color_space.json")
    chk = vector_report.child()
    n = 0
    for _, c in pv.runnable("color_space.json", chk, fn):
        n += 1
        chk.ran(fn)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            st = pgloss.check_perceptual(perceptual(c["input"]["q"]), space=int(c["input"]["space"]))
        chk.status(fn, c, st.c_name)
        chk.outputs(doc, fn, c, {})
    assert n > 0
    chk.finish(fn)


@pytest.mark.parametrize("fn", list(DOUBLE_FUNCS))
def test_double_function(fn: str, vector_report: pv.Report) -> None:
    file, make, outputs = DOUBLE_FUNCS[fn]
    doc = load(file)
    chk = vector_report.child()
    n = 0
    for _, c in pv.runnable(file, chk, fn):
        n += 1
        chk.ran(fn)
        status, res = run(make(c["input"]))
        chk.status(fn, c, status)
        if res is None:
            chk.fail(f"{c['id']} {fn}: no outputs (result None)")
            continue
        chk.outputs(doc, fn, c, outputs(res))
    assert n > 0
    chk.finish(fn)


@pytest.mark.parametrize("fn", ["check_physical", "check_perceptual"])
def test_validity(fn: str, vector_report: pv.Report) -> None:
    doc = load("validity.json")
    chk = vector_report.child()
    for _, c in pv.runnable("validity.json", chk, fn):
        chk.ran(fn)
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the check functions report, they never warn or raise
            if fn == "check_physical":
                st = pgloss.check_physical(physical(c["input"]["p"]))
                assert st == physical(c["input"]["p"]).check()
            else:
                st = pgloss.check_perceptual(perceptual(c["input"]["q"]))
                assert st == perceptual(c["input"]["q"]).check()
        assert isinstance(st, pgloss.Status)
        chk.status(fn, c, st.c_name)
        chk.outputs(doc, fn, c, {})
    chk.finish(fn)


# ------------------------------------------------------------------------------------------------
# material.json

def _material_is_black(m: pgloss.Material) -> bool:
    f = pgloss.eval(m, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0])
    return bool(np.all(f == 0))


MATERIAL_FIELDS = ("rho_d", "rho_s", "alpha_x", "alpha_y", "inv_alpha_x", "inv_alpha_y", "spec_scale",
                   "pdf_scale", "weight_diffuse", "weight_specular")


def test_material_init(vector_report: pv.Report) -> None:
    fn = "material_init"
    doc = load("material.json")
    chk = vector_report.child()
    for _, c in pv.runnable("material.json", chk, fn):
        chk.ran(fn)
        status, m = run(lambda: pgloss.material_init(physical(c["input"]["p"])))
        chk.status(fn, c, status)
        got = {out: getattr(m, out) for out in MATERIAL_FIELDS}
        got.update(lobes=m.lobes, normalization=int(m.normalization), black=_material_is_black(m))
        chk.material_init(doc, c, status, got)
    chk.finish(fn)


def test_specular_probability(vector_report: pv.Report) -> None:
    fn = "specular_probability"
    doc = load("material.json")
    chk = vector_report.child()
    for _, c in pv.runnable("material.json", chk, fn):
        chk.ran(fn)
        p = physical(c["input"]["p"])
        P = pgloss.specular_probability(p, c["input"]["lobes"])
        assert isinstance(P, float)
        assert P == pgloss.specular_probability(p.material(), c["input"]["lobes"])
        chk.outputs(doc, fn, c, {"P": P})
    chk.finish(fn)


# ------------------------------------------------------------------------------------------------
# BRDF


def materials_of(doc: dict) -> Dict[str, pgloss.Material]:
    return {k: physical(v).material() for k, v in doc["materials"].items()}


def test_eval_pdf_scalar(vector_report: pv.Report) -> None:
    """One call per case, Python floats (float64: the double batch of one element), through eval,
    pdf and eval_pdf."""
    doc = load("brdf_eval.json")
    mats = materials_of(doc)
    chk = vector_report.child()
    for _, c in pv.runnable("brdf_eval.json", chk):
        chk.ran("brdf_eval (eval, pdf, eval_pdf)")
        i = c["input"]
        m = mats[i["material"]]
        wo, wi, lobes = [num(x) for x in i["wo"]], [num(x) for x in i["wi"]], i["lobes"]
        st, f = run(lambda: pgloss.eval(m, wo, wi, lobes))
        chk.status("eval", c, st)
        chk.brdf_eval(doc, "eval", c, f=f)
        st, p = run(lambda: pgloss.pdf(m, wo, wi, lobes))
        chk.status("pdf", c, st)
        if not isinstance(p, float):
            chk.fail(f"{c['id']}: pdf of one pair must be a Python float, got {type(p)}")
        chk.brdf_eval(doc, "pdf", c, pdf=p)
        st, fp = run(lambda: pgloss.eval_pdf(m, wo, wi, lobes))
        chk.status("eval_pdf", c, st)
        chk.brdf_eval(doc, "eval_pdf", c, f=fp[0], pdf=fp[1])
    chk.finish("eval/pdf/eval_pdf scalar")


def run_array(chk: pv.Report, label: str, cs: List[dict], thunk: Callable[[], Any]) -> Any:
    """An array call over a group: the error (if any) must be the group's first, at its index."""
    want, index = first_error(cs)
    try:
        return thunk()
    except pgloss.PglossError as e:
        if e.status.c_name != want or e.index != (index,):
            chk.fail(f"{label}: raised {e.status.c_name} at {e.index}, want {want} at ({index},)")
        return e.result


# The function names of the array calls in the statistics: float32 arrays take the float
# batch (eval_batch ... of batch.h), float64 arrays the double batch (eval_batch_d ...).
ARRAY_SUFFIX = {"float32": "_batch", "float64": "_batch_d"}


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_eval_pdf_arrays(dtype: str, vector_report: pv.Report) -> None:
    """Each (material, lobes) group as one array call: float32 = the float batch (eval_batch,
    pdf_batch, eval_pdf_batch), float64 = the double batch (eval_batch_d, …)."""
    doc = load("brdf_eval.json")
    mats = materials_of(doc)
    chk = vector_report.child()
    tag = ARRAY_SUFFIX[dtype]
    groups = groups_of(doc)
    assert groups
    for (mk, lobes), cs in groups.items():
        m = mats[mk]
        wo = np.array([[num(x) for x in c["input"]["wo"]] for c in cs], dtype=dtype)
        wi = np.array([[num(x) for x in c["input"]["wi"]] for c in cs], dtype=dtype)
        want, _ = first_error(cs)
        label = f"{dtype} group {mk}/{lobes}"
        f = run_array(chk, label + " eval", cs, lambda: pgloss.eval(m, wo, wi, lobes))
        p = run_array(chk, label + " pdf", cs, lambda: pgloss.pdf(m, wo, wi, lobes))
        fp = run_array(chk, label + " eval_pdf", cs, lambda: pgloss.eval_pdf(m, wo, wi, lobes))
        for arr in (f, p, fp[0], fp[1]):
            assert arr.dtype == np.dtype(dtype)
        if want == "PGLOSS_OK":  # an OK group returns normally: no warning either
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                pgloss.eval(m, wo, wi, lobes)
        chk.ran(f"brdf_eval {dtype} arrays (*{tag})", len(cs))
        for k, c in enumerate(cs):
            chk.brdf_eval(doc, "eval" + tag, c, f=f[k], tol_fn="eval")
            chk.brdf_eval(doc, "pdf" + tag, c, pdf=p[k], tol_fn="pdf")
            chk.brdf_eval(doc, "eval_pdf" + tag, c, f=fp[0][k], pdf=fp[1][k], tol_fn="eval_pdf")
    chk.finish(f"eval/pdf arrays {dtype}")


# The float API clamps u to [0, 1 - 2^-24] (the vectors' contract); the float64 batch clamps to
# [0, 1 - 2^-53] (pgloss/batch_materials.h). For float64 calls the float clamp is applied to the
# input here, so that the vector's expected sample is the one for the same u.
U_MAX_FLOAT = 1.0 - 2.0 ** -24


def u64(u: Any) -> Any:
    return np.minimum(np.asarray(u, dtype=np.float64), U_MAX_FLOAT)


def test_sample_scalar(vector_report: pv.Report) -> None:
    doc = load("brdf_sample.json")
    mats = materials_of(doc)
    chk = vector_report.child()
    for _, c in pv.runnable("brdf_sample.json", chk):
        chk.ran("brdf_sample (sample)")
        i = c["input"]
        st, r = run(lambda: pgloss.sample(mats[i["material"]], [num(x) for x in i["wo"]],
                                          list(u64([num(x) for x in i["u"]])), i["lobes"]))
        chk.status("sample", c, st)
        if not isinstance(r.pdf, float) or not isinstance(r.lobe, pgloss.Lobe):
            chk.fail(f"{c['id']}: one sample must give a float pdf and a Lobe")
        chk.sample(doc, "sample", c, r.wi, r.pdf, r.weight, r.lobe)
    chk.finish("sample scalar")


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_sample_arrays(dtype: str, vector_report: pv.Report) -> None:
    doc = load("brdf_sample.json")
    mats = materials_of(doc)
    chk = vector_report.child()
    fn = "sample" + ARRAY_SUFFIX[dtype]
    for (mk, lobes), cs in groups_of(doc).items():
        wo = np.array([[num(x) for x in c["input"]["wo"]] for c in cs], dtype=dtype)
        u = np.array([[num(x) for x in c["input"]["u"]] for c in cs], dtype=dtype)
        if dtype == "float64":
            u = u64(u)
        r = run_array(chk, f"{dtype} sample group {mk}/{lobes}", cs, lambda: pgloss.sample(mats[mk], wo, u, lobes))
        assert r.wi.dtype == r.pdf.dtype == r.weight.dtype == np.dtype(dtype) and r.lobe.dtype == np.uint8
        chk.ran(f"brdf_sample {dtype} arrays ({fn})", len(cs))
        for k, c in enumerate(cs):
            chk.sample(doc, fn, c, r.wi[k], float(r.pdf[k]), r.weight[k], r.lobe[k])
    chk.finish(f"sample arrays {dtype}")
