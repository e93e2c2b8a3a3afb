// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss texture benchmark: whole textures of paints through the batched entry points of
 * pgloss/batch.h and pgloss/perceptual_batch.h, as paired comparisons (the two
 * sides of a row run alternately, repetition by repetition, and the median of each is
 * reported, so that a loaded host moves both alike):
 *   - eval_pdf with one material per element against the uniform-material batch (target <= 2x);
 *   - the double path against the float one, uniform and per element (target <= 2x);
 *   - the batched perceptual conversions, ns per element, with validity and statuses, next to
 *     a bare C loop of the same formulas without any check (eqs. 6-7 plus Lab -> RGB; eq. 4).
 * Prints Markdown tables.
 *   bench_texture [--quick]
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pgloss/pgloss.h"
#include "bench_clock.h"


typedef void (*bench_fn)(void *ctx);
static int g_reps = 15;
static size_t g_n = (size_t)1 << 16;

/* Median ns per element of a and b, run alternately g_reps times (one call each, after a
 * warm-up call). */
static void paired(bench_fn a, void *ca, bench_fn b, void *cb, double *na, double *nb)
{
    double ta[64], tb[64];
    a(ca);
    b(cb);
    for (int r = 0; r < g_reps; ++r) {
        double t0 = now_s();
        a(ca);
        ta[r] = now_s() - t0;
        t0 = now_s();
        b(cb);
        tb[r] = now_s() - t0;
    }
    qsort(ta, (size_t)g_reps, sizeof ta[0], cmp_double);
    qsort(tb, (size_t)g_reps, sizeof tb[0], cmp_double);
    *na = 1e9 * ta[g_reps / 2] / (double)g_n;
    *nb = 1e9 * tb[g_reps / 2] / (double)g_n;
}

static double urand(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

/* ---- the data: a texture of paints and a direction pair per texel ------------------------ */

typedef struct data {
    size_t n;
    float *m[6], *o[3], *i[3];
    double *md[6], *od[3], *id[3];
    pgloss_material mat;
    pgloss_batch_options opt;
    float *fr, *fg, *fb, *pdf;
    double *dr, *dg, *db, *dpdf;
    /* sampling: random numbers and the directions drawn */
    float *u[3], *sw[3];
    double *ud[3], *swd[3];
    unsigned char *lobe;
    /* perceptual */
    double *L, *a, *b, *c, *d, *out[6];
    signed char *status;
} data;

static void *xmalloc(size_t bytes)
{
    void *p = malloc(bytes);
    if (!p) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }
    return p;
}

