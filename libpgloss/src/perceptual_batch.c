// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The batched perceptual and colour functions (pgloss/perceptual_batch.h): argument checks,
 * then one driver (run) over chunks of elements, each function giving the code of a chunk.
 * Every function runs the vectorised loops of perceptual_batch_isa.c, on the best ISA of the
 * running CPU (pgloss_isa_best): the per-element code of the scalar functions
 * (perceptual_d.h), so that element j gets the scalar function's status and outputs, bit for
 * bit. */
#include "internal.h"
#include "perceptual_batch_isa.h"
#include "perceptual_d.h"
#include "pgloss/batch.h"
#include "pgloss/perceptual_batch.h"

/* The returned status: first error, else first warning, else OK (perceptual_batch.h). */
typedef struct summary {
    pgloss_status error, warning;
} summary;

/* Folds a chunk's statuses into s. The common case (no error) is a min/max pass that
 * vectorises; the first error or warning is searched for only when there is one. */
static void note_chunk(summary *s, size_t m, const signed char *st)
{
    int lo = 0, hi = 0;
    for (size_t j = 0; j < m; ++j) {
        lo = st[j] < lo ? st[j] : lo;
        hi = st[j] > hi ? st[j] : hi;
    }
    if (lo < 0) {
        for (size_t j = 0; j < m; ++j)
            if (st[j] < 0) {
                s->error = (pgloss_status)st[j];
                break;
            }
    } else if (hi > 0 && s->warning == PGLOSS_OK) {
        for (size_t j = 0; j < m; ++j)
            if (st[j] > 0) {
                s->warning = (pgloss_status)st[j];
                break;
            }
    }
}

#define CHUNK 4096

/* Writes the statuses of elements [base, base + m) to st (and the outputs). */
typedef void (*chunk_fn)(const void *ctx, size_t base, size_t m, signed char *st);

/* Runs f over [0, n) chunk by chunk, the statuses into status or, if NULL, a chunk buffer;
 * returns the summary. Stops summarising, not computing, at the first error. */
static pgloss_status run(size_t n, signed char *status, chunk_fn f, const void *ctx)
{
    summary s = {PGLOSS_OK, PGLOSS_OK};
    signed char buf[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        signed char *st = status ? status + base : buf;
        f(ctx, base, m, st);
        if (s.error == PGLOSS_OK)
            note_chunk(&s, m, st);
    }
    return s.error != PGLOSS_OK ? s.error : s.warning;
}

/* The ISA of the vectorised loops: the best the CPU runs among those built. */
#define PICK_LOOP(name)                                                                            \
    pick_isa() == PGLOSS_ISA_AVX512 ? PICK_AVX512(name)                                            \
    : pick_isa() == PGLOSS_ISA_AVX2 ? PICK_AVX2(name) : name##_baseline
#if defined(PGLOSS_HAVE_AVX512)
#define PICK_AVX512(name) name##_avx512
#else
#define PICK_AVX512(name) name##_baseline
#endif
#if defined(PGLOSS_HAVE_AVX2)
#define PICK_AVX2(name) name##_avx2
#else
#define PICK_AVX2(name) name##_baseline
#endif

static pgloss_isa pick_isa(void)
{
    return pgloss_isa_best();
}

/* ---- gloss space (eqs. 3–8) ------------------------------------------------------------- */

/* Up to three inputs and three outputs of one element-wise function, and its loop. */
typedef void (*loop3_fn)(size_t, const double *, const double *, const double *, double *,
                         double *, double *, signed char *);
typedef struct cols {
    const double *x0, *x1, *x2;
    double *y0, *y1, *y2;
    loop3_fn loop3;
    void (*envelope_loop)(size_t, const double *, double *, signed char *);
    void (*match_loop)(size_t, const double *, const double *, const double *, double *,
                       double *, signed char *);
} cols;

static void loop3_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const cols *k = ctx;
    k->loop3(m, k->x0 + b, k->x1 + b, k->x2 + b, k->y0 + b, k->y1 + b, k->y2 + b, st);
}

pgloss_status pgloss_gloss_from_physical_batch(size_t n, const double *rho_d, const double *rho_s,
                                               const double *alpha, double *L, double *c,
                                               double *d, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!rho_d || !rho_s || !alpha || !L || !c || !d)
        return PGLOSS_ERR_NULL;
    const cols k = {rho_d, rho_s, alpha, L, c, d, PICK_LOOP(pgloss__gloss_from_physical_loop),
                    NULL, NULL};
    return run(n, status, loop3_chunk, &k);
}

