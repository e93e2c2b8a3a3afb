// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Scalar evaluation of the Ward BRDF (paper eq. 2 and its two later normalisations) and of
 * the sampling density. Double internally: this is the reference the float paths
 * (pgloss/inline.h, the batches) and the shader ports are held to. One path: both directions
 * are normalised (pgloss__normalize), then pgloss__eval_pdf_d runs the double lobe of lobe_d.h
 * (brdf.h's formulas literally, with an inline exp instead of libm's; the double batches run
 * the same code) on the float material's constants. */
#include "internal.h"
#define PGLOSS__D_SCALAR 1 /* lobe_d.h: branch-free max and min for one lane */
#include "lobe_d.h"

void pgloss__eval_pdf_d(const pgloss_material *m, unsigned active, const double o[3],
                        const double i[3], double f[3], double *pdf)
{
    /* The float material's constants, widened: the reference evaluates the material that
     * the float paths evaluate. */
    pgloss__consts_d k;
    for (int c = 0; c < 3; ++c)
        k.fd[c] = m->rho_d[c] * PGLOSS_INV_PI;
    k.spec_scale = m->spec_scale;
    k.inv_ax = m->inv_alpha_x;
    k.inv_ay = m->inv_alpha_y;
    k.pdf_scale = m->pdf_scale;
    k.alpha_x = m->alpha_x;
    k.alpha_y = m->alpha_y;
    k.active = active;
    pgloss__lobe_probs_d(m->weight_diffuse, m->weight_specular, active, &k.ps, &k.pd);
    double fv[3], p;
    pgloss__lobe_d(&k, active, (int)m->normalization, o[0], o[1], o[2], i[0], i[1], i[2],
                   f != NULL, pdf != NULL, fv, &p);
    if (f)
        for (int c = 0; c < 3; ++c)
            f[c] = fv[c];
    if (pdf)
        *pdf = p;
}

pgloss_status pgloss__eval_pdf_raw(const pgloss_material *m, unsigned active, pgloss_vec3 wo,
                                   pgloss_vec3 wi, double f[3], double *pdf, double *cos_i)
{
    double o[3], i[3];
    const int ok_o = pgloss__normalize(wo, o);
    const int ok_i = pgloss__normalize(wi, i);
    if (!(ok_o && ok_i)) {
        if (f) f[0] = f[1] = f[2] = 0.0;
        if (pdf) *pdf = 0.0;
        return PGLOSS_ERR_DIRECTION;
    }
    pgloss__eval_pdf_d(m, active, o, i, f, pdf);
    if (cos_i)
        *cos_i = i[2];
    return PGLOSS_OK;
}

static void store_rgb(pgloss_rgb *out, const double f[3])
{
    out->r = pgloss__to_float(f[0]);
    out->g = pgloss__to_float(f[1]);
    out->b = pgloss__to_float(f[2]);
}

pgloss_status pgloss_eval_pdf(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                              unsigned lobes, pgloss_rgb *f, float *pdf)
{
    if (f) f->r = f->g = f->b = 0.0f;
    if (pdf) *pdf = 0.0f;
    if (!m || (!f && !pdf))
        return PGLOSS_ERR_NULL;
    double fv[3], p;
    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    const pgloss_status st =
        pgloss__eval_pdf_raw(m, active, wo, wi, f ? fv : NULL, pdf ? &p : NULL, NULL);
    if (st != PGLOSS_OK)
        return st;
    if (f) store_rgb(f, fv);
    if (pdf) *pdf = pgloss__to_float(p);
    return PGLOSS_OK;
}

pgloss_status pgloss_eval(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                          unsigned lobes, pgloss_rgb *f)
{
    if (!f)
        return PGLOSS_ERR_NULL;
    f->r = f->g = f->b = 0.0f;
    if (!m)
        return PGLOSS_ERR_NULL;
    double fv[3];
    const pgloss_status st =
        pgloss__eval_pdf_raw(m, lobes & m->lobes & PGLOSS_LOBE_ALL, wo, wi, fv, NULL, NULL);
    if (st == PGLOSS_OK)
        store_rgb(f, fv);
    return st;
}

pgloss_status pgloss_pdf(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                         unsigned lobes, float *pdf)
{
    if (!pdf)
        return PGLOSS_ERR_NULL;
    *pdf = 0.0f;
    if (!m)
        return PGLOSS_ERR_NULL;
    double p;
    const pgloss_status st =
        pgloss__eval_pdf_raw(m, lobes & m->lobes & PGLOSS_LOBE_ALL, wo, wi, NULL, &p, NULL);
    if (st == PGLOSS_OK)
        *pdf = pgloss__to_float(p);
    return st;
}
