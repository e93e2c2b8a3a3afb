#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Reference generator for the pgloss shared test vectors.

The vectors are the contract that every pgloss implementation (the C core, its batched
entry points, and the Python / GLSL / OSL ports) must meet.  This script transcribes,
independently of any implementation, the equations of Pellacini, Ferwerda & Greenberg,
"Toward a Psychophysically-Based Light Reflection Model for Image Synthesis", SIGGRAPH
2000 (eq. 2 and eqs. 3-8), the CIE 1976 L*a*b* definitions, the Rec. 709 primaries, and
the algorithms documented in the public headers libpgloss/include/pgloss/*.h (their
comments are the specification: validation order, clamping, normalisations, sampling).
It never calls or reads the C implementation.

Expected values are computed with mpmath at 40 significant digits (``mp.dps = 40``)
from the exact (float32- or double-) representable inputs, and rounded once to the
nearest double.  For every checked output the generator also stores ``sens``, a
first-order sensitivity used by the tolerance model (see tests/vectors/README.md):

    |got - want| <= abs + rel * |want| + kappa_rel * sens

``sens`` = sum over perturbation points p of |d out / d eps_p|, where eps_p is a
relative perturbation of an input or of an intermediate quantity of the documented
algorithm (e.g. the exponent of the specular lobe, the terms of h = wo + wi).  It is
the condition number of the output times |want|; it is computed by central
differences in double arithmetic, or in mpmath where the double step is not in the
linear regime (it only needs two significant digits), and stored rounded up to two
significant digits.  Cases where float cannot resolve the output at all are tagged
"ill_conditioned" (README.md).

Usage:
    python3 tests/vectors/generate.py --out tests/vectors     # (re)write the JSON files
    python3 tests/vectors/generate.py --check                 # exit 1 if a file differs

The output is byte-identical from run to run: fixed seeds, mpmath for every input
that is derived through a transcendental function, fixed number formatting, no
timestamps.
"""

from __future__ import annotations

import argparse
import filecmp
import math
import os
import random
import struct
import sys
import tempfile
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

from mpmath import mp, mpf

mp.dps = 40

FORMAT = "pgloss-vectors"
VERSION = 1
GENERATOR = "tests/vectors/generate.py"

Num = Any  # an mpf (values) or a float (sensitivities)

# ----------------------------------------------------------------------------------
# Constants of the specification (headers), transcribed.
# ----------------------------------------------------------------------------------

OK = "PGLOSS_OK"
WARN_ALPHA = "PGLOSS_WARN_ALPHA_UNTRUSTED"
E_NULL = "PGLOSS_ERR_NULL"
E_NONFINITE = "PGLOSS_ERR_NONFINITE"
E_NEGATIVE = "PGLOSS_ERR_NEGATIVE"
E_ALPHA = "PGLOSS_ERR_ALPHA"
E_ENERGY = "PGLOSS_ERR_ENERGY"
E_ENVELOPE = "PGLOSS_ERR_ENVELOPE"
E_LIGHTNESS = "PGLOSS_ERR_LIGHTNESS"
E_GAMUT = "PGLOSS_ERR_GAMUT"
E_DIRECTION = "PGLOSS_ERR_DIRECTION"
E_NORMALIZATION = "PGLOSS_ERR_NORMALIZATION"
E_ARGUMENT = "PGLOSS_ERR_ARGUMENT"
E_RANDOM = "PGLOSS_ERR_RANDOM"

NORM_WARD, NORM_WARD_DUR, NORM_BOUNDED = 0, 1, 2
LOBE_NONE, LOBE_DIFFUSE, LOBE_SPECULAR, LOBE_ALL = 0, 1, 2, 3
LOBE_NAMES = {0: "PGLOSS_LOBE_NONE", 1: "PGLOSS_LOBE_DIFFUSE", 2: "PGLOSS_LOBE_SPECULAR"}

ALPHA_TRUSTED_MAX = 0.2           # double, as PGLOSS_ALPHA_TRUSTED_MAX
BOUNDARY_TOLERANCE = 1e-12        # PGLOSS_BOUNDARY_TOLERANCE
U_MAX = 1.0 - 2.0 ** -24          # sample(): u clamped to [0, 1 - 2^-24]

# Header luminance weights (the second row of Rec. 709 RGB -> XYZ), as printed in color.h.
LUMA_STR = ("0.21263900587151036", "0.71516867876775593", "0.072192315360733715")


def f32(x: float) -> float:
    """Round a double to the nearest float32 (round-to-nearest-even) and return it as a double."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def is_f32(x: float) -> bool:
    """True if x is exactly representable in float32 (NaN and infinities count as representable)."""
    if math.isnan(x) or math.isinf(x):
        return True
    return f32(x) == x


ALPHA_MIN_F = f32(1e-4)           # PGLOSS_ALPHA_MIN (1e-4f)
COS_MIN_F = f32(1e-9)             # PGLOSS_COS_MIN (1e-9f)
FLT_MAX = struct.unpack("<f", bytes.fromhex("ffff7f7f"))[0]


# ----------------------------------------------------------------------------------
# Arithmetic back ends: mpmath for the expected values, double for the sensitivities.
# ----------------------------------------------------------------------------------

class MPBackend:
    """mpmath at mp.dps digits: the expected values."""
    kind = "mp"
    pi = +mp.pi

    @staticmethod
    def num(x: Union[float, int, str]) -> mpf:
        return mpf(x)

    @staticmethod
    def frac(p: int, q: int) -> mpf:
        return mpf(p) / q

    exp = staticmethod(mp.exp)
    log = staticmethod(mp.log)
    sqrt = staticmethod(mp.sqrt)
    cbrt = staticmethod(mp.cbrt)
    cos = staticmethod(mp.cos)
    sin = staticmethod(mp.sin)


class FLBackend:
    """IEEE double (Python float): only used for the finite-difference sensitivities."""
    kind = "fl"
    pi = math.pi

    @staticmethod
    def num(x: Union[float, int, str]) -> float:
        return float(x)

    @staticmethod
    def frac(p: int, q: int) -> float:
        return p / q

    @staticmethod
    def exp(x: float) -> float:
        return math.exp(x) if x > -745.0 else 0.0

    log = staticmethod(math.log)
    sqrt = staticmethod(math.sqrt)
    cbrt = staticmethod(math.cbrt)
    cos = staticmethod(math.cos)
    sin = staticmethod(math.sin)


MP = MPBackend
FL = FLBackend
Backend = Any


class Hooks:
    """Perturbation points: ``p(name, v)`` returns v * (1 + eps[name]).

    With ``record=True`` the names met during an evaluation are collected, so that the
    sensitivity can perturb each of them in turn.
    """

    __slots__ = ("eps", "seen")

    def __init__(self, eps: Optional[Dict[str, float]] = None, record: bool = False) -> None:
        self.eps = eps or {}
        self.seen: Optional[set] = set() if record else None

    def p(self, name: str, v: Num) -> Num:
        if self.seen is not None:
            self.seen.add(name)
        e = self.eps.get(name)
        return v if e is None else v * (1 + e)


NOHOOK = Hooks()


def _flatten(prefix: str, v: Any, out: Dict[str, float]) -> None:
    if isinstance(v, dict):
        for k, x in v.items():
            _flatten(prefix + "." + k if prefix else k, x, out)
    elif isinstance(v, (list, tuple)):
        for i, x in enumerate(v):
            _flatten(f"{prefix}[{i}]", x, out)
    elif v is None or isinstance(v, (str, bool)):
        return
    else:
        out[prefix] = v


def _unflatten_like(template: Any, flat: Dict[str, float], prefix: str = "") -> Any:
    if isinstance(template, dict):
        return {k: _unflatten_like(x, flat, prefix + "." + k if prefix else k)
                for k, x in template.items()}
    if isinstance(template, (list, tuple)):
        return [_unflatten_like(x, flat, f"{prefix}[{i}]") for i, x in enumerate(template)]
    if template is None or isinstance(template, (str, bool)):
        return None
    return flat.get(prefix, 0.0)


def _sens_pass(fn: Callable[[Backend, Hooks], Dict[str, Any]], B: Backend,
               delta: Num) -> Tuple[Dict[str, float], Dict[str, float], Any, float]:
    """One pass of central differences. Also returns the largest one-sided change of an output
    relative to its value (to detect a step that is not in the linear regime)."""
    rec = Hooks(record=True)
    base = fn(B, rec)
    flat: Dict[str, Any] = {}
    _flatten("", base, flat)
    acc = {k: 0.0 for k in flat}
    worst = 0.0
    for name in sorted(rec.seen or ()):
        hi: Dict[str, Any] = {}
        lo: Dict[str, Any] = {}
        _flatten("", fn(B, Hooks({name: delta})), hi)
        _flatten("", fn(B, Hooks({name: -delta})), lo)
        for k, b in flat.items():
            h, lw = hi.get(k, 0), lo.get(k, 0)
            acc[k] += float(abs(h - lw) / (2 * delta))
            if b != 0:
                worst = max(worst, float(max(abs(h - b), abs(lw - b)) / abs(b)))
    return {k: float(v) for k, v in flat.items()}, acc, base, worst


def sensitivity(fn: Callable[[Backend, Hooks], Dict[str, Any]]) -> Dict[str, Any]:
    """First-order sensitivity: sum over the perturbation points of |d out / d eps|.

    ``fn(backend, hooks)`` returns the outputs (a dict of numbers / lists of numbers).
    Central differences in double with a relative step of 1e-7; where that step is not in
    the linear regime (a one-sided step changes an output by more than 1e-4 of its value,
    or a division by zero occurs), the differences are redone in mpmath with a step of 1e-25.
    """
    try:
        flat, acc, base, worst = _sens_pass(fn, FL, 1e-7)
        linear = worst <= 1e-4
    except (ZeroDivisionError, ValueError, OverflowError):
        linear = False
    if not linear:
        flat, acc, base, worst = _sens_pass(fn, MP, mpf("1e-25"))
    return _unflatten_like(base, acc)


U_FLOAT = 2.0 ** -24
ILL_CONDITIONED = 0.05


def ill_conditioned_float(want: Any, sens: Any, absolute: bool = False) -> bool:
    """True if float's unit roundoff times the sensitivity exceeds 5% of the value (or 0.05
    absolutely for unit vectors): first-order error theory is then not reliable in float."""
    fw: Dict[str, float] = {}
    fs: Dict[str, float] = {}
    _flatten("", want, fw)
    _flatten("", sens, fs)
    for k, w in fw.items():
        scale = 1.0 if absolute else abs(w)
        if w != 0 and fs.get(k, 0.0) * U_FLOAT > ILL_CONDITIONED * scale:
            return True
    return False


def round_up_2(x: float) -> float:
    """Round a non-negative sensitivity up to two significant digits (stable formatting)."""
    if not (x > 0.0) or math.isinf(x):
        return 0.0 if not x > 0.0 else x
    e = math.floor(math.log10(x)) - 1
    m = math.ceil(x / 10.0 ** e - 1e-9)
    return float(f"{m}e{e}")


# ----------------------------------------------------------------------------------
# JSON output: deterministic, exact doubles, one case per line.
# ----------------------------------------------------------------------------------

def enc(x: Any) -> Any:
    """Encode an input number for JSON: non-finite values become "nan", "inf", "-inf"."""
    if isinstance(x, float):
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
    return x


def _fmt_float(x: float) -> str:
    if math.isnan(x) or math.isinf(x):
        raise ValueError("non-finite number must be encoded with enc()")
    if x == 0.0:
        return "-0.0" if math.copysign(1.0, x) < 0 else "0.0"
    s = "%.17g" % x
    if "." not in s and "e" not in s and "n" not in s:
        s += ".0"
    assert float(s) == x
    return s


class Short(float):
    """A metadata number (tolerance, sensitivity): written in the shortest exact form."""


def short_tree(v: Any) -> Any:
    if isinstance(v, dict):
        return {k: short_tree(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [short_tree(x) for x in v]
    if isinstance(v, float):
        return Short(v)
    return v


def _dump(v: Any) -> str:
    if v is None:
        return "null"
    if isinstance(v, Short):
        return _fmt_float(v) if v == 0 else repr(float(v))
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return _fmt_float(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ",".join(_dump(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ",".join(_dump(str(k)) + ":" + _dump(x) for k, x in v.items()) + "}"
    raise TypeError(f"cannot serialise {type(v)}")


def dump_file(doc: Dict[str, Any]) -> str:
    """Top-level keys one per line; the items of list/dict values one per line, compact."""
    lines = ["{"]
    keys = list(doc.keys())
    for i, k in enumerate(keys):
        v = doc[k]
        comma = "," if i + 1 < len(keys) else ""
        if isinstance(v, list) and v:
            lines.append(f"  {_dump(k)}:[")
            for j, x in enumerate(v):
                lines.append("    " + _dump(x) + ("," if j + 1 < len(v) else ""))
            lines.append("  ]" + comma)
        elif isinstance(v, dict) and v:
            lines.append(f"  {_dump(k)}:{{")
            items = list(v.items())
            for j, (kk, x) in enumerate(items):
                lines.append("    " + _dump(kk) + ":" + _dump(x) + ("," if j + 1 < len(items) else ""))
            lines.append("  }" + comma)
        else:
            lines.append(f"  {_dump(k)}:{_dump(v)}{comma}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def D(x: Num) -> float:
    """Round an mpf (or a float) to the nearest double."""
    return float(x)


def exp_out(v: Any) -> Any:
    """Expected outputs: mpf -> nearest double, recursively; None stays null (unspecified)."""
    if isinstance(v, dict):
        return {k: exp_out(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [exp_out(x) for x in v]
    if v is None or isinstance(v, (str, bool, int)):
        return v
    return D(v)


def sens_out(v: Any) -> Any:
    if isinstance(v, dict):
        return {k: sens_out(x) for k, x in v.items() if x is not None}
    if isinstance(v, (list, tuple)):
        return [sens_out(x) for x in v]
    if v is None:
        return None
    return Short(round_up_2(float(v)))


# ----------------------------------------------------------------------------------
# CIE 1976 lightness, CIELAB and Rec. 709 (color.h, perceptual.h).
# ----------------------------------------------------------------------------------

def _rec709_matrices() -> Tuple[List[List[mpf]], List[List[mpf]], mpf, mpf]:
    """RGB -> XYZ and XYZ -> RGB from the Rec. 709 primaries and the D65 chromaticity."""
    prim = [(mpf("0.64"), mpf("0.33")), (mpf("0.30"), mpf("0.60")), (mpf("0.15"), mpf("0.06"))]
    xw, yw = mpf("0.3127"), mpf("0.3290")
    P = mp.matrix(3, 3)
    for j, (x, y) in enumerate(prim):
        P[0, j] = x / y
        P[1, j] = mpf(1)
        P[2, j] = (1 - x - y) / y
    W = mp.matrix([xw / yw, mpf(1), (1 - xw - yw) / yw])
    S = mp.lu_solve(P, W)
    M = mp.matrix(3, 3)
    for i in range(3):
        for j in range(3):
            M[i, j] = P[i, j] * S[j]
    Mi = M ** -1
    Ml = [[M[i, j] for j in range(3)] for i in range(3)]
    Mil = [[Mi[i, j] for j in range(3)] for i in range(3)]
    return Ml, Mil, xw / yw, (1 - xw - yw) / yw


M_RGB2XYZ, M_XYZ2RGB, XN, ZN = _rec709_matrices()
LUMA = [mpf(s) for s in LUMA_STR]
for _j in range(3):  # the header's constants are the derived luminance row
    assert abs(LUMA[_j] - M_RGB2XYZ[1][_j]) < mpf("1e-17"), (_j, LUMA[_j], M_RGB2XYZ[1][_j])
_MF = {"mp": (M_RGB2XYZ, M_XYZ2RGB, XN, ZN, LUMA),
       "fl": ([[float(v) for v in r] for r in M_RGB2XYZ], [[float(v) for v in r] for r in M_XYZ2RGB],
              float(XN), float(ZN), [float(v) for v in LUMA])}

# Working colour spaces (color.h, pgloss_color_space). CIELAB stays relative to D65 in every
# space; a space whose white is not D65 (ACEScg: the ACES white 0.32168, 0.33767) is reached
# through a Bradford chromatic adaptation D65 -> its white. Everything at mp.dps digits.
COLOR_SPACES = ("linear_rec709", "acescg", "linear_display_p3", "linear_rec2020")
_SPACE_DEF = {
    1: ([("0.713", "0.293"), ("0.165", "0.830"), ("0.128", "0.044")], ("0.32168", "0.33767")),  # ACES AP1
    2: ([("0.680", "0.320"), ("0.265", "0.690"), ("0.150", "0.060")], ("0.3127", "0.3290")),    # P3, D65
    3: ([("0.708", "0.292"), ("0.170", "0.797"), ("0.131", "0.046")], ("0.3127", "0.3290")),    # BT.2020
}
BRADFORD = [["0.8951", "0.2664", "-0.1614"], ["-0.7502", "1.7135", "0.0367"], ["0.0389", "-0.0685", "1.0296"]]


def _xyz_of_xy(x: mpf, y: mpf) -> Any:
    return mp.matrix([x / y, mpf(1), (1 - x - y) / y])


def _npm(prim: Sequence[Tuple[str, str]], white: Tuple[str, str]) -> Any:
    """Normalised primary matrix RGB -> XYZ (in the space's own white, Y of white = 1)."""
    P = mp.matrix(3, 3)
    for j, (xs, ys) in enumerate(prim):
        c = _xyz_of_xy(mpf(xs), mpf(ys))
        for i in range(3):
            P[i, j] = c[i]
    S = mp.lu_solve(P, _xyz_of_xy(mpf(white[0]), mpf(white[1])))
    M = mp.matrix(3, 3)
    for i in range(3):
        for j in range(3):
            M[i, j] = P[i, j] * S[j]
    return M


def _bradford(src: Tuple[str, str], dst: Tuple[str, str]) -> Any:
    """Bradford (von Kries in the Bradford cone space) adaptation XYZ(src white) -> XYZ(dst white)."""
    MA = mp.matrix([[mpf(v) for v in r] for r in BRADFORD])
    ls = MA * _xyz_of_xy(mpf(src[0]), mpf(src[1]))
    ld = MA * _xyz_of_xy(mpf(dst[0]), mpf(dst[1]))
    Dg = mp.diag([ld[k] / ls[k] for k in range(3)])
    return MA ** -1 * Dg * MA


def _space_matrices(space: int) -> Tuple[List[List[mpf]], List[List[mpf]]]:
    """(RGB -> XYZ(D65), XYZ(D65) -> RGB) of a working space."""
    if space == 0:
        return M_RGB2XYZ, M_XYZ2RGB
    prim, white = _SPACE_DEF[space]
    M = _npm(prim, white)
    if white != ("0.3127", "0.3290"):
        M = _bradford(white, ("0.3127", "0.3290")) * M
    Mi = M ** -1
    # An entry that is exactly 0 (z of a primary with x + y = 1) comes out as 40-digit noise.
    clean = lambda v: mpf(0) if abs(v) < mpf("1e-30") else v  # noqa: E731
    return ([[clean(M[i, j]) for j in range(3)] for i in range(3)],
            [[clean(Mi[i, j]) for j in range(3)] for i in range(3)])


for _s in range(1, len(COLOR_SPACES)):
    _m, _mi = _space_matrices(_s)
    _MF[("mp", _s)] = (_m, _mi, XN, ZN, _m[1])
    _MF[("fl", _s)] = ([[float(v) for v in r] for r in _m], [[float(v) for v in r] for r in _mi],
                       float(XN), float(ZN), [float(v) for v in _m[1]])


def _mf(B: Backend, space: int) -> Tuple[Any, ...]:
    return _MF[B.kind] if space == 0 else _MF[(B.kind, space)]


def c_matrix_table() -> str:
    """The C table of color.c (``python3 generate.py --print-color-matrices``): %.17g round-trips."""
    out = []
    for s in range(len(COLOR_SPACES)):
        m, mi = _space_matrices(s)
        rows = []
        for name, mat in (("to_xyz", m), ("from_xyz", mi)):
            rows.append("        {" + ",\n         ".join(
                "{" + ", ".join("%.17g" % float(v) for v in r) + "}" for r in mat) + "},")
        out.append("    { /* %s */\n%s\n    }," % (COLOR_SPACES[s], "\n".join(rows)))
    return "\n".join(out)