static void make_data(data *D, size_t n)
{
    unsigned s = 12345u;
    D->n = n;
    for (int k = 0; k < 6; ++k) {
        D->m[k] = xmalloc(n * sizeof(float));
        D->md[k] = xmalloc(n * sizeof(double));
        D->out[k] = xmalloc(n * sizeof(double));
    }
    for (int k = 0; k < 3; ++k) {
        D->o[k] = xmalloc(n * sizeof(float));
        D->i[k] = xmalloc(n * sizeof(float));
        D->od[k] = xmalloc(n * sizeof(double));
        D->id[k] = xmalloc(n * sizeof(double));
    }
    D->fr = xmalloc(n * sizeof(float)), D->fg = xmalloc(n * sizeof(float));
    D->fb = xmalloc(n * sizeof(float)), D->pdf = xmalloc(n * sizeof(float));
    D->dr = xmalloc(n * sizeof(double)), D->dg = xmalloc(n * sizeof(double));
    D->db = xmalloc(n * sizeof(double)), D->dpdf = xmalloc(n * sizeof(double));
    D->L = xmalloc(n * sizeof(double)), D->a = xmalloc(n * sizeof(double));
    D->b = xmalloc(n * sizeof(double)), D->c = xmalloc(n * sizeof(double));
    D->d = xmalloc(n * sizeof(double));
    D->status = xmalloc(n);
    D->lobe = xmalloc(n);
    for (int k = 0; k < 3; ++k) {
        D->u[k] = xmalloc(n * sizeof(float)), D->sw[k] = xmalloc(n * sizeof(float));
        D->ud[k] = xmalloc(n * sizeof(double)), D->swd[k] = xmalloc(n * sizeof(double));
        for (size_t j = 0; j < n; ++j) {
            D->u[k][j] = (float)urand(&s);
            D->ud[k][j] = D->u[k][j];
        }
    }
    for (size_t j = 0; j < n; ++j) {
        const double v[6] = {0.05 + 0.6 * urand(&s), 0.05 + 0.6 * urand(&s), 0.05 + 0.6 * urand(&s),
                             0.1 * urand(&s), 0.02 + 0.2 * urand(&s), 0.0};
        for (int k = 0; k < 6; ++k) {
            D->m[k][j] = (float)(k == 5 ? v[4] : v[k]);
            D->md[k][j] = D->m[k][j];
        }
        /* wo over the hemisphere, wi near the mirror direction half the time (the lobe) */
        const double co = 0.05 + 0.95 * urand(&s), po = 6.283185307 * urand(&s);
        const double so = sqrt(1 - co * co);
        const double ox = so * cos(po), oy = so * sin(po), oz = co;
        double ix, iy, iz;
        if (j & 1) {
            const double ci = 0.05 + 0.95 * urand(&s), pi = 6.283185307 * urand(&s), si = sqrt(1 - ci * ci);
            ix = si * cos(pi), iy = si * sin(pi), iz = ci;
        } else {
            ix = -ox + 0.05 * (urand(&s) - 0.5), iy = -oy + 0.05 * (urand(&s) - 0.5), iz = oz;
            const double l = sqrt(ix * ix + iy * iy + iz * iz);
            ix /= l, iy /= l, iz /= l;
        }
        D->o[0][j] = (float)ox, D->o[1][j] = (float)oy, D->o[2][j] = (float)oz;
        D->i[0][j] = (float)ix, D->i[1][j] = (float)iy, D->i[2][j] = (float)iz;
        D->od[0][j] = ox, D->od[1][j] = oy, D->od[2][j] = oz;
        D->id[0][j] = ix, D->id[1][j] = iy, D->id[2][j] = iz;
        /* paints inside gloss space: L* 20..90, small chroma, c below the envelope, d 0.8..1 */
        D->L[j] = 20 + 70 * urand(&s);
        D->a[j] = 20 * (urand(&s) - 0.5);
        D->b[j] = 20 * (urand(&s) - 0.5);
        D->c[j] = 0.08 * urand(&s);
        D->d[j] = 0.8 + 0.19 * urand(&s);
    }
    const pgloss_physical p = {{0.4, 0.3, 0.2}, 0.05, 0.08, 0.08, PGLOSS_NORM_WARD};
    pgloss_material_init(&D->mat, &p);
    D->opt.precision = PGLOSS_PRECISION_FLOAT;
    D->opt.isa = PGLOSS_ISA_AUTO;
    D->opt.scalar = PGLOSS_FLOAT32;
}

#define F32 sizeof(float)
#define F64 sizeof(double)
static const pgloss_batch_options f64_opt = {PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO, PGLOSS_FLOAT64};

/* The texture's materials as strided columns: the float ones (m), else the double ones. */
static pgloss_physical_array mats_of(float *const *m, double *const *md)
{
    const size_t z = m ? F32 : F64;
    const void *c[6];
    for (int k = 0; k < 6; ++k)
        c[k] = m ? (const void *)m[k] : (const void *)md[k];
    const pgloss_physical_array a = {pgloss_strided3_soa(c[0], c[1], c[2], z), pgloss_strided_of(c[3], (ptrdiff_t)z),
                                     pgloss_strided_of(c[4], (ptrdiff_t)z), pgloss_strided_of(c[5], (ptrdiff_t)z),
                                     PGLOSS_NORM_WARD};
    return a;
}

