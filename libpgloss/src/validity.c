// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Is a parameter set inside the paper's model, and if not, why? Plus the five-parameter
 * colour/gloss description of Fig. 13 in both directions. */
#include "internal.h"
#include "perceptual_d.h"
#include "pgloss/perceptual.h"

pgloss_status pgloss__check_physical_values(const pgloss_physical *p, double limit)
{
    return (pgloss_status)pgloss__physical_values_k(p->rho_d[0], p->rho_d[1], p->rho_d[2],
                                                    p->rho_s, p->alpha_x, p->alpha_y, limit);
}

pgloss_status pgloss_check_physical(const pgloss_physical *p)
{
    if (!p)
        return PGLOSS_ERR_NULL;
    /* The batch's per-element code (perceptual_d.h): the same bits. Values beyond FLT_MAX
     * are NONFINITE, as for pgloss_material_init: a paint is inside the model only if a
     * material can hold it. */
    return (pgloss_status)pgloss__check_physical_k(p->rho_d[0], p->rho_d[1], p->rho_d[2],
                                                   p->rho_s, p->alpha_x, p->alpha_y,
                                                   pgloss__valid_normalization(p->normalization));
}

pgloss_status pgloss_check_perceptual_ex(const pgloss_perceptual *q, pgloss_color_space space)
{
    if (!q)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    /* The batch's per-element code (perceptual_d.h): the same bits. */
    return (pgloss_status)pgloss__check_perceptual_k(q->L, q->a, q->b, q->c, q->d,
                                                     pgloss__from_xyz_matrix(space));
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
    if (!pgloss__valid_normalization(normalization))
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
    /* The batch's per-element code (perceptual_d.h): the same bits. */
    return (pgloss_status)pgloss__perceptual_from_physical_k(
        p->rho_d[0], p->rho_d[1], p->rho_d[2], p->rho_s, p->alpha_x, p->alpha_y,
        pgloss__to_xyz_matrix(space), &q->L, &q->a, &q->b, &q->c, &q->d);
}

pgloss_status pgloss_perceptual_from_physical(const pgloss_physical *p, pgloss_perceptual *q)
{
    return pgloss_perceptual_from_physical_ex(p, PGLOSS_COLOR_SPACE_LINEAR_REC709, q);
}
