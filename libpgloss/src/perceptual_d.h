// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The per-element formulas of the perceptual and colour functions in double, written once:
 * the scalar functions (lightness.c, gloss.c, color.c, validity.c) and the batched loops
 * (perceptual_batch_isa.c) both call these, so that element j of a batch is bit for bit what
 * the scalar function returns. Branch-free: the checks become a status computed as a double
 * (a select per check, the first check in the scalar order winning), which the vectoriser
 * turns into blends; outputs of a failed element are selected to the documented values.
 * Not installed. */
#ifndef PGLOSS_PERCEPTUAL_D_H
#define PGLOSS_PERCEPTUAL_D_H

#include "cbrt_d.h"
#include "pgloss/color.h"
#include "pgloss/perceptual.h"
#include "pgloss/status.h"

#define PGLOSS__P_FN PGLOSS__CBRT_FN

/* x is neither NaN nor ±Inf (one comparison: what vectorises). */
PGLOSS__P_FN int pgloss__finite_d(double x)
{
    return fabs(x) <= DBL_MAX;
}

/* ∛x by the general cube root or, where `in_range` (a compile-time constant) says the caller
 * checked pgloss__cbrt_in_range_d, by its unscaled core: the same bits either way. */
PGLOSS__P_FN double pgloss__cbrt_sel_d(double x, const int in_range)
{
    return in_range ? pgloss__cbrt_in_range_only_d(x) : pgloss__cbrt_d(x);
}

/* B = ∛(ρd/2), the cube root of eqs. 4 and 7. */
PGLOSS__P_FN double pgloss__half_cbrt_d(double rho_d, const int in_range)
{
    return pgloss__cbrt_sel_d(0.5 * rho_d, in_range);
}

/* CIE 1976 L* of Y ≥ 0 (§4, inverse of eq. 6), the exact rational ε, κ, from b = ∛(Y/2):
 * ∛Y = 2^(1/3) b, so that gloss_from_physical takes L* and eq. 4 from one cube root (within
 * 1.5 ulp of ∛Y instead of 0.5: docs/kernels.md). */
PGLOSS__P_FN double pgloss__lightness_b_d(double Y, double b)
{
    const double cbrt2 = 1.2599210498948731648; /* 2^(1/3) */
    return Y <= PGLOSS_CIE_EPSILON ? PGLOSS_CIE_KAPPA * Y : 116.0 * (cbrt2 * b) - 16.0;
}

PGLOSS__P_FN double pgloss__lightness_d(double Y)
{
    return pgloss__lightness_b_d(Y, pgloss__half_cbrt_d(Y, 0));
}

/* Eq. 6, Y = f⁻¹(L*) for L* ≥ 0 (+Inf for L* beyond ~6.6e104: the caller checks). */
PGLOSS__P_FN double pgloss__luminance_d(double L)
{
    const double t = (L + 16.0) / 116.0;
    return L <= PGLOSS_CIE_KAPPA * PGLOSS_CIE_EPSILON ? L / PGLOSS_CIE_KAPPA : t * t * t;
}

/* Eq. 4's denominator A² + AB + B², A = ∛(ρs + ρd/2), b = B = ∛(ρd/2): c = ρs / den. A − B
 * with A³ − B³ = ρs cancels for ρs ≪ ρd, the quotient form does not. */
PGLOSS__P_FN double pgloss__contrast_den_d(double rho_d, double rho_s, double b,
                                           const int in_range)
{
    const double a = pgloss__cbrt_sel_d(rho_s + 0.5 * rho_d, in_range);
    return a * a + a * b + b * b;
}

/* Eq. 4 from its denominator (den = 0 only for ρd = ρs = 0: c = 0). */
PGLOSS__P_FN double pgloss__contrast_d(double rho_s, double den)
{
    return den > 0.0 ? rho_s / den : 0.0;
}

/* Eq. 7 expanded, (c + B)³ − B³ = c (c² + 3cB + 3B²) with B = ∛(ρd/2): free of cancellation. */
PGLOSS__P_FN double pgloss__specular_d(double rho_d, double c)
{
    const double b = pgloss__half_cbrt_d(rho_d, 0);
    return c * (c * c + 3.0 * c * b + 3.0 * b * b);
}

/* Eq. 3, d = 1 − α, rounded down where it would round to 1 (α ≤ 2^-54): d < 1 then holds for
 * every α > 0, the domain of eq. 8, and the result is still within an ulp of 1 − α. */
PGLOSS__P_FN double pgloss__doi_d(double alpha)
{
    const double d = 1.0 - alpha;
    return d < 1.0 ? d : 1.0 - 0x1p-53;
}