/* eval_pdf of the texture: float or double, one material (D->mat) or one per element. */
static void eval_texture(data *D, int f64, int per_element)
{
    const size_t z = f64 ? F64 : F32;
    const void *o[3], *i[3];
    void *f[3];
    for (int k = 0; k < 3; ++k) {
        o[k] = f64 ? (const void *)D->od[k] : (const void *)D->o[k];
        i[k] = f64 ? (const void *)D->id[k] : (const void *)D->i[k];
    }
    f[0] = f64 ? (void *)D->dr : (void *)D->fr;
    f[1] = f64 ? (void *)D->dg : (void *)D->fg;
    f[2] = f64 ? (void *)D->db : (void *)D->fb;
    const pgloss_physical_array m = mats_of(f64 ? NULL : D->m, D->md);
    pgloss_eval_pdf_batch(f64 ? &f64_opt : &D->opt, per_element ? NULL : &D->mat, per_element ? &m : NULL,
                          PGLOSS_LOBE_ALL, D->n, pgloss_strided3_soa(o[0], o[1], o[2], z),
                          pgloss_strided3_soa(i[0], i[1], i[2], z), pgloss_strided3_out_soa(f[0], f[1], f[2], z),
                          pgloss_strided_out_of(f64 ? (void *)D->dpdf : (void *)D->pdf, (ptrdiff_t)z), NULL);
}

/* sample of the texture, as eval_texture. */
static void sample_texture(data *D, int f64, int per_element)
{
    const size_t z = f64 ? F64 : F32;
    const void *o[3], *u[3];
    void *w[3], *g[3];
    for (int k = 0; k < 3; ++k) {
        o[k] = f64 ? (const void *)D->od[k] : (const void *)D->o[k];
        u[k] = f64 ? (const void *)D->ud[k] : (const void *)D->u[k];
        w[k] = f64 ? (void *)D->swd[k] : (void *)D->sw[k];
    }
    g[0] = f64 ? (void *)D->dr : (void *)D->fr;
    g[1] = f64 ? (void *)D->dg : (void *)D->fg;
    g[2] = f64 ? (void *)D->db : (void *)D->fb;
    const pgloss_physical_array m = mats_of(f64 ? NULL : D->m, D->md);
    pgloss_sample_batch(f64 ? &f64_opt : &D->opt, per_element ? NULL : &D->mat, per_element ? &m : NULL,
                        PGLOSS_LOBE_ALL, D->n, pgloss_strided3_soa(o[0], o[1], o[2], z),
                        pgloss_strided3_soa(u[0], u[1], u[2], z), pgloss_strided3_out_soa(w[0], w[1], w[2], z),
                        pgloss_strided_out_of(f64 ? (void *)D->dpdf : (void *)D->pdf, (ptrdiff_t)z),
                        pgloss_strided3_out_soa(g[0], g[1], g[2], z), D->lobe, NULL);
}

static void run_uniform_f(void *ctx) { eval_texture(ctx, 0, 0); }
static void run_materials_f(void *ctx) { eval_texture(ctx, 0, 1); }
static void run_uniform_d(void *ctx) { eval_texture(ctx, 1, 0); }
static void run_materials_d(void *ctx) { eval_texture(ctx, 1, 1); }
static void run_sample_f(void *ctx) { sample_texture(ctx, 0, 0); }
static void run_sample_d(void *ctx) { sample_texture(ctx, 1, 0); }
static void run_sample_materials_f(void *ctx) { sample_texture(ctx, 0, 1); }
static void run_sample_materials_d(void *ctx) { sample_texture(ctx, 1, 1); }

/* ---- perceptual ---------------------------------------------------------------------------- */

static pgloss_strided col(const double *p) { return pgloss_strided_of(p, F64); }
static pgloss_strided_out col_out(double *p) { return pgloss_strided_out_of(p, F64); }

static pgloss_perceptual_array perceptual_of(const data *D)
{
    const pgloss_perceptual_array q = {col(D->L), col(D->a), col(D->b), col(D->c), col(D->d)};
    return q;
}


static void run_pfp(void *ctx)
{
    data *D = ctx;
    const pgloss_perceptual_array q = perceptual_of(D);
    const pgloss_physical_array_out p = {pgloss_strided3_out_soa(D->out[0], D->out[1], D->out[2], F64),
                                         col_out(D->out[3]), col_out(D->out[4]), {NULL, 0}};
    pgloss_physical_from_perceptual_batch(D->n, &q, PGLOSS_NORM_WARD, PGLOSS_COLOR_SPACE_LINEAR_REC709, &p,
                                          D->status);
}

static void run_check_perceptual(void *ctx)
{
    data *D = ctx;
    const pgloss_perceptual_array q = perceptual_of(D);
    pgloss_check_perceptual_batch(D->n, &q, PGLOSS_COLOR_SPACE_LINEAR_REC709, D->status);
}

