#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""What the picker must display, computed by the Python binding (bindings/python, the native
C core): run with the venv of scripts/test-python.sh (.venv-py). Reads a JSON list of
perceptual paints {L, a, b, c, d} on stdin and writes, for each, the status of
``Perceptual.check()`` (name and the core's sentence), ρd, ρs, α of ``to_physical()`` (also when it
raises GAMUT: the exception carries the computed values), and the Fig. 12 match of the paint
(``match_gloss`` of its luminance and ρs to the lightnesses of ρd 0.767, 0.193, 0.03)."""
from __future__ import annotations

import json
import sys
import warnings
from typing import Any, Dict, List

import pgloss


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
    return {"status": st.c_name, "reason": st.reason, "rho_d": [float(x) for x in rho_d],
            "rho_s": float(rho_s), "alpha": float(alpha), "match": match}


if __name__ == "__main__":
    json.dump([expected(p) for p in json.load(sys.stdin)], sys.stdout)