/* The warning of a lobe spread: α > 0.2 (d < 0.8) is beyond the paper's trusted range. */
PGLOSS__P_FN double pgloss__alpha_status_d(double alpha)
{
    return alpha > PGLOSS_ALPHA_TRUSTED_MAX ? (double)PGLOSS_WARN_ALPHA_UNTRUSTED : 0.0;
}

/* Every check of pgloss_gloss_from_physical passes, and its cube roots need no scaling:
 * ρd, ρs in {0} ∪ [2^-899, 2^899] (so ρd/2 and ρs + ρd/2 pass pgloss__cbrt_in_range_d, and
 * eq. 4's denominator is finite), α finite and > 0. As a double, 1 or 0 (what vectorises). */
PGLOSS__P_FN double pgloss__gloss_plain_d(double rho_d, double rho_s, double alpha)
{
    const int in_d = (rho_d == 0.0) | ((rho_d >= 0x1p-899) & (rho_d <= 0x1p899));
    const int in_s = (rho_s == 0.0) | ((rho_s >= 0x1p-899) & (rho_s <= 0x1p899));
    return in_d & in_s & (alpha > 0.0) & (alpha <= DBL_MAX) ? 1.0 : 0.0;
}

/* pgloss_gloss_from_physical on one element (eqs. 3, 4 and L* of ρd): NONFINITE, NEGATIVE,
 * ALPHA, NONFINITE (ρs + ρd/2 beyond DBL_MAX), then the warning; outputs 0 on error. With
 * `plain` (a compile-time constant) for an element pgloss__gloss_plain_d accepts: no checks
 * to make, the same bits. */
PGLOSS__P_FN double pgloss__gloss_from_physical_k(double rho_d, double rho_s, double alpha,
                                                  double *L, double *c, double *d,
                                                  const int plain)
{
    /* every value first, then the selects: no work under a condition (what vectorises) */
    const double b = pgloss__half_cbrt_d(rho_d, plain);
    const double den = pgloss__contrast_den_d(rho_d, rho_s, b, plain);
    const double l = pgloss__lightness_b_d(rho_d, b), cc = pgloss__contrast_d(rho_s, den);
    const double dd = pgloss__doi_d(alpha); /* eq. 3 */
    double st = pgloss__alpha_status_d(alpha);
    if (!plain) {
        st = pgloss__finite_d(den) ? st : (double)PGLOSS_ERR_NONFINITE;
        st = alpha > 0.0 ? st : (double)PGLOSS_ERR_ALPHA;
        st = rho_s < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
        st = rho_d < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
        st = pgloss__finite_d(alpha) ? st : (double)PGLOSS_ERR_NONFINITE;
        st = pgloss__finite_d(rho_s) ? st : (double)PGLOSS_ERR_NONFINITE;
        st = pgloss__finite_d(rho_d) ? st : (double)PGLOSS_ERR_NONFINITE;
    }
    *L = st >= 0.0 ? l : 0.0;
    *c = st >= 0.0 ? cc : 0.0;
    *d = st >= 0.0 ? dd : 0.0;
    return st;
}

/* The D65 white (0.3127, 0.3290) as XYZ with Y = 1. */
#define PGLOSS__WHITE_X (0.3127 / 0.3290)
#define PGLOSS__WHITE_Z (0.3583 / 0.3290)
#define PGLOSS__LAB_DELTA (6.0 / 29.0)

/* CIELAB's companding function and its inverse (CIE 15:2004), in the exact rational form. */
PGLOSS__P_FN double pgloss__lab_f_d(double t)
{
    return t > PGLOSS_CIE_EPSILON ? pgloss__cbrt_d(t) : (PGLOSS_CIE_KAPPA * t + 16.0) / 116.0;
}

PGLOSS__P_FN double pgloss__lab_finv_d(double t)
{
    const double delta = PGLOSS__LAB_DELTA;
    return t > delta ? t * t * t : 3.0 * delta * delta * (t - 4.0 / 29.0);
}

/* Linear RGB (matrix M: XYZ → RGB of the working space, row-major) of a CIELAB colour (D65):
 * NONFINITE (input or result), LIGHTNESS, GAMUT (a channel below −PGLOSS_BOUNDARY_TOLERANCE:
 * the exact values are written); otherwise the channels, those within the tolerance below 0
 * (rounding on the gamut boundary) returned as 0; 0 on NONFINITE and LIGHTNESS. */
