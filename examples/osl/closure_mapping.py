# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Measures how far Cycles' Beckmann microfacet closure, with pgloss_material.osl's mapping,
is from the paper's eq. 2 (isotropic Ward) — with the C core evaluating eq. 2.

Mapping (osl/pgloss_material.osl, for renderers without a ward() closure such as Cycles):
    ρs · Ward(α)  ->  ρs · microfacet("beckmann", N, α, 0, 0)
i.e. the same α (Beckmann's D(h) = exp(-tan²θh/α²)/(π α² cos⁴θh) has exactly Ward's exponent),
weight ρs, no Fresnel. Then
    f_ward = ρs D cos⁴θh / (4 sqrt(ci co)),    f_beckmann = ρs D G2 / (4 ci co),
with G2 the height-correlated Smith term; Λ is Cycles' rational approximation for Beckmann
(Walter et al. 2007), as in intern/cycles/kernel/closure/bsdf_microfacet.h.
Ward's 1/sqrt(ci co) against the microfacet 1/(ci co) makes the plain mapping 1/cos θo too
bright at the mirror direction; pgloss_material.osl therefore weights the closure by
ρs cos θo (θo: the angle of the viewing direction), which is exact at the mirror peak.

For each α of the paper's stimuli and each viewing angle θo it reports, over the hemisphere:
  albedo_ratio  ∫ f_beckmann cos / ∫ f_ward cos         (directional albedo, energy)
  peak_ratio    f_beckmann / f_ward at the mirror direction
  shape_L1      ∫ |f_b/A_b - f_w/A_w| cos dω            (0 = same lobe shape, 2 = disjoint)
Eq. 2 is evaluated by libpgloss (pgloss_eval_pdf_batch through ctypes, built by tests/osl/cref.py).
Run:  .venv-bpy/bin/python examples/osl/closure_mapping.py
"""
from __future__ import annotations

import ctypes as C
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "osl"))
import cref  # noqa: E402


class Strided3(C.Structure):
    """pgloss_strided3 / pgloss_strided3_out (pgloss/batch.h): a pointer per component, a byte stride."""
    _fields_ = [("ptr", C.c_void_p * 3), ("stride", C.c_ssize_t)]


class Strided(C.Structure):
    """pgloss_strided_out."""
    _fields_ = [("ptr", C.c_void_p), ("stride", C.c_ssize_t)]


def _rows(a: np.ndarray) -> Strided3:
    """An (n, 3) float32 array as it is (rows, no copy); a (3,) one for every element (stride 0)."""
    assert a.dtype == np.float32 and a.shape[-1] == 3
    base, item = a.ctypes.data, a.strides[-1]
    return Strided3((C.c_void_p * 3)(base, base + item, base + 2 * item), a.strides[0] if a.ndim == 2 else 0)


def ward_c(alpha: float, wo: np.ndarray, wi: np.ndarray) -> np.ndarray:
    """Specular lobe of eq. 2 with ρs = 1 (libpgloss, PGLOSS_NORM_WARD), float32 directions."""
    lib = cref.lib()
    m = cref.Material()
    p = cref.Physical((C.c_double * 3)(0, 0, 0), 1.0, alpha, alpha, 0)
    assert lib.pgloss_material_init(C.byref(m), C.byref(p)) == 0
    n = wi.shape[0]
    wo32 = np.asarray(wo, np.float32)  # one wo for every element
    wi32 = np.ascontiguousarray(wi, np.float32)
    f = np.zeros((n, 3), np.float32)
    fn = lib.pgloss_eval_pdf_batch
    fn.argtypes = [C.c_void_p, C.c_void_p, C.c_void_p, C.c_uint, C.c_size_t, Strided3, Strided3, Strided3, Strided,
                   C.c_void_p]
    st = fn(None, C.byref(m), None, 2, n, _rows(wo32), _rows(wi32), _rows(f), Strided(None, 0), None)
    assert st == 0
    return f[:, 0].astype(np.float64)


def beckmann_cycles(alpha: float, wo: np.ndarray, wi: np.ndarray) -> np.ndarray:
    """Cycles' microfacet("beckmann", N, α, 0, 0) reflection BRDF with weight 1 (no Fresnel)."""
    h = wo[None, :] + wi
    h /= np.linalg.norm(h, axis=1)[:, None]
    ch = h[:, 2]
    t2 = (1 - ch * ch) / (ch * ch)
    D = np.exp(-t2 / alpha**2) / (np.pi * alpha**2 * ch**4)

    def lam(cz: np.ndarray) -> np.ndarray:
        tan2 = np.maximum(1 - cz * cz, 0) / (cz * cz)
        with np.errstate(divide="ignore", invalid="ignore"):
            a = 1 / np.sqrt(alpha**2 * tan2)
            return np.where(a < 1.6, (1 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a), 0.0)

    G2 = 1 / (1 + lam(np.full_like(ch, wo[2])) + lam(wi[:, 2]))
    return D * G2 / (4 * wo[2] * wi[:, 2])


