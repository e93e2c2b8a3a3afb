"""The shared test vectors (tests/vectors/*.json) through the Python package.

Every case of every file goes through the public Python function of the same name, one
call per case (a scalar call: Python floats in, Python floats out); the BRDF cases are also
run as arrays, grouped by (material, lobe mask) like the C runner's batches, in float32 (the
vectorised batched path) and in float64 (the scalar reference path). Tolerances: the C
runner's (tests/vectors/README.md). A core error is a PglossError whose status must be the
expected one; the outputs the core wrote (its documented fallback, or the computed values
for GAMUT / ENVELOPE) are on the exception's ``result`` and are checked too.
"""

from __future__ import annotations

import math
import warnings
from collections import OrderedDict
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import pytest

import pgloss
from vectors import (FILES, SKIPPED_NULL, Checker, cases, has_tag, is_null_case, load, num, sens_at,
                     tolerance)


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
    want = {
        "lightness.json": ["lightness_from_luminance", "luminance_from_lightness"],
        "gloss.json": ["contrast_gloss", "specular_from_contrast", "gloss_from_physical", "physical_from_gloss",
                       "gloss_distance", "envelope_contrast", "match_gloss", "isogloss_contour"],
        "color.json": ["rgb_from_lab", "lab_from_rgb", "luminance"],
        "validity.json": ["check_physical", "check_perceptual"],
        "perceptual_material.json": ["physical_from_perceptual", "perceptual_from_physical"],
        "material.json": ["material_init", "specular_probability"],
        "brdf_eval.json": ["eval", "pdf", "eval_pdf", "eval_batch", "pdf_batch", "eval_pdf_batch"],
        "brdf_sample.json": ["sample", "sample_batch"],
    }
    for name in FILES:
        doc = load(name)
        for fn in want[name]:
            assert fn in doc["functions"], f"{name} lacks {fn}"
            # Every C function of the vectors has its Python twin (one name across languages).
            assert callable(getattr(pgloss, fn.replace("_batch", ""))), fn
        ids = [c["id"] for c in doc["cases"]]
        assert len(ids) == len(set(ids)), f"{name}: duplicate ids"


# ------------------------------------------------------------------------------------------------
# Double-precision functions: each maps a case's input to a thunk and its outputs to a dict.

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
        num(i["rho_d"]), num(i["rho_s"]), num(i["alpha"])), _scalar_outputs(["L", "c", "d"]))),
    ("physical_from_gloss", ("gloss.json", lambda i: lambda: pgloss.physical_from_gloss(
        num(i["L"]), num(i["c"]), num(i["d"])), _scalar_outputs(["rho_d", "rho_s", "alpha"]))),
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
        perceptual(i["q"]), int(i["normalization"])),
        lambda p: {"rho_d": list(p.rho_d), "rho_s": p.rho_s, "alpha_x": p.alpha_x, "alpha_y": p.alpha_y,
                   "normalization": int(p.normalization)})),
    ("perceptual_from_physical", ("perceptual_material.json", lambda i: lambda: pgloss.perceptual_from_physical(
        physical(i["p"])), lambda q: {"L": q.L, "a": q.a, "b": q.b, "c": q.c, "d": q.d})),
])


@pytest.mark.parametrize("fn", list(DOUBLE_FUNCS))
def test_double_function(fn: str) -> None:
    file, make, outputs = DOUBLE_FUNCS[fn]
    doc = load(file)
    chk = Checker()
    n = 0
    for c in cases(file, fn):
        if is_null_case(c):
            SKIPPED_NULL[fn] = SKIPPED_NULL.get(fn, 0) + 1
            continue
        n += 1
        status, res = run(make(c["input"]))
        chk.status(fn, c, status)
        expected = c["expected"]
        if res is None:
            chk.fail(f"{c['id']} {fn}: no outputs (result None)")
            continue
        got = outputs(res)
        for out, want in expected.items():
            if out == "normalization":
                if want is not None and got[out] != int(want):
                    chk.fail(f"{c['id']} {fn}: normalization {got[out]} want {want}")
                continue
            tol = tolerance(doc, fn, out) if want is not None else None
            if isinstance(want, list) or isinstance(got[out], list):
                g = got[out]
                if want is not None and len(g) != len(want):
                    chk.fail(f"{c['id']} {fn} {out}: {len(g)} values, want {len(want)}")
                    continue
                for k in range(len(g)):
                    chk.value(fn, out, c, g[k], None if want is None else want[k], sens_at(c, out, k), tol)
            else:
                chk.value(fn, out, c, got[out], want, sens_at(c, out), tol)
    assert n > 0
    chk.finish(fn)


@pytest.mark.parametrize("fn", ["check_physical", "check_perceptual"])
def test_validity(fn: str) -> None:
    chk = Checker()
    for c in cases("validity.json", fn):
        if is_null_case(c):
            SKIPPED_NULL[fn] = SKIPPED_NULL.get(fn, 0) + 1
            continue
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
    chk.finish(fn)