pgloss_status pgloss_physical_from_gloss_batch(size_t n, const double *L, const double *c,
                                               const double *d, double *rho_d, double *rho_s,
                                               double *alpha, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!L || !c || !d || !rho_d || !rho_s || !alpha)
        return PGLOSS_ERR_NULL;
    const cols k = {L, c, d, rho_d, rho_s, alpha, PICK_LOOP(pgloss__physical_from_gloss_loop),
                    NULL, NULL};
    return run(n, status, loop3_chunk, &k);
}

static void envelope_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const cols *k = ctx;
    k->envelope_loop(m, k->x0 + b, k->y0 + b, st);
}

pgloss_status pgloss_envelope_contrast_batch(size_t n, const double *L, double *c_max,
                                             signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!L || !c_max)
        return PGLOSS_ERR_NULL;
    const cols k = {L, NULL, NULL, c_max, NULL, NULL, NULL,
                    PICK_LOOP(pgloss__envelope_contrast_loop), NULL};
    return run(n, status, envelope_chunk, &k);
}

static void match_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const cols *k = ctx;
    k->match_loop(m, k->x0 + b, k->x1 + b, k->x2 + b, k->y0 + b, k->y1 + b, st);
}

pgloss_status pgloss_match_gloss_batch(size_t n, const double *rho_d, const double *rho_s,
                                       const double *L_target, double *rho_d_out,
                                       double *rho_s_out, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!rho_d || !rho_s || !L_target || !rho_d_out || !rho_s_out)
        return PGLOSS_ERR_NULL;
    const cols k = {rho_d, rho_s, L_target, rho_d_out, rho_s_out, NULL, NULL, NULL,
                    PICK_LOOP(pgloss__match_gloss_loop)};
    return run(n, status, match_chunk, &k);
}

/* ---- parameter sets (Fig. 13) ------------------------------------------------------------ */

static int physical_array_ok(const pgloss_physical_array *p)
{
    return p && p->rho_d_r && p->rho_d_g && p->rho_d_b && p->rho_s && p->alpha_x;
}

/* The arrays from element b on (alpha_y NULL stays NULL: isotropic). */
static pgloss_physical_array physical_from(const pgloss_physical_array *p, size_t b)
{
    const pgloss_physical_array r = {p->rho_d_r + b, p->rho_d_g + b, p->rho_d_b + b,
                                     p->rho_s + b, p->alpha_x + b,
                                     p->alpha_y ? p->alpha_y + b : NULL, p->normalization};
    return r;
}

static int perceptual_array_ok(pgloss_perceptual_array q)
{
    return q.L && q.a && q.b && q.c && q.d;
}

/* The arrays and options of one call over parameter sets or colours. */
typedef struct sets {
    const pgloss_physical_array *p;
    pgloss_perceptual_array q;
    pgloss_color_space space;
    pgloss_physical_out p_out;
    pgloss_perceptual_out q_out;
    const double *in[3]; /* colour: L*, a*, b* or r, g, b */
    double *out[3];
    void (*physical_loop)(size_t, pgloss_perceptual_array, const double *, pgloss_physical_out,
                          signed char *);
    void (*check_physical_loop)(size_t, pgloss_physical_array, double, signed char *);
    void (*check_perceptual_loop)(size_t, pgloss_perceptual_array, const double *,
                                  signed char *);
    void (*perceptual_loop)(size_t, pgloss_physical_array, const double *, pgloss_perceptual_out,
                            signed char *);
    void (*rgb_loop)(size_t, pgloss_lab_array, const double *, pgloss_rgb_out_d, signed char *);
    void (*lab_loop)(size_t, pgloss_rgb_array_d, const double *, pgloss_lab_out, signed char *);
} sets;

static void check_physical_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    const double norm_ok = pgloss__valid_normalization(k->p->normalization);
    k->check_physical_loop(m, physical_from(k->p, b), norm_ok, st);
}

pgloss_status pgloss_check_physical_batch(size_t n, const pgloss_physical_array *p,
                                          signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!physical_array_ok(p))
        return PGLOSS_ERR_NULL;
    const sets k = {.p = p, .check_physical_loop = PICK_LOOP(pgloss__check_physical_loop)};
    return run(n, status, check_physical_chunk, &k);
}

static pgloss_perceptual_array perceptual_from(pgloss_perceptual_array q, size_t b)
{
    const pgloss_perceptual_array r = {q.L + b, q.a + b, q.b + b, q.c + b, q.d + b};
    return r;
}

static void check_perceptual_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    k->check_perceptual_loop(m, perceptual_from(k->q, b), pgloss__from_xyz_matrix(k->space), st);
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
    const sets k = {.q = q, .space = space,
                    .check_perceptual_loop = PICK_LOOP(pgloss__check_perceptual_loop)};
    return run(n, status, check_perceptual_chunk, &k);
}

