// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
#include <string.h>
#include "internal.h"
#include "pgloss/inline.h"

/* A material that reflects nothing: what a failed init leaves behind, so that a caller
 * who ignores the status renders black rather than garbage. */
static void make_black(pgloss_material *m)
{
    memset(m, 0, sizeof *m);
    m->alpha_x = m->alpha_y = 1.0f;
    m->inv_alpha_x = m->inv_alpha_y = 1.0f;
    m->normalization = PGLOSS_NORM_WARD;
    m->lobes = PGLOSS_LOBE_NONE;
}

pgloss_status pgloss_material_init(pgloss_material *m, const pgloss_physical *p)
{
    if (!m)
        return PGLOSS_ERR_NULL;
    make_black(m);
    if (!p)
        return PGLOSS_ERR_NULL;

    const pgloss_status basic = pgloss__check_physical_values(p, (double)FLT_MAX);
    if (basic != PGLOSS_OK)
        return basic;
    if (p->normalization != PGLOSS_NORM_WARD && p->normalization != PGLOSS_NORM_WARD_DUR &&
        p->normalization != PGLOSS_NORM_BOUNDED)
        return PGLOSS_ERR_NORMALIZATION;

    for (int k = 0; k < 3; ++k)
        m->rho_d[k] = (float)p->rho_d[k];
    m->rho_s = (float)p->rho_s;
    m->alpha_x = (float)p->alpha_x;
    m->alpha_y = (float)p->alpha_y;
    m->normalization = p->normalization;
    /* α floor, 1/α, the lobe constants and the lobe-selection weights: one definition, shared
     * with the per-element batches (pgloss/inline.h). */
    pgloss_inl_material_derive(m);
    return PGLOSS_OK;
}

double pgloss__specular_probability_d(const pgloss_material *m, unsigned active)
{
    if (active == PGLOSS_LOBE_SPECULAR)
        return 1.0;
    if (active != PGLOSS_LOBE_ALL)
        return 0.0;
    const double wd = m->weight_diffuse, ws = m->weight_specular;
    return ws / (wd + ws);
}

float pgloss_specular_probability(const pgloss_material *m, unsigned lobes)
{
    if (!m)
        return 0.0f;
    return (float)pgloss__specular_probability_d(m, lobes & m->lobes & PGLOSS_LOBE_ALL);
}
