# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss.bridge: the round trip paint -> target -> paint, broadcasting, the out-of-reach statuses
and their reasons, and the targets' conventions against the shared vectors tests/vectors/bridge.json
(from the independent mpmath generator tests/vectors/generate.py). The C tool's JSON (`pgloss bridge`,
PGLOSS_CLI) is not an independent source: it is checked only as a consistency test, that both front
ends name the parameters alike and pass the same values through."""

from __future__ import annotations

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import pgloss
from pgloss import bridge

VECTORS = pathlib.Path(__file__).resolve().parents[1] / "vectors" / "bridge.json"
C_TOOL = os.environ.get("PGLOSS_CLI", "")


def paper_paints() -> np.ndarray:
    """Fig. 4's 27 paints and Fig. 12's matched triplet (c = 0.057, d = 0.96), (30, 5)."""
    rows = []
    for rd in (0.03, 0.193, 0.767):
        L = float(pgloss.lightness_from_luminance(rd))
        for rs in (0.033, 0.066, 0.099):
            c = float(pgloss.contrast_gloss(rd, rs))
            for a in (0.04, 0.07, 0.10):
                rows.append([L, 0.0, 0.0, c, 1 - a])
        rows.append([L, 0.0, 0.0, 0.057, 0.96])
    return np.array(rows)


@pytest.mark.parametrize("target", [t for t in bridge.TARGETS if t != "gltf_core"])
def test_round_trip_is_exact_where_reachable(target):
    paints = paper_paints()
    m = bridge.from_paint(target, paints, errors="status")
    ok = m.status >= 0
    assert ok.sum() >= 20, (target, bridge.status_names(m.status))
    assert set(np.unique(m.status[~ok])) <= set(bridge.REACH_STATUSES)
    np.testing.assert_allclose(m.reached[ok], paints[ok], atol=1e-9)
    back = bridge.to_paint(target, bridge.Params(m.params.base_color[ok], m.params.roughness[ok], m.params.ior[ok],
                                                 m.params.specular[ok]))
    np.testing.assert_allclose(back.paint, paints[ok], atol=1e-9)
    assert np.all((back.residual > 0) & (back.residual < 0.3))


def test_colour_round_trip_and_named_parameters():
    q = [45.0, 30.0, -20.0, 0.06, 0.95]
    m = bridge.from_paint("principled", q)
    assert m.status == 0 and m.params.base_color.shape == (3,)
    named = m.params.named("principled")
    assert named["Specular IOR Level"] == 0.5 and named["Metallic"] == 0.0
    back = bridge.to_paint("principled", named)  # the target's own names in, as from the tool's JSON
    np.testing.assert_allclose(back.paint, q, atol=1e-9)
    gltf = bridge.from_paint("gltf", q).params.named("gltf")
    assert gltf["baseColorFactor"].shape == (4,) and gltf["baseColorFactor"][3] == 1.0


def test_broadcasting_matches_one_at_a_time():
    paints = paper_paints()[:12].reshape(3, 4, 5)
    m = bridge.from_paint("openpbr", paints, errors="status")
    assert m.params.base_color.shape == (3, 4, 3) and m.params.roughness.shape == (3, 4)
    assert m.reached.shape == (3, 4, 5) and m.status.shape == (3, 4) and m.status.dtype == np.int8
    for i in range(3):
        for j in range(4):
            one = bridge.from_paint("openpbr", paints[i, j], errors="status")
            assert one.status == m.status[i, j]
            np.testing.assert_array_equal(one.params.base_color, m.params.base_color[i, j])
            assert one.params.roughness == m.params.roughness[i, j]
    # Parameters broadcast: one base colour against three roughnesses.
    r = bridge.to_paint("openpbr", bridge.Params([0.3, 0.3, 0.3], np.array([0.2, 0.3, 0.4]), 1.5, 1.0))
    assert r.paint.shape == (3, 5) and r.status.shape == (3,)
    assert np.all(np.diff(r.paint[:, 4]) < 0)  # rougher reads less distinct


def test_out_of_reach_gives_the_nearest_paint_and_the_reason():
    black_L = float(pgloss.lightness_from_luminance(0.03))
    paints = np.array([[black_L, 0, 0, 0.2, 0.95],   # c beyond glTF's fixed F0 0.04
                       [50, 0, 0, 0.05, 0.999],       # sharper than the tables' smallest alpha
                       [99.5, 0, 0, 0.005, 0.9],      # white, weakest gloss: base colour above 1
                       [50, 0, 0, 0.05, 0.95]])       # reachable
    st = [bridge.from_paint(t, p, errors="status").status
          for t, p in zip(("gltf_core", "openpbr", "principled", "openpbr"), paints)]
    assert st == [bridge.ERR_BRIDGE_SPECULAR, bridge.ERR_BRIDGE_ROUGHNESS, bridge.ERR_BRIDGE_BASE, 0]
    m = bridge.from_paint("gltf_core", paints[0], errors="status")
    assert abs(m.reached[0] - black_L) < 1e-3 and m.reached[3] < 0.2 and m.params.ior == 1.5
    assert m.reasons == pgloss._core.status_string(bridge.ERR_BRIDGE_SPECULAR)
    assert "PGLOSS_ERR_BRIDGE_SPECULAR" == bridge.status_names(m.status)
    # glTF with KHR_materials_ior reaches it.
    assert bridge.from_paint("gltf", paints[0]).params.ior > 1.5
    # An array: the statuses and reasons per element; errors="raise" names the first and keeps all.
    many = bridge.from_paint("openpbr", paints, errors="status")
    assert list(many.status) == [0, bridge.ERR_BRIDGE_ROUGHNESS, bridge.ERR_BRIDGE_BASE, 0]
    assert many.reasons.shape == (4,) and many.reasons[1] == pgloss._core.status_string(bridge.ERR_BRIDGE_ROUGHNESS)
    with pytest.raises(bridge.BridgeError) as e:
        bridge.from_paint("openpbr", paints)
    assert e.value.status == bridge.ERR_BRIDGE_ROUGHNESS and e.value.index == (1,)
    np.testing.assert_array_equal(e.value.status_array, many.status)
    np.testing.assert_array_equal(e.value.result.params.base_color, many.params.base_color)
    # Errors of the paint itself come first; bad arguments are Python errors.
    assert bridge.from_paint("openpbr", [50, 0, 0, -0.1, 0.9], errors="status").status == pgloss.Status.ERR_NEGATIVE
    assert bridge.from_paint("openpbr", [np.nan, 0, 0, 0.05, 0.9], errors="status").status == pgloss.Status.ERR_NONFINITE
    with pytest.raises(ValueError, match="unknown target"):
        bridge.from_paint("arnold", paints)
    with pytest.raises(ValueError, match=r"\(\.\.\., 5\)"):
        bridge.from_paint("openpbr", [50, 0, 0, 0.05])
    # Back: parameters outside the target's or the tables' range.
    p = bridge.Params([0.5, 0.5, 0.5], np.array([0.3, 0.3, 0.01, 0.3]), np.array([1.5, 1.5, 1.5, 1.0]), 1.0)
    p = p._replace(base_color=np.array([[0.5, 0.5, 0.5], [0.5, 1.2, 0.5], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5]]))
    r = bridge.to_paint("openpbr", p, errors="status")
    assert list(r.status) == [0, bridge.ERR_BRIDGE_BASE, bridge.ERR_BRIDGE_ROUGHNESS, bridge.ERR_BRIDGE_SPECULAR]
    assert np.all(np.isfinite(r.paint))


def test_finite_for_any_finite_input():
    rng = np.random.default_rng(29)
    u = rng.uniform(-0.2, 1.2, size=(300, 5))
    paints = u * [120, 80, 80, 0.4, 1] - [0, 40, 40, 0, 0]
    for t in bridge.TARGETS:
        m = bridge.from_paint(t, paints, errors="status")
        assert np.all(np.isfinite(m.reached)) and np.all(np.isfinite(m.params.base_color))


def test_read_and_the_conventions_layer():
    reading, st = bridge.read("principled", [0.0, 0.5, 1.0], 0.04, 0.05)
    assert reading.shape == (3, 4) and list(st) == [0, 0, 0]
    assert np.all(np.diff(reading[:, 0]) > 0)  # brighter base, larger fitted rho_d
    _, st = bridge.read("principled", 0.5, 0.5, 0.05, errors="status")
    assert st == bridge.ERR_BRIDGE_SPECULAR
    f0_min, f0_max, a_min, a_max = bridge.target_range("gltf_core")
    assert f0_min == f0_max == 0.04 and a_min < a_max
    params, st = bridge.params_from_model("gltf", [[0.2, 0.2, 0.2]], [0.02, 0.09], 0.04)
    assert params.base_color.shape == (2, 3) and list(params.specular) == [0.5, 1.0]


def _cases():
    return json.loads(VECTORS.read_text())["cases"]


@pytest.mark.parametrize("case", _cases(), ids=lambda c: c["id"])
def test_conventions_meet_the_shared_vectors(case):
    p = case["params"]
    params = bridge.Params(p["base_color"], p["roughness"], p["ior"], p["specular"])
    beta, f0, alpha, st = bridge.model_inputs(case["target"], params)
    assert st == 0
    assert beta == pytest.approx(case["beta"], abs=1e-14)
    assert f0 == pytest.approx(case["f0"], abs=1e-14)
    assert alpha == pytest.approx(case["alpha"], abs=1e-14)
    q, st = bridge.params_from_model(case["target"], p["base_color"], case["f0"], case["alpha"])
    want = case["canonical"]
    assert (q.roughness, q.ior, q.specular) == pytest.approx((want["roughness"], want["ior"], want["specular"]),
                                                             abs=1e-12)


def _tool(*args: str) -> dict:
    if not C_TOOL:
        pytest.skip("the C tool is not built (PGLOSS_CLI; scripts/test-python.sh builds it)")
    r = subprocess.run([C_TOOL, "bridge", *args], capture_output=True, text=True, timeout=60)
    return json.loads(r.stdout)


@pytest.mark.parametrize("target,paint", [("openpbr", (50, 0, 0, 0.057, 0.96)),
                                          ("principled", (45, 30, -20, 0.06, 0.95)),
                                          ("gltf", (30, 0, 0, 0.15, 0.93)),
                                          ("roughplastic_beckmann", (70, 5, 10, 0.04, 0.9)),
                                          ("gltf_core", (20, 0, 0, 0.2, 0.95))])
def test_agrees_with_the_c_tool(target, paint, tmp_path):
    js = _tool(target, *(repr(float(x)) for x in paint))
    m = bridge.from_paint(target, paint, errors="status")
    assert js["status"] == ("ok" if m.status == 0 else bridge.status_names(m.status))
    assert js["reason"] == m.reasons
    named = m.params.named(target)
    for key, value in js["parameters"].items():
        if isinstance(value, (str, bool)):
            assert named[key] == value
        else:
            np.testing.assert_allclose(named[key], value, rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(m.reached, [js["paint"][k] for k in "Labcd"], rtol=1e-8, atol=1e-8)
    # And back: `pgloss bridge --from TARGET FILE.json` against to_paint on the same parameters.
    f = tmp_path / "params.json"
    f.write_text(json.dumps(js["parameters"]))
    back_js = _tool("--from", target, str(f))
    back = bridge.to_paint(target, js["parameters"], errors="status")
    np.testing.assert_allclose(back.paint, [back_js["paint"][k] for k in "Labcd"], rtol=1e-8, atol=1e-8)
    assert back.residual == pytest.approx(back_js["residual"], rel=1e-5)