def measure(alpha: float, theta_o_deg: float, n_t: int = 600, n_p: int = 720) -> dict:
    """Quadrature over half vectors h (tanθh up to 8α), wi = reflect(wo, h), dωi = 4 (wo·h) dωh."""
    th_o = np.radians(theta_o_deg)
    wo = np.array([np.sin(th_o), 0.0, np.cos(th_o)])
    tmax = np.arctan(8 * alpha)
    t = (np.arange(n_t) + 0.5) * tmax / n_t
    p = (np.arange(n_p) + 0.5) * 2 * np.pi / n_p
    T, Pp = np.meshgrid(t, p, indexing="ij")
    h = np.stack([np.sin(T) * np.cos(Pp), np.sin(T) * np.sin(Pp), np.cos(T)], -1).reshape(-1, 3)
    dwh = (np.sin(T) * (tmax / n_t) * (2 * np.pi / n_p)).reshape(-1)
    oh = h @ wo
    wi = 2 * oh[:, None] * h - wo[None, :]
    ok = (wi[:, 2] > 0) & (oh > 0)
    wi, dwi, ci = wi[ok], (4 * oh * dwh)[ok], wi[ok, 2]
    fw = ward_c(alpha, wo, wi)
    fb = beckmann_cycles(alpha, wo, wi)
    Aw, Ab = np.sum(fw * ci * dwi), np.sum(fb * ci * dwi)
    wm = np.array([-wo[0], -wo[1], wo[2]])[None, :]
    peak = beckmann_cycles(alpha, wo, wm)[0] / ward_c(alpha, wo, wm)[0]
    shape = np.sum(np.abs(fb / Ab - fw / Aw) * ci * dwi)
    return dict(albedo_ward=Aw, albedo_beckmann=Ab, albedo_ratio=Ab / Aw, peak_ratio=peak, shape_L1=shape)


def main() -> None:
    print("Ward eq. 2 (libpgloss) vs Cycles microfacet('beckmann', N, alpha) with weight rho_s, same alpha")
    print("plain: weight rho_s; compensated: weight rho_s*cos(theta_o) (what pgloss_material.osl uses)")
    print(f"{'alpha':>6s} {'theta_o':>7s} {'A_ward/rho_s':>12s} {'A_beck/rho_s':>12s} {'albedo ratio':>12s}"
          f" {'peak ratio':>10s} {'comp. albedo':>12s} {'comp. peak':>10s} {'shape L1':>9s}")
    for alpha in (0.04, 0.07, 0.10, 0.2):
        for th in (0, 15, 30, 45, 60, 70, 80, 85):
            r = measure(alpha, th)
            print(f"{alpha:6.2f} {th:7.0f} {r['albedo_ward']:12.4f} {r['albedo_beckmann']:12.4f}"
                  f" {r['albedo_ratio']:12.4f} {r['peak_ratio']:10.4f}"
                  f" {r['albedo_ratio'] * np.cos(np.radians(th)):12.4f} {r['peak_ratio'] * np.cos(np.radians(th)):10.4f}"
                  f" {r['shape_L1']:9.4f}")


if __name__ == "__main__":
    main()