/* eqs. 6-7 and CIELAB -> linear Rec. 709 without a check: what a numpy user writes. */
static void run_bare_pfp(void *ctx)
{
    data *D = ctx;
    const double M[3][3] = {{3.2409699419045213, -1.5373831775700935, -0.49861076029300328},
                            {-0.96924363628087983, 1.8759675015077207, 0.041555057407175613},
                            {0.055630079696993608, -0.20397695888897656, 1.0569715142428786}};
    const double wx = 0.3127 / 0.3290, wz = 0.3583 / 0.3290, dl = 6.0 / 29.0;
    for (size_t j = 0; j < D->n; ++j) {
        const double fy = (D->L[j] + 16.0) / 116.0, fx = fy + D->a[j] / 500.0, fz = fy - D->b[j] / 200.0;
        const double x = wx * (fx > dl ? fx * fx * fx : 3 * dl * dl * (fx - 4.0 / 29.0));
        const double y = D->L[j] > 8.0 ? fy * fy * fy : D->L[j] / (24389.0 / 27.0);
        const double z = wz * (fz > dl ? fz * fz * fz : 3 * dl * dl * (fz - 4.0 / 29.0));
        for (int k = 0; k < 3; ++k)
            D->out[k][j] = M[k][0] * x + M[k][1] * y + M[k][2] * z;
        const double bb = cbrt(0.5 * y), c = D->c[j];
        D->out[3][j] = c * (c * c + 3 * c * bb + 3 * bb * bb);
        D->out[4][j] = 1.0 - D->d[j];
    }
}

static void run_gfp(void *ctx)
{
    data *D = ctx;
    /* ρd: the texture's diffuse red channel as an achromatic ρd, ρs, α */
    pgloss_gloss_from_physical_batch(D->n, col(D->md[0]), col(D->md[3]), col(D->md[4]), col_out(D->out[0]),
                                     col_out(D->out[1]), col_out(D->out[2]), D->status);
}

static void run_bare_gfp(void *ctx)
{
    data *D = ctx;
    for (size_t j = 0; j < D->n; ++j) {
        const double rd = D->md[0][j], rs = D->md[3][j];
        D->out[1][j] = cbrt(rs + 0.5 * rd) - cbrt(0.5 * rd); /* eq. 4 */
        D->out[0][j] = 116.0 * cbrt(rd) - 16.0;
        D->out[2][j] = 1.0 - D->md[4][j];
    }
}

static void run_rgb_from_lab(void *ctx)
{
    data *D = ctx;
    pgloss_rgb_from_lab_batch(D->n, pgloss_strided3_soa(D->L, D->a, D->b, F64), PGLOSS_COLOR_SPACE_LINEAR_REC709,
                              pgloss_strided3_out_soa(D->out[0], D->out[1], D->out[2], F64), D->status);
}

static void run_perceptual_from_physical(void *ctx)
{
    data *D = ctx;
    const pgloss_physical_array m = mats_of(NULL, D->md);
    const pgloss_perceptual_array_out q = {col_out(D->out[0]), col_out(D->out[1]), col_out(D->out[2]),
                                           col_out(D->out[3]), col_out(D->out[4])};
    pgloss_perceptual_from_physical_batch(D->n, &m, PGLOSS_COLOR_SPACE_LINEAR_REC709, &q, D->status);
}

static void run_lab_from_rgb(void *ctx)
{
    data *D = ctx;
    pgloss_lab_from_rgb_batch(D->n, pgloss_strided3_soa(D->md[0], D->md[1], D->md[2], F64),
                              PGLOSS_COLOR_SPACE_LINEAR_REC709,
                              pgloss_strided3_out_soa(D->out[0], D->out[1], D->out[2], F64), D->status);
}

static void run_check_physical(void *ctx)
{
    data *D = ctx;
    const pgloss_physical_array m = mats_of(NULL, D->md);
    pgloss_check_physical_batch(D->n, &m, D->status);
}

static void run_physical_from_gloss(void *ctx)
{
    data *D = ctx;
    pgloss_physical_from_gloss_batch(D->n, col(D->L), col(D->c), col(D->d), col_out(D->out[0]), col_out(D->out[1]),
                                     col_out(D->out[2]), D->status);
}

