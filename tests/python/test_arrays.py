# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Whole textures: arrays of paints, the batched conversions, status arrays,
per-element materials in eval/pdf/eval_pdf/sample, the float64 batch path, ``out=``.

Expected values come from the shared vectors (tests/vectors, an independent mpmath generator)
or from the scalar API one element at a time (itself checked against the vectors in
test_vectors.py): "an array call is the scalar calls, element by element".
"""

from __future__ import annotations

import pickle
import warnings
from collections import OrderedDict
from typing import Any, Dict, List, Tuple

import numpy as np
import pytest

import pgloss
import pgloss_vectors as pv
from pgloss import Lobe, Normalization, Perceptual, PglossError, Physical, Status
from pgloss_vectors import groups_of, load, num

# ------------------------------------------------------------------------------------------------
# The shared vectors through the batched entry points: every case of a function in one array
# call (grouped by the parameters that are one value per call: normalisation, colour space),
# with errors="status" so that every element's status is compared with the case's.


def _perceptual_cols(cs: List[dict], key: str = "q") -> List[np.ndarray]:
    return [np.array([num(c["input"][key][f]) for c in cs]) for f in ("L", "a", "b", "c", "d")]


def _physical_array(cs: List[dict], key: str = "p") -> Physical:
    rd = np.array([[num(x) for x in c["input"][key]["rho_d"]] for c in cs])
    f = [np.array([num(c["input"][key][n]) for c in cs]) for n in ("rho_s", "alpha_x", "alpha_y")]
    return Physical(rd, f[0], alpha_x=f[1], alpha_y=f[2], normalization=int(cs[0]["input"][key]["normalization"]))


def _group(cs: List[dict], key) -> "OrderedDict[Any, List[dict]]":
    g: "OrderedDict[Any, List[dict]]" = OrderedDict()
    for c in cs:
        g.setdefault(key(c), []).append(c)
    return g


def _elementwise(fn: str, file: str, names: Tuple[str, ...], outs: Tuple[str, ...], chk: pv.Report) -> int:
    doc = load(file)
    cs = [c for _, c in pv.runnable(file, chk, fn)]
    if not cs:
        return 0
    args = [np.array([num(c["input"][n]) for c in cs]) for n in names]
    # The vectors are the C functions' own verdicts: the conversions without the model's check.
    kw = {"check": False} if fn in ("gloss_from_physical", "physical_from_gloss") else {}
    res, st = getattr(pgloss, fn)(*args, errors="status", **kw)
    res = res if isinstance(res, tuple) else (res,)
    assert st.dtype == np.int8 and st.shape == (len(cs),)
    for k, c in enumerate(cs):
        chk.ran(fn + "_batch")
        chk.status(fn + "_batch", c, Status(int(st[k])).c_name)
        chk.outputs(doc, fn, c, {o: float(r[k]) for o, r in zip(outs, res)})
    return len(cs)


ELEMENTWISE = {
    "gloss_from_physical": ("gloss.json", ("rho_d", "rho_s", "alpha"), ("L", "c", "d")),
    "physical_from_gloss": ("gloss.json", ("L", "c", "d"), ("rho_d", "rho_s", "alpha")),
    "envelope_contrast": ("gloss.json", ("L",), ("c_max",)),
    "match_gloss": ("gloss.json", ("rho_d", "rho_s", "L_target"), ("rho_d_out", "rho_s_out")),
}


@pytest.mark.parametrize("fn", list(ELEMENTWISE))
def test_vectors_elementwise_batched(fn: str, vector_report: pv.Report) -> None:
    chk = vector_report.child()
    assert _elementwise(fn, *ELEMENTWISE[fn], chk) > 0
    chk.finish(fn + " batched")


@pytest.mark.parametrize("fn,file", [("rgb_from_lab", "color.json"), ("lab_from_rgb", "color.json"),
                                     ("rgb_from_lab_ex", "color_space.json"), ("lab_from_rgb_ex", "color_space.json")])
def test_vectors_colour_batched(fn: str, file: str, vector_report: pv.Report) -> None:
    doc = load(file)
    chk = vector_report.child()
    src, dst = ("lab", "rgb") if fn.startswith("rgb") else ("rgb", "lab")
    cs = [c for _, c in pv.runnable(file, chk, fn)]
    assert cs
    for space, group in _group(cs, lambda c: int(c["input"].get("space", 0))).items():
        x = np.array([[num(v) for v in c["input"][src]] for c in group])
        y, st = getattr(pgloss, fn.removesuffix("_ex"))(x, space=space, errors="status")
        for k, c in enumerate(group):
            chk.ran(fn + "_batch")
            chk.status(fn + "_batch", c, Status(int(st[k])).c_name)
            chk.outputs(doc, fn, c, {dst: list(y[k])})
    chk.finish(fn + " batched")


@pytest.mark.parametrize("fn,file", [("physical_from_perceptual", "perceptual_material.json"),
                                     ("physical_from_perceptual_ex", "color_space.json")])
def test_vectors_physical_from_perceptual_batched(fn: str, file: str, vector_report: pv.Report) -> None:
    doc = load(file)
    chk = vector_report.child()
    cs = [c for _, c in pv.runnable(file, chk, fn)]
    assert cs
    for (norm, space), group in _group(cs, lambda c: (int(c["input"]["normalization"]),
                                                        int(c["input"].get("space", 0)))).items():
        q = Perceptual(*_perceptual_cols(group))
        p, st = q.to_physical(norm, space, errors="status", check=False)
        assert p.shape == q.shape == (len(group),) and st.shape == q.shape
        for k, c in enumerate(group):
            chk.ran(fn + "_batch")
            chk.status(fn + "_batch", c, Status(int(st[k])).c_name)
            e = p[k]
            chk.outputs(doc, fn, c, {"rho_d": list(e.rho_d), "rho_s": e.rho_s, "alpha_x": e.alpha_x,
                                     "alpha_y": e.alpha_y, "normalization": int(e.normalization)})
    chk.finish(fn + " batched")


@pytest.mark.parametrize("fn,file", [("perceptual_from_physical", "perceptual_material.json"),
                                     ("perceptual_from_physical_ex", "color_space.json")])
def test_vectors_perceptual_from_physical_batched(fn: str, file: str, vector_report: pv.Report) -> None:
    doc = load(file)
    chk = vector_report.child()
    cs = [c for _, c in pv.runnable(file, chk, fn)]
    assert cs
    for (norm, space), group in _group(cs, lambda c: (int(c["input"]["p"]["normalization"]),
                                                        int(c["input"].get("space", 0)))).items():
        q, st = _physical_array(group).to_perceptual(space, errors="status", check=False)
        for k, c in enumerate(group):
            chk.ran(fn + "_batch")
            chk.status(fn + "_batch", c, Status(int(st[k])).c_name)
            chk.outputs(doc, fn, c, {"L": float(q.L[k]), "a": float(q.a[k]), "b": float(q.b[k]), "c": float(q.c[k]),
                                     "d": float(q.d[k])})
    chk.finish(fn + " batched")


@pytest.mark.parametrize("fn,file", [("check_physical", "validity.json"), ("check_perceptual", "validity.json"),
                                     ("check_perceptual_ex", "color_space.json")])
def test_vectors_checks_batched(fn: str, file: str, vector_report: pv.Report) -> None:
    doc = load(file)
    chk = vector_report.child()
    cs = [c for _, c in pv.runnable(file, chk, fn)]
    assert cs
    if fn == "check_physical":
        groups = _group(cs, lambda c: int(c["input"]["p"]["normalization"]))
        results = [(g, _physical_array(g).check()) for g in groups.values()]
    else:
        groups = _group(cs, lambda c: int(c["input"].get("space", 0)))
        results = [(g, Perceptual(*_perceptual_cols(g)).check(space)) for space, g in groups.items()]
    for group, st in results:
        assert isinstance(st, np.ndarray) and st.dtype == np.int8
        for k, c in enumerate(group):
            chk.ran(fn + "_batch")
            chk.status(fn + "_batch", c, Status(int(st[k])).c_name)
            chk.outputs(doc, fn, c, {})
    chk.finish(fn + " batched")


# ------------------------------------------------------------------------------------------------
# BRDF vectors with one material per element: every case of a lobe mask in one call.


def _brdf_material_array(doc: dict, cs: List[dict]) -> Physical:
    ps = [doc["materials"][c["input"]["material"]] for c in cs]
    return _physical_array([{"input": {"p": p}} for p in ps])


def _by_mask_and_norm(doc: dict) -> "OrderedDict[Tuple[int, int], List[dict]]":
    g: "OrderedDict[Tuple[int, int], List[dict]]" = OrderedDict()
    for cs in groups_of(doc).values():
        for c in cs:
            key = (int(c["input"]["lobes"]), int(doc["materials"][c["input"]["material"]]["normalization"]))
            g.setdefault(key, []).append(c)
    return g


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_vectors_eval_per_element_materials(dtype: str, vector_report: pv.Report) -> None:
    doc = load("brdf_eval.json")
    chk = vector_report.child()
    for (lobes, _), cs in _by_mask_and_norm(doc).items():
        mat = _brdf_material_array(doc, cs)
        wo = np.array([[num(x) for x in c["input"]["wo"]] for c in cs], dtype=dtype)
        wi = np.array([[num(x) for x in c["input"]["wi"]] for c in cs], dtype=dtype)
        try:
            f, p = pgloss.eval_pdf(mat, wo, wi, lobes)
            st = np.zeros(len(cs), dtype=np.int8)
        except PglossError as e:
            (f, p), st = e.result, e.status_array
            assert st is not None and e.index == (int(np.argmax(st < 0)),)
        assert f.dtype == p.dtype == np.dtype(dtype)
        for k, c in enumerate(cs):
            chk.ran(f"eval_pdf_batch_materials {dtype}")
            if c["status"] != "PGLOSS_WARN_ALPHA_UNTRUSTED":  # a material's warning is not the BRDF's
                chk.status("eval_pdf_batch_materials", c, Status(int(st[k])).c_name)
            chk.brdf_eval(doc, f"eval_pdf_batch_materials_{dtype}", c, f=f[k], pdf=p[k], tol_fn="eval_pdf")
    chk.finish(f"eval_pdf per-element materials {dtype}")


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_vectors_sample_per_element_materials(dtype: str, vector_report: pv.Report) -> None:
    doc = load("brdf_sample.json")
    chk = vector_report.child()
    for (lobes, _), cs in _by_mask_and_norm(doc).items():
        mat = _brdf_material_array(doc, cs)
        wo = np.array([[num(x) for x in c["input"]["wo"]] for c in cs], dtype=dtype)
        u = np.array([[num(x) for x in c["input"]["u"]] for c in cs], dtype=dtype)
        if dtype == "float64":  # the float API's clamp of u, which the vectors encode (see test_vectors.u64)
            u = np.minimum(u, 1.0 - 2.0 ** -24)
        try:
            r = pgloss.sample(mat, wo, u, lobes)
            st = np.zeros(len(cs), dtype=np.int8)
        except PglossError as e:
            r, st = e.result, e.status_array
        for k, c in enumerate(cs):
            chk.ran(f"sample_batch_materials {dtype}")
            if c["status"] != "PGLOSS_WARN_ALPHA_UNTRUSTED":
                chk.status("sample_batch_materials", c, Status(int(st[k])).c_name)
            chk.sample(doc, f"sample_batch_materials_{dtype}", c, r.wi[k], float(r.pdf[k]), r.weight[k], r.lobe[k])
    chk.finish(f"sample per-element materials {dtype}")


# ------------------------------------------------------------------------------------------------
# Per-element materials = one material per call, element by element.


def _texture(n: int, seed: int = 18) -> Tuple[Physical, np.ndarray, np.ndarray, np.ndarray]:
    """n paints (values exact in float, so that the float64 uniform path, which takes the
    material's float parameters, and the per-element double path see the same numbers), and
    one direction pair and one random triple per paint."""
    rng = np.random.default_rng(seed)
    f32 = lambda x: x.astype(np.float32).astype(np.float64)  # noqa: E731
    rd = f32(rng.uniform(0.0, 0.8, (n, 3)))
    rs = f32(rng.uniform(0.0, 0.2, n))
    ax, ay = f32(rng.uniform(0.01, 0.3, n)), f32(rng.uniform(0.01, 0.3, n))
    rd[::7] = 0.0  # no diffuse lobe
    rs[3::11] = 0.0  # no specular lobe
    ay[::2] = ax[::2]  # half isotropic

    def dirs() -> np.ndarray:
        v = rng.normal(size=(n, 3))
        v[:, 2] = np.abs(v[:, 2]) + 0.05
        return v

    return Physical(rd, rs, alpha_x=ax, alpha_y=ay), dirs(), dirs(), rng.random((n, 3))


@pytest.mark.parametrize("norm", list(Normalization))
def test_per_element_materials_equal_one_call_per_material(norm: Normalization) -> None:
    tex, wo, wi, u = _texture(300)
    tex = tex.replace(normalization=norm)
    for dtype, rtol in ((np.float32, 0.0), (np.float64, 1e-12)):
        o, i, uu = wo.astype(dtype), wi.astype(dtype), u.astype(dtype)
        f, p = pgloss.eval_pdf(tex, o, i)
        fe = pgloss.eval(tex, o, i)
        pe = pgloss.pdf(tex, o, i)
        r = pgloss.sample(tex, o, uu)
        for k in range(tex.size):
            m = tex[k].material()
            f1, p1 = pgloss.eval_pdf(m, o[k:k + 1], i[k:k + 1])
            np.testing.assert_allclose(f[k], f1[0], rtol=rtol, atol=0)
            np.testing.assert_allclose(p[k], p1[0], rtol=rtol, atol=0)
            np.testing.assert_allclose(fe[k], f1[0], rtol=rtol, atol=0)
            np.testing.assert_allclose(pe[k], p1[0], rtol=rtol, atol=0)
            r1 = pgloss.sample(m, o[k:k + 1], uu[k:k + 1])
            assert r.lobe[k] == r1.lobe[0]
            np.testing.assert_allclose(r.wi[k], r1.wi[0], rtol=rtol, atol=1e-12 if rtol else 0)
            np.testing.assert_allclose(r.pdf[k], r1.pdf[0], rtol=rtol, atol=0)
            np.testing.assert_allclose(r.weight[k], r1.weight[0], rtol=rtol, atol=0)


def _ward_numpy(rd: np.ndarray, rs: np.ndarray, ax: np.ndarray, ay: np.ndarray, wo: np.ndarray,
                wi: np.ndarray) -> np.ndarray:
    """Paper eq. 2 with Ward 1992's anisotropic lobe, transcribed in numpy float64:
    ρd/π + ρs exp(−(hx²/αx² + hy²/αy²)/hz²) / (4π αx αy √(cosθi cosθo))."""
    wo = wo / np.linalg.norm(wo, axis=-1, keepdims=True)
    wi = wi / np.linalg.norm(wi, axis=-1, keepdims=True)
    h = wo + wi
    e = (h[:, 0] ** 2 / ax ** 2 + h[:, 1] ** 2 / ay ** 2) / h[:, 2] ** 2
    spec = rs * np.exp(-e) / (4 * np.pi * ax * ay * np.sqrt(wi[:, 2] * wo[:, 2]))
    return rd / np.pi + spec[:, None]


def test_float64_brdf_has_double_reference_accuracy() -> None:
    # Per-element materials in float64 against an independent float64 transcription of eq. 2:
    # double accuracy (the exponent's argument is kept moderate, so that its conditioning,
    # |x| ulp, stays far below the bound).
    tex, wo, wi, _ = _texture(2000, seed=5)
    f = pgloss.eval(tex, wo, wi)
    want = _ward_numpy(np.asarray(tex.rho_d), tex.rho_s, tex.alpha_x, tex.alpha_y, wo, wi)
    h = wo / np.linalg.norm(wo, axis=1, keepdims=True) + wi / np.linalg.norm(wi, axis=1, keepdims=True)
    x = (h[:, 0] ** 2 / tex.alpha_x ** 2 + h[:, 1] ** 2 / tex.alpha_y ** 2) / h[:, 2] ** 2
    keep = x < 50
    assert keep.sum() > 500
    np.testing.assert_allclose(f[keep], want[keep], rtol=1e-12, atol=0)
    # float32 agrees to float accuracy on the same texture
    f32 = pgloss.eval(tex, wo.astype(np.float32), wi.astype(np.float32))
    np.testing.assert_allclose(f32[keep], want[keep], rtol=5e-5, atol=1e-7)


def test_sequence_of_physical_is_an_array_material() -> None:
    ps = [Physical(0.2, 0.05, 0.1), Physical((0.5, 0.3, 0.1), 0.02, alpha_x=0.05, alpha_y=0.2)]
    wo, wi = np.array([0.0, 0.3, 1.0]), np.array([[0.1, -0.3, 1.0], [0.5, 0.0, 1.0]])
    f = pgloss.eval(ps, wo, wi)
    assert f.shape == (2, 3)
    # float64 directions: the array reads the paints' double parameters, one paint's Material holds
    # them rounded to float (pgloss_material): the same up to that rounding.
    for k, p in enumerate(ps):
        np.testing.assert_allclose(f[k], pgloss.eval(p, wo, wi[k]), rtol=1e-6)
        np.testing.assert_allclose(f[k], pgloss.eval(Physical.stack([p]), wo, wi[k])[0], rtol=1e-15)
    f2 = pgloss.eval([p.material() for p in ps], wo, wi)
    np.testing.assert_array_equal(f, f2)
    with pytest.raises(ValueError, match="normalizations"):
        pgloss.eval([ps[0], ps[1].replace(normalization=Normalization.BOUNDED)], wo, wi)


def test_array_physical_keeps_a_float_block_that_never_goes_stale() -> None:
    # An array Physical rounds its parameters to float on its first BRDF call and keeps them
    # (as one paint keeps its Material). The block must always be the fields' values: the
    # caller's arrays are copied, the fields are read-only, replace() makes a new object.
    rng = np.random.default_rng(11)
    n = 300  # more than one chunk of the binding's loops
    rd, rs = rng.uniform(0.05, 0.6, (n, 3)), rng.uniform(0.0, 0.1, n)
    ax, ay = rng.uniform(0.03, 0.2, n), rng.uniform(0.03, 0.2, n)
    tex = Physical(rd, rs, alpha_x=ax, alpha_y=ay)
    wo = np.array([0.1, 0.2, 1.0], np.float32)
    wi = (rng.normal(size=(n, 3)) * [1, 1, 0] + [0, 0, 1]).astype(np.float32)

    def one_by_one(p: Physical, dtype: Any) -> np.ndarray:
        return np.concatenate([pgloss.eval(p[k].material(), wo.astype(dtype), wi[k:k + 1].astype(dtype))
                               for k in range(n)])

    f0 = pgloss.eval(tex, wo, wi)
    np.testing.assert_array_equal(f0, one_by_one(tex, np.float32))
    for a in (rd, rs, ax, ay):  # the caller's arrays: copied at construction
        a[...] = 0.5
    np.testing.assert_array_equal(pgloss.eval(tex, wo, wi), f0)
    np.testing.assert_allclose(pgloss.eval(tex, wo.astype(np.float64), wi.astype(np.float64)), f0, rtol=1e-5)
    for field in (tex.rho_d, tex.rho_s, tex.alpha_x, tex.alpha_y):  # the fields: read-only
        with pytest.raises(ValueError):
            field[0] = 0.9
    assert np.all(tex.rho_s != 0.5) and np.all(tex.rho_d != 0.5)
    other = tex.replace(rho_s=tex.rho_s[::-1].copy())  # a new object, a new block
    np.testing.assert_array_equal(pgloss.eval(other, wo, wi), one_by_one(other, np.float32))
    np.testing.assert_array_equal(pgloss.eval(tex, wo, wi), f0)
    # A conversion's result (an array Physical over the conversion's own outputs) and an
    # indexed part of a texture evaluate as their elements do.
    conv = Perceptual(np.linspace(20.0, 80.0, n), 0.0, 0.0, 0.04, 0.93).to_physical()
    np.testing.assert_array_equal(pgloss.eval(conv, wo, wi), one_by_one(conv, np.float32))
    part = tex[::3]
    np.testing.assert_array_equal(pgloss.eval(part, wo, wi[::3]), f0[::3])


def test_per_element_material_values_beyond_float_range() -> None:
    # The per-element batches see the parameters as the C API does: rounded to float, a value
    # beyond float range is +-inf (NONFINITE), never FLT_MAX by rounding; the same status as one
    # material_init per element.
    big = float(np.finfo(np.float32).max)
    rs = np.array([0.05, big, 3.4028235e38, 1e300, 1e-50])
    tex = Physical(0.2, rs, 0.1)
    for k in range(rs.size):
        try:
            tex[k].material()
            want = Status.OK
        except PglossError as e:
            want = e.status
        for dtype in (np.float32, np.float64):
            try:
                pgloss.eval(tex, np.array([0.0, 0.0, 1.0], dtype), np.array([0.0, 0.3, 1.0], dtype))
                got = np.zeros(rs.size, np.int8)
            except PglossError as e:
                got = e.status_array
            assert got[k] == want, (k, dtype, got)
    assert [Status(int(x)) for x in got] == [Status.OK, Status.OK, Status.ERR_NONFINITE, Status.ERR_NONFINITE,
                                             Status.OK]


def test_status_array_when_the_first_failure_is_late() -> None:
    # The status array is allocated at the first failing chunk of the binding's loops: every
    # element before it is OK, every failing element after it is reported.
    n = 1000
    rs = np.full(n, 0.05)
    rs[700], rs[950] = -1.0, np.nan
    tex = Physical(0.2, rs, 0.1)
    wo = np.array([0.0, 0.2, 1.0])
    for dtype in (np.float32, np.float64):
        for call in (lambda: pgloss.eval(tex, wo.astype(dtype), wo.astype(dtype) * [-1, -1, 1]),
                     lambda: pgloss.sample(tex, wo.astype(dtype), np.full(3, 0.4, dtype))):
            with pytest.raises(PglossError) as info:
                call()
            e = info.value
            assert e.status == Status.ERR_NEGATIVE and e.index == (700,)
            want = np.zeros(n, np.int8)
            want[700], want[950] = Status.ERR_NEGATIVE, Status.ERR_NONFINITE
            np.testing.assert_array_equal(e.status_array, want)
    # broadcast against the directions: the material's block is broadcast, statuses too
    tex2 = Physical(0.2, np.array([[0.05], [-1.0]]), 0.1)  # shape (2, 1)
    wi = np.tile(np.array([0.1, 0.0, 1.0]), (3, 1))  # (3, 3): batch shape (2, 3)
    with pytest.raises(PglossError) as info:
        pgloss.pdf(tex2, wo, wi)
    assert info.value.index == (1, 0) and info.value.status_array.tolist() == [[0, 0, 0], [-3, -3, -3]]
    assert np.all(info.value.result[0] > 0) and np.all(info.value.result[1] == 0)


# ------------------------------------------------------------------------------------------------
# Broadcasting.


def test_broadcasting_of_materials_against_directions() -> None:
    tex = Physical(0.3, np.array([[0.02], [0.05], [0.08], [0.11]]), np.array([0.05, 0.1, 0.2]))
    assert tex.shape == (4, 3) and tex.rho_d.shape == (4, 3, 3)
    wo = np.array([0.0, 0.2, 1.0])
    wi = np.random.default_rng(1).normal(size=(5, 1, 1, 3)) * [1, 1, 0] + [0, 0, 1]
    f = pgloss.eval(tex, wo, wi)
    assert f.shape == (5, 4, 3, 3)
    for a in range(5):
        for b in range(4):
            for c in range(3):
                # the texel's double parameters against its Material's floats (float64 directions)
                np.testing.assert_allclose(f[a, b, c], pgloss.eval(tex[b, c], wo, wi[a, 0, 0]), rtol=1e-6)
                np.testing.assert_array_equal(f[a, b, c], pgloss.eval(tex[b:b + 1, c], wo, wi[a, 0, 0])[0])
    assert pgloss.pdf(tex, wo, wo).shape == (4, 3)
    assert pgloss.sample(tex, wo, np.full((2, 1, 1, 3), 0.3)).wi.shape == (2, 4, 3, 3)
    with pytest.raises(ValueError, match=r"shapes do not broadcast: .*material\(4, 3\)"):
        pgloss.eval(tex, wo, np.zeros((2, 3)) + [0, 0, 1])


def test_broadcasting_of_fields() -> None:
    q = Perceptual(L=np.linspace(20, 80, 6).reshape(2, 3), a=[0.0, 10.0, -10.0], b=0.0, c=0.05, d=0.95)
    assert q.shape == (2, 3) and q.a.shape == (2, 3) and not q.a.flags.writeable
    with pytest.raises(ValueError, match="broadcast"):
        Perceptual(L=[1.0, 2.0], a=[1.0, 2.0, 3.0], b=0.0, c=0.05, d=0.95)
    # rho_d's last axis is the channel; a last axis of 1 is grey.
    grey = Physical(np.full((4, 1), 0.25), 0.05, 0.1)
    assert grey.shape == (4,) and np.all(grey.rho_d == 0.25)
    assert Physical(np.zeros((2, 3)), [0.1, 0.2], 0.1).shape == (2,)
    with pytest.raises(ValueError, match="rho_d"):
        Physical(np.zeros((4, 2)), 0.1, 0.1)
    with pytest.raises(ValueError, match="broadcast"):
        Physical(np.zeros((4, 3)), np.zeros(5), 0.1)


# ------------------------------------------------------------------------------------------------
# Scalars stay as they were; arrays have shape, indexing, no hash.


def test_array_objects_protocol() -> None:
    L = np.array([[30.0, 50.0], [70.0, 90.0]])
    q = Perceptual(L, 5.0, -5.0, 0.04, 0.93)
    assert q.is_array and q.ndim == 2 and q.size == 4 and len(q) == 2
    e = q[1, 0]
    assert isinstance(e, Perceptual) and not e.is_array and e == Perceptual(70.0, 5.0, -5.0, 0.04, 0.93)
    assert hash(e) == hash(Perceptual(70.0, 5.0, -5.0, 0.04, 0.93))
    assert q[0].shape == (2,) and q[:, 1].L.tolist() == [50.0, 90.0] and q[q.L > 40].shape == (3,)
    assert [x.L for x in q[0]] == [30.0, 50.0]
    with pytest.raises(TypeError, match="unhashable"):
        hash(q)
    assert q == Perceptual(L.copy(), 5.0, -5.0, 0.04, 0.93) and q != e and q != q.replace(c=0.05)
    back = pickle.loads(pickle.dumps(q))
    assert back == q and back.shape == q.shape
    assert "shape (2, 2)" in repr(q)
    L[0, 0] = 99.0  # the object copied its input
    assert q.L[0, 0] == 30.0
    with pytest.raises(ValueError):
        q.L[0, 0] = 1.0  # read-only

    p = q.to_physical()
    assert p.shape == (2, 2) and p.rho_d.shape == (2, 2, 3)
    assert p[1, 1] == q[1, 1].to_physical()
    with pytest.raises(TypeError, match="no single Material"):
        p.material()
    with pytest.raises(TypeError, match="unhashable"):
        hash(p)
    assert pickle.loads(pickle.dumps(p)) == p
    assert Physical.stack([p[0, 0], p[1, 1]]) == p[[0, 1], [0, 1]]
    assert Perceptual.stack([q[0, 0], q[1, 1]]) == q[[0, 1], [0, 1]]

    # Scalars: exactly as before (tuples and floats, repr that rebuilds, hash, no len).
    s = Physical((0.5, 0.3, 0.1), 0.05, 0.1)
    assert not s.is_array and s.shape == () and isinstance(s.rho_d, tuple) and isinstance(s.rho_s, float)
    assert eval(repr(s), {"Physical": Physical, "Normalization": Normalization}) == s
    with pytest.raises(TypeError):
        len(s)
    with pytest.raises(TypeError):
        s[0]
    assert Physical(np.array([0.5, 0.3, 0.1]), np.float64(0.05), np.array(0.1)) == s


# ------------------------------------------------------------------------------------------------
# Status arrays: raise with the whole array and the first index, or return it.


def test_texture_with_out_of_gamut_texels() -> None:
    L = np.full((8, 8), 50.0)
    a = np.zeros((8, 8))
    a[2, 5] = a[6, 1] = 150.0  # far outside the Rec. 709 gamut at L* = 50
    tex = Perceptual(L, a, 0.0, 0.05, 0.95)
    with pytest.raises(PglossError) as info:
        tex.to_physical()
    e = info.value
    assert e.status == Status.ERR_GAMUT and e.index == (2, 5)
    assert e.status_array.shape == (8, 8) and e.status_array.dtype == np.int8
    assert set(zip(*np.nonzero(e.status_array))) == {(2, 5), (6, 1)}
    assert "2 of 64 elements failed" in str(e)
    assert isinstance(e.result, Physical) and e.result.shape == (8, 8)
    assert pickle.loads(pickle.dumps(e)).status_array.tolist() == e.status_array.tolist()

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p, st = tex.to_physical(errors="status")
    np.testing.assert_array_equal(st, e.status_array)
    assert p == e.result
    for k in np.ndindex(8, 8):  # element by element = the scalar conversion
        want = tex[k].to_physical(errors="status")
        assert want[1] == st[k] and want[0] == p[k]
    chk = tex.check()
    assert chk[2, 5] == chk[6, 1] == Status.ERR_GAMUT and np.count_nonzero(chk) == 2
    # scalar errors="status": a Status, not an array
    assert tex[2, 5].to_physical(errors="status")[1] is Status.ERR_GAMUT
    with pytest.raises(ValueError, match="errors"):
        tex.to_physical(errors="ignore")


def test_elementwise_status_arrays_and_warnings() -> None:
    L, st = pgloss.lightness_from_luminance(np.array([0.2, -1.0, 0.5]), errors="status")
    assert st.tolist() == [0, Status.ERR_NEGATIVE, 0]
    with pytest.raises(PglossError) as info:
        pgloss.gloss_from_physical([0.2, 0.2, 0.2], [0.05, np.nan, -1.0], 0.1)
    assert info.value.index == (1,) and info.value.status_array.tolist() == [0, Status.ERR_NONFINITE,
                                                                               Status.ERR_NEGATIVE]
    with pytest.warns(pgloss.AlphaUntrustedWarning, match="1 of 2 elements"):
        pgloss.gloss_from_physical(0.2, 0.05, [0.1, 0.3])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, st = pgloss.gloss_from_physical(0.2, 0.05, [0.1, 0.3], errors="status")
    assert st.tolist() == [0, Status.WARN_ALPHA_UNTRUSTED]
    rgb, st = pgloss.rgb_from_lab([[50.0, 0.0, 0.0], [50.0, 150.0, 0.0]], errors="status")
    assert st.tolist() == [0, Status.ERR_GAMUT] and rgb[1, 1] < 0  # the exact values of a GAMUT element


def test_brdf_status_array_of_per_element_materials() -> None:
    tex = Physical(0.2, np.array([0.05, -0.1, 0.05, np.nan]), 0.1)
    with pytest.raises(PglossError) as info:
        pgloss.eval(tex, [0.0, 0.0, 1.0], [0.0, 0.3, 1.0])
    e = info.value
    assert e.status == Status.ERR_NEGATIVE and e.index == (1,)
    assert e.status_array.tolist() == [0, Status.ERR_NEGATIVE, 0, Status.ERR_NONFINITE]
    assert np.all(e.result[[1, 3]] == 0) and np.all(e.result[[0, 2]] > 0)
    with pytest.raises(PglossError) as info:
        pgloss.pdf(Physical(0.2, [0.05, 0.05], 0.1), [[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]], [0.0, 0.3, 1.0])
    assert info.value.status == Status.ERR_DIRECTION and info.value.index == (1,)
    with pytest.raises(PglossError) as info:  # an unknown normalisation: every element
        pgloss.eval(Physical(0.2, [0.05, 0.05], 0.1, normalization=9), [0.0, 0.0, 1.0], [0.0, 0.3, 1.0])
    assert info.value.status == Status.ERR_NORMALIZATION and info.value.index == (0,)


# ------------------------------------------------------------------------------------------------
# out=


def test_out_arrays() -> None:
    tex, wo, wi, u = _texture(50, seed=3)
    for dtype in (np.float32, np.float64):
        o, i, uu = wo.astype(dtype), wi.astype(dtype), u.astype(dtype)
        for mat in (tex, tex[0].material()):
            f = np.empty((50, 3), dtype)
            assert pgloss.eval(mat, o, i, out=f) is f
            np.testing.assert_array_equal(f, pgloss.eval(mat, o, i))
            p = np.empty(50, dtype)
            assert pgloss.pdf(mat, o, i, out=p) is p
            np.testing.assert_array_equal(p, pgloss.pdf(mat, o, i))
            f2, p2 = pgloss.eval_pdf(mat, o, i, out=(f, None))
            assert f2 is f and p2.shape == (50,)
            outs = (np.empty((50, 3), dtype), np.empty(50, dtype), None, np.empty(50, np.uint8))
            r = pgloss.sample(mat, o, uu, out=outs)
            assert r.wi is outs[0] and r.pdf is outs[1] and r.lobe is outs[3]
            ref = pgloss.sample(mat, o, uu)
            for x, y in zip(r, ref):
                np.testing.assert_array_equal(x, y)


def test_out_aliasing_and_checks() -> None:
    m = Physical(0.2, 0.05, 0.1)
    wo = np.tile(np.array([0, 0.2, 1], np.float32), (10, 1))
    wi = np.tile(np.array([0.1, 0, 1], np.float32), (10, 1))
    with pytest.raises(ValueError, match="overlaps"):
        pgloss.eval(m, wo, wi, out=wo)  # in place over an input
    with pytest.raises(ValueError, match="overlaps"):
        pgloss.pdf(m, wo, wi, out=wi.reshape(-1)[:10])  # a view of an input
    f = np.empty((10, 3), np.float32)
    with pytest.raises(ValueError, match="overlaps"):
        pgloss.eval_pdf(m, wo, wi, out=(f, f.reshape(-1)[:10]))  # f and pdf share memory
    with pytest.raises(TypeError, match="dtype"):
        pgloss.eval(m, wo, wi, out=np.empty((10, 3), np.float64))
    with pytest.raises(ValueError, match="shape"):
        pgloss.eval(m, wo, wi, out=np.empty((10, 4), np.float32))
    with pytest.raises(ValueError, match="contiguous"):
        pgloss.eval(m, wo, wi, out=np.empty((3, 10), np.float32).T)
    ro = np.empty((10, 3), np.float32)
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="writeable"):
        pgloss.eval(m, wo, wi, out=ro)
    with pytest.raises(TypeError, match="tuple"):
        pgloss.eval_pdf(m, wo, wi, out=f)
    with pytest.raises(TypeError, match="does not produce"):
        pgloss.eval(m, wo, wi, out=(f, np.empty(10, np.float32)))
    with pytest.raises(TypeError, match="lobe"):
        pgloss.sample(m, wo, wi, out=(None, None, None, np.empty(10, np.int64)))
    # Nothing was written by a refused call.
    g = np.full((10, 3), 7.0, np.float32)
    with pytest.raises(TypeError):
        pgloss.eval_pdf(m, wo, wi, out=(g, np.empty(10, np.float64)))
    assert np.all(g == 7.0)


def test_ctrl_c_interrupts_the_batched_paths() -> None:
    import os
    import signal
    import threading
    import time

    tex = Physical(0.2, np.full(4_000_000, 0.05), 0.1)
    wo = np.array([0.0, 0.2, 1.0], np.float32)
    wi = np.array([0.1, 0.0, 1.0], np.float32)
    t0 = time.perf_counter()
    pgloss.eval(tex, wo, wi)
    full = time.perf_counter() - t0
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        timer = threading.Timer(full / 10, os.kill, (os.getpid(), signal.SIGINT))
        t0 = time.perf_counter()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            pgloss.eval(tex, wo, wi)
            time.sleep(full)
        took = time.perf_counter() - t0
        timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)
    assert took < 0.7 * full + 0.05, (took, full)