def cie_eps(B: Backend) -> Num:
    return B.frac(216, 24389)


def cie_kappa(B: Backend) -> Num:
    return B.frac(24389, 27)


def y_from_l(B: Backend, H: Hooks, L: Num) -> Num:
    """CIE 1976 inverse lightness f^-1 (L in [0, 100], Yn = 1): L/kappa for L <= 8, else ((L+16)/116)^3."""
    if L <= 8:
        return L * 27 / B.num(24389)
    t = (L + 16) / 116
    return t * t * t


def l_from_y(B: Backend, H: Hooks, Y: Num) -> Num:
    """CIE 1976 lightness: kappa*Y for Y <= eps, else 116 cbrt(Y) - 16."""
    if Y <= cie_eps(B):
        return cie_kappa(B) * Y
    return 116 * B.cbrt(Y) - 16


def lab_f(B: Backend, t: Num) -> Num:
    return B.cbrt(t) if t > cie_eps(B) else (cie_kappa(B) * t + 16) / 116


def lab_finv(B: Backend, t: Num, lin: Num) -> Num:
    """Inverse of lab_f; ``lin`` = t - 4/29 computed without cancellation by the caller."""
    if t > B.frac(6, 29):
        return t * t * t
    return 3 * B.frac(36, 841) * lin


def rgb_from_lab_core(B: Backend, H: Hooks, L: Num, a: Num, b: Num, space: int = 0) -> List[Num]:
    M, Mi, Xn, Zn, _ = _mf(B, space)
    L = H.p("L", L)
    a = H.p("a", a)
    b = H.p("b", b)
    fy0 = (L + 16) / 116
    fx0 = fy0 + a / 500
    fz0 = fy0 - b / 200
    # Perturbation points on the CIELAB f values (the standard inverse forms f - 4/29, which
    # cancels for dark colours); the unperturbed linear parts are computed without cancellation.
    fx, fy, fz = H.p("fx", fx0), H.p("fy", fy0), H.p("fz", fz0)
    X = Xn * lab_finv(B, fx, L / 116 + a / 500 + (fx - fx0))
    Y = lab_finv(B, fy, L / 116 + (fy - fy0))
    Z = Zn * lab_finv(B, fz, L / 116 - b / 200 + (fz - fz0))
    v = (X, Y, Z)
    return [sum(H.p(f"m{i}{j}", Mi[i][j] * v[j]) for j in range(3)) for i in range(3)]


def lab_from_rgb_core(B: Backend, H: Hooks, rgb: Sequence[Num], space: int = 0) -> List[Num]:
    M, Mi, Xn, Zn, _ = _mf(B, space)
    r = [H.p(f"rgb{j}", rgb[j]) for j in range(3)]
    X, Y, Z = (sum(M[i][j] * r[j] for j in range(3)) for i in range(3))
    fx = H.p("fx", lab_f(B, X / Xn))
    fy = H.p("fy", lab_f(B, Y))
    fz = H.p("fz", lab_f(B, Z / Zn))
    return [116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)]


def luminance_core(B: Backend, H: Hooks, rgb: Sequence[Num], space: int = 0) -> Num:
    lw = _mf(B, space)[4]
    return sum(H.p(f"y{j}", lw[j] * rgb[j]) for j in range(3))


# ----------------------------------------------------------------------------------
# Gloss space (paper eqs. 3-8, perceptual.h).
# ----------------------------------------------------------------------------------

def contrast_core(B: Backend, rho_d: Num, rho_s: Num) -> Num:
    """Eq. 4, c = cbrt(rs + rd/2) - cbrt(rd/2), as rs / (A^2 + AB + B^2) (exact identity)."""
    if rho_s == 0:
        return rho_s * 0
    A = B.cbrt(rho_s + rho_d / 2)
    Bq = B.cbrt(rho_d / 2)
    return rho_s / (A * A + A * Bq + Bq * Bq)


def specular_core(B: Backend, rho_d: Num, c: Num) -> Num:
    """Eq. 7, rs = (c + cbrt(rd/2))^3 - rd/2, as c (c^2 + 3 c Bq + 3 Bq^2) (exact identity)."""
    Bq = B.cbrt(rho_d / 2)
    return c * (c * c + 3 * c * Bq + 3 * Bq * Bq)


def envelope_core(B: Backend, rho_d: Num) -> Num:
    """cbrt(1 - rd/2) - cbrt(rd/2) = (1 - rd) / (A^2 + AB + B^2) (Fig. 10's envelope)."""
    A = B.cbrt(1 - rho_d / 2)
    Bq = B.cbrt(rho_d / 2)
    return (1 - rho_d) / (A * A + A * Bq + Bq * Bq)


D_WEIGHT_STR = "1.78"


def isfin(*xs: float) -> bool:
    return all(not (math.isnan(x) or math.isinf(x)) for x in xs)


# ----------------------------------------------------------------------------------
# Reference functions of perceptual.h / color.h: ref(B, H, input) -> (status, outputs).
# Outputs of an error are the documented fallback (0), or None where the header leaves
# them unspecified (the runner then only checks that they are finite).
# ----------------------------------------------------------------------------------

Ref = Callable[[Backend, Hooks, Dict[str, Any]], Tuple[str, Dict[str, Any]]]


def _in(B: Backend, H: Hooks, name: str, x: float) -> Num:
    return H.p(name, B.num(x))


