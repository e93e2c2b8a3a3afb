# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss.glossmeter: the shared vectors' Ward readings (tests/vectors/glossmeter.json) through the
array API, broadcasting, the inverse's round trip and statuses, and the finishes."""

import json
import math
import os

import numpy as np
import pytest

import pgloss
from pgloss import glossmeter as gm

VECTORS = os.path.join(os.path.dirname(__file__), "..", "vectors", "glossmeter.json")
KIND = {"PGLOSS_GLOSS_20": gm.GLOSS_20, "PGLOSS_GLOSS_60": gm.GLOSS_60, "PGLOSS_GLOSS_85": gm.GLOSS_85,
        "PGLOSS_HAZE_20": gm.HAZE_20, "PGLOSS_DOI_30": gm.DOI_30}


def test_vectors_ward_readings():
    with open(VECTORS, encoding="utf-8") as fh:
        cases = [c for c in json.load(fh)["cases"] if c["function"] == "glossmeter_read_physical"]
    assert len(cases) >= 7
    for c in cases:
        p = c["input"]["physical"]
        paint = pgloss.Physical(p["rho_d"], p["rho_s"], alpha_x=p["alpha_x"], alpha_y=p["alpha_y"],
                                normalization=p["normalization"])
        r = gm.readings(paint, azimuth=c["input"]["azimuth_deg"], tol=1e-9)
        k = KIND[c["input"]["kind"]]
        want = c["expected"]["value"]
        assert abs(r.values[k] - want) <= r.errors[k] + c["error"] + 1e-12 * abs(want), c["id"]


def test_arrays_broadcast_and_match_scalars():
    paints = pgloss.Physical(np.repeat([[0.03], [0.193], [0.767]], 3, axis=1), 0.066, 0.07)  # three grey paints
    r = gm.readings(paints, azimuth=np.array([[0.0], [30.0]]))
    assert r.values.shape == (2, 3, 7) and r.errors.shape == (2, 3, 7) and r.status.shape == (2, 3)
    one = gm.readings(pgloss.Physical(0.193, 0.066, 0.07))
    assert one.values.shape == (7,)
    assert r.values[0, 1, gm.GLOSS_60] == pytest.approx(one.gloss_60, rel=1e-12)
    assert np.all(np.diff(r.values[0, :, gm.GLOSS_60]) > 0)  # lighter diffuse adds to the reading


def test_round_trip_and_statuses():
    paint = pgloss.Physical(0.193, 0.066, 0.04)
    r = gm.readings(paint, tol=1e-9)
    q0 = paint.to_perceptual()
    q = gm.from_gloss_units(q0.L, r.gloss_60, gloss_20=r.gloss_20)
    assert q.c == pytest.approx(q0.c, abs=2e-6) and q.d == pytest.approx(q0.d, abs=2e-6)
    qs = gm.from_gloss_units(np.array([q0.L, q0.L]), r.gloss_60, d=np.array([0.9, 0.96]))
    assert qs.c.shape == (2,) and qs.c[0] > qs.c[1]  # a blurrier lobe needs more energy for the same 60° gloss
    with pytest.raises(pgloss.PglossError) as e:
        gm.from_gloss_units(50.0, 20.0, gloss_20=90.0)
    assert e.value.status == -16 and math.isfinite(e.value.result.c)
    _, st = gm.from_gloss_units(50.0, 20.0, gloss_20=90.0, errors="status")
    assert st == -16
    with pytest.raises(ValueError):
        gm.from_gloss_units(50.0, 20.0, gloss_20=10.0, haze=3.0)
    with pytest.raises(pgloss.PglossError):
        gm.readings(pgloss.Physical(0.2, -0.1, 0.05))


def test_finishes():
    assert [f.level for f in gm.FINISHES] == [f"MPI G{k}" for k in range(1, 8)]
    satin = gm.finish("satin", L=90.0)
    assert satin.finish == "satin" and satin.c_range[0] <= satin.paint.c <= satin.c_range[1]
    assert satin.d_range == (0.90, 0.96) and satin.sheen_ok is False
    assert gm.readings(satin.paint.to_physical(), tol=1e-8).gloss_60 == pytest.approx(27.5, abs=1e-4)
    with pytest.raises(ValueError):
        gm.finish("lacquer")
    assert gm.fresnel_dielectric(1.567, 1.0) == pytest.approx(((1.567 - 1) / (1.567 + 1)) ** 2, rel=1e-14)


def _fresnel(n: float, c: float) -> float:
    """Unpolarised Fresnel reflectance from the s and p amplitudes (written here)."""
    ct = math.sqrt(1.0 - (1.0 - c * c) / (n * n))
    rs, rp = (c - n * ct) / (c + n * ct), (n * c - ct) / (n * c + ct)
    return 0.5 * (rs * rs + rp * rp)


def test_readings_bridge_arrays_and_the_smooth_limit():
    # A black OpenPBR dielectric in the smooth limit reads ISO 2813's Fresnel ratio; arrays of
    # materials broadcast, and the JSON names of pgloss bridge are accepted.
    from pgloss import bridge
    params = bridge.Params(np.zeros((2, 3)), np.array([1e-3, 0.3]), 1.5, 1.0)
    r = gm.readings_bridge("openpbr", params, tol=1e-4)
    assert r.values.shape == (2, 7) and r.status.shape == (2,)
    for k, th in ((gm.GLOSS_20, 20.0), (gm.GLOSS_60, 60.0), (gm.GLOSS_85, 85.0)):
        c = math.cos(math.radians(th))
        want = 100.0 * _fresnel(1.5, c) / _fresnel(1.567, c)
        assert r.values[0, k] == pytest.approx(want, rel=2e-3)
    assert r.values[1, gm.GLOSS_60] < r.values[0, gm.GLOSS_60]
    named = {"base_color": [0.18, 0.18, 0.18], "specular_roughness": 0.24, "specular_ior": 1.5,
             "specular_weight": 1.13, "base_weight": 1}
    one = gm.readings_bridge("openpbr", named, tol=1e-4)
    assert one.values.shape == (7,) and np.all(np.isfinite(one.values))


def test_readings_bridge_rejects_with_a_status():
    from pgloss import bridge
    bad = bridge.Params(np.array([1.5, 0.2, 0.2]), 0.3, 1.5, 0.5)
    with pytest.raises(pgloss.PglossError) as e:
        gm.readings_bridge("principled", bad)
    assert e.value.status == pgloss.bridge.ERR_BRIDGE_BASE
    with pytest.raises(ValueError):
        gm.readings_bridge("blender", bad)
