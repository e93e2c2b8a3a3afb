// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Batched entry points: argument checks, then dispatch — once per call, outside the loops —
 * to the loops of batch_isa.c for the requested tier and the best (or requested) ISA, or to
 * the scalar reference functions for PGLOSS_PRECISION_REFERENCE. */
#include "batch_internal.h"
#include "internal.h"

static pgloss__batch_consts make_consts(const pgloss_material *m, unsigned active)
{
    pgloss__batch_consts k;
    k.lobe = pgloss_inl_consts_of(m, active);
    k.alpha_x = m->alpha_x;
    k.alpha_y = m->alpha_y;
    const double ax2 = (double)m->alpha_x * m->alpha_x, ay2 = (double)m->alpha_y * m->alpha_y;
    k.inv_ax2_log2 = (float)(1.4426950408889634 / ax2); /* log2 e */
    k.inv_ay2_log2 = (float)(1.4426950408889634 / ay2);
    /* The largest f and pdf over all directions: e <= 1, h·h <= 4, cosines >= COS_MIN. */
    const pgloss_inl_consts *l = &k.lobe;
    const double cm = PGLOSS_COS_MIN, cm2 = cm * cm;
    const double nn_max = m->normalization == PGLOSS_NORM_WARD_DUR ? 1.0 / cm2
                          : m->normalization == PGLOSS_NORM_BOUNDED ? 0.25 / (cm2 * cm2) /* 4/(2cm)⁴ */
                                                                    : 1.0 / cm;
    const double f_max = fmax(l->fd[0], fmax(l->fd[1], l->fd[2])) + (double)l->spec_scale * nn_max;
    const double pdf_max = l->pdf_d + (double)l->pdf_s * (0.5 / (cm2 * cm)); /* 4/(2cm)³ */
    k.may_overflow = !(f_max <= 0.5 * FLT_MAX && pdf_max <= 0.5 * FLT_MAX);
    return k;
}

/* ---- instruction sets ---------------------------------------------------------------- */

#if (defined(PGLOSS_HAVE_AVX2) || defined(PGLOSS_HAVE_AVX512)) && \
    (defined(__GNUC__) || defined(__clang__))
/* __builtin_cpu_supports reads the CPU model that libgcc fills in at start-up: a load and
 * a test, cheap enough to do on every call, and no state of ours. */
#define PGLOSS_CPU(feature) __builtin_cpu_supports(feature)
#else
#define PGLOSS_CPU(feature) 0
#endif

int pgloss_isa_supported(pgloss_isa isa)
{
    switch (isa) {
    case PGLOSS_ISA_AUTO:
    case PGLOSS_ISA_BASELINE: return 1;
#if defined(PGLOSS_HAVE_AVX2)
    case PGLOSS_ISA_AVX2: return PGLOSS_CPU("avx2") && PGLOSS_CPU("fma");
#endif
#if defined(PGLOSS_HAVE_AVX512)
    case PGLOSS_ISA_AVX512:
        return PGLOSS_CPU("avx512f") && PGLOSS_CPU("avx512vl") && PGLOSS_CPU("avx512dq") &&
               PGLOSS_CPU("avx512bw");
#endif
    default: return 0;
    }
}

pgloss_isa pgloss_isa_best(void)
{
    if (pgloss_isa_supported(PGLOSS_ISA_AVX512))
        return PGLOSS_ISA_AVX512;
    if (pgloss_isa_supported(PGLOSS_ISA_AVX2))
        return PGLOSS_ISA_AVX2;
    return PGLOSS_ISA_BASELINE;
}

const char *pgloss_isa_name(pgloss_isa isa)
{
    switch (isa) {
    case PGLOSS_ISA_AUTO: return "auto";
    case PGLOSS_ISA_BASELINE: return "baseline";
    case PGLOSS_ISA_AVX2: return "avx2";
    case PGLOSS_ISA_AVX512: return "avx512";
    default: return "unknown";
    }
}

typedef struct kernels {
    pgloss__eval_pdf_fn eval_pdf;
    pgloss__sample_fn sample;
} kernels;

int pgloss__batch_options_resolve(const pgloss_batch_options *opt, pgloss_precision *prec,
                                  pgloss_isa *isa)
{
    const pgloss_precision p = opt ? opt->precision : PGLOSS_PRECISION_FLOAT;
    const pgloss_isa i = opt ? opt->isa : PGLOSS_ISA_AUTO;
    if (p != PGLOSS_PRECISION_FLOAT && p != PGLOSS_PRECISION_FAST &&
        p != PGLOSS_PRECISION_REFERENCE)
        return 0;
    if (!pgloss_isa_supported(i))
        return 0;
    *prec = p;
    *isa = i == PGLOSS_ISA_AUTO ? pgloss_isa_best() : i;
    return 1;
}

/* The loops for the options, or {NULL, NULL} for REFERENCE; 0 if the options are invalid. */
static int select_kernels(const pgloss_batch_options *opt, kernels *out)
{
    pgloss_precision prec;
    pgloss_isa isa;
    out->eval_pdf = NULL;
    out->sample = NULL;
    if (!pgloss__batch_options_resolve(opt, &prec, &isa))
        return 0;
    if (prec == PGLOSS_PRECISION_REFERENCE)
        return 1;
    const int fast = prec == PGLOSS_PRECISION_FAST;
#define PGLOSS_PICK(name)                                                                          \
    do {                                                                                           \
        out->eval_pdf = fast ? pgloss__eval_pdf_##name##_fast : pgloss__eval_pdf_##name##_float;   \
        out->sample = fast ? pgloss__sample_##name##_fast : pgloss__sample_##name##_float;         \
    } while (0)
    switch (isa) {
#if defined(PGLOSS_HAVE_AVX512)
    case PGLOSS_ISA_AVX512: PGLOSS_PICK(avx512); break;
#endif
#if defined(PGLOSS_HAVE_AVX2)
    case PGLOSS_ISA_AVX2: PGLOSS_PICK(avx2); break;
#endif
    default: PGLOSS_PICK(baseline); break;
    }
#undef PGLOSS_PICK
    return 1;
}

