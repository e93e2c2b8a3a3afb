// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The gloss space of §3.3 and §4: eqs. 3–8, the distance of eq. 5, its envelope (Fig. 10),
 * isogloss contours (Fig. 11) and gloss matching across lightness (Fig. 12). */
#include "internal.h"
#include "perceptual_d.h"
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
    const double den = pgloss__contrast_den_d(rho_d, rho_s, pgloss__half_cbrt_d(rho_d, 0), 0); /* eq. 4 */
    if (!isfinite(den))
        return PGLOSS_ERR_NONFINITE; /* beyond double range: no meaningful c */
    *c = pgloss__contrast_d(rho_s, den);
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
    const double v = pgloss__specular_d(rho_d, c); /* eq. 7 */
    if (!isfinite(v))
        return PGLOSS_ERR_NONFINITE;
    *rho_s = v;
    return PGLOSS_OK;
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
    /* The batch's per-element code (perceptual_d.h): the same bits. */
    return (pgloss_status)pgloss__gloss_from_physical_k(rho_d, rho_s, alpha, L, c, d, 0);
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
    /* The batch's per-element code (perceptual_d.h): the same bits. c ≳ 5e102 overflows ρs
     * (eq. 7): NONFINITE, not a silent ρs = 0. */
    return (pgloss_status)pgloss__physical_from_gloss_k(L, c, d, rho_d, rho_s, alpha);
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
    /* the verdict on the two paints, physical_from_gloss's on c and d */
    const double c[2] = {c1, c2}, d[2] = {d1, d2};
    for (int k = 0; k < 2; ++k) {
        if (c[k] < 0.0)
            return PGLOSS_ERR_NEGATIVE;
        if (d[k] >= 1.0)
            return PGLOSS_ERR_ALPHA;
    }
    const double alpha_max = 1.0 - (d1 < d2 ? d1 : d2); /* eq. 8 */
    return alpha_max > PGLOSS_ALPHA_TRUSTED_MAX ? PGLOSS_WARN_ALPHA_UNTRUSTED : PGLOSS_OK;
}

pgloss_status pgloss_envelope_contrast(double L, double *c_max)
{
    if (!c_max)
        return PGLOSS_ERR_NULL;
    /* ρs = 1 - ρd in eq. 4 (perceptual_d.h, the batch's per-element code: the same bits) */
    return (pgloss_status)pgloss__envelope_k(L, c_max);
}

pgloss_status pgloss_match_gloss(double rho_d, double rho_s, double L_target,
                                 double *rho_d_out, double *rho_s_out)
{
    if (!rho_d_out || !rho_s_out) {
        if (rho_d_out) *rho_d_out = 0.0;
        if (rho_s_out) *rho_s_out = 0.0;
        return PGLOSS_ERR_NULL;
    }
    /* The batch's per-element code (perceptual_d.h): the same bits. */
    return (pgloss_status)pgloss__match_gloss_k(rho_d, rho_s, L_target, rho_d_out, rho_s_out);
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
