# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The C core (libpgloss, double precision) through ctypes: the peer implementation that
decides the cases whose outcome depends on input precision finer than float.

A double-precision vector whose input is not a float (0.7999999999999999, 1e-300, 1e300)
reaches an OSL shader rounded to float32. Where that rounding moves the input across a
decision boundary of the header (d < 1, L <= 100, ρd + ρs <= 1, α > 0, overflow), the
vector's status cannot be met by any float implementation; for those cases the expected
status and values are those of the C core evaluated at the float-rounded inputs.
"""
from __future__ import annotations

import ctypes as C
import subprocess
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[2]
BUILD = REPO / "build-osl" / "core"
LIB = BUILD / "libpgloss" / "libpgloss.so"

D = C.c_double
PD = C.POINTER(C.c_double)


class Physical(C.Structure):
    _fields_ = [("rho_d", D * 3), ("rho_s", D), ("alpha_x", D), ("alpha_y", D), ("normalization", C.c_int)]


class Perceptual(C.Structure):
    _fields_ = [("L", D), ("a", D), ("b", D), ("c", D), ("d", D)]


class Material(C.Structure):
    _fields_ = [("rho_d", C.c_float * 3), ("rho_s", C.c_float), ("alpha_x", C.c_float), ("alpha_y", C.c_float),
                ("normalization", C.c_int), ("lobes", C.c_uint), ("inv_alpha_x", C.c_float),
                ("inv_alpha_y", C.c_float), ("spec_scale", C.c_float), ("pdf_scale", C.c_float),
                ("weight_diffuse", C.c_float), ("weight_specular", C.c_float),
                ("specular_probability", C.c_float), ("pdf_diffuse", C.c_float), ("pdf_specular", C.c_float)]


def build() -> C.CDLL:
    """Builds libpgloss as a shared library with the project's own CMake (incremental: quick
    when nothing changed), so that the batched loops get their per-ISA compile flags."""
    subprocess.run(["cmake", "-S", str(REPO), "-B", str(BUILD), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                    "-DBUILD_SHARED_LIBS=ON", "-DPGLOSS_BUILD_CLI=OFF", "-DPGLOSS_BUILD_TESTS=OFF"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", str(BUILD), "--target", "pgloss"], check=True, stdout=subprocess.DEVNULL)
    return C.CDLL(str(LIB))


_lib: C.CDLL | None = None


def lib() -> C.CDLL:
    global _lib
    if _lib is None:
        _lib = build()
        _lib.pgloss_status_name.restype = C.c_char_p
    return _lib


def _phys(f: list, norm: int) -> Physical:
    return Physical((D * 3)(*f[:3]), f[3], f[4], f[5], norm)


def evaluate(name: str, f: list, i: list) -> tuple[str, dict[str, Any]]:
    """Runs the C function `name` on float inputs f / int inputs i (as the OSL driver lays them out).
    Returns (status name, outputs by the vectors' output names)."""
    L = lib()
    out: dict[str, Any] = {}
    o = [D() for _ in range(8)]
    r = C.byref
    if name in ("lightness_from_luminance", "luminance_from_lightness", "envelope_contrast"):
        st = getattr(L, f"pgloss_{name}")(D(f[0]), r(o[0]))
        out[{"lightness_from_luminance": "L", "luminance_from_lightness": "Y", "envelope_contrast": "c_max"}[name]] = o[0].value
    elif name in ("contrast_gloss", "specular_from_contrast"):
        st = getattr(L, f"pgloss_{name}")(D(f[0]), D(f[1]), r(o[0]))
        out["c" if name == "contrast_gloss" else "rho_s"] = o[0].value
    elif name in ("gloss_from_physical", "physical_from_gloss"):
        st = getattr(L, f"pgloss_{name}")(D(f[0]), D(f[1]), D(f[2]), r(o[0]), r(o[1]), r(o[2]))
        keys = ("L", "c", "d") if name == "gloss_from_physical" else ("rho_d", "rho_s", "alpha")
        out.update({k: o[n].value for n, k in enumerate(keys)})
    elif name == "gloss_distance":
        st = L.pgloss_gloss_distance(D(f[0]), D(f[1]), D(f[2]), D(f[3]), r(o[0]))
        out["D"] = o[0].value
    elif name == "match_gloss":
        st = L.pgloss_match_gloss(D(f[0]), D(f[1]), D(f[2]), r(o[0]), r(o[1]))
        out.update(rho_d_out=o[0].value, rho_s_out=o[1].value)
    elif name == "isogloss_contour":
        n = i[0]
        c, d = (D * max(n, 1))(), (D * max(n, 1))()
        L.pgloss_isogloss_contour.argtypes = [D, D, D, C.c_size_t, PD, PD]
        st = L.pgloss_isogloss_contour(f[0], f[1], f[2], n, c, d)
        out.update(c=list(c)[:n], d=list(d)[:n])
    elif name in ("rgb_from_lab", "lab_from_rgb"):
        a, b = (D * 3)(*f[:3]), (D * 3)()
        st = getattr(L, f"pgloss_{name}")(a, b)
        out["rgb" if name == "rgb_from_lab" else "lab"] = list(b)
    elif name == "luminance":
        st = L.pgloss_luminance((D * 3)(*f[:3]), r(o[0]))
        out["Y"] = o[0].value
    elif name == "check_physical":
        st = L.pgloss_check_physical(r(_phys(f, i[0])))
    elif name == "check_perceptual":
        st = L.pgloss_check_perceptual(r(Perceptual(*f[:5])))
    elif name == "physical_from_perceptual":
        p = Physical()
        st = L.pgloss_physical_from_perceptual(r(Perceptual(*f[:5])), C.c_int(i[0]), r(p))
        out.update(rho_d=list(p.rho_d), rho_s=p.rho_s, alpha_x=p.alpha_x, alpha_y=p.alpha_y,
                   normalization=p.normalization)
    elif name == "perceptual_from_physical":
        q = Perceptual()
        st = L.pgloss_perceptual_from_physical(r(_phys(f, i[0])), r(q))
        out.update(L=q.L, a=q.a, b=q.b, c=q.c, d=q.d)
    elif name == "material_init":
        m = Material()
        st = L.pgloss_material_init(r(m), r(_phys(f, i[0])))
        out.update(lobes=m.lobes, rho_d=list(m.rho_d), rho_s=m.rho_s, alpha_x=m.alpha_x, alpha_y=m.alpha_y,
                   inv_alpha_x=m.inv_alpha_x, inv_alpha_y=m.inv_alpha_y, spec_scale=m.spec_scale,
                   pdf_scale=m.pdf_scale, weight_diffuse=m.weight_diffuse, weight_specular=m.weight_specular)
    else:
        raise KeyError(name)
    return L.pgloss_status_name(st).decode(), out
