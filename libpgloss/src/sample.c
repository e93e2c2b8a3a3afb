// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Importance sampling of the Ward BRDF: lobe selection by albedo, cosine-weighted diffuse
 * directions, and Walter's (2005) half-vector sampling of the specular lobe. Double inside;
 * the record's pdf and weight come from the same code as pgloss_eval_pdf (brdf.c). */
#include "internal.h"
#define PGLOSS__D_SCALAR 1 /* lobe_d.h: branch-free max and min for one lane */
#include "lobe_d.h"

/* Largest float below 1: random numbers are clamped to [0, ONE_MINUS_EPS]. */
#define ONE_MINUS_EPS 0x1.fffffep-1f

static float clamp_u(float u)
{
    return u < 0.0f ? 0.0f : (u > ONE_MINUS_EPS ? ONE_MINUS_EPS : u);
}

static void reject(pgloss_sample_record *s)
{
    s->pdf = 0.0f;
    s->weight.r = s->weight.g = s->weight.b = 0.0f;
}

pgloss_status pgloss_sample(const pgloss_material *m, pgloss_vec3 wo, const float u[3],
                            unsigned lobes, pgloss_sample_record *s)
{
    if (!s)
        return PGLOSS_ERR_NULL;
    s->wi.x = s->wi.y = 0.0f;
    s->wi.z = 1.0f;
    s->lobe = PGLOSS_LOBE_NONE;
    reject(s);
    if (!m || !u)
        return PGLOSS_ERR_NULL;
    if (isnan(u[0]) || isnan(u[1]) || isnan(u[2]))
        return PGLOSS_ERR_RANDOM;
    /* wo's components are floats: their squares neither overflow nor underflow in double
     * (see pgloss__normalize); a zero or non-finite wo is an error. */
    const double ox = wo.x, oy = wo.y, oz = wo.z;
    const double l2o = ox * ox + oy * oy + oz * oz;
    if (!(l2o > 0.0) || !(l2o <= DBL_MAX))
        return PGLOSS_ERR_DIRECTION;

    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    if (!active)
        return PGLOSS_OK;
    const double ps = pgloss__specular_probability_d(m, active);
    const double u0 = clamp_u(u[0]), u1 = clamp_u(u[1]), u2 = clamp_u(u[2]);

    double w[3];
    if (u0 < ps) {
        s->lobe = PGLOSS_LOBE_SPECULAR;
        /* Half vector with density exp(-tan²δ (cos²φ/αx² + sin²φ/αy²)) / (π αx αy cos³δ)
         * (Walter 2005, eq. 5–6 in the anisotropic form of Ward 1992). With t = 2πu2 and
         * s = sqrt(-ln(1-u1)), tanδ·(cosφ, sinφ) = s·(αx cos t, αy sin t): h ∝ g = (αx s cos t,
         * αy s sin t, 1). In double g·g <= 1 + (FLT_MAX · 4.08)² cannot overflow (u1 <= 1-2^-24
         * bounds s), so g needs no rescaling (the float batch rescales; the results agree to
         * rounding). */
        const double og = pgloss__sample_specular_d(m->alpha_x, m->alpha_y, ox, oy, oz, l2o, u1,
                                                    u2, w);
        if (!(og > 0.0)) { /* wo·h <= 0: rejected (wi still written) */
            s->wi.x = (float)w[0]; s->wi.y = (float)w[1]; s->wi.z = (float)w[2];
            return PGLOSS_OK;
        }
    } else {
        s->lobe = PGLOSS_LOBE_DIFFUSE;
        pgloss__sample_cosine_d(u1, u2, w);
    }
    s->wi.x = (float)w[0];
    s->wi.y = (float)w[1];
    s->wi.z = (float)w[2];
    if (!(oz > 0.0)) /* wo below the horizon (its sign survives normalisation) */
        return PGLOSS_OK;

    /* Density and weight at the float direction handed back, computed exactly as
     * pgloss_eval_pdf(wo, s->wi) computes them, so that they agree with pgloss_pdf and
     * pgloss_eval bit for bit. wi at or below the horizon gives p = 0 (rejected below). */
    double f[3], p, ci = 0.0;
    if (pgloss__eval_pdf_raw(m, active, wo, s->wi, f, &p, &ci) != PGLOSS_OK)
        return PGLOSS_OK;
    /* Decide rejection on the float pdf that is stored, not on the double one: a density in
     * (0, FLT_TRUE_MIN/2) rounds to 0, and a sample with pdf 0 must be a rejected sample
     * (weight 0), never one with a finite weight and a zero pdf (found by test_stress). */
    const float pf = pgloss__to_float(p);
    if (!(pf > 0.0f))
        return PGLOSS_OK;
    s->pdf = pf;
    const double ci_p = ci / p; /* weight = f cosθi / pdf */
    s->weight.r = pgloss__to_float(f[0] * ci_p);
    s->weight.g = pgloss__to_float(f[1] * ci_p);
    s->weight.b = pgloss__to_float(f[2] * ci_p);
    return PGLOSS_OK;
}
