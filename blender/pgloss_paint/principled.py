# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The Principled mode of pgloss paint: a paint (L*, a*, b*, c, d), or a 60° gloss in GU, or a
finish name, mapped by the gloss bridge (``pgloss.bridge.from_paint("principled", …)``) to the
inputs of Blender's own Principled BSDF. The material holds nothing but that node, so it renders
in EEVEE and in Cycles on any device, and without the add-on.

The bridge's Principled model is Cycles' (GGX with multiscatter energy compensation, docs/bridge.md):
the paint reads back as requested in Cycles; EEVEE's real-time Principled approximates the same
BSDF. Gloss units are readings of the *mapped* Principled material by the virtual glossmeter
(``pgloss.glossmeter.readings_bridge``: the material's own Fresnel lobe, as a real instrument
would read the paint), not of the Ward paint (whose 60° reading is 3–4 times lower,
docs/glossmeter.md). A paint out of the bridge's reach renders as the nearest reachable paint,
which the panel shows with the status and its reason.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, Tuple

import numpy as np

TARGET = "principled"
#: Name of the Principled BSDF node the mode writes.
NODE = "pgloss Principled"
#: Iterations of the 60° gloss solve (Illinois on c); each is one mapping and one reading.
_GU_ITERATIONS = 40
_GU_TOL = 1e-3  # GU


@dataclass
class Principled:
    """One mapping: the Principled inputs by their Blender names (empty when the paint itself is
    invalid), the paint they read as (``reached``), the core's status and reason, and the
    glossmeter's readings of the material (GU; empty when there is no material)."""

    inputs: Dict[str, object]
    requested: Tuple[float, float, float, float, float]
    reached: Tuple[float, float, float, float, float]
    status: int
    status_name: str
    reason: str
    readings: Dict[str, float] = field(default_factory=dict)
    note: str = ""

    @property
    def renderable(self) -> bool:
        """True when there are inputs to write (the paint, or the nearest reachable one)."""
        return bool(self.inputs)

    @property
    def nearest(self) -> bool:
        """True when the paint is out of the bridge's reach and the inputs are the nearest paint's."""
        from pgloss import bridge

        return self.status in bridge.REACH_STATUSES

    @property
    def exact(self) -> bool:
        """True when the material reads as the requested paint (ok, or a warning)."""
        return self.status >= 0


def from_paint(L: float, a: float, b: float, c: float, d: float, *, readings: bool = True) -> Principled:
    """The Principled inputs of paint (L*, a*, b*, c, d): ``pgloss.bridge.from_paint``."""
    from pgloss import bridge, glossmeter

    paint = (float(L), float(a), float(b), float(c), float(d))
    m = bridge.from_paint(TARGET, list(paint), errors="status")
    st = int(m.status)
    usable = st >= 0 or st in bridge.REACH_STATUSES
    inputs: Dict[str, object] = {}
    if usable:
        for k, v in m.params.named(TARGET).items():
            arr = np.asarray(v, dtype=np.float64)
            inputs[k] = tuple(float(x) for x in arr) if arr.ndim else float(arr)
    out = Principled(inputs, paint, tuple(float(x) for x in m.reached) if usable else paint, st,
                     str(bridge.status_names(st)), str(bridge.reasons(st)))
    if usable and readings:
        r = glossmeter.readings_bridge(TARGET, m.params)
        out.readings = {k: float(r.values[glossmeter.KINDS.index(k)]) for k in ("gloss_20", "gloss_60", "gloss_85")}
    return out


def _gloss_60(L: float, a: float, b: float, c: float, d: float) -> Tuple[float, Principled]:
    p = from_paint(L, a, b, c, d)
    return (p.readings["gloss_60"] if p.renderable else math.nan), p


