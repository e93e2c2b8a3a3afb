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

/* Several conditions on one element as ONE comparison each: GCC 12 turns a && or || chain of
 * double comparisons into branches whose merge it cannot if-convert (a PHI of more than four
 * arguments), and the loop is then not vectorised. The NaN cases of these helpers do not
 * matter: their callers let a finiteness check (made later, winning) decide those elements. */

/* The larger and the smaller of two values neither of which is NaN (selects; fmax is a call
 * or a NaN-aware sequence). */
PGLOSS__P_FN double pgloss__max_d(double x, double y)
{
    return x > y ? x : y;
}

PGLOSS__P_FN double pgloss__min_d(double x, double y)
{
    return x < y ? x : y;
}

/* 0 for a finite x, NaN for NaN and ±Inf: a sum of these is 0 only if every term's x is
 * finite (x − x is never folded without -ffinite-math-only). */
PGLOSS__P_FN double pgloss__nan_unless_finite_d(double x)
{
    return x - x;
}

/* x, y and z are all finite. */
PGLOSS__P_FN int pgloss__finite3_d(double x, double y, double z)
{
    return pgloss__nan_unless_finite_d(x) + pgloss__nan_unless_finite_d(y) +
               pgloss__nan_unless_finite_d(z) == 0.0;
}

/* x < lo or x > hi, for x not NaN: lo − x > 0 and x − hi > 0 are exact tests, a difference of
 * doubles being 0 only for equal ones. */
