// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The batched perceptual and colour functions (pgloss/perceptual_batch.h): argument checks,
 * then one loop per function over the per-element code that the scalar functions run. */
#include "internal.h"
#include "pgloss/perceptual_batch.h"

/* The returned status: first error, else first warning, else OK (perceptual_batch.h). */
typedef struct summary {
    pgloss_status error, warning;
} summary;

static void note(summary *s, pgloss_status st)
{
    if (st < 0 && s->error == PGLOSS_OK)
        s->error = st;
    else if (st > 0 && s->warning == PGLOSS_OK)
        s->warning = st;
}

static pgloss_status result(const summary *s)
{
    return s->error != PGLOSS_OK ? s->error : s->warning;
}

static pgloss_status summarize(size_t n, const signed char *st)
{
    summary s = {PGLOSS_OK, PGLOSS_OK};
    for (size_t j = 0; j < n && s.error == PGLOSS_OK; ++j)
        note(&s, (pgloss_status)st[j]);
    return result(&s);
}

#define CHUNK 512

/* Runs BODY(j, st) for j in [0, n) chunk by chunk, with statuses in a chunk buffer unless
 * the caller gave an array; then summarises. */
#define RUN_BATCH(n, status, ...)                                                                 \
    {                                                                                              \
        summary s_ = {PGLOSS_OK, PGLOSS_OK};                                                       \
        signed char buf_[CHUNK];                                                                   \
        for (size_t base_ = 0; base_ < (n); base_ += CHUNK) {                                      \
            const size_t m_ = (n) - base_ < CHUNK ? (n) - base_ : CHUNK;                           \
            signed char *st = (status) ? (status) + base_ : buf_;                                  \
            for (size_t i_ = 0; i_ < m_; ++i_) {                                                   \
                const size_t j = base_ + i_;                                                       \
                signed char *const stj = &st[i_];                                                  \
                __VA_ARGS__                                                                        \
            }                                                                                      \
            if (s_.error == PGLOSS_OK) {                                                           \
                const pgloss_status r_ = summarize(m_, st);                                        \
                note(&s_, r_);                                                                     \
            }                                                                                      \
        }                                                                                          \
        return result(&s_);                                                                        \
    }

pgloss_status pgloss_gloss_from_physical_batch(size_t n, const double *rho_d, const double *rho_s,
                                               const double *alpha, double *L, double *c,
                                               double *d, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!rho_d || !rho_s || !alpha || !L || !c || !d)
        return PGLOSS_ERR_NULL;
    RUN_BATCH(n, status, {
        *stj = (signed char)pgloss_gloss_from_physical(rho_d[j], rho_s[j], alpha[j], &L[j], &c[j], &d[j]);
    })
}

pgloss_status pgloss_physical_from_gloss_batch(size_t n, const double *L, const double *c,
                                               const double *d, double *rho_d, double *rho_s,
                                               double *alpha, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!L || !c || !d || !rho_d || !rho_s || !alpha)
        return PGLOSS_ERR_NULL;
    RUN_BATCH(n, status, {
        const double l = L[j], cc = c[j], dd = d[j];
        *stj = (signed char)pgloss_physical_from_gloss(l, cc, dd, &rho_d[j], &rho_s[j], &alpha[j]);
    })
}

pgloss_status pgloss_envelope_contrast_batch(size_t n, const double *L, double *c_max,
                                             signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!L || !c_max)
        return PGLOSS_ERR_NULL;
    RUN_BATCH(n, status, {
        const double l = L[j];
        *stj = (signed char)pgloss_envelope_contrast(l, &c_max[j]);
    })
}

pgloss_status pgloss_match_gloss_batch(size_t n, const double *rho_d, const double *rho_s,
                                       const double *L_target, double *rho_d_out,
                                       double *rho_s_out, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!rho_d || !rho_s || !L_target || !rho_d_out || !rho_s_out)
        return PGLOSS_ERR_NULL;
    RUN_BATCH(n, status, {
        const double a = rho_d[j], b = rho_s[j], l = L_target[j];
        *stj = (signed char)pgloss_match_gloss(a, b, l, &rho_d_out[j], &rho_s_out[j]);
    })
}

static int physical_array_ok(const pgloss_physical_array *p)
{
    return p && p->rho_d_r && p->rho_d_g && p->rho_d_b && p->rho_s && p->alpha_x;
}

static pgloss_physical physical_at(const pgloss_physical_array *p, size_t j)
{
    pgloss_physical q;
    q.rho_d[0] = p->rho_d_r[j];
    q.rho_d[1] = p->rho_d_g[j];
    q.rho_d[2] = p->rho_d_b[j];
    q.rho_s = p->rho_s[j];
    q.alpha_x = p->alpha_x[j];
    q.alpha_y = p->alpha_y ? p->alpha_y[j] : p->alpha_x[j];
    q.normalization = p->normalization;
    return q;
}

pgloss_status pgloss_check_physical_batch(size_t n, const pgloss_physical_array *p,
                                          signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!physical_array_ok(p))
        return PGLOSS_ERR_NULL;
    RUN_BATCH(n, status, {
        const pgloss_physical q = physical_at(p, j);
        *stj = (signed char)pgloss_check_physical(&q);
    })
}

static int perceptual_array_ok(pgloss_perceptual_array q)
{
    return q.L && q.a && q.b && q.c && q.d;
}

