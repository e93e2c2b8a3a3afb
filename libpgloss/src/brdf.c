// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Scalar evaluation of the Ward BRDF (paper eq. 2 and its two later normalisations) and of
 * the sampling density. Double internally: this is the reference the float paths
 * (pgloss/inline.h, the batches) and the shader ports are held to. One path: both directions
 * are normalised (pgloss__normalize), then pgloss__eval_pdf_d applies the formulas of brdf.h
 * literally, with exp_parts below instead of libm's exp. */
#include <stdint.h>
#include <string.h>
#include "internal.h"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__GNUC__) || defined(__clang__)
#define BRDF_INLINE static inline __attribute__((always_inline))
#else
#define BRDF_INLINE static inline
#endif

/* 2^(j/32), j = 0..31, correctly rounded (Python: float(Decimal(2) ** (Decimal(j) / 32)) at
 * 60 digits). */
static const double exp2_j32[32] = {
    0x1.0000000000000p+0, 0x1.059b0d3158574p+0, 0x1.0b5586cf9890fp+0, 0x1.11301d0125b51p+0,
    0x1.172b83c7d517bp+0, 0x1.1d4873168b9aap+0, 0x1.2387a6e756238p+0, 0x1.29e9df51fdee1p+0,
    0x1.306fe0a31b715p+0, 0x1.371a7373aa9cbp+0, 0x1.3dea64c123422p+0, 0x1.44e086061892dp+0,
    0x1.4bfdad5362a27p+0, 0x1.5342b569d4f82p+0, 0x1.5ab07dd485429p+0, 0x1.6247eb03a5585p+0,
    0x1.6a09e667f3bcdp+0, 0x1.71f75e8ec5f74p+0, 0x1.7a11473eb0187p+0, 0x1.82589994cce13p+0,
    0x1.8ace5422aa0dbp+0, 0x1.93737b0cdc5e5p+0, 0x1.9c49182a3f090p+0, 0x1.a5503b23e255dp+0,
    0x1.ae89f995ad3adp+0, 0x1.b7f76f2fb5e47p+0, 0x1.c199bdd85529cp+0, 0x1.cb720dcef9069p+0,
    0x1.d5818dcfba487p+0, 0x1.dfc97337b9b5fp+0, 0x1.ea4afa2a490dap+0, 0x1.f50765b6e4540p+0,
};

/* max(x, lo) for x not NaN; with SSE2 one maxsd that the compiler cannot turn into a branch
 * (GCC makes `x > lo ? x : lo` a branch here, which mispredicts on the exponent's tail). */
BRDF_INLINE double max_no_branch(double x, double lo)
{
#if defined(__SSE2__)
    return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(x), _mm_set_sd(lo)));
#else
    return x > lo ? x : lo;
#endif
}

/* -32/ln2: the specular exponent is scaled by it before the exponential (folded into
 * the numerator, off the latency chain). */
#define NEG_32_OVER_LN2 (-0x1.71547652b82fep+5)

/* exp(x) = scale · poly, given y = x·32/ln2 <= 0 (x = -tan²δ/α², the specular exponent),
 * inline and free of libm's call and special cases; returns poly and sets *scale (the caller
 * multiplies its constant into the scale while the polynomial is evaluated: one step off the
 * latency chain). With n = round(y) = 32 m + j: exp(x) = 2^m · 2^(j/32) · 2^((y-n)/32),
 * y - n in [-1/2, 1/2] exact, 2^(t/32) = e^(t ln2/32) from its degree-5 Taylor polynomial
 * (truncation < 0.0109^6/720 < 2.3e-15). Rounding y (its product with 32/ln2) is like a
 * half-ulp change of x: relative error |x|·2^-53 in the result, as the rounding of x itself.
 * Below y = -32686 (x < -708.0) y is raised to -32686, so the result is exp(-708.0) = 3.3e-308
 * instead of a smaller number (or a subnormal, or 0): no output can tell, since e enters them
 * multiplied by at most spec_scale·norm < FLT_MAX·2.5e35 (f) or 2 pdf_scale·(h·h)/hzc³ < 1e34
 * (pdf), so the specular term stays below 1e-233, which is 0 in float and leaves any nonzero
 * diffuse term (>= 1e-168) unchanged in double (and a pdf that small is a rejected sample's).
 * Without a branch: that tail is common (diffuse-sampled wi on a narrow lobe) and
 * unpredictable. */