# ------------------------------------------------------------------------------------------------
# material.json

def _material_is_black(m: pgloss.Material) -> bool:
    f = pgloss.eval(m, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0])
    return bool(np.all(f == 0))


def test_material_init() -> None:
    fn = "material_init"
    doc = load("material.json")
    chk = Checker()
    for c in cases("material.json", fn):
        if is_null_case(c):
            SKIPPED_NULL[fn] = SKIPPED_NULL.get(fn, 0) + 1
            continue
        status, m = run(lambda: pgloss.material_init(physical(c["input"]["p"])))
        chk.status(fn, c, status)
        e = c["expected"]
        if m.lobes != e["lobes"]:
            chk.fail(f"{c['id']}: lobes {m.lobes} want {e['lobes']}")
        if not status.startswith("PGLOSS_OK"):
            if not _material_is_black(m):
                chk.fail(f"{c['id']}: a failed init must give a black material")
            continue
        for k in range(3):
            chk.value(fn, "rho_d", c, m.rho_d[k], e["rho_d"][k], sens_at(c, "rho_d", k), tolerance(doc, fn, "rho_d"))
        for out in ("rho_s", "alpha_x", "alpha_y", "inv_alpha_x", "inv_alpha_y", "spec_scale", "pdf_scale",
                    "weight_diffuse", "weight_specular"):
            chk.value(fn, out, c, getattr(m, out), e[out], sens_at(c, out), tolerance(doc, fn, out))
        if m.normalization != c["input"]["p"]["normalization"]:
            chk.fail(f"{c['id']}: normalization {m.normalization}")
    chk.finish(fn)


def test_specular_probability() -> None:
    fn = "specular_probability"
    doc = load("material.json")
    chk = Checker()
    for c in cases("material.json", fn):
        p = physical(c["input"]["p"])
        P = pgloss.specular_probability(p, c["input"]["lobes"])
        assert isinstance(P, float)
        assert P == pgloss.specular_probability(p.material(), c["input"]["lobes"])
        chk.value(fn, "P", c, P, c["expected"]["P"], sens_at(c, "P"), tolerance(doc, fn, "P"))
    chk.finish(fn)


# ------------------------------------------------------------------------------------------------
# BRDF

def materials_of(doc: dict) -> Dict[str, pgloss.Material]:
    return {k: physical(v).material() for k, v in doc["materials"].items()}


def sanity_float(doc: dict, c: dict) -> bool:
    return has_tag(c, "ill_conditioned") and doc["c_precision"] == "float"


def check_f(chk: Checker, doc: dict, fn: str, tolfn: str, c: dict, f) -> None:
    t = tolerance(doc, tolfn, "f")
    s = sanity_float(doc, c)
    for k in range(3):
        chk.value(fn, "f", c, f[k], c["expected"]["f"][k], sens_at(c, "f", k), t, s, True)


def check_pdf(chk: Checker, doc: dict, fn: str, tolfn: str, c: dict, p) -> None:
    chk.value(fn, "pdf", c, p, c["expected"]["pdf"], sens_at(c, "pdf"), tolerance(doc, tolfn, "pdf"),
              sanity_float(doc, c), True)


def test_eval_pdf_scalar() -> None:
    """One call per case, float64 (the scalar reference path), through eval, pdf and eval_pdf."""
    doc = load("brdf_eval.json")
    mats = materials_of(doc)
    chk = Checker()
    for c in doc["cases"]:
        i = c["input"]
        m = mats[i["material"]]
        wo, wi, lobes = [num(x) for x in i["wo"]], [num(x) for x in i["wi"]], i["lobes"]
        st, f = run(lambda: pgloss.eval(m, wo, wi, lobes))
        chk.status("eval", c, st)
        check_f(chk, doc, "eval", "eval", c, f)
        st, p = run(lambda: pgloss.pdf(m, wo, wi, lobes))
        chk.status("pdf", c, st)
        if not isinstance(p, float):
            chk.fail(f"{c['id']}: pdf of one pair must be a Python float, got {type(p)}")
        check_pdf(chk, doc, "pdf", "pdf", c, p)
        st, fp = run(lambda: pgloss.eval_pdf(m, wo, wi, lobes))
        chk.status("eval_pdf", c, st)
        check_f(chk, doc, "eval_pdf", "eval_pdf", c, fp[0])
        check_pdf(chk, doc, "eval_pdf", "eval_pdf", c, fp[1])
    chk.finish("eval/pdf/eval_pdf scalar")


def groups_of(doc: dict) -> "OrderedDict[Tuple[str, int], List[dict]]":
    g: "OrderedDict[Tuple[str, int], List[dict]]" = OrderedDict()
    for c in doc["cases"]:
        if "null" in c["input"]:
            continue
        g.setdefault((c["input"]["material"], c["input"]["lobes"]), []).append(c)
    return g