pgloss_status pgloss_check_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                            signed char *status)
{
    return pgloss_check_perceptual_batch_ex(n, q, PGLOSS_COLOR_SPACE_LINEAR_REC709, status);
}

static void physical_from_perceptual_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    const pgloss_physical_out o = k->p_out;
    const pgloss_physical_out ob = {o.rho_d_r + b, o.rho_d_g + b, o.rho_d_b + b, o.rho_s + b,
                                    o.alpha_x + b, o.alpha_y ? o.alpha_y + b : NULL};
    k->physical_loop(m, perceptual_from(k->q, b), pgloss__from_xyz_matrix(k->space), ob, st);
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
    if (!pgloss__valid_normalization(normalization))
        return PGLOSS_ERR_NORMALIZATION;
    const sets k = {.q = q, .space = space, .p_out = p,
                    .physical_loop = PICK_LOOP(pgloss__physical_from_perceptual_loop)};
    return run(n, status, physical_from_perceptual_chunk, &k);
}

pgloss_status pgloss_physical_from_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                                    pgloss_normalization normalization,
                                                    pgloss_physical_out p, signed char *status)
{
    return pgloss_physical_from_perceptual_batch_ex(n, q, normalization,
                                                    PGLOSS_COLOR_SPACE_LINEAR_REC709, p, status);
}

static void perceptual_from_physical_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    const pgloss_perceptual_out q = k->q_out;
    const pgloss_perceptual_out qb = {q.L + b, q.a + b, q.b + b, q.c + b, q.d + b};
    k->perceptual_loop(m, physical_from(k->p, b), pgloss__to_xyz_matrix(k->space), qb, st);
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
    const sets k = {.p = p, .space = space, .q_out = q,
                    .perceptual_loop = PICK_LOOP(pgloss__perceptual_from_physical_loop)};
    return run(n, status, perceptual_from_physical_chunk, &k);
}

pgloss_status pgloss_perceptual_from_physical_batch(size_t n, const pgloss_physical_array *p,
                                                    pgloss_perceptual_out q, signed char *status)
{
    return pgloss_perceptual_from_physical_batch_ex(n, p, PGLOSS_COLOR_SPACE_LINEAR_REC709, q,
                                                    status);
}

/* ---- colour ------------------------------------------------------------------------------- */

/* The two colour conversions: three arrays in, three out, a working space. */
static pgloss_status colour_batch(size_t n, const double *in0, const double *in1,
                                  const double *in2, double *out0, double *out1, double *out2,
                                  pgloss_color_space space, signed char *status, chunk_fn f)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!in0 || !in1 || !in2 || !out0 || !out1 || !out2)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    const sets k = {.space = space, .in = {in0, in1, in2}, .out = {out0, out1, out2},
                    .rgb_loop = PICK_LOOP(pgloss__rgb_from_lab_loop),
                    .lab_loop = PICK_LOOP(pgloss__lab_from_rgb_loop)};
    return run(n, status, f, &k);
}

static void rgb_from_lab_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    const pgloss_lab_array in = {k->in[0] + b, k->in[1] + b, k->in[2] + b};
    const pgloss_rgb_out_d out = {k->out[0] + b, k->out[1] + b, k->out[2] + b};
    k->rgb_loop(m, in, pgloss__from_xyz_matrix(k->space), out, st);
}

static void lab_from_rgb_chunk(const void *ctx, size_t b, size_t m, signed char *st)
{
    const sets *k = ctx;
    const pgloss_rgb_array_d in = {k->in[0] + b, k->in[1] + b, k->in[2] + b};
    const pgloss_lab_out out = {k->out[0] + b, k->out[1] + b, k->out[2] + b};
    k->lab_loop(m, in, pgloss__to_xyz_matrix(k->space), out, st);
}

pgloss_status pgloss_rgb_from_lab_batch_ex(size_t n, pgloss_lab_array lab,
                                           pgloss_color_space space, pgloss_rgb_out_d rgb,
                                           signed char *status)
{
    return colour_batch(n, lab.L, lab.a, lab.b, rgb.r, rgb.g, rgb.b, space, status,
                        rgb_from_lab_chunk);
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
    return colour_batch(n, rgb.r, rgb.g, rgb.b, lab.L, lab.a, lab.b, space, status,
                        lab_from_rgb_chunk);
}

pgloss_status pgloss_lab_from_rgb_batch(size_t n, pgloss_rgb_array_d rgb, pgloss_lab_out lab,
                                        signed char *status)
{
    return pgloss_lab_from_rgb_batch_ex(n, rgb, PGLOSS_COLOR_SPACE_LINEAR_REC709, lab, status);
}
