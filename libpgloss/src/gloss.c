// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The gloss space of §3.3 and §4: eqs. 3–8, the distance of eq. 5, its envelope (Fig. 10),
 * isogloss contours (Fig. 11) and gloss matching across lightness (Fig. 12). */
#include "internal.h"
#include "pgloss/perceptual.h"

pgloss_status pgloss_contrast_gloss(double rho_d, double rho_s, double *c)
{
    if (!c)
        return PGLOSS_ERR_NULL;
    *c = 0.0;
    if (!isfinite(rho_d) || !isfinite(rho_s))
        return PGLOSS_ERR_NONFINITE;
    if (rho_d < 0.0 || rho_s < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    /* Eq. 4: A - B with A³ - B³ = ρs; the difference of cube roots cancels for ρs ≪ ρd,
     * the quotient form does not. */
    const double a = cbrt(rho_s + 0.5 * rho_d), b = cbrt(0.5 * rho_d);
    const double den = a * a + a * b + b * b;
    if (!isfinite(den))
        return PGLOSS_ERR_NONFINITE; /* beyond double range: no meaningful c */
    *c = den > 0.0 ? rho_s / den : 0.0;
    return PGLOSS_OK;
}

pgloss_status pgloss_specular_from_contrast(double rho_d, double c, double *rho_s)
{
    if (!rho_s)
        return PGLOSS_ERR_NULL;
    *rho_s = 0.0;
    if (!isfinite(rho_d) || !isfinite(c))
        return PGLOSS_ERR_NONFINITE;
    if (rho_d < 0.0 || c < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    /* Eq. 7 expanded: (c + B)³ - B³ = c (c² + 3cB + 3B²), free of cancellation. */
    const double b = cbrt(0.5 * rho_d);
    const double v = c * (c * c + 3.0 * c * b + 3.0 * b * b);
    if (!isfinite(v))
        return PGLOSS_ERR_NONFINITE;
    *rho_s = v;
    return PGLOSS_OK;
}

static pgloss_status alpha_status(double alpha)
{
    return alpha > PGLOSS_ALPHA_TRUSTED_MAX ? PGLOSS_WARN_ALPHA_UNTRUSTED : PGLOSS_OK;
}

pgloss_status pgloss_gloss_from_physical(double rho_d, double rho_s, double alpha,
                                         double *L, double *c, double *d)
{
    if (!L || !c || !d) {
        if (L) *L = 0.0;
        if (c) *c = 0.0;
        if (d) *d = 0.0;
        return PGLOSS_ERR_NULL;
    }
    *L = *c = *d = 0.0;
    if (!isfinite(rho_d) || !isfinite(rho_s) || !isfinite(alpha))
        return PGLOSS_ERR_NONFINITE;
    if (rho_d < 0.0 || rho_s < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (!(alpha > 0.0))
        return PGLOSS_ERR_ALPHA;
    double l, cc;
    pgloss_lightness_from_luminance(rho_d, &l);
    /* ρs + ρd/2 beyond DBL_MAX: NONFINITE (not a silent c = 0). */
    const pgloss_status cs = pgloss_contrast_gloss(rho_d, rho_s, &cc);
    if (cs != PGLOSS_OK)
        return cs;
    *L = l;
    *c = cc;
    *d = pgloss__doi_from_alpha(alpha); /* eq. 3 */
    return alpha_status(alpha);
}

pgloss_status pgloss_physical_from_gloss(double L, double c, double d,
                                         double *rho_d, double *rho_s, double *alpha)
{
    if (!rho_d || !rho_s || !alpha) {
        if (rho_d) *rho_d = 0.0;
        if (rho_s) *rho_s = 0.0;
        if (alpha) *alpha = 0.0;
        return PGLOSS_ERR_NULL;
    }
    *rho_d = *rho_s = *alpha = 0.0;
    if (!isfinite(L) || !isfinite(c) || !isfinite(d))
        return PGLOSS_ERR_NONFINITE;
    if (L < 0.0 || L > 100.0)
        return PGLOSS_ERR_LIGHTNESS;
    if (c < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (!(d < 1.0))
        return PGLOSS_ERR_ALPHA;
    double y, s;
    pgloss_luminance_from_lightness(L, &y);          /* eq. 6 */
    /* eq. 7; c ≳ 5e102 overflows ρs: NONFINITE, not a silent ρs = 0. */
    const pgloss_status ss = pgloss_specular_from_contrast(y, c, &s);
    if (ss != PGLOSS_OK)
        return ss;
    *rho_d = y;
    *rho_s = s;
    *alpha = 1.0 - d;                                /* eq. 8 */
    return alpha_status(*alpha);
}

pgloss_status pgloss_gloss_distance(double c1, double d1, double c2, double d2, double *D)
{
    if (!D)
        return PGLOSS_ERR_NULL;
    *D = 0.0;
    if (!isfinite(c1) || !isfinite(d1) || !isfinite(c2) || !isfinite(d2))
        return PGLOSS_ERR_NONFINITE;
    const double v = hypot(c1 - c2, PGLOSS_D_WEIGHT * (d1 - d2)); /* eq. 5 */
    if (!isfinite(v))
        return PGLOSS_ERR_NONFINITE;
    *D = v;
    return PGLOSS_OK;
}

pgloss_status pgloss_envelope_contrast(double L, double *c_max)
{
    if (!c_max)
        return PGLOSS_ERR_NULL;
    *c_max = 0.0;
    if (!isfinite(L))
        return PGLOSS_ERR_NONFINITE;
    if (L < 0.0 || L > 100.0)
        return PGLOSS_ERR_LIGHTNESS;
    double y;
    pgloss_luminance_from_lightness(L, &y);
    /* ρs = 1 - ρd in eq. 4: cbrt(1 - ρd/2) - cbrt(ρd/2), again in quotient form. */
    return pgloss_contrast_gloss(y, 1.0 - y, c_max);
}

pgloss_status pgloss_match_gloss(double rho_d, double rho_s, double L_target,
                                 double *rho_d_out, double *rho_s_out)
{
    if (!rho_d_out || !rho_s_out) {
        if (rho_d_out) *rho_d_out = 0.0;
        if (rho_s_out) *rho_s_out = 0.0;
        return PGLOSS_ERR_NULL;
    }
    *rho_d_out = *rho_s_out = 0.0;
    if (!isfinite(rho_d) || !isfinite(rho_s) || !isfinite(L_target))
        return PGLOSS_ERR_NONFINITE;
    if (rho_d < 0.0 || rho_s < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (L_target < 0.0 || L_target > 100.0)
        return PGLOSS_ERR_LIGHTNESS;
    double c, y, s;
    const pgloss_status cs = pgloss_contrast_gloss(rho_d, rho_s, &c);
    if (cs != PGLOSS_OK)
        return cs; /* ρs + ρd/2 beyond DBL_MAX */
    pgloss_luminance_from_lightness(L_target, &y);
    const pgloss_status st = pgloss_specular_from_contrast(y, c, &s);
    if (st != PGLOSS_OK)
        return st;
    *rho_d_out = y;
    *rho_s_out = s;
    return (y + s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE) ? PGLOSS_ERR_ENVELOPE : PGLOSS_OK;
}

pgloss_status pgloss_isogloss_contour(double c0, double d0, double D, size_t n,
                                      double *c, double *d)
{
    if (!c || !d)
        return PGLOSS_ERR_NULL;
    for (size_t k = 0; k < n; ++k)
        c[k] = d[k] = 0.0;
    if (!isfinite(c0) || !isfinite(d0) || !isfinite(D))
        return PGLOSS_ERR_NONFINITE;
    if (D < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (n == 0)
        return PGLOSS_ERR_ARGUMENT;
    /* Eq. 5 with D fixed is an ellipse: semi-axes D along c and D/1.78 along d. */
    for (size_t k = 0; k < n; ++k) {
        const double t = 2.0 * PGLOSS_PI * (double)k / (double)n;
        c[k] = c0 + D * cos(t);
        d[k] = d0 + (D / PGLOSS_D_WEIGHT) * sin(t);
    }
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(c[k]) || !isfinite(d[k])) {
            for (size_t j = 0; j < n; ++j)
                c[j] = d[j] = 0.0;
            return PGLOSS_ERR_NONFINITE;
        }
    return PGLOSS_OK;
}
