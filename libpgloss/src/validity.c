// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Is a parameter set inside the paper's model, and if not, why? Plus the five-parameter
 * colour/gloss description of Fig. 13 in both directions. */
#include "internal.h"
#include "perceptual_d.h"
#include "pgloss/perceptual.h"

static int valid_normalization(pgloss_normalization n)
{
    return n == PGLOSS_NORM_WARD || n == PGLOSS_NORM_WARD_DUR || n == PGLOSS_NORM_BOUNDED;
}

pgloss_status pgloss__check_physical_values(const pgloss_physical *p, double limit)
{
    const double v[6] = {p->rho_d[0], p->rho_d[1], p->rho_d[2], p->rho_s, p->alpha_x, p->alpha_y};
    for (int k = 0; k < 6; ++k)
        if (!isfinite(v[k]) || fabs(v[k]) > limit)
            return PGLOSS_ERR_NONFINITE;
    for (int k = 0; k < 4; ++k)
        if (v[k] < 0.0)
            return PGLOSS_ERR_NEGATIVE;
    if (!(p->alpha_x > 0.0) || !(p->alpha_y > 0.0))
        return PGLOSS_ERR_ALPHA;
    return PGLOSS_OK;
}

pgloss_status pgloss_check_physical(const pgloss_physical *p)
{
    if (!p)
        return PGLOSS_ERR_NULL;
    /* FLT_MAX, as pgloss_material_init: a paint is inside the model only if a material can
     * hold it. */
    const pgloss_status basic = pgloss__check_physical_values(p, FLT_MAX);
    if (basic != PGLOSS_OK)
        return basic;
    if (!valid_normalization(p->normalization))
        return PGLOSS_ERR_NORMALIZATION;
    const double dmax = fmax(p->rho_d[0], fmax(p->rho_d[1], p->rho_d[2]));
    if (dmax + p->rho_s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE)
        return PGLOSS_ERR_ENERGY;
    if (fmax(p->alpha_x, p->alpha_y) > PGLOSS_ALPHA_TRUSTED_MAX)
        return PGLOSS_WARN_ALPHA_UNTRUSTED;
    return PGLOSS_OK;
}

