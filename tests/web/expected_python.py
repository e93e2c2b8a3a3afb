#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""What the picker must display, computed by the Python binding (bindings/python, the native
C core): run with the venv of scripts/test-python.sh (.venv-py). Reads a JSON list of
perceptual paints {L, a, b, c, d} on stdin and writes, for each, the status of
``Perceptual.check()`` (name and the core's sentence), ρd, ρs, α of ``to_physical()`` (also when it
raises GAMUT: the exception carries the computed values), and the Fig. 12 match of the paint
(``match_gloss`` of its luminance and ρs to the lightnesses of ρd 0.767, 0.193, 0.03), the
paint in every gloss-bridge target (``pgloss.bridge.from_paint``: parameters, status, reason, the
paint reached) and the glossmeter's readings of the Ward paint and of each target's material
(``pgloss.glossmeter``, at the page's quadrature tolerance METER_TOL)."""
from __future__ import annotations

import json
import sys
import warnings
from typing import Any, Dict, List

import numpy as np

import pgloss
from pgloss import bridge, glossmeter

METER_TOL = 1e-5  # web/picker/picker.js METER_TOL
KINDS = ("GLOSS_60", "HAZE_20", "DOI_30")


def _readings(r: glossmeter.Readings) -> Dict[str, Dict[str, float]]:
    idx = {"GLOSS_60": glossmeter.GLOSS_60, "HAZE_20": glossmeter.HAZE_20, "DOI_30": glossmeter.DOI_30}
    return {k: {"value": float(r.values[i]), "error": float(r.errors[i])} for k, i in idx.items()}


def targets(paint: Dict[str, float]) -> Dict[str, Any]:
    out: Dict[str, Any] = {}
    for t in bridge.TARGETS:
        m = bridge.from_paint(t, [paint[k] for k in ("L", "a", "b", "c", "d")], errors="status")
        st = int(m.status)
        written = st >= 0 or st in bridge.REACH_STATUSES
        e: Dict[str, Any] = {"status": str(bridge.status_names(st)), "reason": str(bridge.reasons(st)),
                             "params": None, "named": None, "reached": None, "readings": None}
        if written:
            p = m.params
            e["params"] = {"base_color": [float(x) for x in p.base_color], "roughness": float(p.roughness),
                           "ior": float(p.ior), "specular": float(p.specular)}
            e["named"] = {k: (np.asarray(v, dtype=float).tolist() if not isinstance(v, (str, bool)) else v)
                          for k, v in p.named(t).items()}
            e["reached"] = [float(x) for x in m.reached]
            e["readings"] = _readings(glossmeter.readings_bridge(t, p, tol=METER_TOL))
        out[t] = e
    return out


def expected(paint: Dict[str, float]) -> Dict[str, Any]:
    q = pgloss.Perceptual(paint["L"], paint["a"], paint["b"], paint["c"], paint["d"])
    st = q.check()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pgloss.AlphaUntrustedWarning)
        try:
            p = q.to_physical()
            rho_d, rho_s, alpha = list(p.rho_d), p.rho_s, p.alpha
        except pgloss.PglossError as e:  # GAMUT: the computed (negative) values are on e.result
            r = e.result
            rho_d, rho_s, alpha = list(r.rho_d), r.rho_s, r.alpha
        match: List[Dict[str, Any]] = []
        Y = pgloss.luminance(rho_d)
        for rd in (0.767, 0.193, 0.03):
            L_t = pgloss.lightness_from_luminance(rd)
            try:
                rd_out, rs_out = pgloss.match_gloss(Y, rho_s, L_t)
                mst = "PGLOSS_OK"
            except pgloss.PglossError as e:
                rd_out, rs_out = (float(v) for v in e.result)
                mst = e.status.c_name
            match.append({"rho_d": float(rd_out), "rho_s": float(rs_out), "status": mst})
        ward = None
        if min(rho_d) >= 0 and rho_s >= 0 and alpha > 0:
            ward = _readings(glossmeter.readings(pgloss.Physical(np.asarray(rho_d), rho_s, alpha), tol=METER_TOL))
    return {"status": st.c_name, "reason": st.reason, "rho_d": [float(x) for x in rho_d],
            "rho_s": float(rho_s), "alpha": float(alpha), "match": match, "targets": targets(paint),
            "readings": ward}


def entries(spec: Dict[str, Any]) -> Dict[str, Any]:
    """The paints of the gloss-unit and finish entries: {"gloss_units": [[L, a, b, GU60, d]…],
    "finishes": [[name, L, a, b]…]} → their (c, d) and status names."""
    gu = []
    for L, a, b, g60, d in spec["gloss_units"]:
        q, st = glossmeter.from_gloss_units(L, g60, d=d, a=a, b=b, errors="status")
        gu.append({"c": float(q.c), "d": float(q.d), "status": str(bridge.status_names(st))})
    fin = []
    for name, L, a, b in spec["finishes"]:
        f = glossmeter.finish(name, L, a, b)
        fin.append({"c": float(f.paint.c), "d": float(f.paint.d), "status": str(bridge.status_names(f.status)),
                    "c_range": list(f.c_range), "d_range": list(f.d_range), "sheen_ok": bool(f.sheen_ok)})
    return {"gloss_units": gu, "finishes": fin}


if __name__ == "__main__":
    request = json.load(sys.stdin)
    if isinstance(request, dict):
        json.dump(entries(request), sys.stdout)
    else:
        json.dump([expected(p) for p in request], sys.stdout)