static void run_envelope(void *ctx)
{
    data *D = ctx;
    pgloss_envelope_contrast_batch(D->n, col(D->L), col_out(D->out[0]), D->status);
}

static void run_match_gloss(void *ctx)
{
    data *D = ctx;
    pgloss_match_gloss_batch(D->n, col(D->md[0]), col(D->md[3]), col(D->L), col_out(D->out[0]), col_out(D->out[1]),
                             D->status);
}

int main(int argc, char **argv)
{
    for (int k = 1; k < argc; ++k)
        if (!strcmp(argv[k], "--n") && k + 1 < argc) {
            g_n = (size_t)strtoull(argv[++k], NULL, 10);
        } else if (!strcmp(argv[k], "--quick")) {
            g_reps = 5;
            g_n = (size_t)1 << 14;
        }
    data D;
    make_data(&D, g_n);
    printf("n = %zu texels per call (SoA columns), ISA %s, median of %d paired repetitions (ns per texel).\n\n", g_n,
           pgloss_isa_name(pgloss_isa_best()), g_reps);
    double a, b;
    printf("| eval_pdf (f and pdf), WARD | A ns | B ns | B / A |\n|---|---:|---:|---:|\n");
    paired(run_uniform_f, &D, run_materials_f, &D, &a, &b);
    printf("| float: A uniform material, B one material per texel | %.2f | %.2f | %.2f |\n", a, b, b / a);
    paired(run_uniform_f, &D, run_uniform_d, &D, &a, &b);
    printf("| uniform material: A float, B double | %.2f | %.2f | %.2f |\n", a, b, b / a);
    paired(run_materials_f, &D, run_materials_d, &D, &a, &b);
    printf("| one material per texel: A float, B double | %.2f | %.2f | %.2f |\n", a, b, b / a);
    paired(run_uniform_f, &D, run_materials_d, &D, &a, &b);
    printf("| A float uniform, B double per texel | %.2f | %.2f | %.2f |\n\n", a, b, b / a);

    printf("| sample (wi, pdf, weight, lobe), WARD | A ns | B ns | B / A |\n|---|---:|---:|---:|\n");
    paired(run_sample_f, &D, run_sample_d, &D, &a, &b);
    printf("| uniform material: A float, B double | %.2f | %.2f | %.2f |\n", a, b, b / a);
    paired(run_sample_materials_f, &D, run_sample_materials_d, &D, &a, &b);
    printf("| one material per texel: A float, B double | %.2f | %.2f | %.2f |\n\n", a, b, b / a);

    printf("| perceptual (double) | A: pgloss batch, ns | B: bare C loop, no checks, ns | A / B |\n|---|---:|---:|---:|\n");
    paired(run_pfp, &D, run_bare_pfp, &D, &a, &b);
    printf("| physical_from_perceptual_batch (validity, statuses) vs eqs. 6-7 + Lab->RGB | %.2f | %.2f | %.2f |\n", a, b,
           a / b);
    paired(run_gfp, &D, run_bare_gfp, &D, &a, &b);
    printf("| gloss_from_physical_batch vs eq. 4 + L* + eq. 3 | %.2f | %.2f | %.2f |\n", a, b, a / b);
    paired(run_check_perceptual, &D, run_rgb_from_lab, &D, &a, &b);
    printf("| check_perceptual_batch (A) and rgb_from_lab_batch (B) | %.2f | %.2f | %.2f |\n", a, b, a / b);
    paired(run_perceptual_from_physical, &D, run_lab_from_rgb, &D, &a, &b);
    printf("| perceptual_from_physical_batch (A) and lab_from_rgb_batch (B) | %.2f | %.2f | %.2f |\n", a, b, a / b);
    paired(run_check_physical, &D, run_physical_from_gloss, &D, &a, &b);
    printf("| check_physical_batch (A) and physical_from_gloss_batch (B) | %.2f | %.2f | %.2f |\n", a, b, a / b);
    paired(run_envelope, &D, run_match_gloss, &D, &a, &b);
    printf("| envelope_contrast_batch (A) and match_gloss_batch (B) | %.2f | %.2f | %.2f |\n", a, b, a / b);
    return 0;
}
