// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Importance sampling of the Ward BRDF: lobe selection by albedo, cosine-weighted diffuse
 * directions, and Walter's (2005) half-vector sampling of the specular lobe. Double inside;
 * the record's pdf and weight come from the same code as pgloss_eval_pdf (brdf.c). */
#include "internal.h"

/* Largest float below 1: random numbers are clamped to [0, ONE_MINUS_EPS]. */
#define ONE_MINUS_EPS 0x1.fffffep-1f

static float clamp_u(float u)
{
    return u < 0.0f ? 0.0f : (u > ONE_MINUS_EPS ? ONE_MINUS_EPS : u);
}

/* sin u and cos u for |u| <= π/4, from their Taylor series (to u^15 and u^16: truncation below
 * 0.786^17/17! < 5e-17 and 0.786^18/18! < 3e-18), in Estrin's scheme (short dependency
 * chains): within a few ulps, inline, where libm's sincos would reduce an argument that needs
 * no reduction. */
static inline void sincos_quarter(double u, double *s, double *c)
{
    const double v = u * u, v2 = v * v, v4 = v2 * v2;
    const double s01 = 1.0 - v * (1.0 / 6.0), s23 = 1.0 / 120.0 - v * (1.0 / 5040.0),
                 s45 = 1.0 / 362880.0 - v * (1.0 / 39916800.0),
                 s67 = 1.0 / 6227020800.0 - v * (1.0 / 1307674368000.0);
    *s = u * ((s01 + v2 * s23) + v4 * (s45 + v2 * s67));
    const double c01 = 1.0 - v * 0.5, c23 = 1.0 / 24.0 - v * (1.0 / 720.0),
                 c45 = 1.0 / 40320.0 - v * (1.0 / 3628800.0),
                 c67 = 1.0 / 479001600.0 - v * (1.0 / 87178291200.0);
    *c = (c01 + v2 * c23) + v4 * ((c45 + v2 * c67) + v4 * (1.0 / 20922789888000.0));
}

/* Shirley & Chiu's concentric map of [0,1)² onto the unit disk, lifted to the hemisphere
 * (Malley's method): density cosθ/π. The disk angle φ is (π/4)(b/a) or π/2 - (π/4)(a/b),
 * so (cos φ, sin φ) needs sin and cos of an angle in [-π/4, π/4] only. */
static void sample_cosine_hemisphere(double u1, double u2, double w[3])
{
    const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
    double x = 0.0, y = 0.0;
    if (a != 0.0 || b != 0.0) {
        double sn, cs;
        if (fabs(a) > fabs(b)) {
            sincos_quarter((PGLOSS_PI / 4.0) * (b / a), &sn, &cs);
            x = a * cs;
            y = a * sn;
        } else {
            sincos_quarter((PGLOSS_PI / 4.0) * (a / b), &sn, &cs);
            x = b * sn; /* cos(π/2 - u) */
            y = b * cs; /* sin(π/2 - u) */
        }
    }
    const double z2 = 1.0 - x * x - y * y;
    w[0] = x;
    w[1] = y;
    w[2] = sqrt(z2 > 0.0 ? z2 : 0.0);
}

/* cos and sin of t = 2π u for u in [0, 1): with v = 4u = k + r (k = round(v), r in [-1/2, 1/2],
 * both exact), t = k π/2 + r π/2, a quarter turn k times the angle r π/2 of [-π/4, π/4]. */
static void cos_sin_turn(double u, double *c, double *s)
{
    const double v = 4.0 * u;
    const int k = (int)(v + 0.5);
    double sn, cs;
    sincos_quarter((v - (double)k) * (PGLOSS_PI / 2.0), &sn, &cs);
    switch (k & 3) {
    case 0: *c = cs; *s = sn; break;
    case 1: *c = -sn; *s = cs; break;
    case 2: *c = -cs; *s = -sn; break;
    default: *c = sn; *s = -cs; break;
    }
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
        const double sq = sqrt(-log1p(-u1));
        double ct, st;
        cos_sin_turn(u2, &ct, &st);
        const double gx = m->alpha_x * sq * ct, gy = m->alpha_y * sq * st;
        const double gg = gx * gx + gy * gy + 1.0;
        /* Mirror wo about h: wi = 2 (ô·ĥ) ĥ - ô with ô = wo/|wo|, ĥ = g/|g|
         *                      = (2 (wo·g) g - (g·g) wo) / ((g·g) |wo|): one root, one division. */
        const double og = ox * gx + oy * gy + oz;
        const double inv = 1.0 / (gg * sqrt(l2o));
        const double two_og = 2.0 * og;
        w[0] = (two_og * gx - gg * ox) * inv;
        w[1] = (two_og * gy - gg * oy) * inv;
        w[2] = (two_og - gg * oz) * inv;
        if (!(og > 0.0)) { /* wo·h <= 0: rejected (wi still written) */
            s->wi.x = (float)w[0]; s->wi.y = (float)w[1]; s->wi.z = (float)w[2];
            return PGLOSS_OK;
        }
    } else {
        s->lobe = PGLOSS_LOBE_DIFFUSE;
        sample_cosine_hemisphere(u1, u2, w);
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
