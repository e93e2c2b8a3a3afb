# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Writes materialx/pgloss/pgloss_bridge.mtlx: the gloss bridge's forward map (a paint
L*, a*, b*, c, d → OpenPBR / Standard Surface parameters, libpgloss/src/bridge.c) as a MaterialX
node graph of standard nodes only, and prints the approximation's error against the C bridge.

The closed-form parts are written as they are: CIELAB (D65) → XYZ → linear Rec. 709 (CIE 15,
the matrices of libpgloss/src/color.c), Y = f⁻¹(L*) (eq. 6), roughness = √α, the targets' F0
conventions. The C bridge's table inversion is replaced by a least-squares polynomial of total
degree DEGREE in (L*, √c, ln(1 − d)) for (ln F0, ln α, β/Y), fitted to the C bridge's own
answers at the reachable paints of a grid; docs/materialx.md gives the method and the errors.

    .venv-materialx/bin/python materialx/bridge_graph.py          # regenerate (about 2 min)
    .venv-materialx/bin/python materialx/bridge_graph.py --check  # the file is up to date
    .venv-materialx/bin/python materialx/bridge_graph.py --study  # cost against error per degree
    (--rows FILE.npy keeps the C bridge's answers on the grid between runs)
"""
from __future__ import annotations

import ctypes as C
import os
import itertools
import re
import sys
from pathlib import Path
from typing import List, NamedTuple, Sequence, Tuple

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "osl"))
import cref  # noqa: E402  (libpgloss through ctypes, built with the project's CMake)

OUT = ROOT / "materialx" / "pgloss" / "pgloss_bridge.mtlx"
DEGREE = 7
BOUND_DEGREE = 6
# The fitted box of inputs (a shader cannot raise an error: inputs outside are clamped to it).
L_RANGE = (0.0, 100.0)
C_RANGE = (0.0, 0.5)
D_RANGE = (0.6, 0.99)
# The parameter box of the MaterialX targets (pgloss_bridge_range, checked at run time).
F0_RANGE = (0.01, 0.25)
ALPHA_RANGE = (0.004, 0.35)
# Feature scaling onto about [-1, 1]: x = L/50 − 1, y = √c / 0.35 − 1, z = (ln(1 − d) + 2.76) / 1.84.
SQRT_C_SCALE = 0.35
LN_A_CENTRE, LN_A_HALF = -2.76, 1.84
OPENPBR = 0
# PGLOSS_ERR_BRIDGE_BASE, _SPECULAR, _ROUGHNESS (pgloss/status.h): out of the target's reach.
REACH_STATUSES = (-13, -14, -15)


class Paint(C.Structure):
    _fields_ = [("L", C.c_double), ("a", C.c_double), ("b", C.c_double), ("c", C.c_double), ("d", C.c_double)]


class Params(C.Structure):
    _fields_ = [("base_color", C.c_double * 3), ("roughness", C.c_double), ("ior", C.c_double),
                ("specular", C.c_double)]


def bridge_lib() -> C.CDLL:
    lib = cref.lib()
    lib.pgloss_bridge_from_perceptual.argtypes = [C.c_int, C.POINTER(Paint), C.POINTER(Params), C.POINTER(Paint)]
    lib.pgloss_bridge_to_perceptual.argtypes = [C.c_int, C.POINTER(Params), C.POINTER(Paint), C.POINTER(C.c_double)]
    lib.pgloss_bridge_range.argtypes = [C.c_int] + [C.POINTER(C.c_double)] * 4
    return lib


def from_paint(lib: C.CDLL, paint: Sequence[float], target: int = OPENPBR) -> Tuple[int, Params, Paint]:
    """pgloss_bridge_from_perceptual: (status, parameters, the paint they read as)."""
    p, r = Params(), Paint()
    st = lib.pgloss_bridge_from_perceptual(target, C.byref(Paint(*paint)), C.byref(p), C.byref(r))
    return st, p, r


def to_paint(lib: C.CDLL, base: Sequence[float], roughness: float, ior: float, specular: float,
             target: int = OPENPBR) -> Tuple[int, Paint]:
    """pgloss_bridge_to_perceptual: the paint a target's parameters read as."""
    q = Paint()
    st = lib.pgloss_bridge_to_perceptual(target, C.byref(Params((C.c_double * 3)(*base), roughness, ior, specular)),
                                         C.byref(q), None)
    return st, q


def lightness_to_y(L: np.ndarray) -> np.ndarray:
    """Eq. 6: Y = f⁻¹(L*) (CIE 1976)."""
    return np.where(L > 8.0, ((L + 16.0) / 116.0) ** 3, L * 27.0 / 24389.0)


def features(L: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    L = np.clip(L, *L_RANGE)
    c = np.clip(c, *C_RANGE)
    d = np.clip(d, *D_RANGE)
    return np.stack([L / 50.0 - 1.0, np.sqrt(c) / SQRT_C_SCALE - 1.0, (np.log(1.0 - d) - LN_A_CENTRE) / LN_A_HALF], -1)


def exponents(degree: int = DEGREE, dims: int = 3) -> List[Tuple[int, ...]]:
    return [e for e in itertools.product(range(degree + 1), repeat=dims) if sum(e) <= degree]


def monomials(X: np.ndarray, degree: int = DEGREE) -> np.ndarray:
    return np.stack([np.prod([X[:, k] ** e[k] for k in range(X.shape[1])], 0)
                     for e in exponents(degree, X.shape[1])], -1)


class Fit(NamedTuple):
    """The fitted polynomials: the inverse (ln F0, ln α, β/Y) of (x, y, z); the bounds of the
    reachable y (√c) as functions of (x, z) and of z (ln(1 − d)) as functions of (x, y); the
    reachable x (L*) interval; the most y reachable at x < x_dark, where β = 0 limits it (a
    dark paint's L* comes partly from its specular lobe), as a function of (x, z)."""
    inverse: np.ndarray
    y_bounds: np.ndarray
    z_bounds: np.ndarray
    x_range: Tuple[float, float]
    y_dark: np.ndarray
    x_dark: float
    degree: int = DEGREE


def project(fit: Fit, X: np.ndarray) -> np.ndarray:
    """Features onto (about) the reachable set, as the graph does: x into its interval; then z,
    y, z again between their bounds at the other two (the C bridge's order: L* first, then c, d)."""
    x = np.clip(X[:, 0], *fit.x_range)
    y, z = X[:, 1], X[:, 2]

    def clamp(v, b):
        return np.clip(v, np.minimum(b[:, 0], b[:, 1]), np.maximum(b[:, 0], b[:, 1]))
    z = clamp(z, monomials(np.stack([x, y], -1), BOUND_DEGREE) @ fit.z_bounds)
    y = clamp(y, monomials(np.stack([x, z], -1), BOUND_DEGREE) @ fit.y_bounds)
    dark = (monomials(np.stack([x, z], -1), BOUND_DEGREE) @ fit.y_dark)[:, 0]
    y = np.where(x < fit.x_dark, np.minimum(y, dark), y)
    z = clamp(z, monomials(np.stack([x, y], -1), BOUND_DEGREE) @ fit.z_bounds)
    return np.stack([x, y, z], -1)


def predict(fit: Fit, L, c, d) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The graph's arithmetic in numpy (double): F0, α, β/Y after the graph's clamps."""
    L, c, d = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (L, c, d))
    q = monomials(project(fit, features(L, c, d)), fit.degree) @ fit.inverse
    return (np.clip(np.exp(q[:, 0]), *F0_RANGE), np.clip(np.exp(q[:, 1]), *ALPHA_RANGE), np.maximum(q[:, 2], 0.0))


def boundary_paints(lib: C.CDLL) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Features of the paints on the faces of the targets' box (pgloss_bridge_read): F0 at
    either limit (the bounds of c), α at either limit (the bounds of d), and β = 0 (the
    bound of c of dark paints); each row (x, y, z, which limit: 0 low, 1 high)."""
    betas = np.linspace(0.0, 1.0, 41)
    f0s = np.geomspace(*F0_RANGE, 25)
    alphas = np.geomspace(*ALPHA_RANGE, 25)
    reading = (C.c_double * 4)()
    faces = []
    for axis, limits, others in ((0, F0_RANGE, alphas), (1, ALPHA_RANGE, f0s)):
        rows = []
        for side, limit in enumerate(limits):
            for beta in betas:
                for o in others:
                    f0, alpha = (limit, o) if axis == 0 else (o, limit)
                    lib.pgloss_bridge_read(OPENPBR, C.c_double(beta), C.c_double(f0), C.c_double(alpha), reading)
                    rd, rs, aw = reading[0], reading[1], reading[2]
                    L = 116 * np.cbrt(rd) - 16 if rd > 216 / 24389 else rd * 24389 / 27
                    c = np.cbrt(rs + rd / 2) - np.cbrt(rd / 2)
                    rows.append((*features(np.array([L]), np.array([c]), np.array([1 - aw]))[0], side))
        faces.append(np.array(rows))
    dark = []
    for f0 in f0s:
        for alpha in alphas:
            lib.pgloss_bridge_read(OPENPBR, C.c_double(0.0), C.c_double(f0), C.c_double(alpha), reading)
            rd, rs, aw = reading[0], reading[1], reading[2]
            L = 116 * np.cbrt(rd) - 16 if rd > 216 / 24389 else rd * 24389 / 27
            c = np.cbrt(rs + rd / 2) - np.cbrt(rd / 2)
            dark.append((*features(np.array([L]), np.array([c]), np.array([1 - aw]))[0], 0))
    return faces[0], faces[1], np.array(dark)


def fit_bounds(f0_faces: np.ndarray, alpha_faces: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """y on the F0 faces as polynomials of (x, z); z on the α faces as polynomials of (x, y)."""
    out = []
    for faces, (a, b, v) in ((f0_faces, (0, 2, 1)), (alpha_faces, (0, 1, 2))):
        cols = []
        for side in (0, 1):
            r = faces[faces[:, 3] == side]
            cols.append(np.linalg.lstsq(monomials(r[:, [a, b]], BOUND_DEGREE), r[:, v], rcond=None)[0])
        out.append(np.stack(cols, -1))
    return out[0], out[1]


def training_set(lib: C.CDLL) -> np.ndarray:
    """The C bridge's answers at neutral paints on a grid uniform in the features (L*, √c,
    ln(1 − d)): rows (L, c, d, status, β/Y, F0, α, reached L, reached c, reached d)."""
    rows = []
    for L in np.linspace(2.0, 100.0, 50):
        Y = float(lightness_to_y(np.array(L)))
        for c in np.linspace(0.0, np.sqrt(C_RANGE[1]), 45) ** 2:
            for d in 1.0 - np.exp(np.linspace(np.log(1 - D_RANGE[0]), np.log(1 - D_RANGE[1]), 40)):
                st, p, r = from_paint(lib, (L, 0.0, 0.0, c, d))
                rows.append((L, c, d, st, p.base_color[1] / Y, p.specular * 0.04, p.roughness ** 2, r.L, r.c, r.d))
    return np.array(rows)


def fit_inverse(rows: np.ndarray, w_out: float = 0.0, degree: int = DEGREE) -> np.ndarray:
    """Least squares over the reachable paints (status OK or ALPHA_UNTRUSTED), and with weight
    w_out the out-of-reach ones, whose parameters are those of the nearest reachable paint."""
    w = np.where(rows[:, 3] >= 0, 1.0, np.where(np.isin(rows[:, 3], REACH_STATUSES), w_out, 0.0))
    r, sw = rows[w > 0], np.sqrt(w[w > 0])[:, None]
    M = monomials(features(r[:, 0], r[:, 1], r[:, 2]), degree)
    Y = np.stack([np.log(r[:, 5]), np.log(r[:, 6]), r[:, 4]], -1)
    return np.linalg.lstsq(M * sw, Y * sw, rcond=None)[0]


# ---------------------------------------------------------------- the document


def _num(x: float) -> str:
    return repr(float(np.float32(x))) if abs(x) > 0 else "0.0"


class Graph:
    """Accumulates the nodes of one nodegraph as XML lines."""

    def __init__(self) -> None:
        self.lines: List[str] = []
        self.n = 0

    def node(self, kind: str, typ: str, name: str | None = None, **inputs) -> str:
        if name is None:
            self.n += 1
            name = f"n{self.n}"
        self.lines.append(f'    <{kind} name="{name}" type="{typ}">')
        for key, (t, v) in inputs.items():
            key = key.rstrip("_")
            if isinstance(v, str) and v.startswith("@"):
                self.lines.append(f'      <input name="{key}" type="{t}" interfacename="{v[1:]}" />')
            elif isinstance(v, str) and v.startswith("#"):
                node, _, out = v[1:].partition(".")
                extra = f' output="{out}"' if out else ""
                self.lines.append(f'      <input name="{key}" type="{t}" nodename="{node}"{extra} />')
            else:
                vals = v if isinstance(v, (tuple, list)) else (v,)
                self.lines.append(f'      <input name="{key}" type="{t}" value="{", ".join(_num(x) for x in vals)}" />')
        self.lines.append(f"    </{kind}>")
        return "#" + name

    def comment(self, text: str) -> None:
        self.lines.append(f"    <!-- {text} -->")


def _poly(g: Graph, coef: np.ndarray, variables: Sequence[str], degree: int) -> str:
    """Σ_e coef_e Π v^e (a vector coefficient per term: every fitted output at once), nested
    Horner in the variables in order."""
    typ = "float" if coef.shape[1] == 1 else f"vector{coef.shape[1]}"
    index = {e: n for n, e in enumerate(exponents(degree, len(variables)))}

    def rec(prefix: tuple):
        if len(prefix) == len(variables):
            return tuple(float(v) for v in coef[index[prefix]])
        top = degree - sum(prefix)
        acc = rec(prefix + (top,))
        if isinstance(acc, tuple):
            acc = g.node("constant", typ, value=(typ, acc))
        for e in range(top - 1, -1, -1):
            m = g.node("multiply", typ, in1=(typ, acc), in2=("float", variables[len(prefix)]))
            acc = g.node("add", typ, in1=(typ, m), in2=(typ, rec(prefix + (e,))))
        return acc
    return rec(())


def _clamp_between(g: Graph, v: str, bounds: str, name: str) -> str:
    """v clamped between the two components of a vector2 (in either order)."""
    b = g.node("separate2", "multioutput", in_=("vector2", bounds))
    lo = g.node("min", "float", in1=("float", b + ".outx"), in2=("float", b + ".outy"))
    hi = g.node("max", "float", in1=("float", b + ".outx"), in2=("float", b + ".outy"))
    return g.node("clamp", "float", name, in_=("float", v), low=("float", lo), high=("float", hi))


# Linear Rec. 709 from XYZ (D65): libpgloss/src/color.c (IEC 61966-2-1 primaries, D65 white).
XYZ_TO_REC709 = ((3.2409699419045213, -1.5373831775700935, -0.49861076029300328),
                 (-0.96924363628087983, 1.8759675015077207, 0.041555057407175613),
                 (0.055630079696993608, -0.20397695888897656, 1.0569715142428786))
WHITE_X, WHITE_Z = 0.3127 / 0.3290, 0.3583 / 0.3290
CIE_DELTA = 6.0 / 29.0


def _lab_finv(g: Graph, t: str) -> str:
    """CIE 1976 f⁻¹(t): t³ above δ = 6/29, else 3δ²(t − 4/29)."""
    cube = g.node("power", "float", in1=("float", t), in2=("float", 3.0))
    lin = g.node("subtract", "float", in1=("float", t), in2=("float", 4.0 / 29.0))
    lin = g.node("multiply", "float", in1=("float", lin), in2=("float", 3 * CIE_DELTA ** 2))
    return g.node("ifgreater", "float", value1=("float", t), value2=("float", CIE_DELTA), in1=("float", cube),
                  in2=("float", lin))


def bridge_graph(fit: Fit) -> List[str]:
    g = Graph()
    g.comment("The inputs, clamped to the fitted box (a shader cannot report an error).")
    L = g.node("clamp", "float", "L", in_=("float", "@lightness"), low=("float", L_RANGE[0]), high=("float", L_RANGE[1]))
    c = g.node("clamp", "float", "c", in_=("float", "@c"), low=("float", C_RANGE[0]), high=("float", C_RANGE[1]))
    d = g.node("clamp", "float", "d", in_=("float", "@d"), low=("float", D_RANGE[0]), high=("float", D_RANGE[1]))

    g.comment("CIELAB (D65) -> XYZ (CIE 15; Y exactly f^-1(L*), eq. 6) -> linear Rec. 709, negative channels to 0.")
    fy = g.node("divide", "float", "fy", in1=("float", g.node("add", "float", in1=("float", L), in2=("float", 16.0))),
                in2=("float", 116.0))
    fx = g.node("add", "float", in1=("float", fy), in2=("float", g.node("divide", "float", in1=("float", "@a"),
                                                                         in2=("float", 500.0))))
    fz = g.node("subtract", "float", in1=("float", fy), in2=("float", g.node("divide", "float", in1=("float", "@b"),
                                                                              in2=("float", 200.0))))
    X = g.node("multiply", "float", in1=("float", _lab_finv(g, fx)), in2=("float", WHITE_X))
    Z = g.node("multiply", "float", in1=("float", _lab_finv(g, fz)), in2=("float", WHITE_Z))
    Y = g.node("ifgreater", "float", "Y", value1=("float", L), value2=("float", 8.0),
               in1=("float", g.node("power", "float", in1=("float", fy), in2=("float", 3.0))),
               in2=("float", g.node("divide", "float", in1=("float", L), in2=("float", 24389.0 / 27.0))))
    xyz = g.node("combine3", "vector3", "xyz", in1=("float", X), in2=("float", Y), in3=("float", Z))
    rows = [g.node("dotproduct", "float", in1=("vector3", xyz), in2=("vector3", row)) for row in XYZ_TO_REC709]
    rgb = g.node("combine3", "color3", in1=("float", rows[0]), in2=("float", rows[1]), in3=("float", rows[2]))
    rgb = g.node("max", "color3", "rgb", in1=("color3", rgb), in2=("float", 0.0))

    g.comment(f"The fitted inverse of the bridge's tables: (ln F0, ln alpha, beta/Y) = polynomial of degree {fit.degree} "
              "in (x, y, z) = (L*/50 - 1, sqrt(c)/0.35 - 1, (ln(1 - d) + 2.76)/1.84); docs/materialx.md.")
    x = g.node("subtract", "float", "x", in1=("float", g.node("divide", "float", in1=("float", L), in2=("float", 50.0))),
               in2=("float", 1.0))
    y = g.node("subtract", "float", "y", in1=("float", g.node("divide", "float", in1=("float", g.node(
        "sqrt", "float", in_=("float", c))), in2=("float", SQRT_C_SCALE))), in2=("float", 1.0))
    one_minus_d = g.node("subtract", "float", in1=("float", 1.0), in2=("float", d))
    z = g.node("divide", "float", "z", in1=("float", g.node("subtract", "float", in1=("float", g.node(
        "ln", "float", in_=("float", one_minus_d))), in2=("float", LN_A_CENTRE))), in2=("float", LN_A_HALF))
    g.comment("Onto (about) the reachable set, as the C bridge's nearest reachable paint: L* into its interval, then "
              "d, c, d between the fitted faces of the targets' box (F0 and alpha at their limits), "
              "c below the face beta = 0 for dark paints.")
    x = g.node("clamp", "float", "x_reachable", in_=("float", x), low=("float", fit.x_range[0]),
               high=("float", fit.x_range[1]))
    z = _clamp_between(g, z, _poly(g, fit.z_bounds, (x, y), BOUND_DEGREE), "z_between_alpha_faces")
    y = _clamp_between(g, y, _poly(g, fit.y_bounds, (x, z), BOUND_DEGREE), "y_between_f0_faces")
    dark = g.node("min", "float", in1=("float", y), in2=("float", _poly(g, fit.y_dark, (x, z), BOUND_DEGREE)))
    y = g.node("ifgreater", "float", "y_below_dark_face", value1=("float", fit.x_dark), value2=("float", x),
               in1=("float", dark), in2=("float", y))
    z = _clamp_between(g, z, _poly(g, fit.z_bounds, (x, y), BOUND_DEGREE), "z_reachable")
    q = _poly(g, fit.inverse, (x, y, z), fit.degree)
    g.node("separate3", "multioutput", "q", in_=("vector3", q))

    g.comment("Onto the targets' parameter box (pgloss_bridge_range): the nearest reachable F0, alpha, base.")
    g.node("clamp", "float", "f0_clamped", in_=("float", g.node("exp", "float", in_=("float", "#q.outx"))),
                low=("float", F0_RANGE[0]), high=("float", F0_RANGE[1]))
    alpha = g.node("clamp", "float", "alpha", in_=("float", g.node("exp", "float", in_=("float", "#q.outy"))),
                   low=("float", ALPHA_RANGE[0]), high=("float", ALPHA_RANGE[1]))
    g.node("sqrt", "float", "roughness_of_alpha", in_=("float", alpha))
    ratio = g.node("max", "float", "beta_over_y", in1=("float", "#q.outz"), in2=("float", 0.0))
    base = g.node("multiply", "color3", in1=("color3", rgb), in2=("float", ratio))
    g.comment("Every channel <= 1, the chromaticity kept (the bridge's beta <= Y / max channel).")
    g.node("separate3", "multioutput", "base_channels", in_=("color3", base))
    top = g.node("max", "float", in1=("float", g.node("max", "float", in1=("float", "#base_channels.outr"),
                                                      in2=("float", "#base_channels.outg"))),
                 in2=("float", "#base_channels.outb"))
    g.node("divide", "color3", "base_color_in_gamut", in1=("color3", base), in2=("float", g.node(
        "max", "float", in1=("float", top), in2=("float", 1.0))))
    return g.lines


PERCEPTUAL_INPUTS = """\
    <input name="lightness" type="float" value="50.0" uimin="0.0" uimax="100.0" uiname="Lightness L*"
           doc="CIELAB L* of the paint (D65) as the bridge's gloss meter reads it." />
    <input name="a" type="float" value="0.0" uimin="-128.0" uimax="128.0" uisoftmin="-60.0" uisoftmax="60.0" uiname="a*"
           doc="CIELAB a* (green-red), D65." />
    <input name="b" type="float" value="0.0" uimin="-128.0" uimax="128.0" uisoftmin="-60.0" uisoftmax="60.0" uiname="b*"
           doc="CIELAB b* (blue-yellow), D65." />
    <input name="c" type="float" value="0.057" uimin="0.0" uimax="0.5" uisoftmax="0.3" uiname="Contrast Gloss c"
           doc="Contrast gloss (eq. 4) of the paint as the bridge's gloss meter reads it." />
    <input name="d" type="float" value="0.96" uimin="0.6" uimax="0.99" uisoftmin="0.8" uiname="Distinctness Gloss d"
           doc="Distinctness-of-image gloss (eq. 3) of the paint as the bridge's gloss meter reads it." />"""


def document(fit: Fit) -> str:
    head = f"""<?xml version="1.0"?>
<!-- SPDX-FileCopyrightText: 2026 The pgloss authors -->
<!-- SPDX-License-Identifier: Apache-2.0 -->
<!--
  Generated by materialx/bridge_graph.py (do not edit by hand): the gloss bridge of pgloss
  (docs/bridge.md) as MaterialX node graphs of standard nodes only, so that a document using
  them renders in any MaterialX renderer. A paint (L*, a*, b*, c, d) drives OpenPBR Surface
  and Autodesk Standard Surface with the parameters that the bridge's gloss meter reads as that
  paint. The table inversion of the C bridge is a fitted polynomial here: docs/materialx.md
  states its error against the C bridge. An out-of-reach paint is moved onto (about) the
  reachable set first, as the C bridge's nearest reachable paint, and the parameters are kept
  in the targets' box; a shader cannot report the C bridge's status.
-->
<materialx version="1.39">

  <!-- Node: <pgloss_bridge_from_perceptual> - the bridge's forward map (pgloss_bridge_from_perceptual). -->
  <nodedef name="ND_pgloss_bridge_from_perceptual" node="pgloss_bridge_from_perceptual" nodegroup="translation"
           doc="Gloss bridge: a Pellacini-Ferwerda-Greenberg paint to the base colour (linear Rec. 709), microfacet roughness (alpha = roughness^2) and normal-incidence reflectance F0 of a dielectric GGX target (OpenPBR, Standard Surface).">
{PERCEPTUAL_INPUTS}
    <output name="base_color" type="color3" />
    <output name="roughness" type="float" />
    <output name="f0" type="float" />
  </nodedef>

  <nodegraph name="NG_pgloss_bridge_from_perceptual" nodedef="ND_pgloss_bridge_from_perceptual">
"""
    body = "\n".join(bridge_graph(fit))
    tail = f"""
    <output name="base_color" type="color3" nodename="base_color_in_gamut" />
    <output name="roughness" type="float" nodename="roughness_of_alpha" />
    <output name="f0" type="float" nodename="f0_clamped" />
  </nodegraph>

{_surface("pgloss_open_pbr_surface", "OpenPBR Surface", "open_pbr_surface", "geometry_normal", OPENPBR_NOTE,
           OPENPBR_CONVERSION, OPENPBR_INPUTS)}
{_surface("pgloss_standard_surface", "Autodesk Standard Surface", "standard_surface", "normal", STANDARD_NOTE,
           STANDARD_CONVERSION, STANDARD_INPUTS)}
</materialx>
"""
    return head + body + tail


OPENPBR_NOTE = ("base_weight 1, specular_ior 1.5, specular_weight = F0 / 0.04 (OpenPBR spec, \"Specular\": "
                "the weight scales F0 of the IOR)")
OPENPBR_CONVERSION = [("multiply", "specular_weight", (("in1", "#bridge.f0"), ("in2", 25.0)))]
OPENPBR_INPUTS = (("base_weight", 1.0), ("specular_weight", "#specular_weight"), ("specular_ior", 1.5))
STANDARD_NOTE = ("base 1, specular 1, and F0 carried by specular_IOR = (1 + sqrt(F0)) / (1 - sqrt(F0)) "
                 "(Standard Surface spec, \"Specular\")")
STANDARD_CONVERSION = [("sqrt", "sqrt_f0", (("in", "#bridge.f0"),)),
                       ("add", "ior_num", (("in1", 1.0), ("in2", "#sqrt_f0"))),
                       ("subtract", "ior_den", (("in1", 1.0), ("in2", "#sqrt_f0"))),
                       ("divide", "specular_IOR", (("in1", "#ior_num"), ("in2", "#ior_den")))]
STANDARD_INPUTS = (("base", 1.0), ("specular", 1.0), ("specular_IOR", "#specular_IOR"))


def _surface(node: str, title: str, surface: str, normal: str, note: str, conversion, inputs) -> str:
    """A surface node from a paint: the bridge node, the target's F0 convention, the target's
    surface node with the bridge's base colour and roughness."""
    g = Graph()
    for kind, name, ins in conversion:
        g.node(kind, "float", name, **{k: ("float", v) for k, v in ins})
    g.node(surface, "surfaceshader", "surface", base_color=("color3", "#bridge.base_color"),
           specular_roughness=("float", "#bridge.roughness"), **{k: ("float", v) for k, v in inputs},
           **{normal: ("vector3", "@" + normal)})
    body = "\n".join(g.lines)
    return f"""  <!-- Node: <{node}> - {title} from a paint: {note}. -->
  <nodedef name="ND_{node}" node="{node}" nodegroup="pbr"
           doc="{title} with the parameters of the gloss bridge for a paint (L*, a*, b*, c, d).">
{PERCEPTUAL_INPUTS}
    <input name="{normal}" type="vector3" defaultgeomprop="Nworld" uiname="Normal" />
    <output name="out" type="surfaceshader" />
  </nodedef>

  <nodegraph name="NG_{node}" nodedef="ND_{node}">
{_bridge_call()}
{body}
    <output name="out" type="surfaceshader" nodename="surface" />
  </nodegraph>
"""


def _bridge_call() -> str:
    ins = "\n".join(f'      <input name="{n}" type="float" interfacename="{n}" />'
                    for n in ("lightness", "a", "b", "c", "d"))
    return f'    <pgloss_bridge_from_perceptual name="bridge" type="multioutput">\n{ins}\n    </pgloss_bridge_from_perceptual>'


def graph_params(lib: C.CDLL, fit: Fit, paint: Sequence[float]) -> Tuple[List[float], float, float]:
    """The graph's arithmetic in double for one paint: (base colour, roughness, F0)."""
    L, a, b, c, d = paint
    f0, alpha, ratio = (float(v[0]) for v in predict(fit, L, c, d))
    rgb = (C.c_double * 3)()
    lib.pgloss_rgb_from_lab((C.c_double * 3)(min(max(L, 0.0), 100.0), a, b), rgb)
    base = [max(v, 0.0) * ratio for v in rgb]
    top = max(max(base), 1.0)
    return [v / top for v in base], float(np.sqrt(alpha)), f0


def report(lib: C.CDLL, fit: Fit, n: int = 4000, seed: int = 1, quiet: bool = False) -> np.ndarray:
    """The graph's error against the C bridge at random paints (not the fitting grid): prints
    the tables (unless quiet); returns the reachable paints' rows (d, |ΔL*|, |Δa*|, |Δb*|, |Δc|, |Δd|)."""
    rng = np.random.default_rng(seed)
    paints = np.stack([rng.uniform(0, 100, n), rng.uniform(-40, 40, n) * (rng.random(n) < 0.5),
                       rng.uniform(-40, 40, n) * (rng.random(n) < 0.5), rng.uniform(0, 0.5, n),
                       rng.uniform(0.6, 0.99, n)], -1)
    inside, outside, params = [], [], []
    for p in paints:
        st, want, reached = from_paint(lib, p)
        base, rough, f0 = graph_params(lib, fit, p)
        _, got = to_paint(lib, base, rough, 1.5, f0 / 0.04)
        got_v = np.array([got.L, got.a, got.b, got.c, got.d])
        if st >= 0:
            inside.append((p[4], *np.abs(got_v - p)))
            params.append((abs(f0 / (want.specular * 0.04) - 1), abs(rough / want.roughness - 1),
                           abs(base[1] - want.base_color[1])))
        elif st in REACH_STATUSES:
            want = np.array([reached.L, reached.a, reached.b, reached.c, reached.d])
            outside.append((p[4], *np.abs(got_v - want)))
    if quiet:
        return np.array(inside)
    q = np.array(params)
    print(f"parameters at the reachable paints against pgloss_bridge_from_perceptual: relative |dF0| median "
          f"{np.median(q[:, 0]):.4f} p99 {np.percentile(q[:, 0], 99):.4f} max {q[:, 0].max():.4f}; relative "
          f"|droughness| median {np.median(q[:, 1]):.4f} p99 {np.percentile(q[:, 1], 99):.4f} max {q[:, 1].max():.4f}; "
          f"|dG| of the base colour median {np.median(q[:, 2]):.4f} p99 {np.percentile(q[:, 2], 99):.4f} "
          f"max {q[:, 2].max():.4f}")
    for name, rows in (("reachable", inside), ("out of reach (vs the C bridge's nearest reachable paint)", outside)):
        e = np.array(rows)
        for label, m in (("all d", np.ones(len(e), bool)), ("d >= 0.8", e[:, 0] >= 0.8)):
            q = e[m, 1:]
            print(f"{name}, {label}: {m.sum()} paints; |dL*| |da*| |db*| |dc| |dd|")
            for stat, v in (("median", np.median(q, 0)), ("p95", np.percentile(q, 95, 0)),
                            ("p99", np.percentile(q, 99, 0)), ("max", q.max(0))):
                print(f"  {stat:6s} " + " ".join(f"{x:8.4f}" for x in v))
    return np.array(inside)


def study(lib: C.CDLL, rows: np.ndarray, fit: Fit) -> None:
    """Cost against error per degree of the inverse: the graph's nodes, the generated GLSL's size
    and its compile + link time on llvmpipe (moderngl), against the errors of report()."""
    import time  # noqa: PLC0415
    import tempfile  # noqa: PLC0415
    import MaterialX as mx  # noqa: PLC0415
    import MaterialX.PyMaterialXGenGlsl as mx_glsl  # noqa: PLC0415
    import MaterialX.PyMaterialXGenShader as mx_gen  # noqa: PLC0415
    import moderngl  # noqa: PLC0415

    os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"
    os.environ["MESA_SHADER_CACHE_DISABLE"] = "true"  # time the compiler, not its disk cache
    gl = moderngl.create_context(standalone=True, backend="egl", require=400)
    root = Path(mx.__file__).resolve().parent
    search = mx.FileSearchPath(str(root))
    search.append(str(root / "libraries"))
    std = mx.createDocument()
    mx.loadLibraries(["libraries"], search, std)

    def compile_time(text: str | None) -> Tuple[int, float]:
        """GLSL size (pixel stage) and the best of 3 compile + link times of the
        pgloss_open_pbr_surface (or, text None, a plain open_pbr_surface) material."""
        doc = mx.createDocument()
        if text is not None:
            with tempfile.NamedTemporaryFile("w", suffix=".mtlx", delete=False) as f:
                f.write(text)
            mx.readFromXmlFile(doc, f.name, search)
        doc.importLibrary(std)
        node = doc.addNode("open_pbr_surface" if text is None else "pgloss_open_pbr_surface", "SR", "surfaceshader")
        m = doc.addMaterialNode("M", node)
        gen = mx_glsl.GlslShaderGenerator.create()
        ctx = mx_gen.GenContext(gen)
        ctx.registerSourceCodeSearchPath(search)
        shader = gen.generate("M", m, ctx)
        src, vert = shader.getSourceCode(mx_gen.PIXEL_STAGE), shader.getSourceCode(mx_gen.VERTEX_STAGE)
        fbo = gl.simple_framebuffer((1, 1))
        fbo.use()
        times = []
        for _ in range(3):  # Mesa compiles at the first draw: time program, one draw and its read
            t = time.perf_counter()
            prog = gl.program(vertex_shader=vert, fragment_shader=src)
            vao = gl.vertex_array(prog, [])
            vao.render(moderngl.POINTS, vertices=1)
            fbo.read()
            times.append(time.perf_counter() - t)
            vao.release()
            prog.release()
        return len(src), min(times)

    size0, t0 = compile_time(None)
    print(f"open_pbr_surface alone: GLSL {size0 / 1000:.0f} kB, compile + link {t0:.2f} s (llvmpipe; load "
          f"{os.getloadavg()[0]:.1f})")
    print("| degree | terms | nodes | GLSL kB | compile + link s | p99 |dL*| | p99 |dc| | p99 |dd| | max |dL*| | max |dc| | max |dd| |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for degree in (4, 5, 6, 7, 8):
        f = fit._replace(inverse=fit_inverse(rows, degree=degree), degree=degree)
        text = document(f)
        size, t = compile_time(text)
        e = report(lib, f, quiet=True)[:, 1:]
        nodes = len(re.findall(r"^    <(?!input |output |!--)\w+ name=", text, re.M))
        p99, mx_ = np.percentile(e, 99, axis=0), e.max(axis=0)
        print(f"| {degree} | {len(exponents(degree))} | {nodes} | {size / 1000:.0f} | {t:.2f} | {p99[0]:.2f} | "
              f"{p99[3]:.4f} | {p99[4]:.4f} | {mx_[0]:.2f} | {mx_[3]:.4f} | {mx_[4]:.4f} |", flush=True)


def main(argv: Sequence[str]) -> int:
    lib = bridge_lib()
    lo, hi, alo, ahi = (C.c_double() for _ in range(4))
    lib.pgloss_bridge_range(OPENPBR, C.byref(lo), C.byref(hi), C.byref(alo), C.byref(ahi))
    assert np.allclose((lo.value, hi.value), F0_RANGE) and np.allclose((alo.value, ahi.value), ALPHA_RANGE)
    cache = Path(argv[argv.index("--rows") + 1]) if "--rows" in argv else None
    if cache is not None and cache.exists():
        rows = np.load(cache)
    else:
        rows = training_set(lib)
        if cache is not None:
            np.save(cache, rows)
    faces = boundary_paints(lib)
    reach = features(rows[rows[:, 3] >= 0, 0], rows[rows[:, 3] >= 0, 1], rows[rows[:, 3] >= 0, 2])
    xs = np.concatenate([reach[:, 0], faces[0][:, 0], faces[1][:, 0]])
    dark = faces[2]
    y_dark = np.linalg.lstsq(monomials(dark[:, [0, 2]], BOUND_DEGREE), dark[:, 1], rcond=None)[0][:, None]
    fit = Fit(fit_inverse(rows), *fit_bounds(faces[0], faces[1]), (float(xs.min()), float(xs.max())),
              y_dark, float(dark[:, 0].max()))
    if "--study" in argv:
        study(lib, rows, fit)
        return 0
    text = document(fit)
    if "--check" in argv:
        same = OUT.exists() and OUT.read_text() == text
        print("pgloss_bridge.mtlx is " + ("up to date" if same else "OUT OF DATE: rerun materialx/bridge_graph.py"))
        return 0 if same else 1
    OUT.write_text(text)
    print(f"wrote {OUT.relative_to(ROOT)}: degree {DEGREE}, {len(exponents())} terms, "
          f"{int((rows[:, 3] >= 0).sum())} reachable paints of {len(rows)} fitted")
    report(lib, fit)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