static pgloss_perceptual perceptual_at(pgloss_perceptual_array q, size_t j)
{
    const pgloss_perceptual v = {q.L[j], q.a[j], q.b[j], q.c[j], q.d[j]};
    return v;
}

pgloss_status pgloss_check_perceptual_batch_ex(size_t n, pgloss_perceptual_array q,
                                               pgloss_color_space space, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!perceptual_array_ok(q))
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    RUN_BATCH(n, status, {
        const pgloss_perceptual v = perceptual_at(q, j);
        *stj = (signed char)pgloss_check_perceptual_ex(&v, space);
    })
}

pgloss_status pgloss_check_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                            signed char *status)
{
    return pgloss_check_perceptual_batch_ex(n, q, PGLOSS_COLOR_SPACE_LINEAR_REC709, status);
}

pgloss_status pgloss_physical_from_perceptual_batch_ex(size_t n, pgloss_perceptual_array q,
                                                       pgloss_normalization normalization,
                                                       pgloss_color_space space,
                                                       pgloss_physical_out p, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!perceptual_array_ok(q) || !p.rho_d_r || !p.rho_d_g || !p.rho_d_b || !p.rho_s ||
        !p.alpha_x)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    if (normalization != PGLOSS_NORM_WARD && normalization != PGLOSS_NORM_WARD_DUR &&
        normalization != PGLOSS_NORM_BOUNDED)
        return PGLOSS_ERR_NORMALIZATION;
    RUN_BATCH(n, status, {
        const pgloss_perceptual v = perceptual_at(q, j);
        pgloss_physical o;
        *stj = (signed char)pgloss_physical_from_perceptual_ex(&v, normalization, space, &o);
        p.rho_d_r[j] = o.rho_d[0];
        p.rho_d_g[j] = o.rho_d[1];
        p.rho_d_b[j] = o.rho_d[2];
        p.rho_s[j] = o.rho_s;
        p.alpha_x[j] = o.alpha_x;
        if (p.alpha_y)
            p.alpha_y[j] = o.alpha_y;
    })
}

pgloss_status pgloss_physical_from_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                                    pgloss_normalization normalization,
                                                    pgloss_physical_out p, signed char *status)
{
    return pgloss_physical_from_perceptual_batch_ex(n, q, normalization,
                                                    PGLOSS_COLOR_SPACE_LINEAR_REC709, p, status);
}

pgloss_status pgloss_perceptual_from_physical_batch_ex(size_t n, const pgloss_physical_array *p,
                                                       pgloss_color_space space,
                                                       pgloss_perceptual_out q,
                                                       signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!physical_array_ok(p) || !q.L || !q.a || !q.b || !q.c || !q.d)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    RUN_BATCH(n, status, {
        const pgloss_physical v = physical_at(p, j);
        pgloss_perceptual o;
        *stj = (signed char)pgloss_perceptual_from_physical_ex(&v, space, &o);
        q.L[j] = o.L;
        q.a[j] = o.a;
        q.b[j] = o.b;
        q.c[j] = o.c;
        q.d[j] = o.d;
    })
}

pgloss_status pgloss_perceptual_from_physical_batch(size_t n, const pgloss_physical_array *p,
                                                    pgloss_perceptual_out q, signed char *status)
{
    return pgloss_perceptual_from_physical_batch_ex(n, p, PGLOSS_COLOR_SPACE_LINEAR_REC709, q,
                                                    status);
}

pgloss_status pgloss_rgb_from_lab_batch_ex(size_t n, pgloss_lab_array lab,
                                           pgloss_color_space space, pgloss_rgb_out_d rgb,
                                           signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!lab.L || !lab.a || !lab.b || !rgb.r || !rgb.g || !rgb.b)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    RUN_BATCH(n, status, {
        const double in[3] = {lab.L[j], lab.a[j], lab.b[j]};
        double out[3];
        *stj = (signed char)pgloss_rgb_from_lab_ex(in, space, out);
        rgb.r[j] = out[0];
        rgb.g[j] = out[1];
        rgb.b[j] = out[2];
    })
}

pgloss_status pgloss_rgb_from_lab_batch(size_t n, pgloss_lab_array lab, pgloss_rgb_out_d rgb,
                                        signed char *status)
{
    return pgloss_rgb_from_lab_batch_ex(n, lab, PGLOSS_COLOR_SPACE_LINEAR_REC709, rgb, status);
}

pgloss_status pgloss_lab_from_rgb_batch_ex(size_t n, pgloss_rgb_array_d rgb,
                                           pgloss_color_space space, pgloss_lab_out lab,
                                           signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!lab.L || !lab.a || !lab.b || !rgb.r || !rgb.g || !rgb.b)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    RUN_BATCH(n, status, {
        const double in[3] = {rgb.r[j], rgb.g[j], rgb.b[j]};
        double out[3];
        *stj = (signed char)pgloss_lab_from_rgb_ex(in, space, out);
        lab.L[j] = out[0];
        lab.a[j] = out[1];
        lab.b[j] = out[2];
    })
}

pgloss_status pgloss_lab_from_rgb_batch(size_t n, pgloss_rgb_array_d rgb, pgloss_lab_out lab,
                                        signed char *status)
{
    return pgloss_lab_from_rgb_batch_ex(n, rgb, PGLOSS_COLOR_SPACE_LINEAR_REC709, lab, status);
}