PGLOSS__P_FN int pgloss__outside_d(double x, double lo, double hi)
{
    return pgloss__max_d(lo - x, x - hi) > 0.0;
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
PGLOSS__P_FN double pgloss__specular_b_d(double c, double b)
{
    return c * (c * c + 3.0 * c * b + 3.0 * b * b);
}

PGLOSS__P_FN double pgloss__specular_d(double rho_d, double c)
{
    return pgloss__specular_b_d(c, pgloss__half_cbrt_d(rho_d, 0));
}

/* The envelope of Fig. 10: eq. 4 with ρs = 1 − ρd, for ρd = Y in [0, 1] and b = ∛(Y/2)
 * (A² + AB + B² in quotient form again: A − B cancels near Y = 1). */
PGLOSS__P_FN double pgloss__envelope_b_d(double y, double b)
{
    return pgloss__contrast_d(1.0 - y, pgloss__contrast_den_d(y, 1.0 - y, b, 0));
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
    return (in_d & in_s & (alpha > 0.0) & (alpha <= DBL_MAX)) ? 1.0 : 0.0;
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

/* pgloss_physical_from_gloss on one element (eqs. 6, 7, 8): NONFINITE, LIGHTNESS, NEGATIVE,
 * ALPHA, NONFINITE (ρs beyond DBL_MAX), then the warning; outputs 0 on error. */
PGLOSS__P_FN double pgloss__physical_from_gloss_k(double L, double c, double d, double *rho_d,
                                                  double *rho_s, double *alpha)
{
    const double y = pgloss__luminance_d(L);   /* eq. 6 */
    const double s = pgloss__specular_d(y, c); /* eq. 7 */
    const double al = 1.0 - d;                 /* eq. 8 */
    double st = pgloss__alpha_status_d(al);
    st = pgloss__finite_d(s) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = d < 1.0 ? st : (double)PGLOSS_ERR_ALPHA;
    st = c < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
    st = (L < 0.0 || L > 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : st;
    st = (pgloss__finite_d(L) && pgloss__finite_d(c) && pgloss__finite_d(d))
             ? st : (double)PGLOSS_ERR_NONFINITE;
    *rho_d = st >= 0.0 ? y : 0.0;
    *rho_s = st >= 0.0 ? s : 0.0;
    *alpha = st >= 0.0 ? al : 0.0;
    return st;
}

/* pgloss_envelope_contrast on one element: NONFINITE, LIGHTNESS; 0 on error. (Its eq. 4's
 * own checks cannot fail for L* in [0, 100]: Y = f⁻¹(L*) is in [0, 1].) */
PGLOSS__P_FN double pgloss__envelope_k(double L, double *c_max)
{
    const double y = pgloss__luminance_d(L);
    const double cm = pgloss__envelope_b_d(y, pgloss__half_cbrt_d(y, 0));
    double st = (L < 0.0 || L > 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : 0.0;
    st = pgloss__finite_d(L) ? st : (double)PGLOSS_ERR_NONFINITE;
    *c_max = st == 0.0 ? cm : 0.0;
    return st;
}

/* pgloss_match_gloss on one element (§5.2): NONFINITE, NEGATIVE, LIGHTNESS, NONFINITE (eq. 4's
 * ρs + ρd/2, then eq. 7's ρs beyond DBL_MAX), ENVELOPE; outputs 0 on error but ENVELOPE's
 * (the matched values are written). */
PGLOSS__P_FN double pgloss__match_gloss_k(double rho_d, double rho_s, double L_target,
                                          double *rho_d_out, double *rho_s_out)
{
    const double den = pgloss__contrast_den_d(rho_d, rho_s, pgloss__half_cbrt_d(rho_d, 0), 0);
    const double c = pgloss__contrast_d(rho_s, den); /* eq. 4 */
    const double y = pgloss__luminance_d(L_target);  /* eq. 6 */
    const double s = pgloss__specular_d(y, c);       /* eq. 7 */
    double st = y + s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE ? (double)PGLOSS_ERR_ENVELOPE : 0.0;
    st = pgloss__finite_d(s) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = pgloss__finite_d(den) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = pgloss__outside_d(L_target, 0.0, 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : st;
    st = pgloss__min_d(rho_d, rho_s) < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
    st = pgloss__finite3_d(rho_d, rho_s, L_target) ? st : (double)PGLOSS_ERR_NONFINITE;
    /* OK or ENVELOPE (small integers: the product is exact) */
    const int kept = st * (st - (double)PGLOSS_ERR_ENVELOPE) == 0.0;
    *rho_d_out = kept ? y : 0.0;
    *rho_s_out = kept ? s : 0.0;
    return st;
}

/* pgloss__check_physical_values on one element: NONFINITE (a value NaN, ±Inf or beyond
 * limit in magnitude), NEGATIVE (ρd, ρs), ALPHA (αx, αy not > 0); 0 if all pass. */
PGLOSS__P_FN double pgloss__physical_values_k(double r, double g, double b, double s,
                                              double ax, double ay, double limit)
{
    double st = pgloss__min_d(ax, ay) > 0.0 ? 0.0 : (double)PGLOSS_ERR_ALPHA;
    st = pgloss__min_d(pgloss__min_d(r, g), pgloss__min_d(b, s)) < 0.0
             ? (double)PGLOSS_ERR_NEGATIVE : st;
    /* the largest magnitude, made NaN by any NaN or ±Inf value */
    const double big = pgloss__max_d(pgloss__max_d(pgloss__max_d(fabs(r), fabs(g)),
                                                   pgloss__max_d(fabs(b), fabs(s))),
                                     pgloss__max_d(fabs(ax), fabs(ay)));
    const double nan = pgloss__nan_unless_finite_d(r) + pgloss__nan_unless_finite_d(g) +
                       pgloss__nan_unless_finite_d(b) + pgloss__nan_unless_finite_d(s) +
                       pgloss__nan_unless_finite_d(ax) + pgloss__nan_unless_finite_d(ay);
    st = big + nan <= limit ? st : (double)PGLOSS_ERR_NONFINITE;
    return st;
}

/* pgloss_check_physical on one element, `norm_ok` 1 for a known normalisation, else 0:
 * pgloss__physical_values_k (limit FLT_MAX), NORMALIZATION, ENERGY, then the warning. */
PGLOSS__P_FN double pgloss__check_physical_k(double r, double g, double b, double s, double ax,
                                             double ay, double norm_ok)
{
    const double dmax = pgloss__max_d(r, pgloss__max_d(g, b));
    double st = pgloss__max_d(ax, ay) > PGLOSS_ALPHA_TRUSTED_MAX
                    ? (double)PGLOSS_WARN_ALPHA_UNTRUSTED : 0.0;
    st = dmax + s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE ? (double)PGLOSS_ERR_ENERGY : st;
    st = norm_ok != 0.0 ? st : (double)PGLOSS_ERR_NORMALIZATION;
    const double basic = pgloss__physical_values_k(r, g, b, s, ax, ay, (double)FLT_MAX);
    return basic < 0.0 ? basic : st;
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
    double st = pgloss__min_d(o0, pgloss__min_d(o1, o2)) < tol ? (double)PGLOSS_ERR_GAMUT : 0.0;
    st = pgloss__finite3_d(o0, o1, o2) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = pgloss__outside_d(L, 0.0, 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : st;
    st = pgloss__finite3_d(L, a, b) ? st : (double)PGLOSS_ERR_NONFINITE;
    /* GAMUT keeps the exact channels; OK rounds the boundary's −tolerance..0 up to 0 (one
     * select after another: nested ones make a PHI GCC does not if-convert). */
    const int kept = st * (st - (double)PGLOSS_ERR_GAMUT) == 0.0; /* small integers: exact */
    const int ok = st == 0.0;
    const double c0 = o0 < 0.0 ? 0.0 : o0, c1 = o1 < 0.0 ? 0.0 : o1, c2 = o2 < 0.0 ? 0.0 : o2;
    const double v0 = ok ? c0 : o0, v1 = ok ? c1 : o1, v2 = ok ? c2 : o2;
    *r = kept ? v0 : 0.0;
    *g = kept ? v1 : 0.0;
    *bl = kept ? v2 : 0.0;
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
    double y, s, al; /* eqs. 6, 7, 8 */
    const double sgw = pgloss__physical_from_gloss_k(L, c, d, &y, &s, &al);
    double sg = sgw < 0.0 ? sgw : 0.0;
    sg = (pgloss__finite_d(a) && pgloss__finite_d(b)) ? sg : (double)PGLOSS_ERR_NONFINITE;
    *pre = sg;
    double r, g, bb;
    const double cs = pgloss__rgb_from_lab_k(L, a, b, M, &r, &g, &bb);
    /* a failed element: the checks before the colour's, or a non-finite colour; else the
     * warning of physical_from_gloss (sgw ≥ 0 there) */
    const double st = sg < 0.0 ? sg : (cs != 0.0 ? cs : sgw);
    /* kept: an element that passed, and a GAMUT one (its exact ρd, ρs, α) */
    const double gamut = (double)PGLOSS_ERR_GAMUT;
    *rho_r = st >= 0.0 ? r : (st == gamut ? r : 0.0);
    *rho_g = st >= 0.0 ? g : (st == gamut ? g : 0.0);
    *rho_b = st >= 0.0 ? bb : (st == gamut ? bb : 0.0);
    *rho_s = st >= 0.0 ? s : (st == gamut ? s : 0.0);
    *alpha = st >= 0.0 ? al : (st == gamut ? al : 0.0);
    return st;
}

/* pgloss_lab_from_rgb_ex on one element (Mx: the working space's RGB → XYZ, row-major):
 * NONFINITE, NEGATIVE, NONFINITE (a result beyond DBL_MAX); outputs 0 on error. *Y receives
 * the luminance (XYZ's Y), computed on every path. */
PGLOSS__P_FN double pgloss__lab_from_rgb_k(double r, double g, double b, const double *Mx,
                                           double *L, double *a, double *bb, double *Y)
{
    const double X = Mx[0] * r + Mx[1] * g + Mx[2] * b;
    const double y = Mx[3] * r + Mx[4] * g + Mx[5] * b;
    const double Z = Mx[6] * r + Mx[7] * g + Mx[8] * b;
    const double fx = pgloss__lab_f_d(X / PGLOSS__WHITE_X), fy = pgloss__lab_f_d(y),
                 fz = pgloss__lab_f_d(Z / PGLOSS__WHITE_Z);
    const double o0 = 116.0 * fy - 16.0, o1 = 500.0 * (fx - fy), o2 = 200.0 * (fy - fz);
    double st = pgloss__finite3_d(o0, o1, o2) ? 0.0 : (double)PGLOSS_ERR_NONFINITE;
    st = pgloss__min_d(r, pgloss__min_d(g, b)) < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
    st = pgloss__finite3_d(r, g, b) ? st : (double)PGLOSS_ERR_NONFINITE;
    *L = st == 0.0 ? o0 : 0.0;
    *a = st == 0.0 ? o1 : 0.0;
    *bb = st == 0.0 ? o2 : 0.0;
    *Y = y;
    return st;
}

/* pgloss_perceptual_from_physical_ex on one element (Mx: RGB → XYZ): the values' checks
 * (limit DBL_MAX), lab_from_rgb's, NONFINITE (luminance, then eq. 4's ρs + ρd/2 beyond
 * DBL_MAX), then the warning (the wider spread beyond the trusted range); outputs 0 on error.
 * For αx ≠ αy the geometric mean stands in for α in eq. 3: the α with the same solid-angle
 * spread (the lobe's constant is 1/(αx αy)); the paper studied isotropic lobes. */
PGLOSS__P_FN double pgloss__perceptual_from_physical_k(double r, double g, double b, double s,
                                                       double ax, double ay, const double *Mx,
                                                       double *L, double *a, double *bb,
                                                       double *c, double *d)
{
    double l, la, lb, y;
    const double cs = pgloss__lab_from_rgb_k(r, g, b, Mx, &l, &la, &lb, &y);
    const double den = pgloss__contrast_den_d(y, s, pgloss__half_cbrt_d(y, 0), 0);
    const double cc = pgloss__contrast_d(s, den); /* eq. 4 */
    const double dd = pgloss__doi_d(sqrt(ax) * sqrt(ay)); /* eq. 3 */
    double st = pgloss__max_d(ax, ay) > PGLOSS_ALPHA_TRUSTED_MAX
                    ? (double)PGLOSS_WARN_ALPHA_UNTRUSTED : 0.0;
    st = pgloss__finite_d(den) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = y < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st; /* not for these spaces' Y ≥ 0 weights */
    st = pgloss__finite_d(y) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = cs < 0.0 ? cs : st;
    const double basic = pgloss__physical_values_k(r, g, b, s, ax, ay, DBL_MAX);
    st = basic < 0.0 ? basic : st;
    *L = st >= 0.0 ? l : 0.0;
    *a = st >= 0.0 ? la : 0.0;
    *bb = st >= 0.0 ? lb : 0.0;
    *c = st >= 0.0 ? cc : 0.0;
    *d = st >= 0.0 ? dd : 0.0;
    return st;
}

/* pgloss_check_perceptual_ex on one element (M: XYZ → RGB): NONFINITE (also α = 1 − d above
 * FLT_MAX, which no material holds), LIGHTNESS, NEGATIVE, ALPHA, rgb_from_lab's (NONFINITE,
 * GAMUT), ENVELOPE (c above Fig. 10's c_max), NONFINITE (ρs of eq. 7), ENERGY (max ρd + ρs),
 * then the warning. */
PGLOSS__P_FN double pgloss__check_perceptual_k(double L, double a, double b, double c, double d,
                                               const double *M)
{
    double r, g, bl;
    const double cs = pgloss__rgb_from_lab_k(L, a, b, M, &r, &g, &bl);
    const double y = pgloss__luminance_d(L);          /* eq. 6 */
    const double hb = pgloss__half_cbrt_d(y, 0);      /* ∛(Y/2), of eqs. 4 and 7 */
    const double cmax = pgloss__envelope_b_d(y, hb);  /* Fig. 10 */
    const double s = pgloss__specular_b_d(c, hb);     /* eq. 7 */
    const double al = 1.0 - d;                        /* eq. 8 */
    double st = pgloss__alpha_status_d(al);
    st = pgloss__max_d(r, pgloss__max_d(g, bl)) + s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE
             ? (double)PGLOSS_ERR_ENERGY : st;
    st = pgloss__finite_d(s) ? st : (double)PGLOSS_ERR_NONFINITE;
    st = c > cmax + PGLOSS_BOUNDARY_TOLERANCE ? (double)PGLOSS_ERR_ENVELOPE : st;
    st = cs != 0.0 ? cs : st;
    st = d < 1.0 ? st : (double)PGLOSS_ERR_ALPHA;
    st = c < 0.0 ? (double)PGLOSS_ERR_NEGATIVE : st;
    st = (L < 0.0 || L > 100.0) ? (double)PGLOSS_ERR_LIGHTNESS : st;
    st = (pgloss__finite_d(L) && pgloss__finite_d(a) && pgloss__finite_d(b) &&
          pgloss__finite_d(c) && pgloss__finite_d(d) && al <= FLT_MAX)
             ? st : (double)PGLOSS_ERR_NONFINITE;
    return st;
}

/* The XYZ → linear RGB matrix of a known working space, row-major (color.c's table). */
const double *pgloss__from_xyz_matrix(pgloss_color_space space);
/* The linear RGB → XYZ matrix of a known working space, row-major (row 1: its luminance). */
const double *pgloss__to_xyz_matrix(pgloss_color_space space);

#endif