def ref_lightness_from_luminance(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    Y = i["Y"]
    if not isfin(Y):
        return E_NONFINITE, {"L": 0.0}
    if Y < 0:
        return E_NEGATIVE, {"L": 0.0}
    return OK, {"L": l_from_y(B, H, _in(B, H, "Y", Y))}


def ref_luminance_from_lightness(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    L = i["L"]
    if not isfin(L):
        return E_NONFINITE, {"Y": 0.0}
    if L < 0:
        return E_LIGHTNESS, {"Y": 0.0}
    return OK, {"Y": y_from_l(B, H, _in(B, H, "L", L))}


def ref_contrast_gloss(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rd, rs = i["rho_d"], i["rho_s"]
    if not isfin(rd, rs):
        return E_NONFINITE, {"c": 0.0}
    if rd < 0 or rs < 0:
        return E_NEGATIVE, {"c": 0.0}
    return OK, {"c": contrast_core(B, _in(B, H, "rho_d", rd), _in(B, H, "rho_s", rs))}


def ref_specular_from_contrast(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rd, c = i["rho_d"], i["c"]
    if not isfin(rd, c):
        return E_NONFINITE, {"rho_s": 0.0}
    if rd < 0 or c < 0:
        return E_NEGATIVE, {"rho_s": 0.0}
    return OK, {"rho_s": specular_core(B, _in(B, H, "rho_d", rd), _in(B, H, "c", c))}


def ref_gloss_from_physical(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rd, rs, al = i["rho_d"], i["rho_s"], i["alpha"]
    zero = {"L": 0.0, "c": 0.0, "d": 0.0}
    if not isfin(rd, rs, al):
        return E_NONFINITE, zero
    if rd < 0 or rs < 0:
        return E_NEGATIVE, zero
    if al <= 0:
        return E_ALPHA, zero
    st = WARN_ALPHA if al > ALPHA_TRUSTED_MAX else OK
    Rd, Rs, Al = _in(B, H, "rho_d", rd), _in(B, H, "rho_s", rs), _in(B, H, "alpha", al)
    return st, {"L": l_from_y(B, H, Rd), "c": contrast_core(B, Rd, Rs), "d": 1 - Al}


def ref_physical_from_gloss(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    L, c, d = i["L"], i["c"], i["d"]
    zero = {"rho_d": 0.0, "rho_s": 0.0, "alpha": 0.0}
    if not isfin(L, c, d):
        return E_NONFINITE, zero
    if L < 0 or L > 100:
        return E_LIGHTNESS, zero
    if c < 0:
        return E_NEGATIVE, zero
    if d >= 1:
        return E_ALPHA, zero
    st = WARN_ALPHA if d < 0.8 else OK
    Y = y_from_l(B, H, _in(B, H, "L", L))
    return st, {"rho_d": Y, "rho_s": specular_core(B, Y, _in(B, H, "c", c)), "alpha": 1 - _in(B, H, "d", d)}


def ref_gloss_distance(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    """Eq. 5 on any finite points; the status is the verdict on the two paints, as
    physical_from_gloss gives it on c and d (perceptual.h): NEGATIVE (c < 0), ALPHA (d >= 1),
    paint 1 before paint 2, then the warning for d < 0.8. D is written with NEGATIVE and ALPHA."""
    c1, d1, c2, d2 = i["c1"], i["d1"], i["c2"], i["d2"]
    if not isfin(c1, d1, c2, d2):
        return E_NONFINITE, {"D": 0.0}
    st = OK
    for c, d in ((c1, d1), (c2, d2)):
        if st == OK and c < 0:
            st = E_NEGATIVE
        if st == OK and d >= 1:
            st = E_ALPHA
    if st == OK and (d1 < 0.8 or d2 < 0.8):
        st = WARN_ALPHA
    dc = _in(B, H, "c1", c1) - _in(B, H, "c2", c2)
    dd = B.num(D_WEIGHT_STR) * (_in(B, H, "d1", d1) - _in(B, H, "d2", d2))
    if B.kind == "fl":
        return st, {"D": math.hypot(dc, dd)}
    return st, {"D": B.sqrt(dc * dc + dd * dd)}


def ref_envelope_contrast(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    L = i["L"]
    if not isfin(L):
        return E_NONFINITE, {"c_max": 0.0}
    if L < 0 or L > 100:
        return E_LIGHTNESS, {"c_max": 0.0}
    return OK, {"c_max": envelope_core(B, y_from_l(B, H, _in(B, H, "L", L)))}


def ref_match_gloss(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rd, rs, Lt = i["rho_d"], i["rho_s"], i["L_target"]
    zero = {"rho_d_out": 0.0, "rho_s_out": 0.0}
    if not isfin(rd, rs, Lt):
        return E_NONFINITE, zero
    if rd < 0 or rs < 0:
        return E_NEGATIVE, zero
    if Lt < 0 or Lt > 100:
        return E_LIGHTNESS, zero
    c = contrast_core(B, _in(B, H, "rho_d", rd), _in(B, H, "rho_s", rs))
    rd2 = y_from_l(B, H, _in(B, H, "L_target", Lt))
    rs2 = specular_core(B, rd2, c)
    st = OK
    if B.kind == "mp":
        excess = rd2 + rs2 - 1
        st = E_ENVELOPE if excess > BOUNDARY_TOLERANCE else OK
        if not i.get("_boundary"):
            assert abs(excess - BOUNDARY_TOLERANCE) > 1e-10, ("match_gloss too close to the envelope", i)
    return st, {"rho_d_out": rd2, "rho_s_out": rs2}


def ref_isogloss_contour(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    c0, d0, Dd, n = i["c0"], i["d0"], i["D"], i["n"]
    if not isfin(c0, d0, Dd):
        return E_NONFINITE, {"c": [0.0] * n, "d": [0.0] * n}
    if Dd < 0:
        return E_NEGATIVE, {"c": [0.0] * n, "d": [0.0] * n}
    if n == 0:
        return E_ARGUMENT, {"c": [], "d": []}
    C0, D0, DD = _in(B, H, "c0", c0), _in(B, H, "d0", d0), _in(B, H, "D", Dd)
    cs, ds = [], []
    for k in range(n):
        th = H.p(f"th{k}", 2 * B.pi * k / n)
        cs.append(C0 + H.p(f"tc{k}", DD * B.cos(th)))
        ds.append(D0 + H.p(f"td{k}", DD / B.num(D_WEIGHT_STR) * B.sin(th)))
    return OK, {"c": cs, "d": ds}


def _space_of(i: Dict[str, Any]) -> Optional[int]:
    """The working space of an input (absent: Rec. 709, as the functions without _ex); None if unknown."""
    s = i.get("space", 0)
    return s if s in range(len(COLOR_SPACES)) else None


def ref_rgb_from_lab(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    L, a, b = i["lab"]
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, {"rgb": [0.0] * 3}
    if not isfin(L, a, b):
        return E_NONFINITE, {"rgb": [0.0] * 3}
    if L < 0 or L > 100:
        return E_LIGHTNESS, {"rgb": [0.0] * 3}
    rgb = rgb_from_lab_core(B, H, B.num(L), B.num(a), B.num(b), sp)
    st = OK
    if B.kind == "mp":
        for ch in rgb:
            assert ch == 0 or abs(ch) > mpf("1e-9"), ("gamut decision too close to 0", i, ch)
        st = E_GAMUT if min(rgb) < 0 else OK
    return st, {"rgb": rgb}


def ref_lab_from_rgb(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rgb = i["rgb"]
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, {"lab": [0.0] * 3}
    if not isfin(*rgb):
        return E_NONFINITE, {"lab": [0.0] * 3}
    if min(rgb) < 0:
        return E_NEGATIVE, {"lab": [0.0] * 3}
    return OK, {"lab": lab_from_rgb_core(B, H, [B.num(x) for x in rgb], sp)}


def ref_luminance(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    rgb = i["rgb"]
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, {"Y": 0.0}
    if not isfin(*rgb):
        return E_NONFINITE, {"Y": 0.0}
    return OK, {"Y": luminance_core(B, H, [B.num(x) for x in rgb], sp)}


def _phys_fields(p: Dict[str, Any]) -> List[float]:
    return list(p["rho_d"]) + [p["rho_s"], p["alpha_x"], p["alpha_y"]]


def ref_check_physical(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    p = i["p"]
    if not isfin(*_phys_fields(p)):
        return E_NONFINITE, {}
    if max(abs(x) for x in _phys_fields(p)) > FLT_MAX:  # as material_init: a float material holds it
        return E_NONFINITE, {}
    if min(p["rho_d"]) < 0 or p["rho_s"] < 0:
        return E_NEGATIVE, {}
    if p["alpha_x"] <= 0 or p["alpha_y"] <= 0:
        return E_ALPHA, {}
    if p["normalization"] not in (0, 1, 2):
        return E_NORMALIZATION, {}
    excess = max(mpf(x) for x in p["rho_d"]) + mpf(p["rho_s"]) - 1
    if not i.get("_boundary"):
        assert abs(excess - BOUNDARY_TOLERANCE) > 1e-10, ("energy decision too close", i)
    if excess > BOUNDARY_TOLERANCE:
        return E_ENERGY, {}
    if max(p["alpha_x"], p["alpha_y"]) > ALPHA_TRUSTED_MAX:
        return WARN_ALPHA, {}
    return OK, {}


def _perceptual_analysis(q: Dict[str, float], space: int = 0) -> Dict[str, mpf]:
    L, a, b, c, d = (mpf(q[k]) for k in "Labcd")
    rgb = rgb_from_lab_core(MP, NOHOOK, L, a, b, space)
    Y = y_from_l(MP, NOHOOK, L)
    cmax = envelope_core(MP, Y)
    rs = specular_core(MP, Y, c)
    return {"rgb_min": min(rgb), "env_excess": c - cmax, "energy_excess": max(rgb) + rs - 1}


def ref_check_perceptual(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    q = i["q"]
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, {}
    if not isfin(*(q[k] for k in "Labcd")):
        return E_NONFINITE, {}
    if 1 - mpf(q["d"]) > FLT_MAX:  # α = 1 − d: no float material holds it
        return E_NONFINITE, {}
    if q["L"] < 0 or q["L"] > 100:
        return E_LIGHTNESS, {}
    if q["c"] < 0:
        return E_NEGATIVE, {}
    if q["d"] >= 1:
        return E_ALPHA, {}
    an = _perceptual_analysis(q, sp)
    if not i.get("_boundary"):
        assert an["rgb_min"] == 0 or abs(an["rgb_min"]) > 1e-9, ("gamut too close", i)
        assert abs(an["env_excess"] - BOUNDARY_TOLERANCE) > 1e-10, ("envelope too close", i)
        assert abs(an["energy_excess"] - BOUNDARY_TOLERANCE) > 1e-10, ("energy too close", i)
    if an["rgb_min"] < 0:
        return E_GAMUT, {}
    if an["env_excess"] > BOUNDARY_TOLERANCE:
        return E_ENVELOPE, {}
    if an["energy_excess"] > BOUNDARY_TOLERANCE:
        return E_ENERGY, {}
    if q["d"] < 0.8:
        return WARN_ALPHA, {}
    return OK, {}


def ref_physical_from_perceptual(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    q, norm = i["q"], i["normalization"]
    zero = {"rho_d": [0.0] * 3, "rho_s": 0.0, "alpha_x": 0.0, "alpha_y": 0.0, "normalization": None}
    L, a, b, c, d = (q[k] for k in "Labcd")
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, zero
    if not isfin(L, a, b, c, d):
        return E_NONFINITE, zero
    if L < 0 or L > 100:
        return E_LIGHTNESS, zero
    if c < 0:
        return E_NEGATIVE, zero
    if d >= 1:
        return E_ALPHA, zero
    if norm not in (0, 1, 2):
        return E_NORMALIZATION, zero
    rgb = rgb_from_lab_core(B, H, B.num(L), B.num(a), B.num(b), sp)
    Y = y_from_l(B, H, _in(B, H, "L", L))
    rs = specular_core(B, Y, _in(B, H, "c", c))
    al = 1 - _in(B, H, "d", d)
    if B.kind == "mp":
        for ch in rgb:
            assert ch == 0 or abs(ch) > mpf("1e-9"), ("gamut too close", i)
        if min(rgb) < 0:
            return E_GAMUT, {"rho_d": rgb, "rho_s": None, "alpha_x": None, "alpha_y": None,
                             "normalization": None}
    st = WARN_ALPHA if d < 0.8 else OK
    return st, {"rho_d": rgb, "rho_s": rs, "alpha_x": al, "alpha_y": al, "normalization": norm}


def ref_perceptual_from_physical(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
    p = i["p"]
    zero = {"L": 0.0, "a": 0.0, "b": 0.0, "c": 0.0, "d": 0.0}
    sp = _space_of(i)
    if sp is None:
        return E_ARGUMENT, zero
    if not isfin(*_phys_fields(p)):
        return E_NONFINITE, zero
    if min(p["rho_d"]) < 0 or p["rho_s"] < 0:
        return E_NEGATIVE, zero
    if p["alpha_x"] <= 0 or p["alpha_y"] <= 0:
        return E_ALPHA, zero
    rgb = [_in(B, H, f"rd{j}", p["rho_d"][j]) for j in range(3)]
    lab = lab_from_rgb_core(B, H, rgb, sp)
    Y = luminance_core(B, H, rgb, sp)
    c = contrast_core(B, Y, _in(B, H, "rho_s", p["rho_s"]))
    al = B.sqrt(_in(B, H, "alpha_x", p["alpha_x"]) * _in(B, H, "alpha_y", p["alpha_y"]))
    gm = math.sqrt(p["alpha_x"] * p["alpha_y"])
    mx = max(p["alpha_x"], p["alpha_y"])
    # The header does not say which alpha the warning uses; the vectors avoid the cases where
    # the geometric mean and the maximum disagree.
    assert (gm > ALPHA_TRUSTED_MAX) == (mx > ALPHA_TRUSTED_MAX), ("ambiguous warning", p)
    st = WARN_ALPHA if mx > ALPHA_TRUSTED_MAX else OK
    return st, {"L": lab[0], "a": lab[1], "b": lab[2], "c": c, "d": 1 - al}


# ----------------------------------------------------------------------------------
# Case assembly.
# ----------------------------------------------------------------------------------

VALUE_STATUSES = (OK, WARN_ALPHA, E_GAMUT, E_ENVELOPE)


def _enc_input(v: Any) -> Any:
    if isinstance(v, dict):
        return {k: _enc_input(x) for k, x in v.items() if not k.startswith("_")}
    if isinstance(v, (list, tuple)):
        return [_enc_input(x) for x in v]
    return enc(v)


def make_case(cid: str, function: str, ref: Ref, inp: Dict[str, Any], tags: Sequence[str],
              null: Optional[Sequence[str]] = None, with_sens: bool = True,
              expect_status: Optional[str] = None) -> Dict[str, Any]:
    """Evaluate ``ref`` on ``inp`` and build one JSON case.

    ``null`` names pointer arguments that the runner passes as NULL (status ERR_NULL,
    nothing else checked).  ``expect_status`` is a consistency check of the generator.
    """
    case: Dict[str, Any] = {"id": cid, "function": function, "tags": list(tags), "input": _enc_input(inp)}
    if null:
        case["input"]["null"] = list(null)
        case["status"] = E_NULL
        case["expected"] = {}
        return case
    status, out = ref(MP, NOHOOK, inp)
    if expect_status is not None:
        assert status == expect_status, (cid, status, expect_status, inp)
    case["status"] = status
    case["expected"] = exp_out(out)
    if with_sens and status in VALUE_STATUSES and out:
        case["sens"] = sens_out(sensitivity(lambda B, H: ref(B, H, inp)[1]))
    return case


class CaseList:
    """Collects cases with sequential ids ``<prefix>NNNN``."""

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self.cases: List[Dict[str, Any]] = []

    def add(self, function: str, ref: Ref, inp: Dict[str, Any], tags: Sequence[str], **kw: Any) -> Dict[str, Any]:
        cid = f"{self.prefix}{len(self.cases):04d}"
        c = make_case(cid, function, ref, inp, tags, **kw)
        self.cases.append(c)
        return c


# ----------------------------------------------------------------------------------
# Ward BRDF (paper eq. 2 and brdf.h): material, eval, pdf, sample.
# ----------------------------------------------------------------------------------

@dataclass(frozen=True)
class Material:
    """What pgloss_material_init stores: the float32 parameters after rounding and clamping."""
    rho_d: Tuple[float, float, float]
    rho_s: float
    alpha_x: float
    alpha_y: float
    normalization: int
    lobes: int


def material_init_ref(p: Dict[str, Any]) -> Tuple[str, Optional[Material]]:
    """pgloss_material_init: validation order NONFINITE, NEGATIVE, ALPHA, NORMALIZATION;
    double -> float32 rounding; positive alpha below PGLOSS_ALPHA_MIN raised to it."""
    if not isfin(*_phys_fields(p)):
        return E_NONFINITE, None
    if min(p["rho_d"]) < 0 or p["rho_s"] < 0:
        return E_NEGATIVE, None
    if p["alpha_x"] <= 0 or p["alpha_y"] <= 0:
        return E_ALPHA, None
    if p["normalization"] not in (0, 1, 2):
        return E_NORMALIZATION, None
    for x in list(p["rho_d"]) + [p["rho_s"], p["alpha_x"], p["alpha_y"]]:
        # Not specified by the header, so the vectors stay away from them: a finite double that
        # overflows float, and a positive reflectance that rounds to float 0 (is the lobe on?).
        assert x <= FLT_MAX, ("float overflow in material_init is unspecified", p)
    for x in list(p["rho_d"]) + [p["rho_s"]]:
        assert not (x > 0 and f32(x) == 0), ("reflectance rounding to 0 is unspecified", p)
    rd = tuple(f32(x) for x in p["rho_d"])
    rs = f32(p["rho_s"])
    ax = max(f32(p["alpha_x"]), ALPHA_MIN_F)
    ay = max(f32(p["alpha_y"]), ALPHA_MIN_F)
    lobes = (LOBE_DIFFUSE if max(rd) > 0 else 0) | (LOBE_SPECULAR if rs > 0 else 0)
    return OK, Material(rd, rs, ax, ay, p["normalization"], lobes)  # type: ignore[arg-type]


def material_fields_ref(m: Material) -> Dict[str, Any]:
    """The derived fields of pgloss_material, exactly (the C rounds them to float)."""
    ax, ay = mpf(m.alpha_x), mpf(m.alpha_y)
    pi = MP.pi
    k = 1 if m.normalization == NORM_BOUNDED else 4
    return {
        "rho_d": list(m.rho_d), "rho_s": m.rho_s, "alpha_x": m.alpha_x, "alpha_y": m.alpha_y,
        "lobes": m.lobes,
        "inv_alpha_x": 1 / ax, "inv_alpha_y": 1 / ay,
        "spec_scale": mpf(m.rho_s) / (k * pi * ax * ay),
        "pdf_scale": 1 / (4 * pi * ax * ay),
        "weight_diffuse": sum(LUMA[j] * mpf(m.rho_d[j]) for j in range(3)),
        "weight_specular": mpf(m.rho_s),
    }


def spec_prob_ref(B: Backend, H: Hooks, m: Material, lobes: int) -> Num:
    """pgloss_specular_probability: ws / (wd + ws) over the active lobes; 1 / 0 for one; 0 for none."""
    act = lobes & m.lobes
    if act == LOBE_ALL:
        lw = _MF[B.kind][4]
        wd = sum(lw[j] * H.p(f"rd{j}", B.num(m.rho_d[j])) for j in range(3))
        ws = H.p("rs", B.num(m.rho_s))
        return H.p("Ps", ws / (wd + ws))
    return B.num(1 if act == LOBE_SPECULAR else 0)


def valid_dir(v: Sequence[float]) -> bool:
    return isfin(*v) and any(x != 0 for x in v)


def normalize_ref(B: Backend, H: Hooks, tag: Optional[str], v: Sequence[Num]) -> List[Num]:
    w = [H.p(f"{tag}{k}", B.num(v[k])) if tag else v[k] for k in range(3)]
    n = B.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    return [x / n for x in w]


def brdf_ref(B: Backend, H: Hooks, m: Material, wo: Sequence[Num], wi: Sequence[Num], lobes: int,
             wi_tag: Optional[str] = "wi") -> Dict[str, Any]:
    """eval and pdf of brdf.h for valid directions: {"f": [r, g, b], "pdf": p}."""
    act = lobes & m.lobes
    o = normalize_ref(B, H, "wo", wo)
    i = normalize_ref(B, H, wi_tag, wi)
    zero = B.num(0)
    if o[2] <= 0 or i[2] <= 0 or act == 0:
        return {"f": [zero] * 3, "pdf": zero}
    pi = B.pi
    rd = [H.p(f"rd{j}", B.num(m.rho_d[j])) for j in range(3)]
    rs = H.p("rs", B.num(m.rho_s))
    ax = H.p("ax", B.num(m.alpha_x))
    ay = H.p("ay", B.num(m.alpha_y))
    co, ci = o[2], i[2]
    h = [H.p(f"h{k}o", o[k]) + H.p(f"h{k}i", i[k]) for k in range(3)]
    tx, ty = h[0] / ax, h[1] / ay
    x = H.p("expo", (tx * tx + ty * ty) / (h[2] * h[2]))
    E = B.exp(-x)
    spec = zero
    if act & LOBE_SPECULAR:
        cmin = B.num(COS_MIN_F)
        if m.normalization == NORM_WARD:
            spec = rs * E / (4 * pi * ax * ay * B.sqrt(max(ci, cmin) * max(co, cmin)))
        elif m.normalization == NORM_WARD_DUR:
            spec = rs * E / (4 * pi * ax * ay * max(ci, cmin) * max(co, cmin))
        else:
            hh = h[0] * h[0] + h[1] * h[1] + h[2] * h[2]
            spec = rs * E * hh / (pi * ax * ay * h[2] ** 4)
    f = [(rd[j] / pi if act & LOBE_DIFFUSE else zero) + spec for j in range(3)]
    Ps = spec_prob_ref(B, H, m, lobes)
    hl = B.sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2])
    hn = [c / hl for c in h]
    woh = H.p("woh", o[0] * hn[0] + o[1] * hn[1] + o[2] * hn[2])
    pspec = zero
    if Ps > 0 and woh > 0:
        pspec = E / (4 * pi * ax * ay * woh * hn[2] ** 3)
    pdf = (1 - Ps) * ci / pi + Ps * pspec
    fmax = B.num(FLT_MAX)   # "Outputs are finally clamped to at most FLT_MAX"
    return {"f": [min(v, fmax) for v in f], "pdf": min(pdf, fmax)}


def clamp_u(u: float) -> float:
    return min(max(u, 0.0), U_MAX)


def sample_ref(B: Backend, H: Hooks, m: Material, wo: Sequence[float], u: Sequence[float],
               lobes: int) -> Dict[str, Any]:
    """pgloss_sample for a valid wo and non-NaN u.

    Returns {"wi", "pdf", "weight", "lobe"} plus, under "_margin", the distances to the
    discontinuities (lobe choice, horizon, wo.h) used to keep the vectors well posed.
    """
    zero = B.num(0)
    uc = [clamp_u(x) for x in u]
    act = lobes & m.lobes
    rej = {"pdf": zero, "weight": [zero] * 3}
    if act == 0:
        return {"wi": None, **rej, "lobe": LOBE_NONE, "_margin": {}}
    o = normalize_ref(B, H, "wo", wo)
    Ps_exact = spec_prob_ref(MP, NOHOOK, m, lobes)
    lobe = LOBE_SPECULAR if uc[0] < Ps_exact else LOBE_DIFFUSE
    margin: Dict[str, Any] = {"u0": abs(mpf(uc[0]) - Ps_exact) if 0 < Ps_exact < 1 else mpf(1)}
    if o[2] <= 0:
        return {"wi": None, **rej, "lobe": None, "_margin": margin}
    pi = B.pi
    if lobe == LOBE_SPECULAR:
        ax = H.p("ax", B.num(m.alpha_x))
        ay = H.p("ay", B.num(m.alpha_y))
        lg = H.p("lg", -B.log(1 - B.num(uc[1])))  # 1 - u is exact in float for u in [0, 1)
        s = B.sqrt(lg)
        t = H.p("t", 2 * pi * B.num(uc[2]))
        hv = [H.p("hx", ax * s * B.cos(t)), H.p("hy", ay * s * B.sin(t)), B.num(1)]
        hl = B.sqrt(hv[0] * hv[0] + hv[1] * hv[1] + 1)
        h = [c / hl for c in hv]
        d = sum(H.p(f"d{k}", o[k] * h[k]) for k in range(3))
        wi = [H.p(f"r{k}a", 2 * d * h[k]) - H.p(f"r{k}b", o[k]) for k in range(3)]
        margin["woh"] = abs(d)
        rejected = d <= 0 or wi[2] <= 0
    else:
        a = 2 * B.num(uc[1]) - 1
        b = 2 * B.num(uc[2]) - 1
        if (abs(a) == 1 and b == 0) or (a == 0 and abs(b) == 1):
            wi = [a, b, zero]          # exactly on the rim: z = 0 in any arithmetic
        else:
            a = H.p("ca", a)
            b = H.p("cb", b)
            if a == 0 and b == 0:
                x = y = zero
            else:
                if abs(a) > abs(b):
                    r, th = a, H.p("th", pi / 4 * (b / a))
                else:
                    r, th = b, H.p("th", pi / 2 - pi / 4 * (a / b))
                x = H.p("x", r * B.cos(th))
                y = H.p("y", r * B.sin(th))
            zz = H.p("z1", B.num(1)) - H.p("zx", x * x) - H.p("zy", y * y)
            wi = [x, y, B.sqrt(zz) if zz > 0 else zero]
            if B.kind == "mp":
                margin["zz"] = abs(zz)
        rejected = wi[2] <= 0
    margin["wiz"] = abs(wi[2])
    if rejected:
        return {"wi": wi, **rej, "lobe": lobe, "_margin": margin}
    wih = [H.p(f"swi{k}", wi[k]) for k in range(3)]
    r = brdf_ref(B, H, m, wo, wih, lobes, wi_tag=None)
    wl = B.sqrt(wih[0] * wih[0] + wih[1] * wih[1] + wih[2] * wih[2])
    cz = wih[2] / wl
    weight = [min(r["f"][j] * cz / r["pdf"], B.num(FLT_MAX)) if r["pdf"] != 0 else zero for j in range(3)]
    return {"wi": wi, "pdf": r["pdf"], "weight": weight, "lobe": lobe, "_margin": margin}


# ----------------------------------------------------------------------------------
# Tolerances.  |got - want| <= abs + rel*|want| + kappa_rel*sens  (README.md).
# ----------------------------------------------------------------------------------

TOL_DOUBLE = {"rel": 1e-12, "kappa_rel": 4e-15, "abs": 1e-300}
TOL_FLOAT = {"rel": 1e-5, "kappa_rel": 1e-6, "abs": 1e-30}
TOL_EXACT = {"rel": 0.0, "kappa_rel": 0.0, "abs": 0.0}


def tol_both(float_abs: float = 1e-30, double_abs: float = 1e-300) -> Dict[str, Dict[str, float]]:
    return {"float": {**TOL_FLOAT, "abs": float_abs}, "double": {**TOL_DOUBLE, "abs": double_abs}}


def tolerance_for(outputs: Dict[str, Sequence[str]], **kw: float) -> Dict[str, Any]:
    return {fn: {o: tol_both(**kw) for o in outs} for fn, outs in outputs.items()}


PAPER_RD = (0.03, 0.193, 0.767)   # Munsell N2, N5, N9 (§3.2.3.1)
PAPER_RS = (0.033, 0.066, 0.099)
PAPER_AL = (0.04, 0.07, 0.10)


def nextup(x: float) -> float:
    return math.nextafter(x, math.inf)


def nextdown(x: float) -> float:
    return math.nextafter(x, -math.inf)


def lightness_of(Y: float) -> float:
    return D(l_from_y(MP, NOHOOK, mpf(Y)))


def header(functions: Sequence[str], c_precision: str, tolerance: Dict[str, Any], notes: str) -> Dict[str, Any]:
    return {"format": FORMAT, "version": VERSION, "functions": list(functions), "generator": GENERATOR,
            "dps": mp.dps, "c_precision": c_precision, "notes": notes, "tolerance": short_tree(tolerance)}


# ---------------------------------------------------------------------------------- lightness

def gen_lightness() -> Dict[str, Any]:
    rng = random.Random(1001)
    cl = CaseList("lt")
    fl, fy = "lightness_from_luminance", "luminance_from_lightness"
    eps = 216.0 / 24389.0
    for Y, tags in [(0.0, ["zero"]), (-0.0, ["negative_zero"]), (1e-300, ["tiny"]), (1e-10, ["linear"]),
                    (0.001, ["linear"]), (nextdown(eps), ["break"]), (eps, ["break"]), (nextup(eps), ["break"]),
                    (0.008856, ["break", "legacy_constant"]), (0.0088565, ["break"]), (0.01, []),
                    (0.03, ["paper"]), (0.18, []), (0.193, ["paper"]), (0.5, []), (0.767, ["paper"]),
                    (1.0, ["white"]), (1.5, ["above_white"]), (100.0, ["above_white"]), (1e300, ["extreme"])]:
        cl.add(fl, ref_lightness_from_luminance, {"Y": Y}, ["regular"] + tags, expect_status=OK)
    for _ in range(40):
        cl.add(fl, ref_lightness_from_luminance, {"Y": rng.random() ** 3}, ["regular", "random"])
    for Y, st in [(math.nan, E_NONFINITE), (math.inf, E_NONFINITE), (-math.inf, E_NONFINITE),
                  (-1e-300, E_NEGATIVE), (-1.0, E_NEGATIVE)]:
        cl.add(fl, ref_lightness_from_luminance, {"Y": Y}, ["error"], expect_status=st)
    cl.add(fl, ref_lightness_from_luminance, {"Y": 0.5}, ["error", "null_pointer"], null=["L"])

    for L, tags in [(0.0, ["zero"]), (-0.0, ["negative_zero"]), (1e-300, ["tiny"]), (1e-6, ["linear"]),
                    (1.0, ["linear"]), (nextdown(8.0), ["break"]), (8.0, ["break"]), (nextup(8.0), ["break"]),
                    (8.000001, ["break"]), (50.0, []), (99.99, []), (100.0, ["white"]),
                    (100.5, ["above_white"]), (150.0, ["above_white"]), (1e6, ["extreme"])]:
        cl.add(fy, ref_luminance_from_lightness, {"L": L}, ["regular"] + tags, expect_status=OK)
    for _ in range(40):
        cl.add(fy, ref_luminance_from_lightness, {"L": 100.0 * rng.random()}, ["regular", "random"])
    for L, st in [(math.nan, E_NONFINITE), (math.inf, E_NONFINITE), (-math.inf, E_NONFINITE),
                  (-1e-300, E_LIGHTNESS), (-1.0, E_LIGHTNESS)]:
        cl.add(fy, ref_luminance_from_lightness, {"L": L}, ["error"], expect_status=st)
    cl.add(fy, ref_luminance_from_lightness, {"L": 50.0}, ["error", "null_pointer"], null=["Y"])
    tol = tolerance_for({fl: ["L"], fy: ["Y"]})
    return {**header([fl, fy], "double", tol,
                     "CIE 1976 lightness with the exact rational eps = 216/24389, kappa = 24389/27."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- gloss

def gen_gloss() -> Dict[str, Any]:
    rng = random.Random(2002)
    cl = CaseList("gl")
    F = {"cg": "contrast_gloss", "sc": "specular_from_contrast", "gp": "gloss_from_physical",
         "pg": "physical_from_gloss", "gd": "gloss_distance", "ec": "envelope_contrast",
         "mg": "match_gloss", "ic": "isogloss_contour"}

    # contrast_gloss (eq. 4)
    for rd in PAPER_RD:
        for rs in PAPER_RS:
            c = cl.add(F["cg"], ref_contrast_gloss, {"rho_d": rd, "rho_s": rs}, ["regular", "paper", "experiment1"])
            if rd == 0.767 and rs == 0.099:   # Fig. 12: the white sphere has c = 0.057
                assert abs(c["expected"]["c"] - 0.057) < 0.001, c
                c["tags"].append("fig12")
    for rd, rs, tags in [(0.0, 0.0, ["zero"]), (0.0, 0.1, ["zero_diffuse"]), (0.5, 0.0, ["zero_specular"]),
                         (0.5, 1e-12, ["tiny"]), (1e-300, 1e-300, ["tiny"]), (1.0, 0.0, []), (0.0, 1.0, []),
                         (0.5, 0.5, ["energy_boundary"]), (-0.0, 0.1, ["negative_zero"]), (2.0, 3.0, ["above_one"]),
                         (1e300, 1e300, ["extreme"])]:
        cl.add(F["cg"], ref_contrast_gloss, {"rho_d": rd, "rho_s": rs}, ["regular"] + tags, expect_status=OK)
    for _ in range(30):
        rd = rng.random()
        cl.add(F["cg"], ref_contrast_gloss, {"rho_d": rd, "rho_s": (1 - rd) * rng.random()}, ["regular", "random"])
    for rd, rs, st in [(math.nan, 0.1, E_NONFINITE), (0.1, math.inf, E_NONFINITE), (-math.inf, 0.1, E_NONFINITE),
                       (-1e-300, 0.1, E_NEGATIVE), (0.1, -0.5, E_NEGATIVE), (math.nan, -1.0, E_NONFINITE)]:
        cl.add(F["cg"], ref_contrast_gloss, {"rho_d": rd, "rho_s": rs}, ["error"], expect_status=st)
    cl.add(F["cg"], ref_contrast_gloss, {"rho_d": 0.5, "rho_s": 0.1}, ["error", "null_pointer"], null=["c"])

    # specular_from_contrast (eq. 7)
    for rd in PAPER_RD:
        cl.add(F["sc"], ref_specular_from_contrast, {"rho_d": rd, "c": 0.057}, ["regular", "paper", "fig12"])
    for rd, c, tags in [(0.0, 0.0, ["zero"]), (0.0, 0.3, ["zero_diffuse"]), (0.5, 0.0, ["zero_contrast"]),
                        (0.5, 1e-12, ["tiny"]), (1.0, 0.0, []), (0.0, 1.0, []), (-0.0, 0.1, ["negative_zero"]),
                        (1e300, 1e50, ["extreme"])]:
        cl.add(F["sc"], ref_specular_from_contrast, {"rho_d": rd, "c": c}, ["regular"] + tags, expect_status=OK)
    for _ in range(30):
        cl.add(F["sc"], ref_specular_from_contrast, {"rho_d": rng.random(), "c": 0.3 * rng.random()},
               ["regular", "random"])
    for rd, c, st in [(math.nan, 0.1, E_NONFINITE), (0.1, -math.inf, E_NONFINITE), (-0.1, 0.1, E_NEGATIVE),
                      (0.1, -1e-300, E_NEGATIVE)]:
        cl.add(F["sc"], ref_specular_from_contrast, {"rho_d": rd, "c": c}, ["error"], expect_status=st)
    cl.add(F["sc"], ref_specular_from_contrast, {"rho_d": 0.5, "c": 0.1}, ["error", "null_pointer"], null=["rho_s"])

    # gloss_from_physical (eqs. 3, 4, L*)
    for rd in PAPER_RD:
        for rs in PAPER_RS:
            for al in PAPER_AL:
                cl.add(F["gp"], ref_gloss_from_physical, {"rho_d": rd, "rho_s": rs, "alpha": al},
                       ["regular", "paper", "experiment1"], expect_status=OK)
    for rd, rs, al, tags, st in [
            (0.767, 0.099, 0.04, ["paper", "fig12"], OK),
            (0.2, 0.05, 0.2, ["alpha_trusted_boundary"], OK),
            (0.2, 0.05, nextup(0.2), ["alpha_trusted_boundary"], WARN_ALPHA),
            (0.2, 0.05, 1.0, ["alpha_one"], WARN_ALPHA),
            (0.2, 0.05, 1.5, ["alpha_above_one"], WARN_ALPHA),
            (0.2, 0.05, 1e-300, ["tiny_alpha"], OK),
            (0.2, 0.05, 1e-3, ["tiny_alpha"], OK),
            (0.0, 0.0, 0.1, ["zero"], OK),
            (0.0088, 0.01, 0.05, ["break"], OK)]:
        cl.add(F["gp"], ref_gloss_from_physical, {"rho_d": rd, "rho_s": rs, "alpha": al}, ["regular"] + tags,
               expect_status=st)
    for rd, rs, al, st in [(math.nan, 0.1, 0.1, E_NONFINITE), (0.1, 0.1, math.inf, E_NONFINITE),
                           (-0.1, 0.1, 0.1, E_NEGATIVE), (0.1, -0.1, 0.1, E_NEGATIVE),
                           (0.1, 0.1, 0.0, E_ALPHA), (0.1, 0.1, -0.0, E_ALPHA), (0.1, 0.1, -1e-300, E_ALPHA),
                           (-0.1, 0.1, 0.0, E_NEGATIVE), (math.nan, -0.1, 0.0, E_NONFINITE)]:
        cl.add(F["gp"], ref_gloss_from_physical, {"rho_d": rd, "rho_s": rs, "alpha": al}, ["error"],
               expect_status=st)
    for n in ("L", "c", "d"):
        cl.add(F["gp"], ref_gloss_from_physical, {"rho_d": 0.2, "rho_s": 0.05, "alpha": 0.1},
               ["error", "null_pointer"], null=[n])

    # physical_from_gloss (eqs. 6, 7, 8)
    for rd in PAPER_RD:   # Fig. 12, bottom row: same (c, d) = (0.057, 0.96) at the three lightnesses
        cl.add(F["pg"], ref_physical_from_gloss, {"L": lightness_of(rd), "c": 0.057, "d": 0.96},
               ["regular", "paper", "fig12"], expect_status=OK)
    c = cl.add(F["pg"], ref_physical_from_gloss, {"L": lightness_of(0.193), "c": 0.087, "d": 0.93},
               ["regular", "paper", "fig11"], expect_status=OK)
    # Fig. 11's reference object is the grey Experiment-1 stimulus (0.193, 0.066, 0.07).
    assert abs(c["expected"]["rho_s"] - 0.066) < 5e-4 and abs(c["expected"]["alpha"] - 0.07) < 1e-12, c
    for L, c, d, tags, st in [
            (0.0, 0.1, 0.9, ["black"], OK), (-0.0, 0.1, 0.9, ["negative_zero"], OK),
            (8.0, 0.1, 0.9, ["break"], OK), (nextup(8.0), 0.1, 0.9, ["break"], OK),
            (100.0, 0.0, 0.9, ["white"], OK), (50.0, 0.0, 0.9, ["zero_contrast"], OK),
            (50.0, 0.1, 0.8, ["alpha_trusted_boundary"], OK),
            (50.0, 0.1, nextdown(0.8), ["alpha_trusted_boundary"], WARN_ALPHA),
            (50.0, 0.1, nextdown(1.0), ["tiny_alpha"], OK), (50.0, 0.1, 0.999, ["tiny_alpha"], OK),
            (50.0, 0.1, 0.0, ["alpha_one"], WARN_ALPHA), (50.0, 0.1, -1.0, ["alpha_above_one"], WARN_ALPHA),
            (50.0, 1.0, 0.9, ["beyond_envelope"], OK)]:
        cl.add(F["pg"], ref_physical_from_gloss, {"L": L, "c": c, "d": d}, ["regular"] + tags, expect_status=st)
    for _ in range(30):
        cl.add(F["pg"], ref_physical_from_gloss,
               {"L": 100 * rng.random(), "c": 0.2 * rng.random(), "d": 0.8 + 0.2 * rng.random()},
               ["regular", "random"])
    for L, c, d, st in [(math.nan, 0.1, 0.9, E_NONFINITE), (50.0, math.inf, 0.9, E_NONFINITE),
                        (50.0, 0.1, -math.inf, E_NONFINITE), (-1e-300, 0.1, 0.9, E_LIGHTNESS),
                        (nextup(100.0), 0.1, 0.9, E_LIGHTNESS), (150.0, 0.1, 0.9, E_LIGHTNESS),
                        (50.0, -1e-300, 0.9, E_NEGATIVE), (50.0, 0.1, 1.0, E_ALPHA), (50.0, 0.1, 1.5, E_ALPHA),
                        (-1.0, -0.1, 1.0, E_LIGHTNESS), (50.0, -0.1, 1.0, E_NEGATIVE),
                        (math.nan, -0.1, 2.0, E_NONFINITE)]:
        cl.add(F["pg"], ref_physical_from_gloss, {"L": L, "c": c, "d": d}, ["error"], expect_status=st)
    for n in ("rho_d", "rho_s", "alpha"):
        cl.add(F["pg"], ref_physical_from_gloss, {"L": 50.0, "c": 0.1, "d": 0.9}, ["error", "null_pointer"],
               null=[n])

    # gloss_distance (eq. 5)
    for c2, d2, tags in [(0.087, 0.93, ["identical"]), (0.127, 0.93, ["fig11"]), (0.087, 0.93 + 0.04 / 1.78, ["fig11"]),
                         (0.047, 0.93, ["fig11"]), (0.167, 0.93, ["fig11"]), (0.057, 0.96, ["fig12"])]:
        cl.add(F["gd"], ref_gloss_distance, {"c1": 0.087, "d1": 0.93, "c2": c2, "d2": d2},
               ["regular", "paper"] + tags, expect_status=OK)
    for c1, d1, c2, d2, tags, st in [(0.0, 0.9, 0.0, 0.9, ["zero"], OK), (0.1, 0.9, 0.1, 0.9 + 1e-15, ["tiny"], OK),
                                     (0.0, 0.0, 0.0, 0.0, ["zero", "untrusted"], WARN_ALPHA),
                                     (0.05, 0.95, 0.05, 0.5, ["untrusted"], WARN_ALPHA),
                                     (-1.0, 2.0, 3.0, -4.0, ["outside_space"], E_NEGATIVE),
                                     (0.05, 1.5, 0.05, 0.95, ["outside_space"], E_ALPHA),
                                     (0.05, 0.95, -0.01, 0.95, ["outside_space"], E_NEGATIVE),
                                     (0.05, 0.95, 0.05, 1.0, ["outside_space"], E_ALPHA),
                                     (0.05, 1.0, -0.01, 0.95, ["outside_space"], E_ALPHA),
                                     (1e200, 0.9, -1e200, 0.9, ["extreme"], E_NEGATIVE),
                                     (0.0, 1e200, 0.0, -1e200, ["extreme"], E_ALPHA)]:
        cl.add(F["gd"], ref_gloss_distance, {"c1": c1, "d1": d1, "c2": c2, "d2": d2}, ["regular"] + tags,
               expect_status=st)
    for _ in range(25):
        cl.add(F["gd"], ref_gloss_distance, {"c1": 0.2 * rng.random(), "d1": 0.8 + 0.2 * rng.random(),
                                             "c2": 0.2 * rng.random(), "d2": 0.8 + 0.2 * rng.random()},
               ["regular", "random"])
    for args in [(math.nan, 0.9, 0.1, 0.9), (0.1, math.inf, 0.1, 0.9), (0.1, 0.9, -math.inf, 0.9),
                 (0.1, 0.9, 0.1, math.nan)]:
        cl.add(F["gd"], ref_gloss_distance, dict(zip(("c1", "d1", "c2", "d2"), args)), ["error"],
               expect_status=E_NONFINITE)
    cl.add(F["gd"], ref_gloss_distance, {"c1": 0.1, "d1": 0.9, "c2": 0.2, "d2": 0.95}, ["error", "null_pointer"],
           null=["D"])

    # envelope_contrast (Fig. 10)
    for L, tags in [(0.0, ["black"]), (-0.0, ["negative_zero"]), (1e-9, ["tiny"]), (8.0, ["break"]),
                    (nextup(8.0), ["break"]), (lightness_of(0.03), ["paper"]), (lightness_of(0.193), ["paper"]),
                    (lightness_of(0.767), ["paper"]), (50.0, []), (99.0, ["near_white"]),
                    (99.9999, ["near_white"]), (100.0 - 1e-12, ["near_white"]), (nextdown(100.0), ["near_white"]),
                    (100.0, ["white"])]:
        cl.add(F["ec"], ref_envelope_contrast, {"L": L}, ["regular"] + tags, expect_status=OK)
    for _ in range(25):
        cl.add(F["ec"], ref_envelope_contrast, {"L": 100 * rng.random()}, ["regular", "random"])
    for L, st in [(math.nan, E_NONFINITE), (-math.inf, E_NONFINITE), (-1e-300, E_LIGHTNESS),
                  (nextup(100.0), E_LIGHTNESS), (1000.0, E_LIGHTNESS)]:
        cl.add(F["ec"], ref_envelope_contrast, {"L": L}, ["error"], expect_status=st)
    cl.add(F["ec"], ref_envelope_contrast, {"L": 50.0}, ["error", "null_pointer"], null=["c_max"])

    # match_gloss (§5.2, Fig. 12)
    for rd in PAPER_RD:
        for rd2 in PAPER_RD:
            cl.add(F["mg"], ref_match_gloss, {"rho_d": rd, "rho_s": 0.099, "L_target": lightness_of(rd2)},
                   ["regular", "paper", "fig12"])
    for rd, rs, Lt, tags, st in [
            (0.03, 0.099, 0.0, ["black"], OK), (0.03, 0.099, 100.0, ["white"], E_ENVELOPE),
            (0.5, 0.0, 80.0, ["zero_specular"], OK), (0.0, 0.0, 50.0, ["zero"], OK),
            (0.03, 0.9, 95.0, ["beyond_envelope"], E_ENVELOPE), (0.767, 0.2, 10.0, [], OK),
            (0.5, 0.5, lightness_of(0.5), ["energy_boundary"], OK)]:
        cl.add(F["mg"], ref_match_gloss, {"rho_d": rd, "rho_s": rs, "L_target": Lt, "_boundary": "energy_boundary" in tags},
               ["regular"] + tags, expect_status=st)
    for _ in range(25):
        rd = rng.random()
        cl.add(F["mg"], ref_match_gloss, {"rho_d": rd, "rho_s": (1 - rd) * 0.3 * rng.random(),
                                          "L_target": 100 * rng.random()}, ["regular", "random"])
    for rd, rs, Lt, st in [(math.nan, 0.1, 50.0, E_NONFINITE), (0.1, 0.1, math.inf, E_NONFINITE),
                           (-0.1, 0.1, 50.0, E_NEGATIVE), (0.1, -0.1, 50.0, E_NEGATIVE),
                           (0.1, 0.1, -1.0, E_LIGHTNESS), (0.1, 0.1, 100.5, E_LIGHTNESS),
                           (-0.1, 0.1, 150.0, E_NEGATIVE)]:
        cl.add(F["mg"], ref_match_gloss, {"rho_d": rd, "rho_s": rs, "L_target": Lt}, ["error"], expect_status=st)
    for n in ("rho_d_out", "rho_s_out"):
        cl.add(F["mg"], ref_match_gloss, {"rho_d": 0.1, "rho_s": 0.1, "L_target": 50.0}, ["error", "null_pointer"],
               null=[n])

    # isogloss_contour (§5.1, Fig. 11)
    for c0, d0, Dd, n, tags in [(0.087, 0.93, 0.04, 8, ["paper", "fig11"]), (0.087, 0.93, 0.08, 12, ["paper", "fig11"]),
                                (0.087, 0.93, 0.04, 1, ["single"]), (0.087, 0.93, 0.04, 3, []),
                                (0.1, 0.9, 0.0, 4, ["zero_distance"]), (0.0, 0.0, 0.5, 7, ["outside_space"]),
                                (0.05, 0.95, 0.02, 360, ["many"])]:
        cl.add(F["ic"], ref_isogloss_contour, {"c0": c0, "d0": d0, "D": Dd, "n": n}, ["regular"] + tags,
               expect_status=OK)
    for c0, d0, Dd, n, st in [(math.nan, 0.9, 0.1, 4, E_NONFINITE), (0.1, 0.9, math.inf, 4, E_NONFINITE),
                              (0.1, 0.9, -1e-300, 4, E_NEGATIVE), (0.1, 0.9, -0.1, 2, E_NEGATIVE),
                              (0.1, 0.9, 0.1, 0, E_ARGUMENT)]:
        cl.add(F["ic"], ref_isogloss_contour, {"c0": c0, "d0": d0, "D": Dd, "n": n}, ["error"], expect_status=st)
    for n in ("c", "d"):
        cl.add(F["ic"], ref_isogloss_contour, {"c0": 0.1, "d0": 0.9, "D": 0.1, "n": 4}, ["error", "null_pointer"],
               null=[n])

    tol = tolerance_for({F["cg"]: ["c"], F["sc"]: ["rho_s"], F["gp"]: ["L", "c", "d"],
                         F["pg"]: ["rho_d", "rho_s", "alpha"], F["gd"]: ["D"], F["ec"]: ["c_max"],
                         F["mg"]: ["rho_d_out", "rho_s_out"], F["ic"]: ["c", "d"]})
    return {**header(list(F.values()), "double", tol,
                     "Paper eqs. 3-8 and the envelope / matching / contour functions of perceptual.h."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- color

def lab_of(rgb: Sequence[float]) -> List[float]:
    return [D(v) for v in lab_from_rgb_core(MP, NOHOOK, [mpf(x) for x in rgb])]


def gen_color() -> Dict[str, Any]:
    rng = random.Random(3003)
    cl = CaseList("co")
    fr, fl, fy = "rgb_from_lab", "lab_from_rgb", "luminance"

    # rgb_from_lab
    for L, tags in [(0.0, ["black"]), (-0.0, ["negative_zero"]), (1e-6, ["tiny"]), (8.0, ["break"]),
                    (nextup(8.0), ["break"]), (50.0, ["grey"]), (100.0, ["white"])]:
        cl.add(fr, ref_rgb_from_lab, {"lab": [L, 0.0, 0.0]}, ["regular", "grey"] + tags, expect_status=OK)
    for rgb in ([1.0, 1e-6, 1e-6], [1e-6, 1.0, 1e-6], [1e-6, 1e-6, 1.0]):   # near the primaries
        cl.add(fr, ref_rgb_from_lab, {"lab": lab_of(rgb)}, ["regular", "near_gamut_boundary", "saturated"],
               expect_status=OK)
    for _ in range(40):   # in gamut: Lab of a random RGB with channels >= 0.01
        rgb = [0.01 + 0.99 * rng.random() for _ in range(3)]
        if rng.random() < 0.2:
            rgb = [x * 0.005 for x in rgb]    # dark: the linear branch of the inverse
        cl.add(fr, ref_rgb_from_lab, {"lab": lab_of(rgb)}, ["regular", "random"], expect_status=OK)
    for lab, tags in [([50.0, 100.0, 0.0], ["out_of_gamut"]), ([50.0, 0.0, -120.0], ["out_of_gamut"]),
                      ([5.0, -60.0, 40.0], ["out_of_gamut", "dark"]), ([70.0, 0.0, 100.0], ["out_of_gamut"]),
                      ([0.0, 10.0, 10.0], ["out_of_gamut", "black"])]:
        cl.add(fr, ref_rgb_from_lab, {"lab": lab}, ["error"] + tags, expect_status=E_GAMUT)
    for lab, st in [([math.nan, 0.0, 0.0], E_NONFINITE), ([50.0, math.inf, 0.0], E_NONFINITE),
                    ([50.0, 0.0, -math.inf], E_NONFINITE), ([-1e-300, 0.0, 0.0], E_LIGHTNESS),
                    ([nextup(100.0), 0.0, 0.0], E_LIGHTNESS), ([-5.0, 200.0, 0.0], E_LIGHTNESS)]:
        cl.add(fr, ref_rgb_from_lab, {"lab": lab}, ["error"], expect_status=st)
    for n in ("lab", "rgb"):
        cl.add(fr, ref_rgb_from_lab, {"lab": [50.0, 0.0, 0.0]}, ["error", "null_pointer"], null=[n])

    # lab_from_rgb
    for rgb, tags in [([0.0, 0.0, 0.0], ["black"]), ([-0.0, 0.0, -0.0], ["negative_zero", "black"]),
                      ([1.0, 1.0, 1.0], ["white"]), ([0.18, 0.18, 0.18], ["grey"]),
                      ([1e-10, 1e-10, 1e-10], ["grey", "linear"]), ([1.0, 0.0, 0.0], ["primary"]),
                      ([0.0, 1.0, 0.0], ["primary"]), ([0.0, 0.0, 1.0], ["primary"]),
                      ([0.3, 1e-9, 0.0], ["linear", "saturated"]), ([2.0, 1.5, 3.0], ["above_white"])]:
        cl.add(fl, ref_lab_from_rgb, {"rgb": rgb}, ["regular"] + tags, expect_status=OK)
    for _ in range(40):
        rgb = [rng.random() for _ in range(3)]
        if rng.random() < 0.2:
            rgb = [x * 0.005 for x in rgb]
        cl.add(fl, ref_lab_from_rgb, {"rgb": rgb}, ["regular", "random"], expect_status=OK)
    for rgb, st in [([math.nan, 0.1, 0.1], E_NONFINITE), ([0.1, math.inf, 0.1], E_NONFINITE),
                    ([0.1, 0.1, -1e-300], E_NEGATIVE), ([-0.5, 0.1, 0.1], E_NEGATIVE),
                    ([-0.5, math.nan, 0.1], E_NONFINITE)]:
        cl.add(fl, ref_lab_from_rgb, {"rgb": rgb}, ["error"], expect_status=st)
    for n in ("rgb", "lab"):
        cl.add(fl, ref_lab_from_rgb, {"rgb": [0.1, 0.2, 0.3]}, ["error", "null_pointer"], null=[n])

    # luminance
    for rgb, tags in [([0.0, 0.0, 0.0], ["black"]), ([1.0, 1.0, 1.0], ["white"]), ([1.0, 0.0, 0.0], ["primary"]),
                      ([0.0, 1.0, 0.0], ["primary"]), ([0.0, 0.0, 1.0], ["primary"]),
                      ([-0.5, 0.2, 0.9], ["negative_channel"]), ([1e300, 1e300, 1e300], ["extreme"])]:
        cl.add(fy, ref_luminance, {"rgb": rgb}, ["regular"] + tags, expect_status=OK)
    for _ in range(25):
        cl.add(fy, ref_luminance, {"rgb": [rng.random() for _ in range(3)]}, ["regular", "random"])
    for rgb in ([math.nan, 0.0, 0.0], [0.0, -math.inf, 0.0]):
        cl.add(fy, ref_luminance, {"rgb": rgb}, ["error"], expect_status=E_NONFINITE)
    for n in ("rgb", "Y"):
        cl.add(fy, ref_luminance, {"rgb": [0.1, 0.2, 0.3]}, ["error", "null_pointer"], null=[n])

    tol = tolerance_for({fr: ["rgb"], fl: ["lab"], fy: ["Y"]})
    return {**header([fr, fl, fy], "double", tol,
                     "CIELAB (D65 by its Rec. 709 chromaticity 0.3127, 0.3290) <-> linear Rec. 709 RGB; "
                     "matrices derived in the generator from the primaries at 40 digits."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- validity

def phys(rd: Sequence[float], rs: float, ax: float, ay: Optional[float] = None, norm: int = 0) -> Dict[str, Any]:
    return {"rho_d": list(rd), "rho_s": rs, "alpha_x": ax, "alpha_y": ax if ay is None else ay,
            "normalization": norm}


def perc(L: float, a: float, b: float, c: float, d: float) -> Dict[str, float]:
    return {"L": L, "a": a, "b": b, "c": c, "d": d}


def envelope_at(L: float) -> float:
    return D(envelope_core(MP, y_from_l(MP, NOHOOK, mpf(L))))


def gen_validity() -> Dict[str, Any]:
    cl = CaseList("va")
    fp, fq = "check_physical", "check_perceptual"
    g3 = lambda x: [x, x, x]  # noqa: E731
    for rd in PAPER_RD:
        for rs in PAPER_RS:
            for al in PAPER_AL:
                cl.add(fp, ref_check_physical, {"p": phys(g3(rd), rs, al)}, ["regular", "paper", "experiment1"],
                       expect_status=OK)
    rows: List[Tuple[Dict[str, Any], List[str], str]] = [
        (phys([0.5, 0.4, 0.3], 0.1, 0.05, 0.1, 1), ["anisotropic"], OK),
        (phys(g3(0.0), 0.0, 0.1, norm=2), ["zero"], OK),
        (phys(g3(-0.0), -0.0, 0.1), ["negative_zero"], OK),
        (phys(g3(0.5), 0.5, 0.1), ["energy_boundary", "_boundary"], OK),
        (phys([0.7, 0.1, 0.2], 0.3, 0.1), ["energy_boundary", "_boundary"], OK),
        (phys(g3(0.5), 0.5 + 5e-13, 0.1), ["energy_boundary", "within_slack", "_boundary"], OK),
        (phys(g3(0.5), 0.5 + 2e-12, 0.1), ["energy_boundary", "beyond_slack", "_boundary"], E_ENERGY),
        (phys([0.9, 0.1, 0.1], 0.2, 0.1), ["coloured"], E_ENERGY),
        (phys(g3(0.9), 0.2, 0.1), [], E_ENERGY),
        (phys(g3(0.2), 0.1, 0.2), ["alpha_trusted_boundary"], OK),
        (phys(g3(0.2), 0.1, nextup(0.2)), ["alpha_trusted_boundary"], WARN_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, 0.3), ["anisotropic"], WARN_ALPHA),
        (phys(g3(0.2), 0.1, 0.5, 0.01), ["anisotropic"], WARN_ALPHA),
        (phys(g3(0.2), 0.1, 1e-300), ["tiny_alpha"], OK),
        (phys(g3(0.2), 0.1, 1.0), [], WARN_ALPHA),
        (phys(g3(math.nan), 0.1, 0.1), [], E_NONFINITE),
        (phys(g3(0.2), math.inf, 0.1), [], E_NONFINITE),
        (phys(g3(0.2), 0.1, 0.1, -math.inf), [], E_NONFINITE),
        (phys(g3(0.2), 0.1, 0.1, 1e39), ["beyond_float"], E_NONFINITE),
        (phys(g3(0.2), 0.1, FLT_MAX), ["float_max"], WARN_ALPHA),
        (phys([0.2, -1e-300, 0.2], 0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), -0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), 0.1, 0.0), [], E_ALPHA),
        (phys(g3(0.2), 0.1, -0.0), ["negative_zero"], E_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, -1.0), [], E_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, norm=3), [], E_NORMALIZATION),
        (phys(g3(0.2), 0.1, 0.1, norm=-1), [], E_NORMALIZATION),
        (phys(g3(0.2), 0.1, 0.1, norm=1000), [], E_NORMALIZATION),
        # validation order: the first failing check wins
        (phys([math.nan, -1.0, 0.2], 0.1, 0.0, norm=5), ["order"], E_NONFINITE),
        (phys(g3(-1.0), 0.1, 0.0, norm=5), ["order"], E_NEGATIVE),
        (phys(g3(0.9), 0.5, 0.0, norm=5), ["order"], E_ALPHA),
        (phys(g3(0.9), 0.5, 0.5, norm=5), ["order"], E_NORMALIZATION),
        (phys(g3(0.9), 0.5, 0.5), ["order"], E_ENERGY),
    ]
    for p, tags, st in rows:
        b = "_boundary" in tags
        cl.add(fp, ref_check_physical, {"p": p, "_boundary": b}, [t for t in tags if t != "_boundary"] +
               (["error"] if st not in (OK, WARN_ALPHA) else ["regular"]), expect_status=st)
    cl.add(fp, ref_check_physical, {"p": phys(g3(0.2), 0.1, 0.1)}, ["error", "null_pointer"], null=["p"])

    L50 = 50.0
    env50 = envelope_at(L50)
    rowsq: List[Tuple[Dict[str, float], List[str], str]] = [
        (perc(lightness_of(0.193), 0.0, 0.0, 0.087, 0.93), ["paper", "fig11"], OK),
        (perc(lightness_of(0.767), 0.0, 0.0, 0.057, 0.96), ["paper", "fig12"], OK),
        (perc(lightness_of(0.03), 0.0, 0.0, 0.057, 0.96), ["paper", "fig12"], OK),
        (perc(40.0, 30.0, 20.0, 0.05, 0.95), ["coloured"], OK),
        (perc(70.0, -10.0, -30.0, 0.05, 0.9), ["coloured"], OK),
        (perc(0.0, 0.0, 0.0, 0.1, 0.9), ["black"], OK),
        (perc(100.0, 0.0, 0.0, 0.0, 0.9), ["white", "on_envelope", "_boundary"], OK),
        (perc(L50, 0.0, 0.0, env50, 0.9), ["on_envelope", "_boundary"], OK),
        (perc(L50, 0.0, 0.0, env50 + 1e-9, 0.9), ["beyond_envelope"], E_ENVELOPE),
        (perc(90.0, 0.0, 0.0, 0.5, 0.9), ["beyond_envelope"], E_ENVELOPE),
        (perc(60.0, 60.0, 60.0, envelope_at(60.0) - 1e-3, 0.9), ["coloured", "energy"], E_ENERGY),
        (perc(L50, 0.0, 0.0, 0.1, 0.8), ["alpha_trusted_boundary"], OK),
        (perc(L50, 0.0, 0.0, 0.1, nextdown(0.8)), ["alpha_trusted_boundary"], WARN_ALPHA),
        (perc(L50, 0.0, 0.0, 0.1, 0.0), [], WARN_ALPHA),
        (perc(L50, 100.0, 0.0, 0.1, 0.9), ["out_of_gamut"], E_GAMUT),
        (perc(0.0, 5.0, 0.0, 0.1, 0.9), ["out_of_gamut", "black"], E_GAMUT),
        (perc(math.nan, 0.0, 0.0, 0.1, 0.9), [], E_NONFINITE),
        (perc(L50, 0.0, math.inf, 0.1, 0.9), [], E_NONFINITE),
        (perc(L50, 0.0, 0.0, 0.1, -math.inf), [], E_NONFINITE),
        (perc(L50, 0.0, 0.0, 0.1, -1e39), ["beyond_float"], E_NONFINITE),
        (perc(L50, 0.0, 0.0, 0.1, -1e30), ["huge_alpha"], WARN_ALPHA),
        (perc(-1e-300, 0.0, 0.0, 0.1, 0.9), [], E_LIGHTNESS),
        (perc(nextup(100.0), 0.0, 0.0, 0.1, 0.9), [], E_LIGHTNESS),
        (perc(L50, 0.0, 0.0, -1e-300, 0.9), [], E_NEGATIVE),
        (perc(L50, 0.0, 0.0, 0.1, 1.0), [], E_ALPHA),
        # validation order
        (perc(math.nan, 0.0, 0.0, -1.0, 1.0), ["order"], E_NONFINITE),
        (perc(101.0, 0.0, 0.0, -1.0, 1.0), ["order"], E_LIGHTNESS),
        (perc(L50, 200.0, 0.0, -1.0, 1.0), ["order"], E_NEGATIVE),
        (perc(L50, 200.0, 0.0, 0.9, 1.0), ["order"], E_ALPHA),
        (perc(L50, 200.0, 0.0, 0.9, 0.5), ["order"], E_GAMUT),
        (perc(L50, 0.0, 0.0, 0.9, 0.5), ["order"], E_ENVELOPE),
        (perc(60.0, 60.0, 60.0, envelope_at(60.0) - 1e-3, 0.5), ["order"], E_ENERGY),
    ]
    for q, tags, st in rowsq:
        b = "_boundary" in tags
        cl.add(fq, ref_check_perceptual, {"q": q, "_boundary": b}, [t for t in tags if t != "_boundary"] +
               (["error"] if st not in (OK, WARN_ALPHA) else ["regular"]), expect_status=st)
    cl.add(fq, ref_check_perceptual, {"q": perc(50.0, 0.0, 0.0, 0.1, 0.9)}, ["error", "null_pointer"], null=["q"])
    return {**header([fp, fq], "double", {},
                     "Status-only functions: the expected value is the status name."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- perceptual <-> physical

def gen_perceptual_material() -> Dict[str, Any]:
    rng = random.Random(5005)
    cl = CaseList("pm")
    fpp, fpq = "physical_from_perceptual", "perceptual_from_physical"
    g3 = lambda x: [x, x, x]  # noqa: E731
    for rd in PAPER_RD:
        for norm in (0, 1, 2):
            cl.add(fpp, ref_physical_from_perceptual,
                   {"q": perc(lightness_of(rd), 0.0, 0.0, 0.057, 0.96), "normalization": norm},
                   ["regular", "paper", "fig12"], expect_status=OK)
    rows: List[Tuple[Dict[str, float], int, List[str], str]] = [
        (perc(35.0, 45.0, 25.0, 0.06, 0.95), 0, ["coloured", "fig14"], OK),
        (perc(75.0, -5.0, -25.0, 0.06, 0.95), 0, ["coloured", "fig14"], OK),
        (perc(0.0, 0.0, 0.0, 0.1, 0.9), 0, ["black"], OK),
        (perc(100.0, 0.0, 0.0, 0.0, 0.9), 2, ["white"], OK),
        (perc(50.0, 0.0, 0.0, envelope_at(50.0), 0.9), 0, ["on_envelope"], OK),
        (perc(50.0, 0.0, 0.0, 0.1, 0.8), 0, ["alpha_trusted_boundary"], OK),
        (perc(50.0, 0.0, 0.0, 0.1, 0.7), 1, ["alpha_untrusted"], WARN_ALPHA),
        (perc(50.0, 0.0, 0.0, 0.1, nextdown(1.0)), 0, ["tiny_alpha"], OK),
        (perc(50.0, 0.0, 0.0, 0.9, 0.9), 0, ["beyond_envelope"], OK),
        (perc(50.0, 100.0, 0.0, 0.1, 0.9), 0, ["out_of_gamut"], E_GAMUT),
        (perc(20.0, 0.0, -90.0, 0.1, 0.9), 2, ["out_of_gamut"], E_GAMUT),
        (perc(math.nan, 0.0, 0.0, 0.1, 0.9), 0, [], E_NONFINITE),
        (perc(50.0, -math.inf, 0.0, 0.1, 0.9), 0, [], E_NONFINITE),
        (perc(-1.0, 0.0, 0.0, 0.1, 0.9), 0, [], E_LIGHTNESS),
        (perc(nextup(100.0), 0.0, 0.0, 0.1, 0.9), 0, [], E_LIGHTNESS),
        (perc(50.0, 0.0, 0.0, -0.1, 0.9), 0, [], E_NEGATIVE),
        (perc(50.0, 0.0, 0.0, 0.1, 1.0), 0, [], E_ALPHA),
        (perc(50.0, 0.0, 0.0, 0.1, 0.9), 3, [], E_NORMALIZATION),
        (perc(50.0, 0.0, 0.0, 0.1, 0.9), -1, [], E_NORMALIZATION),
    ]
    for q, norm, tags, st in rows:
        cl.add(fpp, ref_physical_from_perceptual, {"q": q, "normalization": norm},
               tags + (["error"] if st not in (OK, WARN_ALPHA) else ["regular"]), expect_status=st)
    for _ in range(30):
        rgb = [0.02 + 0.9 * rng.random() for _ in range(3)]
        L, a, b = lab_of(rgb)
        c = envelope_at(L) * 0.9 * rng.random()
        cl.add(fpp, ref_physical_from_perceptual,
               {"q": perc(L, a, b, c, 0.8 + 0.2 * rng.random()), "normalization": rng.randrange(3)},
               ["regular", "random"])
    for n in ("q", "p"):
        cl.add(fpp, ref_physical_from_perceptual, {"q": perc(50.0, 0.0, 0.0, 0.1, 0.9), "normalization": 0},
               ["error", "null_pointer"], null=[n])

    for rd in PAPER_RD:
        for rs in PAPER_RS:
            for al in PAPER_AL:
                cl.add(fpq, ref_perceptual_from_physical, {"p": phys(g3(rd), rs, al)},
                       ["regular", "paper", "experiment1"], expect_status=OK)
    rowsp: List[Tuple[Dict[str, Any], List[str], str]] = [
        (phys([0.5, 0.2, 0.1], 0.05, 0.05), ["coloured"], OK),
        (phys([0.05, 0.3, 0.7], 0.02, 0.1, 0.05), ["coloured", "anisotropic"], OK),
        (phys(g3(0.0), 0.0, 0.1), ["black", "zero"], OK),
        (phys(g3(1.0), 0.0, 0.1), ["white"], OK),
        (phys(g3(0.2), 0.1, 0.2), ["alpha_trusted_boundary"], OK),
        (phys(g3(0.2), 0.1, 0.3, 0.5), ["anisotropic", "alpha_untrusted"], WARN_ALPHA),
        (phys(g3(0.2), 0.1, 1e-300), ["tiny_alpha"], OK),
        (phys(g3(0.9), 0.5, 0.1), ["energy_violating"], OK),
        (phys(g3(0.2), 0.1, 0.1, norm=7), ["unknown_normalization_ignored"], OK),
        (phys([math.nan, 0.1, 0.1], 0.1, 0.1), [], E_NONFINITE),
        (phys(g3(0.2), 0.1, math.inf), [], E_NONFINITE),
        (phys([0.2, -0.1, 0.2], 0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), -0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), 0.1, 0.0), [], E_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, -0.5), [], E_ALPHA),
        (phys(g3(-0.2), 0.1, 0.0), ["order"], E_NEGATIVE),
    ]
    for p, tags, st in rowsp:
        cl.add(fpq, ref_perceptual_from_physical, {"p": p},
               tags + (["error"] if st not in (OK, WARN_ALPHA) else ["regular"]), expect_status=st)
    for _ in range(30):
        rd = [0.9 * rng.random() for _ in range(3)]
        cl.add(fpq, ref_perceptual_from_physical,
               {"p": phys(rd, 0.1 * rng.random(), 0.01 + 0.19 * rng.random(), 0.01 + 0.19 * rng.random())},
               ["regular", "random"])
    for n in ("p", "q"):
        cl.add(fpq, ref_perceptual_from_physical, {"p": phys(g3(0.2), 0.1, 0.1)}, ["error", "null_pointer"], null=[n])

    tol = tolerance_for({fpp: ["rho_d", "rho_s", "alpha_x", "alpha_y"], fpq: ["L", "a", "b", "c", "d"]})
    tol[fpp]["normalization"] = {"float": TOL_EXACT, "double": TOL_EXACT}
    return {**header([fpp, fpq], "double", tol,
                     "Fig. 13's five-parameter description <-> physical parameters."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- working colour spaces

def gen_color_space() -> Dict[str, Any]:
    """The _ex functions of color.h / perceptual.h in every working space (the functions
    without _ex are the Rec. 709 case and keep their own files)."""
    rng = random.Random(7007)
    cl = CaseList("cs")
    fr, fl, fy = "rgb_from_lab_ex", "lab_from_rgb_ex", "luminance_ex"
    fq, fpp, fpq = "check_perceptual_ex", "physical_from_perceptual_ex", "perceptual_from_physical_ex"
    g3 = lambda x: [x, x, x]  # noqa: E731
    spaces = range(len(COLOR_SPACES))
    for sp in spaces:
        name = COLOR_SPACES[sp]
        lab_in = lambda rgb: [D(v) for v in lab_from_rgb_core(MP, NOHOOK, [mpf(x) for x in rgb], sp)]  # noqa: E731
        # rgb_from_lab_ex: neutrals (R = G = B = Y in every space), in gamut, out of gamut.
        for L in (0.0, 8.0, 50.0, 100.0):
            cl.add(fr, ref_rgb_from_lab, {"lab": [L, 0.0, 0.0], "space": sp}, ["regular", "grey", name],
                   expect_status=OK)
        for _ in range(12):
            rgb = [0.01 + 0.99 * rng.random() for _ in range(3)]
            if rng.random() < 0.2:
                rgb = [x * 0.005 for x in rgb]
            cl.add(fr, ref_rgb_from_lab, {"lab": lab_in(rgb), "space": sp}, ["regular", "random", name],
                   expect_status=OK)
        for rgb in ([1.0, 1e-6, 1e-6], [1e-6, 1.0, 1e-6], [1e-6, 1e-6, 1.0]):
            cl.add(fr, ref_rgb_from_lab, {"lab": lab_in(rgb), "space": sp},
                   ["regular", "near_gamut_boundary", "saturated", name], expect_status=OK)
        for lab in ([50.0, 0.0, -140.0], [5.0, -90.0, 60.0], [0.0, 10.0, 10.0]):
            cl.add(fr, ref_rgb_from_lab, {"lab": lab, "space": sp}, ["error", "out_of_gamut", name],
                   expect_status=E_GAMUT)
        # lab_from_rgb_ex and luminance_ex.
        for rgb in ([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [0.18, 0.18, 0.18], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
                    [0.0, 0.0, 1.0], [2.0, 1.5, 3.0]):
            cl.add(fl, ref_lab_from_rgb, {"rgb": rgb, "space": sp}, ["regular", name], expect_status=OK)
            cl.add(fy, ref_luminance, {"rgb": rgb, "space": sp}, ["regular", name], expect_status=OK)
        for _ in range(10):
            rgb = [rng.random() for _ in range(3)]
            cl.add(fl, ref_lab_from_rgb, {"rgb": rgb, "space": sp}, ["regular", "random", name], expect_status=OK)
            cl.add(fy, ref_luminance, {"rgb": rgb, "space": sp}, ["regular", "random", name], expect_status=OK)
        cl.add(fl, ref_lab_from_rgb, {"rgb": [0.1, -0.5, 0.1], "space": sp}, ["error", name],
               expect_status=E_NEGATIVE)
        cl.add(fy, ref_luminance, {"rgb": [math.nan, 0.0, 0.0], "space": sp}, ["error", name],
               expect_status=E_NONFINITE)
        # check_perceptual_ex: the gamut and energy checks apply in the chosen space.
        for q, st in [(perc(50.0, 0.0, 0.0, 0.05, 0.9), OK), (perc(50.0, 0.0, 0.0, 0.1, 0.7), WARN_ALPHA),
                      (perc(50.0, 0.0, 0.0, 0.9, 0.9), E_ENVELOPE), (perc(50.0, 0.0, -140.0, 0.05, 0.9), E_GAMUT),
                      (perc(101.0, 0.0, 0.0, 0.05, 0.9), E_LIGHTNESS)]:
            cl.add(fq, ref_check_perceptual, {"q": q, "space": sp},
                   (["error"] if st not in (OK, WARN_ALPHA) else ["regular"]) + [name], expect_status=st)
        # physical_from_perceptual_ex / perceptual_from_physical_ex.
        for _ in range(8):
            rgb = [0.02 + 0.9 * rng.random() for _ in range(3)]
            L, a, b = lab_in(rgb)
            c = envelope_at(L) * 0.9 * rng.random()
            cl.add(fpp, ref_physical_from_perceptual,
                   {"q": perc(L, a, b, c, 0.8 + 0.2 * rng.random()), "normalization": rng.randrange(3), "space": sp},
                   ["regular", "random", name])
            rd = [0.9 * rng.random() for _ in range(3)]
            cl.add(fpq, ref_perceptual_from_physical,
                   {"p": phys(rd, 0.1 * rng.random(), 0.01 + 0.19 * rng.random()), "space": sp},
                   ["regular", "random", name])
        for rd in PAPER_RD:
            cl.add(fpp, ref_physical_from_perceptual,
                   {"q": perc(lightness_of(rd), 0.0, 0.0, 0.057, 0.96), "normalization": 0, "space": sp},
                   ["regular", "paper", "grey", name], expect_status=OK)
            cl.add(fpq, ref_perceptual_from_physical, {"p": phys(g3(rd), 0.066, 0.07), "space": sp},
                   ["regular", "paper", "grey", name], expect_status=OK)
        cl.add(fpp, ref_physical_from_perceptual,
               {"q": perc(50.0, 0.0, -140.0, 0.05, 0.9), "normalization": 0, "space": sp},
               ["error", "out_of_gamut", name], expect_status=E_GAMUT)
    # Where the spaces disagree: a saturated green outside Rec. 709 but inside P3, Rec. 2020, AP1.
    lab_p3_green = [D(v) for v in lab_from_rgb_core(MP, NOHOOK, [mpf("0.05"), mpf("0.6"), mpf("0.05")], 2)]
    for sp, st in [(0, E_GAMUT), (1, OK), (2, OK), (3, OK)]:
        cl.add(fr, ref_rgb_from_lab, {"lab": lab_p3_green, "space": sp},
               ["wide_gamut", COLOR_SPACES[sp]] + (["error"] if st != OK else ["regular"]), expect_status=st)
        cl.add(fq, ref_check_perceptual, {"q": perc(*lab_p3_green, 0.02, 0.9), "space": sp},
               ["wide_gamut", COLOR_SPACES[sp]] + (["error"] if st != OK else ["regular"]), expect_status=st)
    # Unknown spaces, then NULL pointers (checked first).
    for sp in (-1, len(COLOR_SPACES), 1000):
        cl.add(fr, ref_rgb_from_lab, {"lab": [50.0, 0.0, 0.0], "space": sp}, ["error", "unknown_space"],
               expect_status=E_ARGUMENT)
        cl.add(fl, ref_lab_from_rgb, {"rgb": [0.1, 0.2, 0.3], "space": sp}, ["error", "unknown_space"],
               expect_status=E_ARGUMENT)
        cl.add(fy, ref_luminance, {"rgb": [0.1, 0.2, 0.3], "space": sp}, ["error", "unknown_space"],
               expect_status=E_ARGUMENT)
        cl.add(fq, ref_check_perceptual, {"q": perc(50.0, 0.0, 0.0, 0.05, 0.9), "space": sp},
               ["error", "unknown_space"], expect_status=E_ARGUMENT)
        cl.add(fpp, ref_physical_from_perceptual,
               {"q": perc(50.0, 0.0, 0.0, 0.05, 0.9), "normalization": 0, "space": sp},
               ["error", "unknown_space"], expect_status=E_ARGUMENT)
        cl.add(fpq, ref_perceptual_from_physical, {"p": phys(g3(0.2), 0.1, 0.1), "space": sp},
               ["error", "unknown_space"], expect_status=E_ARGUMENT)
    cl.add(fr, ref_rgb_from_lab, {"lab": [50.0, 0.0, 0.0], "space": 1}, ["error", "null_pointer"], null=["rgb"])
    cl.add(fl, ref_lab_from_rgb, {"rgb": [0.1, 0.2, 0.3], "space": 1}, ["error", "null_pointer"], null=["lab"])
    cl.add(fy, ref_luminance, {"rgb": [0.1, 0.2, 0.3], "space": 1}, ["error", "null_pointer"], null=["Y"])
    cl.add(fq, ref_check_perceptual, {"q": perc(50.0, 0.0, 0.0, 0.1, 0.9), "space": 1}, ["error", "null_pointer"],
           null=["q"])
    cl.add(fpp, ref_physical_from_perceptual, {"q": perc(50.0, 0.0, 0.0, 0.1, 0.9), "normalization": 0, "space": 1},
           ["error", "null_pointer"], null=["q"])
    cl.add(fpq, ref_perceptual_from_physical, {"p": phys(g3(0.2), 0.1, 0.1), "space": 1}, ["error", "null_pointer"],
           null=["q"])

    tol = tolerance_for({fr: ["rgb"], fl: ["lab"], fy: ["Y"], fpp: ["rho_d", "rho_s", "alpha_x", "alpha_y"],
                         fpq: ["L", "a", "b", "c", "d"]})
    tol[fpp]["normalization"] = {"float": TOL_EXACT, "double": TOL_EXACT}
    return {**header([fr, fl, fy, fq, fpp, fpq], "double", tol,
                     "Working colour spaces (input 'space': 0 linear Rec. 709, 1 ACEScg (AP1, ACES white "
                     "0.32168, 0.33767, reached from D65 by a Bradford adaptation), 2 linear Display P3, "
                     "3 linear Rec. 2020); CIELAB relative to D65 in all; matrices derived in the generator "
                     "from primaries and whites at 40 digits. c and L use the luminance Y, the same in every "
                     "space. Unknown space: PGLOSS_ERR_ARGUMENT."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- BRDF helpers

Vec = List[float]


def f32v(v: Sequence[Any]) -> Vec:
    return [f32(float(x)) for x in v]


def dir_from(z: float, phi: float, scale: float = 1.0) -> Vec:
    """Direction with cosine z and azimuth phi (radians), times ``scale``, rounded to float32.

    Computed with mpmath so that the float32 inputs do not depend on the platform's libm.
    """
    Z = mpf(z)
    s = mp.sqrt(max(1 - Z * Z, mpf(0)))
    P = mpf(phi)
    return f32v([s * mp.cos(P) * scale, s * mp.sin(P) * scale, Z * scale])


def rand_dir(rng: random.Random, zmin: float = 0.0, zmax: float = 1.0) -> Vec:
    z = zmin + (zmax - zmin) * rng.random()
    d = dir_from(z, 2 * math.pi * rng.random())
    if rng.random() < 0.3:   # non-unit, by a power of two so that it stays float-exact
        k = rng.randrange(-20, 21)
        d = [x * 2.0 ** k for x in d]
    return d


def mirror(wo: Vec) -> Vec:
    return [-wo[0], -wo[1], wo[2]]


def reflect_about(wo: Vec, h: Sequence[mpf]) -> Optional[Vec]:
    o = normalize_ref(MP, NOHOOK, None, [mpf(x) for x in wo])
    hn = normalize_ref(MP, NOHOOK, None, list(h))
    d = sum(o[k] * hn[k] for k in range(3))
    wi = [2 * d * hn[k] - o[k] for k in range(3)]
    if wi[2] < mpf("1e-3"):
        return None
    return f32v(wi)


def near_specular(wo: Vec, m: Material, x: float, phi: float) -> Optional[Vec]:
    """wi such that the lobe exponent ((hx/ax)^2 + (hy/ay)^2)/hz^2 is ~x (before float rounding)."""
    sx = mp.sqrt(mpf(x))
    h = [mpf(m.alpha_x) * sx * mp.cos(phi), mpf(m.alpha_y) * sx * mp.sin(phi), mpf(1)]
    return reflect_about(wo, h)


LOBE_CYCLE = (3, 3, 3, 1, 2, 3, 0, 0xFFFFFFFF, 3, 2)


def material_table(mats: Dict[str, Tuple[Dict[str, Any], Material]]) -> Dict[str, Any]:
    return {mid: _enc_input(p) for mid, (p, _m) in mats.items()}


def brdf_materials() -> Dict[str, Tuple[Dict[str, Any], Material]]:
    """The materials of brdf_eval.json / brdf_sample.json (float-exact physical parameters)."""
    out: Dict[str, Tuple[Dict[str, Any], Material]] = {}
    n = 0

    def add(rd: Sequence[float], rs: float, ax: float, ay: float, norm: int, note: str) -> None:
        nonlocal n
        p = {"rho_d": f32v(rd), "rho_s": f32(rs), "alpha_x": f32(ax), "alpha_y": f32(ay), "normalization": norm,
             "_note": note}
        assert all(is_f32(x) for x in _phys_fields(p)), p   # float API: float-exact parameters
        st, m = material_init_ref(p)
        assert st == OK and m is not None
        out[f"m{n:02d}"] = (p, m)
        n += 1

    for norm in (NORM_WARD, NORM_WARD_DUR, NORM_BOUNDED):
        for al in (1e-3, 0.04, 0.2, 1.0):
            add((0.5, 0.3, 0.1), 0.05, al, al, norm, "isotropic")
        add((0.2, 0.2, 0.2), 0.1, 5e-5, 5e-5, norm, "alpha below PGLOSS_ALPHA_MIN: clamped to 1e-4f")
        add((0.3, 0.4, 0.5), 0.08, 0.05, 0.3, norm, "anisotropic")
        add((0.1, 0.1, 0.1), 0.2, 0.5, 0.01, norm, "anisotropic")
        add((0.0, 0.0, 0.0), 0.1, 0.1, 0.1, norm, "specular only")
    add((0.8, 0.6, 0.4), 0.0, 0.1, 0.1, NORM_WARD, "diffuse only")
    add((0.0, 0.0, 0.0), 0.0, 0.1, 0.1, NORM_WARD, "black: no lobe")
    add((0.5, 0.5, 0.5), 1e30, 1e-4, 1e-4, NORM_WARD_DUR, "huge rho_s: outputs clamped to FLT_MAX")
    for rd in PAPER_RD:
        for rs in PAPER_RS:
            for al in PAPER_AL:
                add((rd, rd, rd), rs, al, al, NORM_WARD, "paper Experiment 1 stimulus")
    for rd in (1e-5, 1e-6, 1e-8, 1e-12):  # 1 − Ps cancels in float unless written wd/(wd + ws)
        add((rd, rd, rd), 0.34, 0.1, 0.1, NORM_WARD, "weak diffuse lobe")
    return out


# ---------------------------------------------------------------------------------- material

def gen_material() -> Dict[str, Any]:
    cl = CaseList("ma")
    fi, fp = "material_init", "specular_probability"

    def ref_init(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
        st, m = material_init_ref(i["p"])
        if m is None:
            return st, {"lobes": 0}
        return st, material_fields_ref(m)

    g3 = lambda x: [x, x, x]  # noqa: E731
    rows: List[Tuple[Dict[str, Any], List[str], str]] = []
    for rd in PAPER_RD:
        for rs in PAPER_RS:
            rows.append((phys(g3(rd), rs, 0.04), ["paper", "not_float_exact"], OK))
    rows += [
        (phys([0.5, 0.3, 0.1], 0.05, 0.1, 0.1, 0), ["isotropic"], OK),
        (phys([0.5, 0.3, 0.1], 0.05, 0.1, 0.1, 1), ["isotropic"], OK),
        (phys([0.5, 0.3, 0.1], 0.05, 0.1, 0.1, 2), ["isotropic"], OK),
        (phys([0.5, 0.3, 0.1], 0.05, 0.05, 0.3, 2), ["anisotropic"], OK),
        (phys(g3(0.2), 0.1, 1e-3), ["tiny_alpha"], OK),
        (phys(g3(0.2), 0.1, 1e-4), ["alpha_min"], OK),
        (phys(g3(0.2), 0.1, f32(1e-4)), ["alpha_min"], OK),
        (phys(g3(0.2), 0.1, 5e-5), ["alpha_clamp"], OK),
        (phys(g3(0.2), 0.1, 1e-50), ["alpha_clamp", "below_float"], OK),
        (phys(g3(0.2), 0.1, 0.3, 1e-7), ["alpha_clamp", "anisotropic"], OK),
        (phys(g3(0.0), 0.1, 0.1), ["specular_only"], OK),
        (phys([0.0, 0.0, 0.2], 0.1, 0.1), ["one_channel"], OK),
        (phys(g3(0.2), 0.0, 0.1), ["diffuse_only"], OK),
        (phys(g3(0.0), 0.0, 0.1), ["black"], OK),
        (phys(g3(-0.0), -0.0, 0.1), ["negative_zero", "black"], OK),
        (phys(g3(2.0), 3.0, 2.0), ["energy_not_checked", "above_one"], OK),
        (phys([0.1, 0.2, 0.3], 0.4, 0.123456789012345), ["not_float_exact"], OK),
        (phys(g3(math.nan), 0.1, 0.1), [], E_NONFINITE),
        (phys(g3(0.2), -math.inf, 0.1), [], E_NONFINITE),
        (phys(g3(0.2), 0.1, 0.1, math.inf), [], E_NONFINITE),
        (phys([0.2, 0.2, -1e-30], 0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), -0.1, 0.1), [], E_NEGATIVE),
        (phys(g3(0.2), 0.1, 0.0), [], E_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, -0.0), ["negative_zero"], E_ALPHA),
        (phys(g3(0.2), 0.1, -1.0), [], E_ALPHA),
        (phys(g3(0.2), 0.1, 0.1, norm=3), [], E_NORMALIZATION),
        (phys(g3(0.2), 0.1, 0.1, norm=-1), [], E_NORMALIZATION),
        (phys([math.nan, -1.0, 0.1], -1.0, 0.0, norm=9), ["order"], E_NONFINITE),
        (phys(g3(-1.0), 0.1, 0.0, norm=9), ["order"], E_NEGATIVE),
        (phys(g3(0.1), 0.1, 0.0, norm=9), ["order"], E_ALPHA),
    ]
    for p, tags, st in rows:
        cl.add(fi, ref_init, {"p": p}, tags + (["error"] if st != OK else ["regular"]), with_sens=False,
               expect_status=st)
    for n in ("m", "p"):
        cl.add(fi, ref_init, {"p": phys(g3(0.2), 0.1, 0.1)}, ["error", "null_pointer"], null=[n])

    def ref_ps(B: Backend, H: Hooks, i: Dict[str, Any]) -> Tuple[str, Dict[str, Any]]:
        st, m = material_init_ref(i["p"])
        assert m is not None
        return OK, {"P": spec_prob_ref(B, H, m, i["lobes"])}

    for p in (phys([0.5, 0.3, 0.1], 0.05, 0.1), phys(g3(f32(0.767)), f32(0.033), 0.04),
              phys(g3(f32(0.03)), f32(0.099), 0.04), phys(g3(0.0), 0.1, 0.1), phys(g3(0.2), 0.0, 0.1),
              phys(g3(0.0), 0.0, 0.1), phys([0.0, 0.0, 1e-6], 0.9, 0.1), phys(g3(1.0), 1e-6, 0.1)):
        for lobes in (0, 1, 2, 3, 4, 0xFFFFFFFF):
            cl.add(fp, ref_ps, {"p": p, "lobes": lobes}, ["regular"])
    fields = ["rho_d", "rho_s", "alpha_x", "alpha_y", "lobes"]
    tol: Dict[str, Any] = {fi: {k: {"float": TOL_EXACT, "double": TOL_EXACT} for k in fields}}
    for k in ("inv_alpha_x", "inv_alpha_y", "spec_scale", "pdf_scale", "weight_diffuse", "weight_specular"):
        tol[fi][k] = {"float": {"rel": 1e-6, "kappa_rel": 0.0, "abs": 0.0},
                      "double": {"rel": 1e-6, "kappa_rel": 0.0, "abs": 0.0}}
    tol[fp] = {"P": tol_both()}
    return {**header([fi, fp], "float", tol,
                     "material_init: rho/alpha are the float32 roundings (exact), alpha raised to "
                     "PGLOSS_ALPHA_MIN; derived fields within 1e-6 (they are stored as float). On an error "
                     "only lobes == 0 is specified (and eval must return 0)."),
            "cases": cl.cases}


# ---------------------------------------------------------------------------------- eval / pdf

def eval_value(m: Material, wo: Vec, wi: Vec, lobes: int) -> Tuple[str, Dict[str, Any], Dict[str, Any]]:
    if not valid_dir(wo) or not valid_dir(wi):
        return E_DIRECTION, {"f": [0.0] * 3, "pdf": 0.0}, {}
    r = brdf_ref(MP, NOHOOK, m, wo, wi, lobes)
    info: Dict[str, Any] = {}
    o = normalize_ref(MP, NOHOOK, None, [mpf(x) for x in wo])
    i = normalize_ref(MP, NOHOOK, None, [mpf(x) for x in wi])
    if o[2] > 0 and i[2] > 0:
        if min(o[2], i[2]) < COS_MIN_F:
            # The header's replacement of h.z in the pdf's denominator does not say whether h is
            # the normalised or the unnormalised half vector there: the pdf is left unspecified.
            r = {"f": r["f"], "pdf": None}
        h = [o[k] + i[k] for k in range(3)]
        x = ((h[0] / m.alpha_x) ** 2 + (h[1] / m.alpha_y) ** 2) / h[2] ** 2
        info["exponent"] = Short(round_up_2(float(x)) if x > 0 else 0.0)
    return OK, r, info


def gen_eval(mats: Dict[str, Tuple[Dict[str, Any], Material]]) -> Dict[str, Any]:
    rng = random.Random(7007)
    cl: List[Dict[str, Any]] = []

    def add(mid: str, wo: Vec, wi: Vec, lobes: int, tags: Sequence[str]) -> None:
        m = mats[mid][1]
        wo, wi = f32v(wo), f32v(wi)   # literal inputs are rounded to float32 first
        st, r, info = eval_value(m, wo, wi, lobes)
        exp = exp_out(r)
        for v in exp["f"] + [exp["pdf"]]:
            assert v is None or v <= FLT_MAX, ("float overflow", mid, wo, wi)
        case: Dict[str, Any] = {"id": f"ev{len(cl):04d}", "tags": list(tags),
                                "input": {"material": mid, "wo": [enc(x) for x in wo], "wi": [enc(x) for x in wi],
                                          "lobes": lobes},
                                "status": st, "expected": exp}
        if st == OK and (any(v != 0 for v in exp["f"]) or exp["pdf"] != 0):
            sn = sensitivity(lambda B, H: brdf_ref(B, H, m, wo, wi, lobes))
            if exp["pdf"] is None:
                sn["pdf"] = None
            case["sens"] = sens_out(sn)
            if ill_conditioned_float(exp, sn):
                case["tags"].append("ill_conditioned")
        if info:
            case["info"] = info
        cl.append(case)

    generic = [k for k, (p, _m) in mats.items()
               if "paper" not in p["_note"] and "huge" not in p["_note"] and "weak" not in p["_note"]]
    paper = [k for k, (p, _m) in mats.items() if "paper" in p["_note"]]
    huge = [k for k, (p, _m) in mats.items() if "huge" in p["_note"]]
    for mid in huge:
        add(mid, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], 3, ["regular", "normal_incidence"])
        add(mid, [0.6, 0.0, 0.8], [-0.6, 0.0, 0.8], 3, ["regular", "mirror", "large_value"])
        add(mid, [1.0, 0.0, 1e-6], [-1.0, 0.0, 1e-6], 3, ["edge", "grazing", "overflow_clamp"])
        add(mid, [1.0, 0.0, 1e-6], [-1.0, 0.0, 1e-6], 1, ["edge", "grazing"])
    j = 0
    for mid in generic:
        m = mats[mid][1]
        bounded = m.normalization == NORM_BOUNDED
        for _ in range(14):
            add(mid, rand_dir(rng, 0.05), rand_dir(rng, 0.05), LOBE_CYCLE[j % 10], ["regular", "random"])
            j += 1
        wo, wi = rand_dir(rng, 0.1), rand_dir(rng, 0.1)
        add(mid, wo, wi, 3, ["regular", "reciprocity"])
        add(mid, wi, wo, 3, ["regular", "reciprocity"])
        for x in (0.0, 0.25, 1.0, 4.0, 16.0, 40.0, 80.0):
            wo = rand_dir(rng, 0.2)
            wi2 = near_specular(wo, m, x, 2 * math.pi * rng.random())
            if wi2 is not None:
                add(mid, wo, wi2, LOBE_CYCLE[j % 10], ["regular", "near_specular"] + (["large_exponent"] if x >= 40 else []))
                j += 1
        wo = rand_dir(rng, 0.05)
        add(mid, wo, mirror(wo), 3, ["regular", "mirror"])
        wo = dir_from(1.0, 0.0)
        add(mid, wo, wo, 3, ["regular", "normal_incidence"])
        # exponent ~100: E ~ 4e-44, the specular term near or below float underflow
        wo = rand_dir(rng, 0.3)
        wi2 = near_specular(wo, m, 100.0, 2 * math.pi * rng.random())
        if wi2 is not None:
            add(mid, wo, wi2, 2, ["edge", "near_underflow"])
        # grazing
        for z in (1e-6, 1e-4, 1e-2):
            wo = dir_from(z, 2 * math.pi * rng.random())
            add(mid, wo, rand_dir(rng, 0.1), 3, ["edge", "grazing"])
            add(mid, wo, mirror(wo), 3, ["edge", "grazing", "mirror"])
            add(mid, rand_dir(rng, 0.1), wo, 3, ["edge", "grazing"])
            add(mid, wo, [-wo[0], -wo[1], wo[2] * 2], 3, ["edge", "grazing", "opposite"])
        add(mid, [1.0, 0.0, 1e-6], [-1.0, 0.0, 1e-6], 2, ["edge", "grazing", "opposite"])
        add(mid, dir_from(0.0, 0.3), rand_dir(rng), 3, ["edge", "horizon"])
        add(mid, rand_dir(rng), [0.0, 1.0, 0.0], 3, ["edge", "horizon"])
        if not bounded:   # cosines below PGLOSS_COS_MIN (clamped in the normalisation factor)
            add(mid, [1.0, 0.0, 1e-10], [-1.0, 0.0, 1e-10], 3, ["edge", "grazing", "cos_min_clamp"])
            add(mid, [1.0, 0.0, 1e-30], [-1.0, 0.0, 1e-30], 2, ["edge", "grazing", "cos_min_clamp"])
            add(mid, [0.0, 1.0, 1e-12], [0.0, -1.0, 1e-6], 2, ["edge", "grazing", "cos_min_clamp"])
        # below the horizon (one-sided BRDF: value and pdf 0, status OK)
        add(mid, rand_dir(rng), [0.3, 0.2, -0.5], 3, ["edge", "below_horizon"])
        add(mid, [0.3, 0.2, -0.5], rand_dir(rng), 3, ["edge", "below_horizon"])
        add(mid, [0.3, 0.2, -0.0], rand_dir(rng), 3, ["edge", "below_horizon", "negative_zero"])
    # non-unit directions, extreme scales, denormals (they are normalised first)
    for mid in ("m01", "m09", "m17"):
        wo, wi = dir_from(0.8, 0.4), dir_from(0.6, 3.0)
        for s in (1e-30, 1e30, 1e-40, 3e38):
            add(mid, f32v([x * s for x in wo]), f32v([x * s for x in wi]), 3, ["edge", "non_unit", "extreme_scale"])
        add(mid, [1e-45, 0.0, 1e-45], [0.0, 3e-45, 4e-45], 3, ["edge", "non_unit", "denormal"])
        add(mid, [3e38, 3e38, 3e38], [-3e38, 0.0, 3e38], 3, ["edge", "non_unit", "extreme_scale"])
        add(mid, [0.0, 0.0, 1e-45], [0.0, 0.0, 3e38], 3, ["edge", "non_unit", "extreme_scale"])
    # errors
    for mid in ("m01", "m09", "m17"):
        good = dir_from(0.7, 1.0)
        for bad, tag in (([0.0, 0.0, 0.0], "zero"), ([-0.0, 0.0, -0.0], "zero"), ([math.nan, 0.0, 1.0], "nan"),
                         ([0.0, math.inf, 1.0], "inf"), ([0.0, 0.0, -math.inf], "inf")):
            add(mid, bad, good, 3, ["error", "direction", tag])
            add(mid, good, bad, 3, ["error", "direction", tag])
        add(mid, [0.0, 0.0, 0.0], [0.0, 0.0, -1.0], 3, ["error", "direction", "zero", "below_horizon"])
    # the 27 stimuli of Experiment 1
    for mid in paper:
        m = mats[mid][1]
        wo = rand_dir(rng, 0.2)
        add(mid, wo, rand_dir(rng, 0.05), 3, ["regular", "paper"])
        add(mid, wo, mirror(wo), 3, ["regular", "paper", "mirror"])
        for x in (1.0, 9.0):
            wi2 = near_specular(wo, m, x, 2 * math.pi * rng.random())
            if wi2 is not None:
                add(mid, wo, wi2, 3, ["regular", "paper", "near_specular"])
    # A weak diffuse lobe beside a strong specular one: far from the mirror direction the pdf is
    # its diffuse part, (1 − Ps) cos/π with 1 − Ps ~ 3e-5 .. 3e-12 (fixed directions).
    for mid in [k for k, (p, _m) in mats.items() if "weak" in p["_note"]]:
        wo = dir_from(0.8, 0.0)
        for wi in (dir_from(0.5, 2.0), dir_from(0.9, 4.0), dir_from(0.2, 1.0)):
            add(mid, wo, wi, 3, ["regular", "weak_diffuse"])

    tol = {"eval": {"f": tol_both(1e-35)}, "pdf": {"pdf": tol_both(1e-35)},
           "eval_pdf": {"f": tol_both(1e-35), "pdf": tol_both(1e-35)}}
    doc = header(["eval", "pdf", "eval_pdf", "eval_batch", "pdf_batch", "eval_pdf_batch"], "float", tol,
                 "One case checks eval (f), pdf (pdf) and eval_pdf (both); the batched functions are run on all "
                 "non-NULL cases grouped by (material, lobes), with the same tolerance.")
    doc["materials"] = material_table(mats)
    doc["cases"] = cl
    return doc


# ---------------------------------------------------------------------------------- sample

def gen_sample(mats: Dict[str, Tuple[Dict[str, Any], Material]]) -> Dict[str, Any]:
    rng = random.Random(8008)
    cl: List[Dict[str, Any]] = []
    skipped = 0

    def add(mid: str, wo: Vec, u: Sequence[float], lobes: int, tags: Sequence[str], force: bool = False) -> bool:
        nonlocal skipped
        m = mats[mid][1]
        wo, u = f32v(wo), f32v(u)     # literal inputs are rounded to float32 first
        inp = {"material": mid, "wo": [enc(x) for x in wo], "u": [enc(x) for x in u], "lobes": lobes}
        case: Dict[str, Any] = {"id": f"sa{len(cl):04d}", "tags": list(tags), "input": inp}
        if not valid_dir(wo):
            case.update(status=E_DIRECTION, expected={"wi": None, "pdf": 0.0, "weight": [0.0] * 3, "lobe": None})
        elif any(math.isnan(x) for x in u):
            case.update(status=E_RANDOM, expected={"wi": None, "pdf": 0.0, "weight": [0.0] * 3, "lobe": None})
        else:
            r = sample_ref(MP, NOHOOK, m, wo, u, lobes)
            mg = r.pop("_margin")
            ok = (mg.get("u0", 1) > 1e-5 and mg.get("woh", 1) > 1e-6 and
                  (mg.get("wiz", 1) > 1e-4 or mg.get("wiz", 1) == 0 and "zz" not in mg) and
                  mg.get("zz", 1) > 1e-6)
            if not ok and not force:
                skipped += 1
                return False
            assert ok, (mid, wo, u, mg)
            exp = exp_out({**r, "lobe": LOBE_NAMES[r["lobe"]] if r["lobe"] is not None else None})
            for v in exp["weight"] + [exp["pdf"]]:
                assert v < 1e38, ("float overflow", mid, wo, u)
            if exp["pdf"] == 0:
                case["tags"].append("rejected")
            case.update(status=OK, expected=exp)
            if exp["pdf"] != 0 or exp["wi"] is not None:
                def fn(B: Backend, H: Hooks) -> Dict[str, Any]:
                    s = sample_ref(B, H, m, wo, u, lobes)
                    return {"wi": s["wi"], "pdf": s["pdf"], "weight": s["weight"]}
                sn = sensitivity(fn)
                if (ill_conditioned_float({"pdf": exp["pdf"], "weight": exp["weight"]},
                                          {"pdf": sn["pdf"], "weight": sn["weight"]}) or
                        exp["wi"] is not None and ill_conditioned_float({"wi": exp["wi"]}, {"wi": sn["wi"]}, True)):
                    if not force:
                        skipped += 1
                        return False
                    case["tags"].append("ill_conditioned")
                case["sens"] = sens_out(sn)
        cl.append(case)
        return True

    generic = [k for k, (p, _m) in mats.items()
               if "paper" not in p["_note"] and "huge" not in p["_note"] and "weak" not in p["_note"]]
    paper = [k for k, (p, _m) in mats.items() if "paper" in p["_note"]]
    j = 0
    for mid in generic:
        wos = [dir_from(1.0, 0.0), dir_from(0.7071, 2 * math.pi * rng.random()),
               dir_from(0.17, 2 * math.pi * rng.random()), dir_from(1e-3, 2 * math.pi * rng.random()),
               dir_from(1e-6, 2 * math.pi * rng.random())]
        for k, wo in enumerate(wos):
            tags = ["regular"] if k < 3 else ["edge", "grazing"]
            n = 0
            for _attempt in range(100):
                if n == 6:
                    break
                u = f32v([rng.random() for _ in range(3)])
                if add(mid, wo, u, LOBE_CYCLE[j % 10], tags + ["random"]):
                    n += 1
                    j += 1
            if rng.random() < 0.5:   # non-unit wo
                add(mid, [x * 1024.0 for x in wo], f32v([rng.random() for _ in range(3)]), 3, tags + ["non_unit"])
    # special random numbers
    specials: List[Tuple[List[float], List[str]]] = [
        ([0.0, 0.0, 0.0], ["u_zero"]), ([0.0, 0.0, 0.5], ["u_zero"]), ([0.0, 0.5, 0.0], ["u_zero"]),
        ([0.0, 0.5, 0.5], ["u_zero", "center"]), ([U_MAX, U_MAX, U_MAX], ["u_max"]),
        ([U_MAX, 0.0, 0.5], ["u_max", "u_zero"]), ([1.0, 1.0, 1.0], ["u_clamped"]),
        ([2.0, -1.0, 0.25], ["u_clamped"]), ([-0.0, 0.3, 0.7], ["negative_zero"]),
        ([0.5, 1e-7, 0.3], ["u_tiny"]), ([1e-30, 0.75, 0.9], ["u_tiny"]), ([0.999, 0.9999, 0.1], ["u_large"]),
    ]
    for mid in ("m00", "m01", "m03", "m05", "m09", "m13", "m17", "m20", "m23", "m24"):
        for wo in (dir_from(1.0, 0.0), dir_from(0.5, 0.7), dir_from(1e-3, 2.0)):
            for lobes in (3, 1, 2):
                for u, tags in specials:
                    add(mid, wo, f32v(u), lobes, ["edge"] + tags)
    # wo at or below the horizon, no active lobe, errors
    for mid in ("m01", "m09", "m17"):
        for wo, tags in (([0.3, 0.2, -0.5], ["below_horizon"]), (dir_from(0.0, 1.0), ["horizon"]),
                         ([0.3, 0.2, -0.0], ["horizon", "negative_zero"])):
            add(mid, wo, [0.5, 0.5, 0.5], 3, ["edge"] + tags, force=True)
            add(mid, wo, [0.9, 0.5, 0.5], 3, ["edge"] + tags, force=True)
        add(mid, dir_from(0.5, 1.0), [0.5, 0.5, 0.5], 0, ["edge", "no_lobe"], force=True)
        add(mid, dir_from(0.5, 1.0), [0.5, 0.5, 0.5], 4, ["edge", "no_lobe"], force=True)
        for wo in ([0.0, 0.0, 0.0], [math.nan, 0.0, 1.0], [0.0, 0.0, math.inf]):
            add(mid, wo, [0.5, 0.5, 0.5], 3, ["error", "direction"])
        for u in ([math.nan, 0.5, 0.5], [0.5, math.nan, 0.5], [0.5, 0.5, math.nan]):
            add(mid, dir_from(0.5, 1.0), u, 3, ["error", "random"])
    assert mats["m24"][0]["_note"] == "diffuse only" and mats["m25"][0]["_note"].startswith("black")
    add("m25", dir_from(0.5, 1.0), [0.5, 0.5, 0.5], 3, ["edge", "no_lobe", "black"], force=True)
    for mid in paper:
        n = 0
        for _attempt in range(100):
            if n == 4:
                break
            if add(mid, dir_from(0.3 + 0.7 * rng.random(), 2 * math.pi * rng.random()),
                   f32v([rng.random() for _ in range(3)]), 3, ["regular", "paper"]):
                n += 1

    # The header returns wi as float and evaluates pdf and weight at that float wi, so even a
    # double implementation differs from the exact values by float's rounding of wi: the double
    # column allows 1e-7 on wi and float's kappa_rel on pdf and weight.
    wi_tol = {"float": {"rel": 0.0, "kappa_rel": 1e-6, "abs": 2e-6},
              "double": {"rel": 0.0, "kappa_rel": 4e-15, "abs": 1e-7}}
    pw_tol = tol_both(1e-35)
    pw_tol["double"]["kappa_rel"] = 1e-6
    tol = {"sample": {"wi": wi_tol, "pdf": pw_tol, "weight": pw_tol,
                      "lobe": {"float": TOL_EXACT, "double": TOL_EXACT}}}
    doc = header(["sample", "sample_batch"], "float", tol,
                 f"wi compared component-wise (absolute); pdf and weight relative. {skipped} draws were "
                 "discarded by the generator: within 1e-5 of the lobe choice, 1e-4 of the horizon or 1e-6 of "
                 "wo.h = 0, or ill-conditioned in float (README).")
    doc["materials"] = material_table(mats)
    doc["cases"] = cl
    return doc



# ----------------------------------------------------------------------------------
# Glossmeter (pgloss/glossmeter.h): instrument readings from the measurement equation
#   Φ(W) = ∫_S dωi ∫_W f(ωi, ωo) cos θo dωo
# over the gnomonic windows of the header's table, transcribed here. The standard, the Fresnel
# mirrors and the Lambertian readings are in mpmath (closed forms and 24-point Gauss–Legendre of
# smooth integrands); the Ward readings by product Gauss–Legendre in double (nodes from mpmath,
# the integrand in Python floats, sums by math.fsum) on panels of this generator's own design —
# uniform over the source, graded from the mirror point at 1, 2, 4, … α over the receptor — at 6
# and 12 points a panel. The 12-point value is stored rounded to 12 significant digits, so that a
# platform's libm cannot change the file, with its error bound: |Q12 − Q6| plus the rounding.
# ----------------------------------------------------------------------------------

GM_SOURCE = (0.0, 0.75, 2.5)
GM_GEOMETRY: Dict[str, Tuple[float, Tuple[float, float, float], Tuple[float, float, float],
                             Tuple[Tuple[float, float, float], ...]]] = {
    "PGLOSS_GLOSS_20": (20.0, GM_SOURCE, (0.0, 1.8, 3.6), ()),
    "PGLOSS_GLOSS_60": (60.0, GM_SOURCE, (0.0, 4.4, 11.7), ()),
    "PGLOSS_GLOSS_85": (85.0, GM_SOURCE, (0.0, 4.0, 6.0), ()),
    "PGLOSS_HAZE_20": (20.0, GM_SOURCE, (0.0, 1.8, 3.6), ((-2.0, 1.0, 3.6), (2.0, 1.0, 3.6))),
    "PGLOSS_DOI_30": (30.0, (0.0, 0.1, 2.5), (0.0, 0.1, 3.6), ((-0.3, 0.1, 3.6), (0.3, 0.1, 3.6))),
    "PGLOSS_CONTRAST_60": (60.0, GM_SOURCE, (0.0, 4.4, 11.7), ()),
}
GM_STANDARD_INDEX = mpf("1.567")
GM_LUMA = [float(x) for x in LUMA_STR]


def gm_rect(win: Tuple[float, float, float]) -> Tuple[mpf, mpf, mpf, mpf]:
    """(s0, s1, t0, t1): the window in the focal plane of its axis (header: "Windows")."""
    c, w, h = (mpf(repr(x)) for x in win)
    d = mp.pi / 180
    return mp.tan((c - w / 2) * d), mp.tan((c + w / 2) * d), -mp.tan(h / 2 * d), mp.tan(h / 2 * d)


def gm_fresnel(n: mpf, c: mpf) -> mpf:
    """Unpolarised Fresnel reflectance of a dielectric: the mean of |r_s|² and |r_p|²."""
    sin2 = 1 - c * c
    ct = mp.sqrt(1 - sin2 / (n * n))
    rs = (c - n * ct) / (c + n * ct)
    rp = (n * c - ct) / (n * c + ct)
    return (rs * rs + rp * rp) / 2


_GM_GL: Dict[int, List[Tuple[mpf, mpf]]] = {}


def gm_gl(n: int) -> List[Tuple[mpf, mpf]]:
    """The n-point Gauss–Legendre rule on [−1, 1] (n = 6, 12, 24), at the working precision."""
    if n not in _GM_GL:
        from mpmath.calculus.quadrature import GaussLegendre
        _GM_GL[n] = GaussLegendre(mp).calc_nodes({6: 2, 12: 3, 24: 4}[n], mp.prec)
    return _GM_GL[n]


def gm_mirror_flux(theta: float, src: Tuple[float, float, float], rec: Tuple[float, float, float], n: mpf) -> mpf:
    """Φ of a Fresnel mirror of index n: ∫ R(cos θi) dωi over the source points whose mirror
    (s, −t) lies in the receptor (24 × 24 Gauss–Legendre; the integrand is smooth)."""
    S, W = gm_rect(src), gm_rect(rec)
    s0, s1 = max(S[0], W[0]), min(S[1], W[1])
    t0, t1 = max(S[2], -W[3]), min(S[3], -W[2])
    if s1 <= s0 or t1 <= t0:
        return mpf(0)
    th = mpf(repr(theta)) * mp.pi / 180
    st, ct = mp.sin(th), mp.cos(th)
    hs, cs, ht, cc = (s1 - s0) / 2, (s1 + s0) / 2, (t1 - t0) / 2, (t1 + t0) / 2
    total = mpf(0)
    for x, wx in gm_gl(24):
        s = cs + hs * x
        for y, wy in gm_gl(24):
            t = cc + ht * y
            q = 1 + s * s + t * t
            total += wx * wy * gm_fresnel(n, (ct - s * st) / mp.sqrt(q)) / q ** mpf(1.5)
    return hs * ht * total


def gm_solid_angle(r: Tuple[mpf, mpf, mpf, mpf]) -> mpf:
    """∫∫ (1 + s² + t²)^(-3/2) ds dt: the corner function atan(ab/√(1 + a² + b²))."""
    def corner(a: mpf, b: mpf) -> mpf:
        return mp.atan(a * b / mp.sqrt(1 + a * a + b * b))
    return corner(r[1], r[3]) - corner(r[0], r[3]) - corner(r[1], r[2]) + corner(r[0], r[2])


def gm_projected(theta: float, r: Tuple[mpf, mpf, mpf, mpf]) -> mpf:
    """∫_W cos θo dωo = cos θ ∫∫ (1+s²+t²)^-2 − sin θ ∫∫ s (1+s²+t²)^-2, both in closed form:
    G(a, b) = ½[a/√(1+a²) atan(b/√(1+a²)) + b/√(1+b²) atan(a/√(1+b²))] (the form factor of a
    rectangle, times π), and ∫ s (c + s²)^-2 ds = −1/(2(c + s²)), ∫ dt/(A² + t²) = atan(t/A)/A."""
    def G(a: mpf, b: mpf) -> mpf:
        A, B = mp.sqrt(1 + a * a), mp.sqrt(1 + b * b)
        return (a / A * mp.atan(b / A) + b / B * mp.atan(a / B)) / 2
    s0, s1, t0, t1 = r
    Q = G(s1, t1) - G(s0, t1) - G(s1, t0) + G(s0, t0)
    def H(s: mpf) -> mpf:
        A = mp.sqrt(1 + s * s)
        return (mp.atan(t1 / A) - mp.atan(t0 / A)) / A
    M = -(H(s1) - H(s0)) / 2
    th = mpf(repr(theta)) * mp.pi / 180
    return mp.cos(th) * Q - mp.sin(th) * M


def gm_lambert_reading(kind: str, rho: mpf) -> mpf:
    theta, src, rec, off = GM_GEOMETRY[kind]
    std = gm_mirror_flux(theta, src, rec, GM_STANDARD_INDEX)
    om = gm_solid_angle(gm_rect(src))
    def phi(w: Tuple[float, float, float]) -> mpf:
        return rho / mp.pi * om * gm_projected(theta, gm_rect(w))
    if kind == "PGLOSS_HAZE_20":
        return 100 * (phi(off[0]) + phi(off[1])) / std
    if kind == "PGLOSS_DOI_30":
        rs = phi(rec)
        return 100 * (rs - (phi(off[0]) + phi(off[1])) / 2) / rs
    if kind == "PGLOSS_CONTRAST_60":
        return mpf(1)   # a perfect diffuser: specular and diffuse luminance factors are both ρ
    return 100 * phi(rec) / std


_GM_NODES: Dict[int, List[Tuple[float, float]]] = {}


def _gm_nodes(brk: Sequence[float], n: int) -> Tuple[List[float], List[float]]:
    if n not in _GM_NODES:
        _GM_NODES[n] = [(float(x), float(w)) for x, w in gm_gl(n)]
    xs: List[float] = []
    ws: List[float] = []
    for a, b in zip(brk[:-1], brk[1:]):
        h, c = (b - a) / 2, (a + b) / 2
        for x, w in _GM_NODES[n]:
            xs.append(c + h * x)
            ws.append(h * w)
    return xs, ws


def _gm_graded(lo: float, hi: float, focus: float, base: float) -> List[float]:
    """lo, hi, the focus and focus ± base·2^k inside (lo, hi); breaks closer than base/5 merge."""
    pts = {lo, hi}
    if lo < focus < hi:
        pts.add(focus)
    d = base
    while d < 2 * (hi - lo) + abs(focus - lo) + abs(focus - hi):
        for x in (focus - d, focus + d):
            if lo < x < hi:
                pts.add(x)
        d *= 2
    out = [lo]
    for x in sorted(pts)[1:]:
        if x - out[-1] > base / 5:
            out.append(x)
    out[-1] = hi
    return out


def gm_ward_f(p: Dict[str, Any], wo: Tuple[float, float, float], wi: Tuple[float, float, float]) -> float:
    """Luminance of eq. 2 (brdf.h: WARD, WARD_DUR, BOUNDED) at unit directions, in double."""
    rd, rs, ax, ay, norm = p["rho_d"], p["rho_s"], p["alpha_x"], p["alpha_y"], p["normalization"]
    f = (GM_LUMA[0] * rd[0] + GM_LUMA[1] * rd[1] + GM_LUMA[2] * rd[2]) / math.pi
    hx, hy, hz = wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]
    e = math.exp(-((hx / ax) ** 2 + (hy / ay) ** 2) / (hz * hz))
    if norm == NORM_WARD:
        return f + rs * e / (4 * math.pi * ax * ay * math.sqrt(wi[2] * wo[2]))
    if norm == NORM_WARD_DUR:
        return f + rs * e / (4 * math.pi * ax * ay * wi[2] * wo[2])
    return f + rs * e * (hx * hx + hy * hy + hz * hz) / (math.pi * ax * ay * hz ** 4)


def gm_ward_flux(theta: float, src: Tuple[float, float, float], rec: Tuple[float, float, float],
                 p: Dict[str, Any], azimuth: float, n: int) -> float:
    d = mp.pi / 180
    st, ct = float(mp.sin(mpf(repr(theta)) * d)), float(mp.cos(mpf(repr(theta)) * d))
    ca, sa = float(mp.cos(mpf(repr(azimuth)) * d)), float(mp.sin(mpf(repr(azimuth)) * d))
    S = [float(x) for x in gm_rect(src)]
    W = [float(x) for x in gm_rect(rec)]
    a = min(p["alpha_x"], p["alpha_y"])
    bs, bt = 2 * a, 2 * a * ct   # the lobe's scale in s and t (h turns by half the receptor's turn)
    ns_, nt_ = max(1, math.ceil((S[1] - S[0]) / bs)), max(1, math.ceil((S[3] - S[2]) / bt))
    oxs, ows = _gm_nodes([S[0] + (S[1] - S[0]) * k / ns_ for k in range(ns_ + 1)], n)
    oxt, owt = _gm_nodes([S[2] + (S[3] - S[2]) * k / nt_ for k in range(nt_ + 1)], n)
    terms: List[float] = []
    for si, wsi in zip(oxs, ows):
        ixs, iws = _gm_nodes(_gm_graded(W[0], W[1], si, bs / 2), n)
        for ti, wti in zip(oxt, owt):
            q = 1 + si * si + ti * ti
            inv = 1 / math.sqrt(q)
            x, y = -(st + si * ct) * inv, ti * inv
            wi = (ca * x + sa * y, -sa * x + ca * y, (ct - si * st) * inv)
            ixt, iwt = _gm_nodes(_gm_graded(W[2], W[3], -ti, bt / 2), n)
            acc = 0.0
            for so, wso in zip(ixs, iws):
                row = 0.0
                for to, wto in zip(ixt, iwt):
                    q2 = 1 + so * so + to * to
                    inv2 = 1 / math.sqrt(q2)
                    x2, y2, z2 = (st + so * ct) * inv2, to * inv2, (ct - so * st) * inv2
                    row += wto * inv2 / q2 * z2 * gm_ward_f(p, (ca * x2 + sa * y2, -sa * x2 + ca * y2, z2), wi)
                acc += wso * row
            terms.append(wsi * wti * inv / q * acc)
    return math.fsum(terms)


def gm_ward_reading(kind: str, p: Dict[str, Any], azimuth: float) -> Tuple[float, float]:
    """(value, error bound) of a reading of a Ward paint."""
    theta, src, rec, off = GM_GEOMETRY[kind]
    std = float(gm_mirror_flux(theta, src, rec, GM_STANDARD_INDEX))
    wins = [rec] + list(off) if kind in ("PGLOSS_HAZE_20", "PGLOSS_DOI_30") else [rec]
    lo = [gm_ward_flux(theta, src, w, p, azimuth, 6) for w in wins]
    hi = [gm_ward_flux(theta, src, w, p, azimuth, 12) for w in wins]
    def read(ph: List[float]) -> float:
        if kind == "PGLOSS_HAZE_20":
            return 100 * (ph[1] + ph[2]) / std
        if kind == "PGLOSS_DOI_30":
            return 100 * (ph[0] - (ph[1] + ph[2]) / 2) / ph[0]
        return 100 * ph[0] / std
    v, v6 = read(hi), read(lo)
    rounded = float("%.12g" % v)
    return rounded, round_up_2(abs(v - v6) + abs(rounded - v) + 1e-13 * abs(v))


def gen_glossmeter() -> Dict[str, Any]:
    cases: List[Dict[str, Any]] = []

    def add(function: str, inp: Dict[str, Any], value: Optional[float], error: float, tags: Sequence[str],
            status: str = OK) -> None:
        c: Dict[str, Any] = {"id": f"gm{len(cases):04d}", "function": function, "tags": list(tags),
                             "input": inp, "status": status}
        c["expected"] = {} if value is None else {"value": value}
        c["error"] = Short(error)
        cases.append(c)

    # Fresnel reflectance of a dielectric (unpolarised)
    for n, c, tags in [("1.567", "1", ["normal"]), ("1.567", "0.9396926207859084", ["20deg"]),
                       ("1.567", "0.5", ["60deg"]), ("1.567", "0.08715574274765817", ["85deg"]),
                       ("1.5", "0", ["grazing"]), ("2.4", "0.3", []), ("1.000001", "0.7", ["near_one"])]:
        add("fresnel_dielectric", {"n": float(n), "c": float(c)}, D(gm_fresnel(mpf(float(n)), mpf(float(c)))), 0.0, tags)
    for n, c, st in [(1.0, 0.5, E_ARGUMENT), (0.8, 0.5, E_ARGUMENT), (1.5, 1.5, E_ARGUMENT),
                     (1.5, -0.1, E_ARGUMENT), (math.nan, 0.5, E_NONFINITE), (1.5, math.inf, E_NONFINITE)]:
        add("fresnel_dielectric", {"n": enc(n), "c": enc(c)}, None, 0.0, ["error"], st)

    # the primary standard's flux, and Fresnel mirrors of other indices (ratio × 100)
    for kind in ("PGLOSS_GLOSS_20", "PGLOSS_GLOSS_60", "PGLOSS_GLOSS_85", "PGLOSS_DOI_30"):
        theta, src, rec, off = GM_GEOMETRY[kind]
        std = gm_mirror_flux(theta, src, rec, GM_STANDARD_INDEX)
        add("glossmeter_standard_flux", {"kind": kind}, D(std), 0.0, ["standard"])
        for n in ("1.567", "1.5", "1.6", "2.0"):
            rs = gm_mirror_flux(theta, src, rec, mpf(n))
            if kind == "PGLOSS_DOI_30":   # a mirror's image misses the ±0.3° windows: DOI 100
                r03 = sum(gm_mirror_flux(theta, src, w, mpf(n)) for w in off) / 2
                v = 100 * (rs - r03) / rs
            else:
                v = 100 * rs / std
            add("glossmeter_read_fresnel", {"kind": kind, "n": float(n)}, D(v), 0.0,
                ["standard"] if n == "1.567" else ["fresnel"])
    # a perfect diffuser, in closed form
    for kind in GM_GEOMETRY:
        for rho in ("1", "0.5"):
            add("glossmeter_read_lambert", {"kind": kind, "rho": float(rho)}, D(gm_lambert_reading(kind, mpf(rho))),
                0.0, ["lambert", "closed_form"])
    # Ward paints: every normalisation, anisotropic lobes and a rotated sample, coloured ρd
    def paint(rd: Sequence[float], rs: float, ax: float, ay: float, norm: int) -> Dict[str, Any]:
        return {"rho_d": list(rd), "rho_s": rs, "alpha_x": ax, "alpha_y": ay, "normalization": norm}
    for kind, p, az, tags in [
            ("PGLOSS_GLOSS_20", paint([0.193] * 3, 0.066, 0.07, 0.07, NORM_WARD), 0.0, ["paper"]),
            ("PGLOSS_GLOSS_60", paint([0.03] * 3, 0.099, 0.04, 0.04, NORM_WARD_DUR), 0.0, ["ward_dur"]),
            ("PGLOSS_GLOSS_85", paint([0.767] * 3, 0.033, 0.10, 0.10, NORM_BOUNDED), 0.0, ["bounded"]),
            ("PGLOSS_GLOSS_60", paint([0.1] * 3, 0.05, 0.03, 0.08, NORM_WARD), 30.0, ["anisotropic", "azimuth"]),
            ("PGLOSS_GLOSS_20", paint([0.6, 0.3, 0.1], 0.05, 0.02, 0.02, NORM_WARD), 0.0, ["coloured"]),
            ("PGLOSS_HAZE_20", paint([0.2] * 3, 0.05, 0.015, 0.015, NORM_WARD), 0.0, ["haze"]),
            ("PGLOSS_DOI_30", paint([0.2] * 3, 0.05, 0.008, 0.008, NORM_WARD), 0.0, ["doi"])]:
        v, e = gm_ward_reading(kind, p, az)
        add("glossmeter_read_physical", {"kind": kind, "physical": p, "azimuth_deg": az}, v, e, ["ward"] + tags)
    notes = ("Readings of pgloss/glossmeter.h's virtual glossmeter. Each case's 'error' bounds the error of "
             "'expected.value'; the runner asserts |got - value| <= got_error + error + 1e-12 |value|, where "
             "got_error is the implementation's own error estimate, and that got_error stays below the tolerance "
             "it was asked for.")
    return {**header(["fresnel_dielectric", "glossmeter_standard_flux", "glossmeter_read_fresnel",
                      "glossmeter_read_lambert", "glossmeter_read_physical"], "double", {}, notes),
            "cases": cases}

# ----------------------------------------------------------------------------------
# Main.
# ----------------------------------------------------------------------------------

# ----------------------------------------------------------------------------------
# The gloss bridge's conventions (libpgloss/include/pgloss/bridge.h, docs/bridge.md): a target's
# parameters <-> (base luminance, F0, microfacet alpha), transcribed from the header's rules.
# ----------------------------------------------------------------------------------

def gen_bridge() -> Dict[str, Any]:
    ggx = {"openpbr", "standard_surface", "gltf", "gltf_core", "principled"}
    air = mpf("1.000277")  # Mitsuba's ext_ior default, "air"

    def f0_ior(ior: Any) -> Any:
        return ((ior - 1) / (ior + 1)) ** 2

    def ior_f0(f0: Any) -> Any:
        return (1 + mp.sqrt(f0)) / (1 - mp.sqrt(f0))

    def f0_of(t: str, ior: Any, spec: Any) -> Any:
        if t in ("roughplastic_ggx", "roughplastic_beckmann"):
            return f0_ior(ior / air)
        k = 2 * spec if t == "principled" else spec
        return min(k * f0_ior(ior), mpf("0.99999") if t == "openpbr" else mpf(1))

    def canonical(t: str, f0: Any, alpha: Any) -> Dict[str, float]:
        rough = mp.sqrt(alpha) if t in ggx else alpha
        if t == "openpbr":
            ior, spec = mpf("1.5"), f0 / mpf("0.04")
        elif t == "gltf":
            ior, spec = (mpf("1.5"), f0 / mpf("0.04")) if f0 <= mpf("0.04") else (ior_f0(f0), mpf(1))
        elif t == "gltf_core":
            ior, spec = mpf("1.5"), mpf(1)
        elif t == "principled":
            ior, spec = ior_f0(f0), mpf("0.5")
        elif t in ("roughplastic_ggx", "roughplastic_beckmann"):
            ior, spec = ior_f0(f0) * air, mpf(1)
        else:
            ior, spec = ior_f0(f0), mpf(1)
        return {"roughness": D(rough), "ior": D(ior), "specular": D(spec)}

    rows = [
        ("openpbr", [0.8, 0.2, 0.1], 0.3, 1.5, 1.0), ("openpbr", [0.5, 0.5, 0.5], 0.1, 1.5, 2.5),
        ("standard_surface", [0.2, 0.3, 0.4], 0.25, 1.6, 1.0), ("standard_surface", [0.9, 0.9, 0.9], 0.5, 2.0, 1.0),
        ("gltf", [0.1, 0.6, 0.2], 0.3, 1.5, 0.5), ("gltf", [0.03, 0.03, 0.03], 0.2, 1.9, 1.0),
        ("gltf_core", [0.7, 0.7, 0.2], 0.4, 1.5, 1.0), ("gltf_core", [0.193, 0.193, 0.193], 0.15, 1.5, 1.0),
        ("principled", [0.6, 0.1, 0.1], 0.2, 1.45, 0.5), ("principled", [0.3, 0.3, 0.3], 0.35, 1.5, 0.8),
        ("roughplastic_ggx", [0.193, 0.193, 0.193], 0.07, 1.5, 1.0), ("roughplastic_ggx", [0.5, 0.4, 0.3], 0.2, 1.8, 1.0),
        ("roughplastic_beckmann", [0.767, 0.767, 0.767], 0.04, 1.5, 1.0),
        ("roughplastic_beckmann", [0.05, 0.1, 0.2], 0.15, 2.2, 1.0),
    ]
    cases = []
    for t, base, rough, ior, spec in rows:
        b = [mpf(x) for x in base]
        beta = sum(LUMA[j] * b[j] for j in range(3))
        f0 = f0_of(t, mpf(ior), mpf(spec))
        alpha = mpf(rough) ** 2 if t in ggx else mpf(rough)
        cases.append({"id": f"bridge_{len(cases):02d}_{t}", "target": t,
                      "params": {"base_color": base, "roughness": rough, "ior": ior, "specular": spec},
                      "beta": D(beta), "f0": D(f0), "alpha": D(alpha),
                      "canonical": canonical(t, mpf(D(f0)), mpf(D(alpha)))})
    return {"format": FORMAT, "version": VERSION, "generator": GENERATOR,
            "notes": "pgloss_bridge_model_inputs: params -> beta (Rec. 709 Y of base_color), f0, alpha; "
                     "pgloss_bridge_params_from_model(base_color, f0, alpha) -> canonical (roughness, ior, specular)",
            "cases": cases}


def generate_all() -> Dict[str, str]:
    """File name -> content."""
    mats = brdf_materials()
    docs = {
        "lightness.json": gen_lightness(),
        "gloss.json": gen_gloss(),
        "color.json": gen_color(),
        "validity.json": gen_validity(),
        "perceptual_material.json": gen_perceptual_material(),
        "color_space.json": gen_color_space(),
        "material.json": gen_material(),
        "brdf_eval.json": gen_eval(mats),
        "brdf_sample.json": gen_sample(mats),
        "glossmeter.json": gen_glossmeter(),
        "bridge.json": gen_bridge(),
    }
    return {name: dump_file(doc) for name, doc in docs.items()}


def main(argv: Optional[Sequence[str]] = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=None, help="directory to write the JSON files into")
    ap.add_argument("--check", action="store_true",
                    help="regenerate into a temporary directory and fail if any file differs from --out "
                         "(default: the directory of this script)")
    ap.add_argument("--print-color-matrices", action="store_true",
                    help="print the RGB <-> XYZ(D65) table of libpgloss/src/color.c and exit")
    a = ap.parse_args(argv)
    if a.print_color_matrices:
        print(c_matrix_table())
        return 0
    here = os.path.dirname(os.path.abspath(__file__))
    target = a.out or here
    files = generate_all()
    if a.check:
        bad = 0
        with tempfile.TemporaryDirectory() as tmp:
            for name, text in files.items():
                with open(os.path.join(tmp, name), "w", encoding="utf-8", newline="\n") as fh:
                    fh.write(text)
                ref = os.path.join(target, name)
                if not os.path.exists(ref):
                    print(f"missing: {ref}", file=sys.stderr)
                    bad += 1
                elif not filecmp.cmp(ref, os.path.join(tmp, name), shallow=False):
                    print(f"differs: {ref}", file=sys.stderr)
                    bad += 1
        if bad:
            print(f"{bad} vector file(s) out of date; run: python3 {GENERATOR} --out tests/vectors", file=sys.stderr)
            return 1
        print(f"{len(files)} vector files up to date in {target}")
        return 0
    os.makedirs(target, exist_ok=True)
    for name, text in files.items():
        with open(os.path.join(target, name), "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
        ncase = text.count('{"id":')
        print(f"{name}: {ncase} cases, {len(text)} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