/* ---- eval / pdf ---------------------------------------------------------------------- */

static int arrays_ok(pgloss_vec3_array v)
{
    return v.x && v.y && v.z;
}

static size_t eval_pdf_reference(const pgloss_material *m, unsigned lobes, size_t n,
                                 pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f,
                                 float *pdf)
{
    size_t bad = 0;
    for (size_t j = 0; j < n; ++j) {
        const pgloss_vec3 o = {wo.x[j], wo.y[j], wo.z[j]}, i = {wi.x[j], wi.y[j], wi.z[j]};
        pgloss_rgb v;
        float p;
        bad += pgloss_eval_pdf(m, o, i, lobes, &v, &p) != PGLOSS_OK;
        if (f.r) {
            f.r[j] = v.r;
            f.g[j] = v.g;
            f.b[j] = v.b;
        }
        if (pdf)
            pdf[j] = p;
    }
    return bad;
}

pgloss_status pgloss_eval_pdf_batch_ex(const pgloss_batch_options *options,
                                       const pgloss_material *m, unsigned lobes, size_t n,
                                       pgloss_vec3_array wo, pgloss_vec3_array wi,
                                       pgloss_rgb_out f, float *pdf)
{
    kernels kn;
    if (!select_kernels(options, &kn))
        return PGLOSS_ERR_ARGUMENT;
    if (n == 0)
        return PGLOSS_OK;
    if (f.r && (!f.g || !f.b))
        return PGLOSS_ERR_NULL;
    if (!m || !arrays_ok(wo) || !arrays_ok(wi) || (!f.r && !pdf))
        return PGLOSS_ERR_NULL;
    if (!f.r)
        f.g = f.b = NULL;
    size_t bad;
    if (kn.eval_pdf) {
        const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
        const pgloss__batch_consts k = make_consts(m, active);
        bad = kn.eval_pdf(&k, active, (int)m->normalization, n, wo, wi, f, pdf);
    } else {
        bad = eval_pdf_reference(m, lobes, n, wo, wi, f, pdf);
    }
    return bad ? PGLOSS_ERR_DIRECTION : PGLOSS_OK;
}

pgloss_status pgloss_eval_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_ex(NULL, m, lobes, n, wo, wi, f, NULL);
}

pgloss_status pgloss_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                               pgloss_vec3_array wo, pgloss_vec3_array wi, float *pdf)
{
    const pgloss_rgb_out none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_ex(NULL, m, lobes, n, wo, wi, none, pdf);
}

pgloss_status pgloss_eval_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array wo, pgloss_vec3_array wi,
                                    pgloss_rgb_out f, float *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_ex(NULL, m, lobes, n, wo, wi, f, pdf);
}

/* ---- sampling ------------------------------------------------------------------------ */

static void sample_reference(const pgloss_material *m, unsigned lobes, size_t n,
                             pgloss_vec3_array wo, const float *u0, const float *u1,
                             const float *u2, pgloss_vec3_out wi, float *pdf,
                             pgloss_rgb_out weight, unsigned char *lobe)
{
    for (size_t j = 0; j < n; ++j) {
        const pgloss_vec3 o = {wo.x[j], wo.y[j], wo.z[j]};
        const float u[3] = {u0[j], u1[j], u2[j]};
        pgloss_sample_record s;
        (void)pgloss_sample(m, o, u, lobes, &s);
        pgloss__put_sample_record(&s, j, wi, pdf, weight, lobe);
    }
}

pgloss_status pgloss_sample_batch_ex(const pgloss_batch_options *options,
                                     const pgloss_material *m, unsigned lobes, size_t n,
                                     pgloss_vec3_array wo, const float *u0, const float *u1,
                                     const float *u2, pgloss_vec3_out wi, float *pdf,
                                     pgloss_rgb_out weight, unsigned char *lobe)
{
    kernels kn;
    if (!select_kernels(options, &kn))
        return PGLOSS_ERR_ARGUMENT;
    if (n == 0)
        return PGLOSS_OK;
    if (!m || !arrays_ok(wo) || !u0 || !u1 || !u2 || !wi.x || !wi.y || !wi.z || !pdf ||
        !weight.r || !weight.g || !weight.b)
        return PGLOSS_ERR_NULL;
    if (kn.sample) {
        const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
        const pgloss__batch_consts k = make_consts(m, active);
        kn.sample(&k, active, (int)m->normalization, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
    } else {
        sample_reference(m, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
    }

    /* Report the first invalid element's reason, in the scalar function's order. */
    for (size_t j = 0; j < n; ++j) {
        if (isnan(u0[j]) || isnan(u1[j]) || isnan(u2[j]))
            return PGLOSS_ERR_RANDOM;
        const pgloss_vec3 v = {wo.x[j], wo.y[j], wo.z[j]};
        double o[3];
        if (!pgloss__normalize(v, o))
            return PGLOSS_ERR_DIRECTION;
    }
    return PGLOSS_OK;
}

pgloss_status pgloss_sample_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array wo, const float *u0, const float *u1,
                                  const float *u2, pgloss_vec3_out wi, float *pdf,
                                  pgloss_rgb_out weight, unsigned char *lobe)
{
    return pgloss_sample_batch_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe);
}