pgloss_status pgloss_check_perceptual_ex(const pgloss_perceptual *q, pgloss_color_space space)
{
    if (!q)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    /* α = 1 − d above FLT_MAX: no material can hold it (as pgloss_check_physical). */
    if (!isfinite(q->L) || !isfinite(q->a) || !isfinite(q->b) || !isfinite(q->c) || !isfinite(q->d) ||
        1.0 - q->d > FLT_MAX)
        return PGLOSS_ERR_NONFINITE;
    if (q->L < 0.0 || q->L > 100.0)
        return PGLOSS_ERR_LIGHTNESS;
    if (q->c < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    if (!(q->d < 1.0))
        return PGLOSS_ERR_ALPHA;
    const double lab[3] = {q->L, q->a, q->b};
    double rgb[3];
    pgloss_status st = pgloss_rgb_from_lab_ex(lab, space, rgb);
    if (st != PGLOSS_OK)
        return st;
    double cmax;
    pgloss_envelope_contrast(q->L, &cmax);
    if (q->c > cmax + PGLOSS_BOUNDARY_TOLERANCE)
        return PGLOSS_ERR_ENVELOPE;
    double y, rho_s;
    pgloss_luminance_from_lightness(q->L, &y);
    st = pgloss_specular_from_contrast(y, q->c, &rho_s);
    if (st != PGLOSS_OK)
        return st;
    if (fmax(rgb[0], fmax(rgb[1], rgb[2])) + rho_s > 1.0 + PGLOSS_BOUNDARY_TOLERANCE)
        return PGLOSS_ERR_ENERGY;
    if (1.0 - q->d > PGLOSS_ALPHA_TRUSTED_MAX)
        return PGLOSS_WARN_ALPHA_UNTRUSTED;
    return PGLOSS_OK;
}

pgloss_status pgloss_check_perceptual(const pgloss_perceptual *q)
{
    return pgloss_check_perceptual_ex(q, PGLOSS_COLOR_SPACE_LINEAR_REC709);
}

static void zero_physical(pgloss_physical *p, pgloss_normalization n)
{
    p->rho_d[0] = p->rho_d[1] = p->rho_d[2] = 0.0;
    p->rho_s = 0.0;
    p->alpha_x = p->alpha_y = 0.0;
    p->normalization = n;
}

pgloss_status pgloss_physical_from_perceptual_ex(const pgloss_perceptual *q,
                                                 pgloss_normalization normalization,
                                                 pgloss_color_space space, pgloss_physical *p)
{
    if (!p)
        return PGLOSS_ERR_NULL;
    zero_physical(p, normalization);
    if (!q)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    /* The batch's per-element code (perceptual_d.h): the same bits. Its status assumes a
     * valid normalisation, which is checked after physical_from_gloss's checks (pre). */
    double pre, rgb[3], rho_s, alpha;
    const pgloss_status st = (pgloss_status)pgloss__physical_from_perceptual_k(
        q->L, q->a, q->b, q->c, q->d, pgloss__from_xyz_matrix(space), &rgb[0], &rgb[1], &rgb[2],
        &rho_s, &alpha, &pre);
    if (pre < 0.0)
        return (pgloss_status)pre;
    if (!valid_normalization(normalization))
        return PGLOSS_ERR_NORMALIZATION;
    p->rho_d[0] = rgb[0]; p->rho_d[1] = rgb[1]; p->rho_d[2] = rgb[2];
    p->rho_s = rho_s;           /* eq. 7 with the luminance of ρd (= Y of L*) */
    p->alpha_x = p->alpha_y = alpha;
    return st;
}

pgloss_status pgloss_physical_from_perceptual(const pgloss_perceptual *q,
                                              pgloss_normalization normalization,
                                              pgloss_physical *p)
{
    return pgloss_physical_from_perceptual_ex(q, normalization, PGLOSS_COLOR_SPACE_LINEAR_REC709, p);
}

pgloss_status pgloss_perceptual_from_physical_ex(const pgloss_physical *p, pgloss_color_space space,
                                                 pgloss_perceptual *q)
{
    if (!q)
        return PGLOSS_ERR_NULL;
    q->L = q->a = q->b = q->c = q->d = 0.0;
    if (!p)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    const pgloss_status basic = pgloss__check_physical_values(p, DBL_MAX);
    if (basic != PGLOSS_OK)
        return basic;
    double lab[3], y, c;
    pgloss_status st = pgloss_lab_from_rgb_ex(p->rho_d, space, lab);
    if (st != PGLOSS_OK)
        return st;
    st = pgloss_luminance_ex(p->rho_d, space, &y);
    if (st != PGLOSS_OK)
        return st;
    st = pgloss_contrast_gloss(y, p->rho_s, &c);
    if (st != PGLOSS_OK)
        return st;
    /* The paper studied isotropic lobes; for αx ≠ αy the geometric mean (the α with the same
     * solid-angle spread, since the lobe's constant is 1/(αx αy)) stands in for α in eq. 3. */
    const double alpha = sqrt(p->alpha_x) * sqrt(p->alpha_y);
    q->L = lab[0]; q->a = lab[1]; q->b = lab[2];
    q->c = c;
    q->d = pgloss__doi_d(alpha); /* eq. 3 */
    /* The warning asks the same question as pgloss_check_physical: is the wider of the two
     * spreads beyond the trusted range? (Not the geometric mean used for d.) */
    return fmax(p->alpha_x, p->alpha_y) > PGLOSS_ALPHA_TRUSTED_MAX ? PGLOSS_WARN_ALPHA_UNTRUSTED
                                                                   : PGLOSS_OK;
}

pgloss_status pgloss_perceptual_from_physical(const pgloss_physical *p, pgloss_perceptual *q)
{
    return pgloss_perceptual_from_physical_ex(p, PGLOSS_COLOR_SPACE_LINEAR_REC709, q);
}