PGLOSS__P_FN double pgloss__rgb_from_lab_k(double L, double a, double b, const double *M,
                                           double *r, double *g, double *bl)
{
    const double fy = (L + 16.0) / 116.0;
    const double X = PGLOSS__WHITE_X * pgloss__lab_finv_d(fy + a / 500.0);
    const double Y = pgloss__luminance_d(L); /* exact on both branches */
    const double Z = PGLOSS__WHITE_Z * pgloss__lab_finv_d(fy - b / 200.0);
    const double o0 = M[0] * X + M[1] * Y + M[2] * Z;
    const double o1 = M[3] * X + M[4] * Y + M[5] * Z;
    const double o2 = M[6] * X + M[7] * Y + M[8] * Z;
    const double tol = -PGLOSS_BOUNDARY_TOLERANCE;
    double st = (o0 < tol || o1 < tol || o2 < tol) ? (double)PGLOSS_ERR_GAMUT : 0.0;
    st = (pgloss__finite_d(o0) && pgloss__finite_d(o1) && pgloss__finite_d(o2))
             ? st : (double)PGLOSS_ERR_NONFINITE;
    st = (L < 0.0 || L > 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : st;
    st = (pgloss__finite_d(L) && pgloss__finite_d(a) && pgloss__finite_d(b))
             ? st : (double)PGLOSS_ERR_NONFINITE;
    /* GAMUT keeps the exact channels; OK rounds the boundary's −tolerance..0 up to 0. */
    const double gamut = (double)PGLOSS_ERR_GAMUT;
    *r = st == 0.0 ? (o0 < 0.0 ? 0.0 : o0) : (st == gamut ? o0 : 0.0);
    *g = st == 0.0 ? (o1 < 0.0 ? 0.0 : o1) : (st == gamut ? o1 : 0.0);
    *bl = st == 0.0 ? (o2 < 0.0 ? 0.0 : o2) : (st == gamut ? o2 : 0.0);
    return st;
}

/* pgloss_physical_from_perceptual_ex on one element, the normalisation known to be valid:
 * NONFINITE (a*, b*), then pgloss_physical_from_gloss's checks (NONFINITE, LIGHTNESS,
 * NEGATIVE, ALPHA, NONFINITE ρs), then the colour's (NONFINITE, GAMUT), then the warning.
 * *pre receives the status of the checks made before the normalisation's (the scalar
 * function's order), 0 if they pass. Outputs 0 on error, but for GAMUT: the exact ρd and
 * ρs, α. */
PGLOSS__P_FN double pgloss__physical_from_perceptual_k(double L, double a, double b, double c,
                                                       double d, const double *M, double *rho_r,
                                                       double *rho_g, double *rho_b,
                                                       double *rho_s, double *alpha,
                                                       double *pre)
{
    const double y = pgloss__luminance_d(L);    /* eq. 6 */
    const double s = pgloss__specular_d(y, c);  /* eq. 7 */
    const double al = 1.0 - d;                  /* eq. 8 */
    double sg = pgloss__finite_d(s) ? 0.0 : (double)PGLOSS_ERR_NONFINITE;
    sg = d < 1.0 ? sg : (double)PGLOSS_ERR_ALPHA;
    sg = c < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : sg;
    sg = (L < 0.0 || L > 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : sg;
    sg = (pgloss__finite_d(L) && pgloss__finite_d(c) && pgloss__finite_d(d))
             ? sg : (double)PGLOSS_ERR_NONFINITE;
    sg = (pgloss__finite_d(a) && pgloss__finite_d(b)) ? sg : (double)PGLOSS_ERR_NONFINITE;
    *pre = sg;
    double r, g, bb;
    const double cs = pgloss__rgb_from_lab_k(L, a, b, M, &r, &g, &bb);
    /* a failed element: the checks before the colour's, or a non-finite colour */
    const double st = sg < 0.0 ? sg : (cs != 0.0 ? cs : pgloss__alpha_status_d(al));
    /* kept: an element that passed, and a GAMUT one (its exact ρd, ρs, α) */
    const double gamut = (double)PGLOSS_ERR_GAMUT;
    *rho_r = st >= 0.0 ? r : (st == gamut ? r : 0.0);
    *rho_g = st >= 0.0 ? g : (st == gamut ? g : 0.0);
    *rho_b = st >= 0.0 ? bb : (st == gamut ? bb : 0.0);
    *rho_s = st >= 0.0 ? s : (st == gamut ? s : 0.0);
    *alpha = st >= 0.0 ? al : (st == gamut ? al : 0.0);
    return st;
}

/* The XYZ → linear RGB matrix of a known working space, row-major (color.c's table). */
const double *pgloss__from_xyz_matrix(pgloss_color_space space);

#endif
