# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""One paint, one verdict: every conversion of the package judges a paint as the C core's checks
do (``check_perceptual``, ``check_physical``), as the C tool does, unless ``check=False`` asks
for the bare conversion; ``gloss_distance`` rejects points that are no gloss (c < 0, d >= 1);
channel-last arrays (the layout of images in numpy, OpenImageIO and colour-science) go in and out
of the paint functions; ``dir(pgloss)`` lists the API, not its imports.

Expected values come from the paper's formulas written out here (CIE 1976 L* inverse, eqs. 4, 5
and 7) and from the C tool (PGLOSS_CLI, built by scripts/test-python.sh).
"""

from __future__ import annotations

import math
import os
import re
import subprocess
import warnings
from typing import List

import numpy as np
import pytest

import pgloss
from pgloss import Perceptual, Physical, PglossError, Status

C_TOOL = os.environ.get("PGLOSS_CLI", "")


def y_from_lightness(L: float) -> float:
    """CIE 1976: Y = ((L + 16) / 116)³ above L = 8, else L / κ."""
    return ((L + 16) / 116) ** 3 if L > 8 else L * 27 / 24389


def specular(rho_d: float, c: float) -> float:
    """Eq. 7: ρs = (c + ∛(ρd/2))³ − ρd/2."""
    return (c + (rho_d / 2) ** (1 / 3)) ** 3 - rho_d / 2


def contrast(rho_d: float, rho_s: float) -> float:
    """Eq. 4: c = ∛(ρs + ρd/2) − ∛(ρd/2)."""
    return (rho_s + rho_d / 2) ** (1 / 3) - (rho_d / 2) ** (1 / 3)


def quiet(fn):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pgloss.AlphaUntrustedWarning)
        return fn()


# ------------------------------------------------------------------------------------------------
# The same paint gets the same verdict everywhere.

BRIGHT_AND_GLOSSY = Perceptual(L=95.0, a=0.0, b=0.0, c=0.3, d=0.95)  # ρd + ρs = 0.876 + 0.751


def test_to_physical_beyond_the_envelope_is_an_error() -> None:
    rho_d = y_from_lightness(95.0)
    rho_s = specular(rho_d, 0.3)
    assert round(rho_d, 3) == 0.876 and round(rho_s, 3) == 0.751 and rho_d + rho_s > 1
    for convert in (BRIGHT_AND_GLOSSY.to_physical, lambda: pgloss.physical_from_perceptual(BRIGHT_AND_GLOSSY)):
        with pytest.raises(PglossError) as e:
            convert()
        assert e.value.status == Status.ERR_ENVELOPE
        p = e.value.result  # the computed paint, as for GAMUT
        assert p.rho_d == pytest.approx((rho_d,) * 3, rel=1e-12) and p.rho_s == pytest.approx(rho_s, rel=1e-12)
    p, st = BRIGHT_AND_GLOSSY.to_physical(errors="status")
    assert st == Status.ERR_ENVELOPE and p.rho_s == pytest.approx(rho_s, rel=1e-12)
    assert BRIGHT_AND_GLOSSY.check() == Status.ERR_ENVELOPE
    # The bare conversion (pgloss_physical_from_perceptual's own checks) is there when asked for.
    assert BRIGHT_AND_GLOSSY.to_physical(check=False).rho_s == pytest.approx(rho_s, rel=1e-12)


def test_the_siblings_judge_as_the_checks() -> None:
    # The grey conversions (L, c, d) <-> (ρd, ρs, α).
    with pytest.raises(PglossError) as e:
        pgloss.physical_from_gloss(95.0, 0.3, 0.95)
    assert e.value.status == Status.ERR_ENVELOPE
    assert e.value.result[1] == pytest.approx(specular(y_from_lightness(95.0), 0.3), rel=1e-12)
    assert pgloss.physical_from_gloss(95.0, 0.3, 0.95, check=False)[1] == pytest.approx(e.value.result[1])
    with pytest.raises(PglossError) as e:
        pgloss.gloss_from_physical(0.9, 0.3, 0.07)  # ρd + ρs = 1.2
    assert e.value.status == Status.ERR_ENERGY
    assert e.value.result[1] == pytest.approx(contrast(0.9, 0.3), rel=1e-12)
    assert pgloss.gloss_from_physical(0.9, 0.3, 0.07, check=False)[1] == pytest.approx(contrast(0.9, 0.3), rel=1e-12)
    # Physical → Perceptual: ENERGY and an unknown normalisation, as check_physical says.
    for p, status in [(Physical(0.9, 0.3, 0.07), Status.ERR_ENERGY),
                      (Physical(0.2, 0.05, 0.07, normalization=7), Status.ERR_NORMALIZATION)]:
        assert p.check() == status
        with pytest.raises(PglossError) as e:
            p.to_perceptual()
        assert e.value.status == status
        assert pgloss.perceptual_from_physical(p, errors="status")[1] == status
        assert p.to_perceptual(check=False).c == pytest.approx(contrast(p.rho_d[0], p.rho_s), rel=1e-12)
    # Arrays: the status of every element is the merged verdict, in element order.
    q = Perceptual(L=[50.0, 95.0, 120.0, 50.0], a=0.0, b=0.0, c=[0.05, 0.3, 0.05, 0.05], d=[0.95, 0.95, 0.95, 0.7])
    _, st = q.to_physical(errors="status")
    assert st.tolist() == [Status.OK, Status.ERR_ENVELOPE, Status.ERR_LIGHTNESS, Status.WARN_ALPHA_UNTRUSTED]
    assert st.tolist() == q.check().tolist()
    with pytest.raises(PglossError) as e:
        q.to_physical()
    assert e.value.index == (1,) and e.value.status_array.tolist() == st.tolist()


def c_tool_status(*args: str) -> str:
    """The status name the C tool reports (PGLOSS_OK when it names none)."""
    r = subprocess.run([C_TOOL, *args], capture_output=True, text=True, timeout=30)
    m = re.search(r"PGLOSS_(?:ERR|WARN)_[A-Z_]+", r.stdout + r.stderr)
    return m.group(0) if m else "PGLOSS_OK"


@pytest.mark.skipif(not C_TOOL, reason="PGLOSS_CLI (the C tool) not set: scripts/test-python.sh builds it")
def test_the_c_tool_gives_the_same_verdicts() -> None:
    paints = [(50, 0, 0, 0.05, 0.95), (95, 0, 0, 0.3, 0.95), (95, 0, 0, 0.5, 0.95), (35, 45, 25, 0.06, 0.95),
              (50, 120, 0, 0.05, 0.95), (50, 0, 0, 0.05, 0.7), (120, 0, 0, 0.05, 0.95), (50, 0, 0, -0.01, 0.95),
              (50, 0, 0, 0.05, 1.0), (60, 60, 60, 0.2, 0.9), (99, 0, 0, 0.02, 0.9), (8, -30, 40, 0.1, 0.85)]
    for v in paints:
        want = c_tool_status("to-physical", *map(str, v))
        got = quiet(lambda: Perceptual(*v).to_physical(errors="status"))[1]
        assert got.c_name == want, (v, got.c_name, want)
        L, a, b, c, d = v
        if a == 0 and b == 0:  # the grey conversion of the same paint
            got = quiet(lambda: pgloss.physical_from_gloss(L, c, d, errors="status"))[1]
            assert got.c_name == want, (v, got.c_name, want)
    for rho_d, rho_s, alpha in [(0.193, 0.066, 0.07), (0.9, 0.3, 0.07), (0.2, 0.05, 0.3), (-0.2, 0.05, 0.1),
                                (0.6, 0.4, 0.05), (0.7, 0.31, 0.05)]:
        want = c_tool_status("to-perceptual", str(rho_d), str(rho_s), str(alpha))
        got = quiet(lambda: Physical(rho_d, rho_s, alpha).to_perceptual(errors="status"))[1]
        assert got.c_name == want, (rho_d, rho_s, alpha, got.c_name, want)
        got = quiet(lambda: pgloss.gloss_from_physical(rho_d, rho_s, alpha, errors="status"))[1]
        assert got.c_name == want, (rho_d, rho_s, alpha, got.c_name, want)


# ------------------------------------------------------------------------------------------------
# gloss_distance and the paints' distance.

def test_gloss_distance_rejects_what_is_no_gloss() -> None:
    for args, status in [((0.05, 1.5, 0.05, 0.95), Status.ERR_ALPHA), ((0.05, 0.95, 0.05, 1.0), Status.ERR_ALPHA),
                         ((-0.1, 0.9, 0.1, 0.9), Status.ERR_NEGATIVE), ((0.1, 0.9, -1e-300, 0.9), Status.ERR_NEGATIVE)]:
        with pytest.raises(PglossError) as e:
            pgloss.gloss_distance(*args)
        assert e.value.status == status, args
        # Eq. 5 on any point of the plane when asked for (pgloss_gloss_distance itself).
        c1, d1, c2, d2 = args
        assert pgloss.gloss_distance(*args, check=False) == pytest.approx(math.hypot(c1 - c2, 1.78 * (d1 - d2)))
    D, st = pgloss.gloss_distance([0.05, -0.1, 0.05, 0.1], [0.9, 0.9, 1.2, 0.7], 0.05, 0.93, errors="status")
    assert st.tolist() == [Status.OK, Status.ERR_NEGATIVE, Status.ERR_ALPHA, Status.WARN_ALPHA_UNTRUSTED]
    assert D[0] == pytest.approx(1.78 * 0.03, rel=1e-12)
    with pytest.warns(pgloss.AlphaUntrustedWarning):
        pgloss.gloss_distance(0.1, 0.7, 0.1, 0.9)


def test_physical_has_the_distance_of_its_gloss() -> None:
    grey = Physical(0.193, 0.066, 0.07)       # Fig. 11's reference, c = 0.087, d = 0.93
    white = Physical(0.767, 0.099, 0.04)      # Fig. 12's white paint
    want = math.hypot(contrast(0.193, 0.066) - contrast(0.767, 0.099), 1.78 * ((1 - 0.07) - (1 - 0.04)))
    assert grey.distance(white) == pytest.approx(want, rel=1e-12)
    assert grey.distance(white.to_perceptual()) == pytest.approx(want, rel=1e-12)
    assert grey.to_perceptual().distance(white) == pytest.approx(want, rel=1e-12)
    assert grey.distance(grey) == 0.0
    texture = Physical(0.193, [0.066, 0.033], 0.07)
    assert texture.distance(grey).tolist() == pytest.approx([0.0, contrast(0.193, 0.066) - contrast(0.193, 0.033)])
    with pytest.raises(PglossError) as e:
        grey.distance(Physical(0.9, 0.3, 0.07))  # outside the model: no gloss to compare
    assert e.value.status == Status.ERR_ENERGY
    with pytest.raises(TypeError):
        grey.distance((0.1, 0.9))  # type: ignore[arg-type]


# ------------------------------------------------------------------------------------------------
# Channel-last arrays in and out.

def image_of_paints(h: int = 4, w: int = 5) -> np.ndarray:
    rng = np.random.default_rng(31)
    L = rng.uniform(20, 80, (h, w))
    c = rng.uniform(0.0, 0.05, (h, w))
    d = rng.uniform(0.85, 0.99, (h, w))
    ab = rng.uniform(-10, 10, (h, w, 2))
    return np.stack([L, ab[..., 0], ab[..., 1], c, d], axis=-1)


def test_physical_from_perceptual_takes_and_gives_channel_last_images() -> None:
    img = image_of_paints()
    out = pgloss.physical_from_perceptual(img)
    assert isinstance(out, np.ndarray) and out.shape == (4, 5, 6) and out.dtype == np.float64
    # Texel by texel, what one paint gives; αx = αy = 1 - d (eq. 8); grey texels' ρd from L* alone.
    for i, j in [(0, 0), (3, 4), (2, 1)]:
        np.testing.assert_array_equal(out[i, j], Perceptual(*img[i, j]).to_physical().to_array())
        assert out[i, j, 4] == out[i, j, 5] == pytest.approx(1 - img[i, j, 4], abs=1e-15)
        assert out[i, j, 3] == pytest.approx(specular(y_from_lightness(img[i, j, 0]), img[i, j, 3]), rel=1e-12)
    grey = pgloss.physical_from_perceptual([50.0, 0.0, 0.0, 0.05, 0.95])
    assert grey.shape == (6,) and grey[0:3] == pytest.approx([y_from_lightness(50.0)] * 3, rel=1e-6)
    # float32 in, float32 out; the paint types' own pair reads and writes the same layout.
    out32 = pgloss.physical_from_perceptual(img.astype(np.float32))
    assert out32.dtype == np.float32 and out32.shape == (4, 5, 6)
    np.testing.assert_array_equal(Perceptual.from_array(img).to_physical().to_array(), out)
    back = pgloss.perceptual_from_physical(out)
    assert back.shape == (4, 5, 5)
    np.testing.assert_allclose(back, img, rtol=1e-9, atol=1e-9)
    st = pgloss.check_perceptual(img)
    assert st.shape == (4, 5) and (st == 0).all()
    assert pgloss.check_physical(out).shape == (4, 5)
    # errors="status" and the exception's result keep the layout.
    bad = img.copy()
    bad[1, 2, 0] = 120.0
    arr, st = pgloss.physical_from_perceptual(bad, errors="status")
    assert arr.shape == (4, 5, 6) and st[1, 2] == Status.ERR_LIGHTNESS and np.count_nonzero(st) == 1
    with pytest.raises(PglossError) as e:
        pgloss.physical_from_perceptual(bad)
    assert e.value.index == (1, 2) and e.value.result.shape == (4, 5, 6)


def test_to_array_and_from_array_round_trip() -> None:
    img = image_of_paints()
    q = Perceptual.from_array(img)
    assert q.shape == (4, 5) and q.L[1, 2] == img[1, 2, 0] and q.d[3, 4] == img[3, 4, 4]
    np.testing.assert_array_equal(q.to_array(), img)
    assert Perceptual.from_array(img[0, 0]) == Perceptual(*img[0, 0]) and not Perceptual.from_array(img[0, 0]).is_array
    np.testing.assert_array_equal(Perceptual(50.0, 1.0, 2.0, 0.05, 0.9).to_array(), [50.0, 1.0, 2.0, 0.05, 0.9])
    tex = np.concatenate([np.full((4, 5, 3), 0.2), np.full((4, 5, 1), 0.05), np.full((4, 5, 1), 0.1),
                          np.full((4, 5, 1), 0.2)], axis=-1)
    tex[0, 0, 0] = 0.3
    p = Physical.from_array(tex, normalization=pgloss.Normalization.BOUNDED)
    assert p.shape == (4, 5) and p.normalization == pgloss.Normalization.BOUNDED
    assert p.rho_d[0, 0].tolist() == [0.3, 0.2, 0.2] and p.alpha_x[1, 1] == 0.1 and p.alpha_y[1, 1] == 0.2
    np.testing.assert_array_equal(p.to_array(), tex)
    assert Physical.from_array(tex[0, 0]) == Physical((0.3, 0.2, 0.2), 0.05, alpha_x=0.1, alpha_y=0.2)
    np.testing.assert_array_equal(Physical(0.193, 0.066, 0.07).to_array(), [0.193, 0.193, 0.193, 0.066, 0.07, 0.07])


def test_brdf_takes_a_channel_last_material_array() -> None:
    rng = np.random.default_rng(5)
    tex = np.concatenate([rng.uniform(0, 0.5, (8, 3)), rng.uniform(0, 0.3, (8, 1)), rng.uniform(0.02, 0.2, (8, 1)),
                          rng.uniform(0.02, 0.2, (8, 1))], axis=-1)
    wo, wi = np.array([0.1, 0.2, 0.9]), np.array([-0.3, 0.1, 0.8])
    np.testing.assert_array_equal(pgloss.eval(tex, wo, wi), pgloss.eval(Physical.from_array(tex), wo, wi))
    np.testing.assert_array_equal(pgloss.eval(tex[3], wo, wi), pgloss.eval(Physical.from_array(tex[3]), wo, wi))


def test_wrong_channel_counts_and_types_name_what_was_expected() -> None:
    with pytest.raises(ValueError, match=r"\(\.\.\., 5\), got \(4, 6\)"):
        pgloss.physical_from_perceptual(np.zeros((4, 6)))
    with pytest.raises(ValueError, match=r"\(\.\.\., 6\), got \(4, 5\)"):
        Physical.from_array(np.zeros((4, 5)))
    with pytest.raises(TypeError, match="expected a pgloss.Perceptual or an array"):
        pgloss.physical_from_perceptual(Physical(0.2, 0.05, 0.1))
    with pytest.raises(TypeError, match="expected a pgloss.Physical or an array"):
        pgloss.perceptual_from_physical(BRIGHT_AND_GLOSSY)
    with pytest.raises(TypeError, match="real numbers"):
        pgloss.check_perceptual(np.array(["a"] * 5))


# ------------------------------------------------------------------------------------------------
# The namespace.

def test_dir_lists_the_api_and_not_its_imports() -> None:
    names = set(dir(pgloss))
    assert not names & {"np", "os", "List", "Any", "Optional", "Tuple", "Union", "enum", "math", "warnings",
                        "operator", "annotations"}
    public = {n for n in names if not n.startswith("_")}
    subpackages = {"experiment", "psychophysics", "cli", "glossmeter", "bridge"}  # modules, once imported
    assert public - subpackages == set(pgloss.__all__) - {"__version__"}
    assert len(pgloss.__all__) == len(set(pgloss.__all__))
    for name in pgloss.__all__:
        obj = getattr(pgloss, name)
        if isinstance(obj, type) or callable(obj):
            assert obj.__module__ in ("pgloss", "pgloss._core"), (name, obj.__module__)
