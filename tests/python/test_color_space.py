# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Working colour spaces against a peer: colour-science's CIELAB and RGB colourspaces.

pgloss derives its matrices from the primaries and whites (tests/vectors/generate.py); colour
derives its own from the same published primaries and whites, and adapts ACEScg's ACES white
from D65 with its own Bradford implementation. Agreement to 1e-12 (absolute, on values of
order 1) checks the primaries, the whites, the direction of the adaptation and the CIELAB
formulas at once. colour-science is a test-only dependency (pinned in scripts/test-python.sh).
"""
from __future__ import annotations

from typing import Tuple

import numpy as np
import pytest

import pgloss
from pgloss import ColorSpace

colour = pytest.importorskip("colour", reason="colour-science is the peer of the working-space tests")

D65 = np.array([0.3127, 0.3290])
# pgloss space -> colour's colourspace (whites: D65 except ACEScg's ACES white 0.32168, 0.33767).
PEERS = {
    ColorSpace.LINEAR_REC709: "ITU-R BT.709",
    ColorSpace.ACESCG: "ACEScg",
    ColorSpace.LINEAR_DISPLAY_P3: "Display P3",
    ColorSpace.LINEAR_REC2020: "ITU-R BT.2020",
}
TOL = 1e-12


def _peer(space: ColorSpace):
    cs = colour.RGB_COLOURSPACES[PEERS[space]]
    return cs


def _labs(space: ColorSpace, n: int = 200) -> np.ndarray:
    """In-gamut L*a*b* (from random linear RGB of the space, via the peer) plus neutrals."""
    rng = np.random.default_rng(2000 + int(space))
    rgb = rng.uniform(0.0, 1.0, (n, 3))
    rgb[: n // 5] *= 0.005  # dark: the linear branch of CIELAB
    xyz = colour.RGB_to_XYZ(rgb, _peer(space), illuminant=D65, chromatic_adaptation_transform="Bradford")
    lab = colour.XYZ_to_Lab(xyz, illuminant=D65)
    grey = np.stack([np.linspace(0.0, 100.0, 11), np.zeros(11), np.zeros(11)], axis=-1)
    return np.concatenate([lab, grey])


def test_peer_whites_and_primaries_are_the_documented_ones() -> None:
    np.testing.assert_array_equal(_peer(ColorSpace.ACESCG).whitepoint, [0.32168, 0.33767])
    for s in (ColorSpace.LINEAR_REC709, ColorSpace.LINEAR_DISPLAY_P3, ColorSpace.LINEAR_REC2020):
        np.testing.assert_array_equal(_peer(s).whitepoint, D65)
    np.testing.assert_array_equal(_peer(ColorSpace.ACESCG).primaries, [[0.713, 0.293], [0.165, 0.830], [0.128, 0.044]])


@pytest.mark.parametrize("space", list(ColorSpace))
def test_rgb_from_lab_matches_colour(space: ColorSpace) -> None:
    lab = _labs(space)
    xyz = colour.Lab_to_XYZ(lab, illuminant=D65)
    want = colour.XYZ_to_RGB(xyz, _peer(space), illuminant=D65, chromatic_adaptation_transform="Bradford")
    got = pgloss.rgb_from_lab(lab, space)
    np.testing.assert_allclose(got, want, rtol=0, atol=TOL)


@pytest.mark.parametrize("space", list(ColorSpace))
def test_lab_from_rgb_and_luminance_match_colour(space: ColorSpace) -> None:
    rng = np.random.default_rng(3000 + int(space))
    rgb = rng.uniform(0.0, 1.0, (200, 3))
    rgb[:40] *= 0.005
    xyz = colour.RGB_to_XYZ(rgb, _peer(space), illuminant=D65, chromatic_adaptation_transform="Bradford")
    np.testing.assert_allclose(pgloss.luminance(rgb, space), xyz[:, 1], rtol=0, atol=TOL)
    np.testing.assert_allclose(pgloss.lab_from_rgb(rgb, space), colour.XYZ_to_Lab(xyz, illuminant=D65),
                               rtol=0, atol=100 * TOL)  # L*a*b* is on a 0..100 scale


@pytest.mark.parametrize("space", list(ColorSpace))
def test_luminance_and_gloss_do_not_depend_on_the_space(space: ColorSpace) -> None:
    """Y of ρd is f⁻¹(L*) in every space, so ρs (eq. 7) and α are the same; neutral ρd is R = G = B = Y."""
    q = pgloss.Perceptual(L=62.0, a=12.0, b=-20.0, c=0.05, d=0.93)
    ref = pgloss.physical_from_perceptual(q)
    p = pgloss.physical_from_perceptual(q, space=space)
    assert p.rho_s == pytest.approx(ref.rho_s, rel=1e-15)
    assert p.alpha_x == ref.alpha_x
    Y = pgloss.luminance_from_lightness(62.0)
    assert pgloss.luminance(np.array(p.rho_d), space) == pytest.approx(Y, abs=TOL)
    back = pgloss.perceptual_from_physical(p, space=space)
    np.testing.assert_allclose([back.L, back.a, back.b, back.c, back.d], [62.0, 12.0, -20.0, 0.05, 0.93],
                               rtol=0, atol=1e-10)
    grey = pgloss.rgb_from_lab([50.0, 0.0, 0.0], space)
    np.testing.assert_allclose(grey, pgloss.luminance_from_lightness(50.0), rtol=0, atol=TOL)


def test_gamut_is_decided_in_the_working_space() -> None:
    """A P3 green outside Rec. 709: GAMUT there, inside the wider spaces."""
    lab = pgloss.lab_from_rgb([0.05, 0.6, 0.05], ColorSpace.LINEAR_DISPLAY_P3)
    q = pgloss.Perceptual(*(float(x) for x in lab), c=0.02, d=0.9)
    assert pgloss.check_perceptual(q) is pgloss.Status.ERR_GAMUT
    for s in (ColorSpace.ACESCG, ColorSpace.LINEAR_DISPLAY_P3, ColorSpace.LINEAR_REC2020):
        assert pgloss.check_perceptual(q, space=s) is pgloss.Status.OK
    with pytest.raises(pgloss.PglossError) as e:
        pgloss.rgb_from_lab(lab, 7)
    assert e.value.status is pgloss.Status.ERR_ARGUMENT
    with pytest.raises(TypeError):
        pgloss.rgb_from_lab(lab, "acescg")  # type: ignore[arg-type]