def from_gloss_60(L: float, a: float, b: float, gloss_60: float, d: float) -> Principled:
    """The paint of lightness/colour (L*, a*, b*) and DOI gloss d whose mapped Principled
    material reads ``gloss_60`` GU at 60° (ISO 2813 geometry, the virtual glossmeter). c is
    solved by the Illinois method between the c the bridge reaches at this (L*, d) (the 60°
    reading rises with c: F0 rises). Out of reach, the nearest end with the bridge's status and
    a note naming the reading it gets."""
    from pgloss import bridge

    if not (math.isfinite(gloss_60) and gloss_60 >= 0):
        raise ValueError(f"pgloss paint: the 60° gloss must be a finite number ≥ 0 GU, not {gloss_60}")
    # The c the bridge reaches at this L*, d: the nearest paint to c = 0, and to the largest c
    # inside the model's envelope (Fig. 10) on a grid (the envelope's c depends on L*).
    grid = np.linspace(0.5, 0.0, 51)
    m = bridge.from_paint(TARGET, [[L, a, b, c, d] for c in grid], errors="status")
    st = np.asarray(m.status)
    usable = (st >= 0) | np.isin(st, bridge.REACH_STATUSES)
    if not usable.any():
        return from_paint(L, a, b, 0.0, d)  # the colour or d itself is invalid: say why
    lo_c, hi_c = float(m.reached[-1][3]), float(m.reached[int(np.argmax(usable))][3])
    g_lo, p_lo = _gloss_60(L, a, b, lo_c, d)
    g_hi, p_hi = _gloss_60(L, a, b, hi_c, d)
    if not g_lo < gloss_60 < g_hi:
        p = p_lo if gloss_60 <= g_lo else p_hi
        if p.status >= 0:
            p.status, p.status_name = bridge.ERR_BRIDGE_SPECULAR, str(bridge.status_names(bridge.ERR_BRIDGE_SPECULAR))
            p.reason = str(bridge.reasons(bridge.ERR_BRIDGE_SPECULAR))
        p.note = (f"{gloss_60:g} GU at 60° is outside the {g_lo:.1f}–{g_hi:.1f} GU the Principled BSDF "
                  f"reaches at L* {L:g}, d {d:g}: the nearest, {p.readings['gloss_60']:.1f} GU")
        return p
    # Illinois (regula falsi, halving the kept end's value when it is kept twice) on g(c) − target.
    x0, f0, x1, f1 = lo_c, g_lo - gloss_60, hi_c, g_hi - gloss_60
    best = p_hi
    for _ in range(_GU_ITERATIONS):
        x = x1 - f1 * (x1 - x0) / (f1 - f0)
        g, best = _gloss_60(L, a, b, x, d)
        fx = g - gloss_60
        if abs(fx) <= _GU_TOL:
            break
        if fx * f1 < 0:
            x0, f0 = x1, f1
        else:
            f0 /= 2
        x1, f1 = x, fx
    return best


def finish_gloss_60(name: str) -> Tuple[str, float, Tuple[float, float], Tuple[float, float]]:
    """(the finish's name, the middle of its 60° range, its 60° range, its 85° range) from the MPI
    table (``pgloss.glossmeter.FINISHES``; an open end is 0 or 100 GU, NaN in the 85° range)."""
    from pgloss import glossmeter

    key = name.strip().lower()
    for f in glossmeter.FINISHES:
        if key in (f.name.lower(), f.level.lower(), f.level.lower().split()[-1]):
            lo = 0.0 if math.isnan(f.gloss_60_min) else f.gloss_60_min
            hi = 100.0 if math.isnan(f.gloss_60_max) else f.gloss_60_max
            return f.name, (lo + hi) / 2, (lo, hi), (f.sheen_85_min, f.sheen_85_max)
    names = ", ".join(f"{f.level} {f.name}" for f in glossmeter.FINISHES)
    raise ValueError(f"unknown finish {name!r}; one of {names}")


def from_finish(L: float, a: float, b: float, name: str, d: float) -> Principled:
    """The paint of a trade finish: the middle of its 60° range (:func:`from_gloss_60`), with a
    note on whether the material's 85° reading meets the finish's sheen range."""
    fname, g60, _, (s_lo, s_hi) = finish_gloss_60(name)
    p = from_gloss_60(L, a, b, g60, d)
    if p.readings:
        g85 = p.readings["gloss_85"]
        ok = (math.isnan(s_lo) or g85 >= s_lo) and (math.isnan(s_hi) or g85 <= s_hi)
        sheen = "meets" if ok else "misses"
        rng = "–".join("…" if math.isnan(v) else f"{v:g}" for v in (s_lo, s_hi))
        p.note = (p.note + "; " if p.note else "") + \
            f"{fname}: 60° {g60:g} GU wanted; 85° {g85:.1f} GU {sheen} the finish's {rng} GU"
    return p


#: Blender 5's working spaces (``bpy.data.colorspace.working_space``) as pgloss colour spaces.
WORKING_SPACES = {"Linear Rec.709": 0, "ACEScg": 1, "Linear Rec.2020": 3}


def base_color_in(rgb709: Tuple[float, float, float], working_space: str) -> Tuple[float, float, float]:
    """The bridge's linear Rec. 709 base colour in the .blend's working space, through CIELAB
    (``pgloss.lab_from_rgb`` / ``rgb_from_lab``: D65, ACEScg Bradford-adapted); Y is unchanged,
    so the paint's L* and gloss are too."""
    import pgloss

    space = WORKING_SPACES.get(working_space)
    if space is None:
        raise ValueError(f"pgloss paint: unknown working space {working_space!r}; one of {', '.join(WORKING_SPACES)}")
    if space == 0:
        return rgb709
    lab = pgloss.lab_from_rgb(np.asarray(rgb709, dtype=np.float64), 0)
    return tuple(float(x) for x in pgloss.rgb_from_lab(lab, space))


def write(node, p: Principled, working_space: str = "Linear Rec.709") -> None:
    """Writes the mapping's inputs into a Principled BSDF node (nothing if the paint is invalid),
    the base colour in the .blend's working space."""
    for k, v in p.inputs.items():
        sock = node.inputs[k]
        if k == "Base Color":
            v = base_color_in(v, working_space)
        sock.default_value = (*v, 1.0) if isinstance(v, tuple) else v