def first_error(cs: List[dict]) -> Tuple[str, int]:
    for k, c in enumerate(cs):
        if c["status"] != "PGLOSS_OK":
            return c["status"], k
    return "PGLOSS_OK", -1


def run_array(chk: Checker, label: str, cs: List[dict], thunk: Callable[[], Any]) -> Any:
    """An array call over a group: the error (if any) must be the group's first, at its index."""
    want, index = first_error(cs)
    try:
        return thunk()
    except pgloss.PglossError as e:
        if e.status.c_name != want or e.index != (index,):
            chk.fail(f"{label}: raised {e.status.c_name} at {e.index}, want {want} at ({index},)")
        return e.result
    finally:
        pass


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_eval_pdf_arrays(dtype: str) -> None:
    """Each (material, lobes) group as one array call: float32 = the batched path (eval_batch,
    pdf_batch, eval_pdf_batch), float64 = the scalar path looped in C."""
    doc = load("brdf_eval.json")
    mats = materials_of(doc)
    chk = Checker()
    tag = "_batch" if dtype == "float32" else "_array64"
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
        for k, c in enumerate(cs):
            check_f(chk, doc, "eval" + tag, "eval", c, f[k])
            check_pdf(chk, doc, "pdf" + tag, "pdf", c, p[k])
            check_f(chk, doc, "eval_pdf" + tag, "eval_pdf", c, fp[0][k])
            check_pdf(chk, doc, "eval_pdf" + tag, "eval_pdf", c, fp[1][k])
    chk.finish(f"eval/pdf arrays {dtype}")


LOBE_NAMES = {"PGLOSS_LOBE_NONE": 0, "PGLOSS_LOBE_DIFFUSE": 1, "PGLOSS_LOBE_SPECULAR": 2}


def check_sample(chk: Checker, doc: dict, fn: str, c: dict, wi, pdf_, weight, lobe) -> None:
    e = c["expected"]
    s = sanity_float(doc, c)
    twi, tpdf, tw = tolerance(doc, "sample", "wi"), tolerance(doc, "sample", "pdf"), tolerance(doc, "sample", "weight")
    for k in range(3):
        chk.value(fn, "wi", c, wi[k], None if e["wi"] is None else e["wi"][k], sens_at(c, "wi", k), twi, s)
        chk.value(fn, "weight", c, weight[k], e["weight"][k], sens_at(c, "weight", k), tw, s, True)
    chk.value(fn, "pdf", c, pdf_, e["pdf"], sens_at(c, "pdf"), tpdf, s, True)
    if e["lobe"] is not None and int(lobe) != LOBE_NAMES[e["lobe"]]:
        chk.fail(f"{c['id']} {fn}: lobe {int(lobe)} want {e['lobe']}")
    if num(e["pdf"]) == 0:
        if pdf_ != 0 or any(w != 0 for w in weight):
            chk.fail(f"{c['id']} {fn}: rejected sample must have pdf 0 and weight 0")
    elif e["wi"] is not None:
        if abs(math.sqrt(sum(float(x) ** 2 for x in wi)) - 1.0) > 1e-5:
            chk.fail(f"{c['id']} {fn}: wi not unit length")


def test_sample_scalar() -> None:
    doc = load("brdf_sample.json")
    mats = materials_of(doc)
    chk = Checker()
    for c in doc["cases"]:
        i = c["input"]
        st, r = run(lambda: pgloss.sample(mats[i["material"]], [num(x) for x in i["wo"]], [num(x) for x in i["u"]],
                                          i["lobes"]))
        chk.status("sample", c, st)
        if not isinstance(r.pdf, float) or not isinstance(r.lobe, pgloss.Lobe):
            chk.fail(f"{c['id']}: one sample must give a float pdf and a Lobe")
        check_sample(chk, doc, "sample", c, r.wi, r.pdf, r.weight, r.lobe)
    chk.finish("sample scalar")


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_sample_arrays(dtype: str) -> None:
    doc = load("brdf_sample.json")
    mats = materials_of(doc)
    chk = Checker()
    fn = "sample_batch" if dtype == "float32" else "sample_array64"
    for (mk, lobes), cs in groups_of(doc).items():
        wo = np.array([[num(x) for x in c["input"]["wo"]] for c in cs], dtype=dtype)
        u = np.array([[num(x) for x in c["input"]["u"]] for c in cs], dtype=dtype)
        r = run_array(chk, f"{dtype} sample group {mk}/{lobes}", cs, lambda: pgloss.sample(mats[mk], wo, u, lobes))
        assert r.wi.dtype == r.pdf.dtype == r.weight.dtype == np.dtype(dtype) and r.lobe.dtype == np.uint8
        for k, c in enumerate(cs):
            check_sample(chk, doc, fn, c, r.wi[k], float(r.pdf[k]), r.weight[k], r.lobe[k])
    chk.finish(f"sample arrays {dtype}")
