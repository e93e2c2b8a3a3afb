# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Behaviour of the Python binding: broadcasting, dtypes, scalars, every error path, odd
arrays (wrong shape/dtype, non-contiguous, read-only, empty), parameter objects, pickling,
thread safety, documentation.

Values are asserted against independent sources — the paper's numbers, a numpy
transcription of eq. 2 — or between two paths of the package (scalar vs array, float32
batched vs float64 scalar reference), never against pasted output.
"""

from __future__ import annotations

import math
import pickle
import pydoc
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import pgloss
from pgloss import Lobe, Normalization, Perceptual, Physical, PglossError, Status

GREY = Physical(0.193, 0.066, 0.07)  # Experiment 1's grey stimulus = Fig. 11's reference


def random_dirs(rng: np.random.Generator, n: int, dtype=np.float64, upper: bool = True) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    if upper:
        v[:, 2] = np.abs(v[:, 2]) + 0.05
    return (v / np.linalg.norm(v, axis=1, keepdims=True)).astype(dtype)


# ------------------------------------------------------------------------------------------------
# Independent values: the paper.

def test_paper_values() -> None:
    # §5.1: the reference of Fig. 11 is c = 0.087, d = 0.93 — the grey stimulus.
    q = GREY.to_perceptual()
    assert round(q.c, 3) == 0.087 and round(q.d, 2) == 0.93 and q.a == pytest.approx(0, abs=1e-9)
    # §5.2: ρs = 0.099, α = 0.04 on white gives c ≈ 0.057, d = 0.96 (Fig. 12).
    L, c, d = pgloss.gloss_from_physical(0.767, 0.099, 0.04)
    assert round(c, 3) == 0.058 and c == pytest.approx(0.057, abs=1.5e-3) and d == pytest.approx(0.96)
    # eq. 5 with the paper's steps: Δc = 0.04 ⇔ Δd = 0.04 / 1.78.
    assert pgloss.gloss_distance(0.087, 0.93, 0.087, 0.93 + 0.04 / 1.78) == pytest.approx(0.04, rel=1e-14)
    assert pgloss.D_WEIGHT == 1.78 and pgloss.ALPHA_TRUSTED_MAX == 0.2
    assert pgloss.CIE_EPSILON == 216 / 24389 and pgloss.CIE_KAPPA == 24389 / 27


def ward_numpy(rho_d, rho_s, alpha, wo, wi):
    """Paper eq. 2, transcribed in numpy (float64): ρd/π + ρs exp(-tan²δ/α²)/(4πα²√(ci co))."""
    wo = wo / np.linalg.norm(wo, axis=-1, keepdims=True)
    wi = wi / np.linalg.norm(wi, axis=-1, keepdims=True)
    h = wo + wi
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    tan2 = (h[..., 0] ** 2 + h[..., 1] ** 2) / h[..., 2] ** 2
    spec = rho_s * np.exp(-tan2 / alpha**2) / (4 * np.pi * alpha**2 * np.sqrt(wi[..., 2] * wo[..., 2]))
    return rho_d / np.pi + spec


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_eval_matches_eq2(dtype) -> None:
    rng = np.random.default_rng(1)
    p = Physical(0.3, 0.08, 0.1)
    wo, wi = random_dirs(rng, 2000, dtype), random_dirs(rng, 2000, dtype)
    f = pgloss.eval(p, wo, wi)
    want = ward_numpy(0.3, 0.08, 0.1, wo.astype(np.float64), wi.astype(np.float64))
    np.testing.assert_allclose(f[:, 0], want, rtol=2e-5 if dtype == np.float32 else 1e-6)
    assert np.array_equal(f[:, 0], f[:, 1]) and np.array_equal(f[:, 0], f[:, 2])  # achromatic ρs, grey ρd
    # The diffuse lobe alone is ρd/π per channel; nothing below the horizon.
    fd = pgloss.eval(Physical((0.5, 0.25, 0.125), 0.08, 0.1), wo, wi, Lobe.DIFFUSE)
    np.testing.assert_allclose(fd, np.broadcast_to(np.array([0.5, 0.25, 0.125]) / np.pi, fd.shape), rtol=1e-6)
    below = wi * np.array([1, 1, -1], dtype=dtype)
    assert not pgloss.eval(p, wo, below).any()


# ------------------------------------------------------------------------------------------------
# Broadcasting, dtypes, scalars.

def test_broadcasting_brdf() -> None:
    rng = np.random.default_rng(2)
    wo = random_dirs(rng, 4).reshape(4, 1, 3)
    wi = random_dirs(rng, 5)
    f, p = pgloss.eval_pdf(GREY, wo, wi)
    assert f.shape == (4, 5, 3) and p.shape == (4, 5)
    for a in range(4):
        for b in range(5):
            np.testing.assert_array_equal(f[a, b], pgloss.eval(GREY, wo[a, 0], wi[b]))
            assert p[a, b] == pgloss.pdf(GREY, wo[a, 0], wi[b])
    # one wo against many wi, and the lobe mask as Lobe or int
    assert pgloss.eval(GREY, [0, 0, 1], wi, 3).shape == (5, 3)
    assert pgloss.sample(GREY, [0, 0, 1], rng.random((7, 2, 3))).wi.shape == (7, 2, 3)
    with pytest.raises(ValueError, match="broadcast"):
        pgloss.eval(GREY, np.zeros((2, 3)) + [0, 0, 1], np.zeros((3, 3)) + [0, 0, 1])


def test_broadcasting_perceptual() -> None:
    rho_d = np.array([0.03, 0.193, 0.767])[:, None, None]
    rho_s = np.array([0.033, 0.066, 0.099])[None, :, None]
    alpha = np.array([0.04, 0.07, 0.10])
    L, c, d = pgloss.gloss_from_physical(rho_d, rho_s, alpha)
    assert L.shape == c.shape == d.shape == (3, 3, 3)
    for i in range(3):
        for j in range(3):
            for k in range(3):
                s = pgloss.gloss_from_physical(float(rho_d[i, 0, 0]), float(rho_s[0, j, 0]), float(alpha[k]))
                assert (L[i, j, k], c[i, j, k], d[i, j, k]) == s  # same C function, same doubles
    with pytest.raises(ValueError, match="broadcast"):
        pgloss.contrast_gloss(np.ones(3) * 0.1, np.ones(4) * 0.1)


def test_dtypes() -> None:
    rng = np.random.default_rng(3)
    wo64, wi64 = random_dirs(rng, 100), random_dirs(rng, 100)
    wo32, wi32 = wo64.astype(np.float32), wi64.astype(np.float32)
    assert pgloss.eval(GREY, wo32, wi32).dtype == np.float32
    assert pgloss.eval(GREY, wo64, wi64).dtype == np.float64
    assert pgloss.eval(GREY, wo32, wi64).dtype == np.float64  # numpy promotion
    assert pgloss.eval(GREY, wo32.astype(np.float16), wi32.astype(np.float16)).dtype == np.float32
    assert pgloss.eval(GREY, [[0, 0, 1]], [[0, 1, 1]]).dtype == np.float64  # integers
    assert pgloss.pdf(GREY, wo32, wi32).dtype == np.float32
    # float32 (batched, float arithmetic) and float64 (scalar reference on the same float inputs) agree
    np.testing.assert_allclose(pgloss.eval(GREY, wo32, wi32), pgloss.eval(GREY, wo32.astype(np.float64), wi32),
                               rtol=2e-6)
    # Perceptual functions: double inside; float32 stays float32, Python scalars do not promote it.
    assert pgloss.contrast_gloss(np.float32([0.1, 0.2]), 0.05).dtype == np.float32
    assert pgloss.contrast_gloss(np.float32([0.1, 0.2]), np.float64(0.05)).dtype == np.float64
    assert pgloss.contrast_gloss([0.1, 0.2], 0.05).dtype == np.float64
    assert pgloss.rgb_from_lab(np.float32([[50, 0, 0]])).dtype == np.float32
    c32 = pgloss.contrast_gloss(np.float32([0.193]), np.float32(0.066))
    c64 = pgloss.contrast_gloss(np.float64(np.float32(0.193)), np.float64(np.float32(0.066)))
    assert c32[0] == np.float32(c64)  # computed in double, rounded once


def test_scalars_are_python_floats() -> None:
    assert type(pgloss.contrast_gloss(0.193, 0.066)) is float
    assert type(pgloss.contrast_gloss(np.float64(0.193), np.array(0.066))) is float  # 0-d arrays too
    assert all(type(x) is float for x in pgloss.physical_from_gloss(50.0, 0.05, 0.95))
    assert type(pgloss.luminance([0.2, 0.3, 0.4])) is float
    assert type(pgloss.pdf(GREY, [0, 0, 1], [0, 0.2, 1])) is float
    f = pgloss.eval(GREY, [0, 0, 1], [0, 0.2, 1])
    assert isinstance(f, np.ndarray) and f.shape == (3,)
    s = pgloss.sample(GREY, [0, 0, 1], [0.2, 0.3, 0.4])
    assert type(s.pdf) is float and isinstance(s.lobe, Lobe) and s.wi.shape == (3,)
    assert type(pgloss.specular_probability(GREY)) is float


def test_scalar_vs_array_perceptual() -> None:
    rng = np.random.default_rng(4)
    L = rng.uniform(0, 100, 50)
    c = rng.uniform(0, 0.1, 50)
    d = rng.uniform(0.85, 0.99, 50)
    # Across the whole (L, c) square, beyond the envelope too: the conversion alone (check=False).
    arr = pgloss.physical_from_gloss(L, c, d, check=False)
    for k in range(50):
        assert tuple(a[k] for a in arr) == pgloss.physical_from_gloss(L[k], c[k], d[k], check=False)
    env = pgloss.envelope_contrast(L)
    assert [pgloss.envelope_contrast(x) for x in L] == list(env)
    lab = np.stack([L, rng.uniform(-5, 5, 50), rng.uniform(-5, 5, 50)], axis=-1)
    rgb = pgloss.rgb_from_lab(lab)
    for k in range(50):
        np.testing.assert_array_equal(rgb[k], pgloss.rgb_from_lab(lab[k]))
    np.testing.assert_allclose(pgloss.lab_from_rgb(rgb), lab, atol=1e-9)  # round trip


def test_scalar_vs_array_brdf() -> None:
    rng = np.random.default_rng(5)
    wo, wi = random_dirs(rng, 64, upper=False), random_dirs(rng, 64, upper=False)
    u = rng.random((64, 3))
    for dtype in (np.float32, np.float64):
        f, p = pgloss.eval_pdf(GREY, wo.astype(dtype), wi.astype(dtype))
        s = pgloss.sample(GREY, wo.astype(dtype), u.astype(dtype))
        for k in range(64):
            fk, pk = pgloss.eval_pdf(GREY, wo[k].astype(dtype), wi[k].astype(dtype))
            sk = pgloss.sample(GREY, wo[k].astype(dtype), u[k].astype(dtype))
            if dtype == np.float64:  # the double batch: an element does not depend on its neighbours
                np.testing.assert_array_equal(f[k], fk)
                assert p[k] == pk and s.pdf[k] == sk.pdf and s.lobe[k] == sk.lobe
                np.testing.assert_array_equal(s.wi[k], sk.wi)
            else:  # a 1-element batch is still the batched path: identical
                np.testing.assert_array_equal(f[k], fk)
                assert p[k] == pk and s.pdf[k] == sk.pdf


def test_sample_consistent_with_pdf_and_eval() -> None:
    rng = np.random.default_rng(6)
    wo = random_dirs(rng, 5000)
    s = pgloss.sample(GREY, wo, rng.random((5000, 3)))
    ok = s.pdf > 0
    assert ok.mean() > 0.9 and set(np.unique(s.lobe)) <= {1, 2}
    np.testing.assert_allclose(s.pdf[ok], pgloss.pdf(GREY, wo[ok], s.wi[ok]), rtol=1e-5)
    f = pgloss.eval(GREY, wo[ok], s.wi[ok])
    np.testing.assert_allclose(s.weight[ok], f * s.wi[ok][:, 2:3] / s.pdf[ok][:, None], rtol=1e-5)
    assert not s.weight[~ok].any()


def test_lobe_masks() -> None:
    rng = np.random.default_rng(7)
    wo, wi = random_dirs(rng, 300), random_dirs(rng, 300)
    total = pgloss.eval(GREY, wo, wi, Lobe.ALL)
    parts = pgloss.eval(GREY, wo, wi, Lobe.DIFFUSE) + pgloss.eval(GREY, wo, wi, Lobe.SPECULAR)
    np.testing.assert_allclose(total, parts, rtol=3e-7)  # each part rounded to float once
    assert not pgloss.eval(GREY, wo, wi, Lobe.NONE).any()
    assert pgloss.specular_probability(GREY, Lobe.SPECULAR) == 1.0
    assert pgloss.specular_probability(GREY, Lobe.NONE) == 0.0
    assert Physical(0.0, 0.05, 0.1).material().lobes == Lobe.SPECULAR
    assert Physical(0.5, 0.0, 0.1).material().lobes == Lobe.DIFFUSE
    assert Lobe.DIFFUSE | Lobe.SPECULAR == Lobe.ALL


# ------------------------------------------------------------------------------------------------
# Every error path.

def raises(status: Status, fn, *args, **kw) -> PglossError:
    with pytest.raises(PglossError) as info:
        fn(*args, **kw)
    e = info.value
    assert isinstance(e, ValueError)
    assert e.status == status, (e.status, status)
    assert e.reason == status.reason and status.reason in str(e) and status.c_name in str(e)
    return e


def test_every_error_status() -> None:
    nan, inf = math.nan, math.inf
    raises(Status.ERR_NONFINITE, pgloss.contrast_gloss, nan, 0.1)
    raises(Status.ERR_NONFINITE, pgloss.lightness_from_luminance, inf)
    raises(Status.ERR_NEGATIVE, pgloss.contrast_gloss, 0.1, -0.1)
    raises(Status.ERR_ALPHA, pgloss.gloss_from_physical, 0.1, 0.1, 0.0)
    raises(Status.ERR_ALPHA, pgloss.physical_from_gloss, 50.0, 0.05, 1.0)
    raises(Status.ERR_LIGHTNESS, pgloss.envelope_contrast, 100.5)
    raises(Status.ERR_LIGHTNESS, pgloss.luminance_from_lightness, -1.0)
    raises(Status.ERR_ARGUMENT, pgloss.isogloss_contour, 0.087, 0.93, 0.04, 0)
    raises(Status.ERR_NEGATIVE, pgloss.isogloss_contour, 0.087, 0.93, -0.04, 8)
    # ENVELOPE: white paint with the black paint's gloss; the matched values come with the error.
    e = raises(Status.ERR_ENVELOPE, pgloss.match_gloss, 0.03, 0.5, 99.0)
    rd, rs = e.result
    assert rd + rs > 1 and math.isfinite(rs)
    # GAMUT: a saturated colour; the exact (negative) RGB comes with the error.
    e = raises(Status.ERR_GAMUT, pgloss.rgb_from_lab, [50.0, 120.0, 0.0])
    assert e.result.min() < 0
    e = raises(Status.ERR_GAMUT, Perceptual(50.0, 120.0, 0.0, 0.05, 0.95).to_physical)
    assert min(e.result.rho_d) < 0
    # Material errors (on use: a Physical is a record).
    raises(Status.ERR_NEGATIVE, Physical(-0.1, 0.05, 0.1).material)
    raises(Status.ERR_ALPHA, pgloss.eval, Physical(0.1, 0.05, 0.0), [0, 0, 1], [0, 0, 1])
    raises(Status.ERR_NONFINITE, pgloss.material_init, Physical(0.1, nan, 0.1))
    raises(Status.ERR_NORMALIZATION, Physical(0.1, 0.05, 0.1, normalization=7).material)
    raises(Status.ERR_NORMALIZATION, Physical, 0.1, 0.05, 0.1, normalization=2**40)
    raises(Status.ERR_NORMALIZATION, Perceptual(50, 0, 0, 0.05, 0.95).to_physical, 5)
    # BRDF
    e = raises(Status.ERR_DIRECTION, pgloss.eval, GREY, [0, 0, 0], [0, 0, 1])
    assert e.index is None and not e.result.any()  # the documented fallback: 0
    raises(Status.ERR_DIRECTION, pgloss.pdf, GREY, [0, 0, 1], [nan, 0, 1])
    raises(Status.ERR_RANDOM, pgloss.sample, GREY, [0, 0, 1], [0.5, nan, 0.5])
    # The report statuses (not exceptions): ENERGY, ENVELOPE, GAMUT, warnings.
    assert Physical(0.9, 0.2, 0.1).check() == Status.ERR_ENERGY
    assert Physical(0.5, 0.2, 0.3).check() == Status.WARN_ALPHA_UNTRUSTED
    assert GREY.check() == Status.OK
    assert Perceptual(95.0, 0, 0, 0.5, 0.95).check() == Status.ERR_ENVELOPE
    assert Perceptual(50.0, 120.0, 0, 0.05, 0.95).check() == Status.ERR_GAMUT
    # NULL is the only status Python cannot produce: there are no pointers.
    assert Status.ERR_NULL.reason == pgloss.status_string(-1)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_error_index_in_arrays(dtype) -> None:
    wo = np.tile(np.array([0, 0, 1], dtype=dtype), (3, 4, 1))
    wi = wo.copy()
    wi[1, 2] = [0, 0, 0]
    wi[2, 0] = [np.inf, 0, 1]
    e = raises(Status.ERR_DIRECTION, pgloss.eval, GREY, wo, wi)
    assert e.index == (1, 2)
    f = e.result  # the other elements are computed normally
    assert f.shape == (3, 4, 3) and not f[1, 2].any() and f[0, 0, 0] > 0 and np.isfinite(f).all()
    # a failure in a later chunk of the batched path is located too
    big = np.tile(np.array([0, 0.1, 1], dtype=dtype), (5000, 1))
    bad = big.copy()
    bad[4321] = [np.nan, 0, 1]
    assert raises(Status.ERR_DIRECTION, pgloss.pdf, GREY, big, bad).index == (4321,)
    u = np.full((5000, 3), 0.5, dtype=dtype)
    u[3000, 1] = np.nan
    assert raises(Status.ERR_RANDOM, pgloss.sample, GREY, big, u).index == (3000,)
    e = raises(Status.ERR_NEGATIVE, pgloss.contrast_gloss, [[0.1, 0.2], [0.3, -0.4]], 0.1)
    assert e.index == (1, 1) and e.result.shape == (2, 2)


def test_warnings() -> None:
    assert issubclass(pgloss.AlphaUntrustedWarning, pgloss.PglossWarning)
    assert issubclass(pgloss.PglossWarning, UserWarning)
    with pytest.warns(pgloss.AlphaUntrustedWarning, match="2 of 3 elements") as rec:
        L, c, d = pgloss.gloss_from_physical(0.2, 0.05, [0.1, 0.3, 0.5])
    assert len(rec) == 1 and np.isfinite(d).all() and d[2] == pytest.approx(0.5)
    assert Path(rec[0].filename).name == Path(__file__).name  # points at the caller's line
    with pytest.warns(pgloss.AlphaUntrustedWarning):
        Physical(0.2, 0.05, 0.3).to_perceptual()
    with pytest.warns(pgloss.AlphaUntrustedWarning):
        Perceptual(50, 0, 0, 0.05, 0.7).to_physical()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pgloss.gloss_from_physical(0.2, 0.05, 0.2)  # α = 0.2 is trusted
        pgloss.eval(Physical(0.2, 0.05, 0.5), [0, 0, 1], [0, 0, 1])  # a renderer may use any α


# ------------------------------------------------------------------------------------------------
# Odd arrays: never a crash, never a silent NaN.

@pytest.mark.parametrize("bad", [np.zeros(4), np.zeros((2, 2)), np.zeros(()), 1.0, [[0, 0, 1, 0]]])
def test_wrong_shape(bad) -> None:
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        pgloss.eval(GREY, bad, [0, 0, 1])
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        pgloss.sample(GREY, [0, 0, 1], bad)
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        pgloss.rgb_from_lab(bad)


@pytest.mark.parametrize("bad", [np.array([0, 0, 1j]), np.array(["a", "b", "c"]), np.array([None, 0, 1]),
                                 [[0, 0, 1], [0, 1]], "xyz"])
def test_wrong_dtype(bad) -> None:
    with pytest.raises(TypeError):
        pgloss.eval(GREY, bad, [0, 0, 1])
    with pytest.raises(TypeError):
        pgloss.luminance(bad)
    with pytest.raises(TypeError):
        pgloss.contrast_gloss(bad, 0.1)


def test_wrong_argument_types() -> None:
    with pytest.raises(TypeError, match="Physical or pgloss.Material"):
        pgloss.eval(None, [0, 0, 1], [0, 0, 1])
    with pytest.raises(TypeError, match="lobes"):
        pgloss.eval(GREY, [0, 0, 1], [0, 0, 1], 1.5)
    with pytest.raises(ValueError, match="lobes"):
        pgloss.eval(GREY, [0, 0, 1], [0, 0, 1], -1)
    with pytest.raises(TypeError, match="normalization"):
        Physical(0.1, 0.1, 0.1, normalization="ward")
    with pytest.raises(TypeError):
        Physical(0.1, "x", 0.1)
    with pytest.raises(ValueError, match="rho_d"):
        Physical([0.1, 0.2], 0.1, 0.1)
    with pytest.raises(TypeError, match="alpha"):
        Physical(0.1, 0.1)
    with pytest.raises(TypeError, match="not both"):
        Physical(0.1, 0.1, 0.1, alpha_x=0.2)
    with pytest.raises(TypeError):
        pgloss.check_physical("paint")
    with pytest.raises(TypeError):
        pgloss.isogloss_contour(0.1, 0.9, 0.04, 2.5)
    with pytest.raises(ValueError):
        pgloss.isogloss_contour(0.1, 0.9, 0.04, -3)
    # undefined lobe bits are allowed (C unsigned mask), as in the vectors
    np.testing.assert_array_equal(pgloss.eval(GREY, [0, 0, 1], [0, 0, 1], 0xFFFFFFFF), pgloss.eval(GREY, [0, 0, 1], [0, 0, 1]))


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_non_contiguous_and_read_only(dtype) -> None:
    rng = np.random.default_rng(8)
    wo, wi = random_dirs(rng, 200, dtype), random_dirs(rng, 200, dtype)
    want_f, want_p = pgloss.eval_pdf(GREY, wo, wi)
    # strided rows, Fortran order, a transposed view, a reversed view
    big = np.zeros((400, 6), dtype=dtype)
    big[::2, 1::2] = wo
    strided = big[::2, 1::2]
    assert not strided.flags.c_contiguous
    fortran = np.asfortranarray(wi)
    transposed = np.ascontiguousarray(wo.T).T
    f1, p1 = pgloss.eval_pdf(GREY, strided, fortran)
    np.testing.assert_array_equal(f1, want_f)
    np.testing.assert_array_equal(p1, want_p)
    np.testing.assert_array_equal(pgloss.eval(GREY, transposed, wi), want_f)
    np.testing.assert_array_equal(pgloss.eval(GREY, wo[::-1], wi[::-1]), want_f[::-1])
    # read-only inputs, and inputs are never written
    ro_o, ro_i = wo.copy(), wi.copy()
    ro_o.flags.writeable = False
    ro_i.flags.writeable = False
    np.testing.assert_array_equal(pgloss.eval(GREY, ro_o, ro_i), want_f)
    np.testing.assert_array_equal(ro_o, wo)
    u = rng.random((200, 3)).astype(dtype)
    u.flags.writeable = False
    s = pgloss.sample(GREY, ro_o, u)
    assert s.wi.flags.writeable  # outputs are fresh arrays
    lab = np.asfortranarray(np.tile([50.0, 10.0, -5.0], (10, 1)))[:, :]
    lab.flags.writeable = False
    assert pgloss.rgb_from_lab(lab).shape == (10, 3)


def test_empty_arrays() -> None:
    assert pgloss.eval(GREY, np.zeros((0, 3)), np.zeros((0, 3))).shape == (0, 3)
    assert pgloss.pdf(GREY, np.zeros((0, 3), np.float32), [0, 0, 1]).shape == (0,)
    assert pgloss.sample(GREY, np.zeros((2, 0, 3)), [0.5, 0.5, 0.5]).pdf.shape == (2, 0)
    assert pgloss.contrast_gloss(np.zeros(0), 0.1).shape == (0,)
    assert pgloss.luminance(np.zeros((0, 3))).shape == (0,)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_extreme_finite_inputs_give_finite_outputs(dtype) -> None:
    rng = np.random.default_rng(9)
    scale = 10.0 ** rng.uniform(-30, 30, size=(3000, 1))
    wo = (random_dirs(rng, 3000, upper=False) * scale).astype(dtype)
    wi = (random_dirs(rng, 3000, upper=False) * scale[::-1]).astype(dtype)
    for m in (Physical(0.5, 0.5, 1e-6), Physical(0.1, 0.9, 0.9, normalization=Normalization.WARD_DUR),
              Physical(0.1, 0.9, 0.01, normalization=Normalization.BOUNDED)):
        f, p = pgloss.eval_pdf(m, wo, wi)
        assert np.isfinite(f).all() and np.isfinite(p).all() and (f >= 0).all() and (p >= 0).all()
        s = pgloss.sample(m, wo, rng.uniform(-1, 2, (3000, 3)).astype(dtype))
        assert all(np.isfinite(x).all() for x in (s.wi, s.pdf, s.weight))


# ------------------------------------------------------------------------------------------------
# Parameter objects, pickling.

def test_physical_and_perceptual_objects() -> None:
    p = Physical((0.5, 0.3, 0.1), 0.05, alpha_x=0.05, alpha_y=0.2, normalization=Normalization.BOUNDED)
    assert p.rho_d == (0.5, 0.3, 0.1) and not p.is_isotropic
    assert p.alpha == pytest.approx(math.sqrt(0.05 * 0.2))
    assert p.normalization is Normalization.BOUNDED
    assert p.replace(alpha=0.1) == Physical((0.5, 0.3, 0.1), 0.05, 0.1, normalization=2)
    assert p.replace(rho_s=0.07).rho_s == 0.07 and p.replace(rho_s=0.07).alpha_y == 0.2
    env = {"Physical": Physical, "Perceptual": Perceptual, "Normalization": Normalization}
    assert eval(repr(p), env) == p and eval(repr(GREY), env) == GREY  # noqa: S307 - repr round trip
    q = Perceptual.achromatic(50.0, 0.05, 0.95)
    assert eval(repr(q), env) == q and q.replace(c=0.06).c == 0.06
    assert q.distance(q.replace(c=0.09)) == pytest.approx(0.04)
    assert hash(q) == hash(Perceptual(50.0, 0.0, 0.0, 0.05, 0.95)) and q != GREY
    # conversions round trip: perceptual → physical → perceptual (the second paint's blue channel
    # of ρd plus ρs exceeds 1: ENERGY, converted all the same with check=False)
    assert Perceptual(80, -10, -30, 0.02, 0.9).check() == Status.ERR_ENERGY
    for q in (Perceptual(35, 45, 25, 0.06, 0.95), Perceptual(80, -10, -30, 0.02, 0.9), q):
        back = q.to_physical(check=False).to_perceptual(check=False)
        for a, b in zip((back.L, back.a, back.b, back.c, back.d), (q.L, q.a, q.b, q.c, q.d)):
            assert a == pytest.approx(b, abs=1e-9)
    assert pgloss.physical_from_perceptual(q, Normalization.WARD_DUR).normalization is Normalization.WARD_DUR
    m = GREY.material()
    assert m is GREY.material()  # cached
    assert m.rho_d == (np.float32(0.193),) * 3 and m.lobes == 3 and m.alpha_x == np.float32(0.07)
    assert "Material(" in repr(m)


def test_pickling() -> None:
    objs = [GREY, Physical((0.5, 0.3, 0.1), 0.05, alpha_x=0.05, alpha_y=0.2, normalization=2),
            Physical(0.1, 0.1, 0.1, normalization=9), Perceptual(35, 45, 25, 0.06, 0.95), GREY.material(),
            Lobe.DIFFUSE, Normalization.WARD_DUR, Status.ERR_GAMUT]
    for o in objs:
        for proto in (2, pickle.HIGHEST_PROTOCOL):
            back = pickle.loads(pickle.dumps(o, proto))
            assert back == o and type(back) is type(o)
    m2 = pickle.loads(pickle.dumps(GREY.material()))
    np.testing.assert_array_equal(pgloss.eval(m2, [0, 0.3, 1], [0, -0.3, 1]), pgloss.eval(GREY, [0, 0.3, 1], [0, -0.3, 1]))
    try:
        pgloss.contrast_gloss([0.1, -1.0], 0.1)
    except PglossError as e:
        back = pickle.loads(pickle.dumps(e))
        assert back.status == e.status and back.index == (1,) and str(back) == str(e)


# ------------------------------------------------------------------------------------------------
# Threads: the GIL is released in the loops; concurrent calls give identical results.

def test_thread_pool_identical_results() -> None:
    rng = np.random.default_rng(10)
    n = 200_000
    wo32, wi32 = random_dirs(rng, n, np.float32), random_dirs(rng, n, np.float32)
    wo64, u = wo32.astype(np.float64), rng.random((n, 3)).astype(np.float32)
    mats = [GREY, Physical((0.5, 0.3, 0.1), 0.05, alpha_x=0.05, alpha_y=0.2, normalization=2)]
    L = rng.uniform(0, 100, n)
    jobs = []
    for m in mats:
        jobs += [lambda m=m: pgloss.eval_pdf(m, wo32, wi32), lambda m=m: pgloss.eval(m, wo64[:20000], wi32[:20000]),
                 lambda m=m: pgloss.sample(m, wo32, u)]
    jobs += [lambda: pgloss.envelope_contrast(L), lambda: pgloss.physical_from_gloss(L, 0.05, 0.95, errors="status")]
    reference = [job() for job in jobs]

    def flat(r):
        return [np.asarray(x) for x in (r if isinstance(r, tuple) else (r,))]

    with ThreadPoolExecutor(max_workers=8) as pool:
        futures = [(k, pool.submit(jobs[k])) for _ in range(4) for k in range(len(jobs))]
        for k, fut in futures:
            for a, b in zip(flat(fut.result()), flat(reference[k])):
                np.testing.assert_array_equal(a, b)


# ------------------------------------------------------------------------------------------------
# Documentation and stubs.

def test_docstrings_and_help() -> None:
    for name in pgloss.__all__:
        obj = getattr(pgloss, name)
        if callable(obj) or isinstance(obj, type):
            assert obj.__doc__ and len(obj.__doc__.strip()) > 20, f"{name} lacks a docstring"
    text = pydoc.render_doc(pgloss.eval, renderer=pydoc.plaintext)
    for part in ("eval(material", "Parameters", "wo, wi", "(..., 3)", "Returns", "float32", "float64", "Raises",
                 "PglossError", "Examples"):
        assert part in text, part
    assert "eq. 2" in text


def test_docstring_examples() -> None:
    """The examples in the docstrings run and print what they say: the package's modules (its
    classes are pgloss.X, found from the package; its functions from their modules)."""
    import doctest
    import importlib

    import pgloss.__main__ as main_module

    modules = [pgloss, main_module] + [importlib.import_module(f"pgloss.{p.stem}")
                                       for p in sorted(Path(pgloss.__file__).parent.glob("_[a-z]*.py"))]
    attempted = 0
    for module in modules:
        result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE, raise_on_error=False)
        assert result.failed == 0, f"{module.__name__}: {result.failed} docstring examples failed"
        attempted += result.attempted
    assert attempted >= 20