BRDF_INLINE double exp_parts(double y, double *scale)
{
    /* n >= -32686: m >= -1022, so 2^m 2^(j/32) e^t stays normal */
    y = max_no_branch(y, -32686.0);
    const double shift = 0x1.8p52; /* (y + shift) - shift = round(y) */
    const double nd0 = y + shift;
    const double t = y - (nd0 - shift);
    uint64_t nbits, sbits;
    memcpy(&nbits, &nd0, sizeof nbits);
    /* nbits = bits(shift) + n, n = 32 m + j (two's complement below the 2^51 bit; bits(shift)
     * is a multiple of 2^51), so j = nbits mod 32 and (nbits - j) << 47 = m << 52 mod 2^64:
     * adding it to the bits of 2^(j/32) multiplies by 2^m. */
    memcpy(&sbits, &exp2_j32[nbits & 31u], sizeof sbits);
    sbits += (nbits & ~(uint64_t)31) << 47;
    memcpy(scale, &sbits, sizeof *scale);
    /* (ln2/32)^i / i!, i = 1..5 */
    const double c1 = 0x1.62e42fefa39efp-6, c2 = 0x1.ebfbdff82c58fp-13,
                 c3 = 0x1.c6b08d704a0c0p-20, c4 = 0x1.3b2ab6fba4e77p-27,
                 c5 = 0x1.5d87fe78a6731p-35;
    const double t2 = t * t;
    return (1.0 + t * c1) + t2 * (c2 + t * c3) + (t2 * t2) * (c4 + t * c5);
}

void pgloss__eval_pdf_d(const pgloss_material *m, unsigned active, const double o[3],
                        const double i[3], double f[3], double *pdf)
{
    double fd[3] = {0.0, 0.0, 0.0}, fs = 0.0, p = 0.0;
    if (o[2] > 0.0 && i[2] > 0.0 && active) {
        /* The lobe-selection probability only matters to the pdf: skip it for eval alone. */
        const double ps = pdf ? pgloss__specular_probability_d(m, active) : 0.0;
        if (active & PGLOSS_LOBE_DIFFUSE) {
            for (int k = 0; k < 3; ++k)
                fd[k] = m->rho_d[k] * PGLOSS_INV_PI;
            /* 1 − Ps as wd / (wd + ws), exact for a weak diffuse lobe too */
            const double pd = active == PGLOSS_LOBE_ALL
                                  ? m->weight_diffuse / ((double)m->weight_diffuse + m->weight_specular)
                                  : 1.0;
            p += pd * i[2] * PGLOSS_INV_PI;
        }
        if (active & PGLOSS_LOBE_SPECULAR) {
            const double hx = o[0] + i[0], hy = o[1] + i[1], hz = o[2] + i[2];
            const double ex = hx * m->inv_alpha_x, ey = hy * m->inv_alpha_y;
            /* exp(-tan²δ/α²) of eq. 2, anisotropic form (Ward 1992). */
            double scale;
            const double poly = exp_parts(((ex * ex + ey * ey) * NEG_32_OVER_LN2) / (hz * hz), &scale);
            const double e = scale * poly;
            const double ci = fmax(i[2], (double)PGLOSS_COS_MIN);
            const double co = fmax(o[2], (double)PGLOSS_COS_MIN);
            const double hzc = ci + co;
            const double hh = hx * hx + hy * hy + hz * hz;
            if (f) {
                double norm;
                switch (m->normalization) {
                case PGLOSS_NORM_WARD_DUR: norm = 1.0 / (ci * co); break;          /* Dür 2006 */
                case PGLOSS_NORM_BOUNDED: norm = hh / ((hzc * hzc) * (hzc * hzc)); break; /* GM&D 2010 */
                default: norm = 1.0 / sqrt(ci * co); break;                         /* eq. 2 */
                }
                fs = m->spec_scale * e * norm;
            }
            /* Walter 2005: p(wi) = D(h) / (4 (wo·h)), and for unit wo, wi: wo·ĥ ĥz³ = hz³ / (2 h·h). */
            if (pdf)
                p += ps * 2.0 * m->pdf_scale * e * hh / (hzc * hzc * hzc);
        }
    }
    if (f)
        for (int k = 0; k < 3; ++k)
            f[k] = fd[k] + fs;
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
