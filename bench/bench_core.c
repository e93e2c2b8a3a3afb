// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss core benchmark: run time against error for every evaluation path.
 *
 * Prints Markdown tables (the body of BENCHMARKS.md's C section): for eval, pdf, eval_pdf and
 * sample, scalar and batched, in each accuracy tier and on each instruction set the CPU has,
 * the median ns per call and the max / mean relative error against an independent
 * long-double transcription of eq. 2 and Walter's pdf on the same inputs; the batch-size
 * sweep; what lobe masks save; and the perceptual conversions against long-double formulas.
 *
 * Inputs are what a renderer feeds a BRDF: wo uniform over the hemisphere (cosθo >= 0.05),
 * wi drawn by pgloss_sample itself, so the specular lobe is exercised where it matters
 * (errors are measured on the regular range: specular exponent tan²δ/α² <= 10).
 *   bench_core [--quick] [--csv FILE]
 */
#define _POSIX_C_SOURCE 199309L
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pgloss/pgloss.h"
#include "bench_clock.h"

#define PI_L 3.141592653589793238462643383279502884L

/* ---- timing -------------------------------------------------------------------------- */


static int g_reps = 9;         /* repetitions; the median is reported */
static double g_min_time = 0.02; /* seconds per repetition at least */
static volatile float g_sink;

typedef void (*bench_fn)(void *ctx);

/* Median over g_reps repetitions of the time per call of fn, each repetition running fn
 * enough times to last g_min_time; returns seconds per fn call. */
static double time_median(bench_fn fn, void *ctx)
{
    long iters = 1;
    for (;;) {
        const double t0 = now_s();
        for (long i = 0; i < iters; ++i)
            fn(ctx);
        const double dt = now_s() - t0;
        if (dt >= g_min_time || iters > (1L << 30))
            break;
        iters = dt > 0 ? (long)(iters * fmin(100.0, 1.2 * g_min_time / dt)) + 1 : iters * 10;
    }
    double t[64];
    for (int r = 0; r < g_reps; ++r) {
        const double t0 = now_s();
        for (long i = 0; i < iters; ++i)
            fn(ctx);
        t[r] = (now_s() - t0) / (double)iters;
    }
    qsort(t, (size_t)g_reps, sizeof t[0], cmp_double);
    return t[g_reps / 2];
}

/* ---- the independent reference (long double, straight from the formulas) -------------- */

typedef struct ref_material {
    long double rd[3], rs, ax, ay;
    int norm;
    long double ps; /* specular-lobe probability for the full mask */
} ref_material;

static ref_material ref_from(const pgloss_material *m)
{
    ref_material r;
    for (int c = 0; c < 3; ++c)
        r.rd[c] = m->rho_d[c];
    r.rs = m->rho_s;
    r.ax = m->alpha_x;
    r.ay = m->alpha_y;
    r.norm = (int)m->normalization;
    /* Lobe selection by albedo: luminance of ρd against ρs. The weights are the model's
     * definition (pgloss/color.h), not part of what the reference checks. */
    const long double wd = PGLOSS_LUMA_R * r.rd[0] + PGLOSS_LUMA_G * r.rd[1] + PGLOSS_LUMA_B * r.rd[2];
    r.ps = (wd + r.rs) > 0 ? r.rs / (wd + r.rs) : 0;
    return r;
}

static void ref_unit(const float v[3], long double u[3])
{
    const long double l = sqrtl((long double)v[0] * v[0] + (long double)v[1] * v[1] +
                                (long double)v[2] * v[2]);
    for (int k = 0; k < 3; ++k)
        u[k] = v[k] / l;
}

/* Eq. 2 (and its two later normalisations) and Walter's mixture pdf, for the lobes in mask. */
/* The regular range of the error statistics: specular exponent tan²δ/α² <= REGULAR_X, i.e.
 * exp(-x) >= 4.5e-5 of the peak, where 99.995 % of the lobe's energy lies. Beyond it the
 * relative error of any float exp grows as x times its argument's rounding (conditioning). */
#define REGULAR_X 10.0L
static long double g_last_x; /* the exponent of the last ref_eval_pdf call (0: no specular) */

static void ref_eval_pdf(const ref_material *r, unsigned mask, const float wo[3],
                         const float wi[3], long double f[3], long double *pdf)
{
    g_last_x = 0;
    long double o[3], i[3];
    ref_unit(wo, o);
    ref_unit(wi, i);
    f[0] = f[1] = f[2] = 0;
    *pdf = 0;
    if (!(o[2] > 0 && i[2] > 0))
        return;
    const int has_d = (mask & 1) && (r->rd[0] > 0 || r->rd[1] > 0 || r->rd[2] > 0);
    const int has_s = (mask & 2) && r->rs > 0;
    long double ps = has_d && has_s ? r->ps : (has_s ? 1 : 0);
    if (has_d) {
        for (int c = 0; c < 3; ++c)
            f[c] += r->rd[c] / PI_L;
        *pdf += (1 - ps) * i[2] / PI_L;
    }
    if (has_s) {
        long double h[3] = {o[0] + i[0], o[1] + i[1], o[2] + i[2]};
        const long double hl = sqrtl(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        for (int k = 0; k < 3; ++k)
            h[k] /= hl;
        const long double t2 = ((h[0] / r->ax) * (h[0] / r->ax) + (h[1] / r->ay) * (h[1] / r->ay)) /
                               (h[2] * h[2]);
        const long double e = expl(-t2);
        g_last_x = t2;
        long double fs;
        if (r->norm == PGLOSS_NORM_WARD_DUR)
            fs = r->rs * e / (4 * PI_L * r->ax * r->ay * i[2] * o[2]);
        else if (r->norm == PGLOSS_NORM_BOUNDED)
            fs = r->rs * e / (PI_L * r->ax * r->ay * powl(h[2], 4)) ; /* (h·h)/hz⁴ for unit h */
        else
            fs = r->rs * e / (4 * PI_L * r->ax * r->ay * sqrtl(i[2] * o[2]));
        for (int c = 0; c < 3; ++c)
            f[c] += fs;
        const long double oh = o[0] * h[0] + o[1] * h[1] + o[2] * h[2];
        *pdf += ps * e / (4 * PI_L * r->ax * r->ay * oh * h[2] * h[2] * h[2]);
    }
}

/* ---- error accumulation -------------------------------------------------------------- */

typedef struct err_acc { double max, sum; long n; } err_acc;

static void err_add(err_acc *a, double got, long double want, long double floor)
{
    if (fabsl(want) < floor)
        return;
    const double e = (double)(fabsl((long double)got - want) / fabsl(want));
    if (e > a->max)
        a->max = e;
    a->sum += e;
    a->n++;
}

/* ---- the inputs ------------------------------------------------------------------------ */

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static float rnd(void) /* uniform [0, 1), 24 bits */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (float)(rng_state >> 40) * 0x1p-24f;
}

typedef struct inputs {
    size_t n;
    float *ox, *oy, *oz, *ix, *iy, *iz, *u0, *u1, *u2;
    /* outputs */
    float *fr, *fg, *fb, *pdf, *wx, *wy, *wz;
    unsigned char *lobe;
} inputs;

static float *falloc(size_t n)
{
    float *p = aligned_alloc(64, ((n * sizeof(float) + 63) / 64) * 64);
    if (!p) {
        fprintf(stderr, "bench_core: out of memory\n");
        exit(1);
    }
    memset(p, 0, n * sizeof(float));
    return p;
}

static void make_inputs(inputs *in, size_t n, const pgloss_material *m)
{
    in->n = n;
    float **all[] = {&in->ox, &in->oy, &in->oz, &in->ix, &in->iy, &in->iz, &in->u0, &in->u1,
                     &in->u2, &in->fr, &in->fg, &in->fb, &in->pdf, &in->wx, &in->wy, &in->wz};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k)
        *all[k] = falloc(n);
    in->lobe = malloc(n);
    for (size_t j = 0; j < n; ++j) {
        /* wo: uniform solid angle with cosθo in [0.05, 1]. */
        const float z = 0.05f + 0.95f * rnd(), phi = 6.2831853f * rnd();
        const float s = sqrtf(1.0f - z * z);
        in->ox[j] = s * cosf(phi);
        in->oy[j] = s * sinf(phi);
        in->oz[j] = z;
        in->u0[j] = rnd();
        in->u1[j] = rnd();
        in->u2[j] = rnd();
        /* wi: drawn by the reference sampler; redraw until it is above the horizon. */
        for (int tries = 0;; ++tries) {
            const pgloss_vec3 o = {in->ox[j], in->oy[j], in->oz[j]};
            const float u[3] = {rnd(), rnd(), rnd()};
            pgloss_sample_record rec;
            pgloss_sample(m, o, u, PGLOSS_LOBE_ALL, &rec);
            if (rec.pdf > 0 || tries > 100) {
                in->ix[j] = rec.pdf > 0 ? rec.wi.x : 0.0f;
                in->iy[j] = rec.pdf > 0 ? rec.wi.y : 0.0f;
                in->iz[j] = rec.pdf > 0 ? rec.wi.z : 1.0f;
                break;
            }
        }
    }
}

/* ---- the paths under test --------------------------------------------------------------- */

enum fn_kind { FN_EVAL, FN_PDF, FN_EVAL_PDF, FN_SAMPLE, FN_COUNT };
static const char *fn_name[] = {"eval", "pdf", "eval_pdf", "sample"};

typedef struct ctx {
    const pgloss_material *m;
    unsigned lobes;
    inputs *in;
    size_t n;
    int fn;
    int scalar;                  /* 1: the scalar API, one call per element; 2: an empty call */
    pgloss_batch_options opt;
} ctx;

/* A function of pgloss_eval's signature that does nothing: what the scalar loop costs
 * without any evaluation (call, arguments, stores). */
__attribute__((noinline)) static pgloss_status empty_eval(const pgloss_material *m, pgloss_vec3 wo,
                                                          pgloss_vec3 wi, unsigned lobes,
                                                          pgloss_rgb *f)
{
    (void)m, (void)wo, (void)wi, (void)lobes;
    f->r = f->g = f->b = 0.0f;
    __asm__ volatile("" ::: "memory");
    return PGLOSS_OK;
}

static void run_path(void *vp)
{
    ctx *c = vp;
    inputs *in = c->in;
    const size_t n = c->n;
    if (c->scalar) {
        float acc = 0.0f;
        for (size_t j = 0; j < n; ++j) {
            const pgloss_vec3 o = {in->ox[j], in->oy[j], in->oz[j]};
            const pgloss_vec3 i = {in->ix[j], in->iy[j], in->iz[j]};
            pgloss_rgb f;
            float p;
            switch (c->fn) {
            case FN_EVAL:
                (c->scalar == 2 ? empty_eval : pgloss_eval)(c->m, o, i, c->lobes, &f);
                in->fr[j] = f.r; in->fg[j] = f.g; in->fb[j] = f.b;
                break;
            case FN_PDF: pgloss_pdf(c->m, o, i, c->lobes, &p); in->pdf[j] = p; break;
            case FN_EVAL_PDF:
                pgloss_eval_pdf(c->m, o, i, c->lobes, &f, &p);
                in->fr[j] = f.r; in->fg[j] = f.g; in->fb[j] = f.b; in->pdf[j] = p;
                break;
            default: {
                const float u[3] = {in->u0[j], in->u1[j], in->u2[j]};
                pgloss_sample_record s;
                pgloss_sample(c->m, o, u, c->lobes, &s);
                in->wx[j] = s.wi.x; in->wy[j] = s.wi.y; in->wz[j] = s.wi.z;
                in->pdf[j] = s.pdf; in->fr[j] = s.weight.r; in->fg[j] = s.weight.g; in->fb[j] = s.weight.b;
            }
            }
            acc += in->fr[j];
        }
        g_sink = acc;
        return;
    }
    const size_t F = sizeof(float);
    const pgloss_strided3 wo = pgloss_strided3_soa(in->ox, in->oy, in->oz, F);
    const pgloss_strided3 wi = pgloss_strided3_soa(in->ix, in->iy, in->iz, F);
    const pgloss_strided3_out f = pgloss_strided3_out_soa(in->fr, in->fg, in->fb, F);
    const pgloss_strided3_out none = {{NULL, NULL, NULL}, 0};
    const pgloss_strided_out pdf = pgloss_strided_out_of(in->pdf, F), no_pdf = {NULL, 0};
    switch (c->fn) {
    case FN_EVAL: pgloss_eval_pdf_batch(&c->opt, c->m, NULL, c->lobes, n, wo, wi, f, no_pdf, NULL); break;
    case FN_PDF: pgloss_eval_pdf_batch(&c->opt, c->m, NULL, c->lobes, n, wo, wi, none, pdf, NULL); break;
    case FN_EVAL_PDF: pgloss_eval_pdf_batch(&c->opt, c->m, NULL, c->lobes, n, wo, wi, f, pdf, NULL); break;
    default:
        pgloss_sample_batch(&c->opt, c->m, NULL, c->lobes, n, wo,
                            pgloss_strided3_soa(in->u0, in->u1, in->u2, F),
                            pgloss_strided3_out_soa(in->wx, in->wy, in->wz, F), pdf, f, in->lobe, NULL);
    }
    g_sink = in->fr[0] + in->pdf[0];
}

/* Errors of the outputs just written by run_path against the long-double reference. For
 * sample: the pdf and weight at the returned direction (the reference evaluates eq. 2 at
 * the same float wi), and wi itself against the scalar reference sampler's direction. */
static void measure_errors(const ctx *c, err_acc *ef, err_acc *ep)
{
    const ref_material r = ref_from(c->m);
    inputs *in = c->in;
    memset(ef, 0, sizeof *ef);
    memset(ep, 0, sizeof *ep);
    for (size_t j = 0; j < c->n; ++j) {
        const float wo[3] = {in->ox[j], in->oy[j], in->oz[j]};
        long double f[3], p;
        if (c->fn == FN_SAMPLE) {
            const float wi[3] = {in->wx[j], in->wy[j], in->wz[j]};
            if (!(in->pdf[j] > 0))
                continue;
            ref_eval_pdf(&r, c->lobes, wo, wi, f, &p);
            if (g_last_x > REGULAR_X)
                continue;
            long double wl[3];
            ref_unit(wi, wl);
            for (int k = 0; k < 3; ++k) {
                const float got = k == 0 ? in->fr[j] : (k == 1 ? in->fg[j] : in->fb[j]);
                err_add(ef, got, f[k] * wl[2] / p, 1e-30L);
            }
            err_add(ep, in->pdf[j], p, 1e-30L);
            continue;
        }
        const float wi[3] = {in->ix[j], in->iy[j], in->iz[j]};
        ref_eval_pdf(&r, c->lobes, wo, wi, f, &p);
        if (g_last_x > REGULAR_X)
            continue;
        if (c->fn != FN_PDF)
            for (int k = 0; k < 3; ++k)
                err_add(ef, k == 0 ? in->fr[j] : (k == 1 ? in->fg[j] : in->fb[j]), f[k], 1e-30L);
        if (c->fn != FN_EVAL)
            err_add(ep, in->pdf[j], p, 1e-30L);
    }
}

/* The floor of any float evaluation of the specular lobe: the exact half vector and exponent
 * x, with only hx, hy, hz and then x rounded to float, everything else exact. Returns the
 * max relative error of f on the regular range (one lobe, inputs of the material). */
static double float_floor(const pgloss_material *m, const inputs *in, size_t n)
{
    const long double a2 = (long double)m->alpha_x * m->alpha_x;
    double worst = 0.0;
    for (size_t j = 0; j < n; ++j) {
        const float wo[3] = {in->ox[j], in->oy[j], in->oz[j]}, wi[3] = {in->ix[j], in->iy[j], in->iz[j]};
        long double o[3], i[3];
        ref_unit(wo, o);
        ref_unit(wi, i);
        if (!(o[2] > 0 && i[2] > 0))
            continue;
        const long double hx = o[0] + i[0], hy = o[1] + i[1], hz = o[2] + i[2];
        const long double x = (hx * hx + hy * hy) / (hz * hz * a2);
        if (x > REGULAR_X)
            continue;
        const float fx = (float)hx, fy = (float)hy, fz = (float)hz;
        const float xf = (float)(((long double)fx * fx + (long double)fy * fy) / ((long double)fz * fz * a2));
        const double e = (double)fabsl(expl(-(long double)xf) / expl(-x) - 1);
        worst = e > worst ? e : worst;
    }
    return worst;
}

static FILE *g_csv;

static void row(const char *material, ctx *c, const char *path, const char *tier, const char *isa)
{
    const double t = time_median(run_path, c) / (double)c->n * 1e9;
    run_path(c);
    err_acc ef, ep;
    measure_errors(c, &ef, &ep);
    const double emax = fmax(ef.max, ep.max);
    const double emean = (ef.n + ep.n) ? (ef.sum + ep.sum) / (double)(ef.n + ep.n) : 0.0;
    printf("| %-8s | %-8s | %-6s | %-9s | %-8s | %8.2f | %9.2e | %9.2e |\n", fn_name[c->fn], path,
           tier, isa, material, t, emax, emean);
    if (g_csv)
        fprintf(g_csv, "%s,%s,%s,%s,\"%s\",%.4f,%.4e,%.4e\n", fn_name[c->fn], path, tier, isa, material,
                t, emax, emean);
}

static void material_of(pgloss_material *m, double rd, double rs, double a, int norm)
{
    const pgloss_physical p = {{rd, rd, rd}, rs, a, a, (pgloss_normalization)norm};
    if (pgloss_material_init(m, &p) != PGLOSS_OK) {
        fprintf(stderr, "bench_core: bad material\n");
        exit(1);
    }
}

/* ---- perceptual conversions ------------------------------------------------------------ */

static long double ref_L_of_Y(long double Y)
{
    const long double eps = 216.0L / 24389.0L, kappa = 24389.0L / 27.0L;
    return Y <= eps ? kappa * Y : 116.0L * cbrtl(Y) - 16.0L;
}

typedef struct pctx { int which; size_t n; const double *a, *b, *cc; double *out; } pctx;

static void run_perceptual(void *vp)
{
    pctx *c = vp;
    double acc = 0;
    for (size_t j = 0; j < c->n; ++j) {
        double x = 0, y = 0, z = 0;
        switch (c->which) {
        case 0: pgloss_lightness_from_luminance(c->a[j], &x); break;
        case 1: pgloss_luminance_from_lightness(c->a[j] * 100.0, &x); break;
        case 2: pgloss_gloss_from_physical(c->a[j], c->b[j], c->cc[j], &x, &y, &z); break;
        default: pgloss_physical_from_gloss(c->a[j] * 100.0, c->b[j] * 0.1, 1.0 - c->cc[j], &x, &y, &z); break;
        }
        c->out[j] = x + y;
        acc += x;
    }
    g_sink = (float)acc;
}

static void perceptual_table(size_t n)
{
    static const char *names[] = {"lightness_from_luminance", "luminance_from_lightness",
                                  "gloss_from_physical", "physical_from_gloss"};
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b), *cc = malloc(n * sizeof *cc),
           *out = malloc(n * sizeof *out);
    for (size_t j = 0; j < n; ++j) {
        a[j] = 0.8 * rnd() + 0.001;    /* ρd or Y or L/100 */
        b[j] = 0.15 * rnd() * (1.0 - a[j]) + 1e-4; /* ρs */
        cc[j] = 0.01 + 0.19 * rnd();   /* α */
    }
    printf("\n| function | ns/call | max rel err | mean rel err |\n|---|---:|---:|---:|\n");
    for (int w = 0; w < 4; ++w) {
        pctx c = {w, n, a, b, cc, out};
        const double t = time_median(run_perceptual, &c) / (double)n * 1e9;
        double mx = 0, sum = 0;
        for (size_t j = 0; j < n; ++j) {
            double x = 0, y = 0, z = 0;
            long double want;
            switch (w) {
            case 0: pgloss_lightness_from_luminance(a[j], &x); want = ref_L_of_Y(a[j]); break;
            case 1: {
                pgloss_luminance_from_lightness(a[j] * 100.0, &x);
                const long double L = (long double)(a[j] * 100.0);
                want = L <= 8.0L ? L * 27.0L / 24389.0L : powl((L + 16.0L) / 116.0L, 3.0L);
                break;
            }
            case 2: { /* c of eq. 4 */
                pgloss_gloss_from_physical(a[j], b[j], cc[j], &y, &x, &z);
                want = cbrtl((long double)b[j] + a[j] / 2.0L) - cbrtl(a[j] / 2.0L);
                break;
            }
            default: { /* ρs of eq. 7 */
                double rd;
                pgloss_physical_from_gloss(a[j] * 100.0, b[j] * 0.1, 1.0 - cc[j], &rd, &x, &z);
                const long double L = (long double)(a[j] * 100.0);
                const long double Y = L <= 8.0L ? L * 27.0L / 24389.0L : powl((L + 16.0L) / 116.0L, 3.0L);
                const long double cl = (long double)(b[j] * 0.1);
                want = powl(cl + cbrtl(Y / 2.0L), 3.0L) - Y / 2.0L;
                break;
            }
            }
            const double e = (double)(fabsl(x - want) / fabsl(want));
            mx = fmax(mx, e);
            sum += e;
        }
        printf("| %s | %.1f | %.2e | %.2e |\n", names[w], t, mx, sum / (double)n);
        if (g_csv)
            fprintf(g_csv, "%s,scalar,double,-,-,%.4f,%.4e,%.4e\n", names[w], t, mx, sum / (double)n);
    }
    free(a); free(b); free(cc); free(out);
}

/* ---- the core clock --------------------------------------------------------------------- */

/* GHz of the running core, from a chain of dependent integer adds (one per cycle on every
 * x86-64 core), to turn ns into cycles (bench/mca.sh counts cycles). 0 elsewhere. */
static double core_ghz(void)
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    double best = 0.0;
    for (int r = 0; r < 5; ++r) {
        const long n = 200000000;
        long x = 0;
        const double t0 = now_s();
        __asm__ volatile("mov %1, %%rcx\n1:\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\t"
                         "add $1, %0\n\tsub $4, %%rcx\n\tjnz 1b\n"
                         : "+r"(x)
                         : "r"(n)
                         : "rcx", "cc");
        const double ghz = (double)n / (now_s() - t0) * 1e-9;
        best = ghz > best ? ghz : best;
    }
    return best;
#else
    return 0.0;
#endif
}

/* ---- main ------------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    int quick = 0;
    for (int k = 1; k < argc; ++k) {
        if (!strcmp(argv[k], "--quick"))
            quick = 1;
        else if (!strcmp(argv[k], "--csv") && k + 1 < argc)
            g_csv = fopen(argv[++k], "w");
        else {
            fprintf(stderr, "usage: bench_core [--quick] [--csv FILE]\n");
            return 2;
        }
    }
    if (quick) {
        g_reps = 3;
        g_min_time = 0.005;
    }
    if (g_csv)
        fprintf(g_csv, "function,path,tier,isa,material,ns,max_rel_err,mean_rel_err\n");

    const size_t n = 4096;
    pgloss_material glossy, diffuse, specular;
    material_of(&glossy, 0.193, 0.066, 0.07, PGLOSS_NORM_WARD);   /* Experiment 1, mid stimulus */
    material_of(&diffuse, 0.193, 0.0, 0.07, PGLOSS_NORM_WARD);
    material_of(&specular, 0.0, 0.066, 0.07, PGLOSS_NORM_WARD);
    inputs in;
    make_inputs(&in, 1u << 20, &glossy);

    printf("Best ISA here: %s; batch of %zu; median of %d runs of at least %.0f ms each; ns per call\n\n",
           pgloss_isa_name(pgloss_isa_best()), n, g_reps, g_min_time * 1e3);
    printf("Core clock: %.2f GHz (dependent integer adds; 0: not measured)\n\n", core_ghz());
    printf("| function | path | tier | ISA | material | ns/call | max rel err | mean rel err |\n");
    printf("|---|---|---|---|---|---:|---:|---:|\n");
    const pgloss_isa isas[] = {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512};
    for (int fn = 0; fn < FN_COUNT; ++fn) {
        ctx c = {&glossy, PGLOSS_LOBE_ALL, &in, n, fn, 1,
                 {PGLOSS_PRECISION_REFERENCE, PGLOSS_ISA_AUTO, PGLOSS_FLOAT32}};
        row("both", &c, "scalar", "double", "-");
        if (fn == FN_EVAL) { /* the loop and call alone, for comparison */
            c.scalar = 2;
            const double t = time_median(run_path, &c) / (double)n * 1e9;
            printf("| eval     | scalar   | (empty call) | -   | both     | %8.2f |           |           |\n", t);
            if (g_csv)
                fprintf(g_csv, "eval,scalar-empty,-,-,both,%.4f,,\n", t);
        }
        c.scalar = 0;
        row("both", &c, "batch", "double", "-");
        for (int t = 0; t < 2; ++t)
            for (int k = 0; k < 3; ++k) {
                if (!pgloss_isa_supported(isas[k]))
                    continue;
                c.opt.precision = t ? PGLOSS_PRECISION_FAST : PGLOSS_PRECISION_FLOAT;
                c.opt.isa = isas[k];
                row("both", &c, "batch", t ? "fast" : "float", pgloss_isa_name(isas[k]));
            }
    }

    printf("\nLobe masks (batched eval_pdf, eval and sample, best ISA; materials with both lobes, or "
           "one; batch of %zu; median of %d runs):\n\n", n, g_reps);
    printf("| function | path | tier | ISA | material | ns/call | max rel err | mean rel err |\n");
    printf("|---|---|---|---|---|---:|---:|---:|\n");
    {
        ctx c = {&glossy, PGLOSS_LOBE_ALL, &in, n, FN_EVAL_PDF, 0, {PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO, PGLOSS_FLOAT32}};
        row("both", &c, "batch", "float", "auto");
        c.m = &diffuse;
        row("diffuse", &c, "batch", "float", "auto");
        c.m = &specular;
        row("specular", &c, "batch", "float", "auto");
        c.m = &glossy;
        c.lobes = PGLOSS_LOBE_DIFFUSE;
        row("both, mask D", &c, "batch", "float", "auto");
        /* eval in both tiers: the specular-only material shows the lobe's own error, which
         * the diffuse term hides in the tails of the material with both lobes. */
        c.fn = FN_EVAL;
        c.lobes = PGLOSS_LOBE_ALL;
        for (int t = 0; t < 2; ++t) {
            c.opt.precision = t ? PGLOSS_PRECISION_FAST : PGLOSS_PRECISION_FLOAT;
            const pgloss_material *ms[] = {&glossy, &diffuse, &specular};
            const char *names[] = {"both", "diffuse", "specular"};
            for (int k = 0; k < 3; ++k) {
                c.m = ms[k];
                row(names[k], &c, "batch", t ? "fast" : "float", "auto");
            }
        }
        c.opt.precision = PGLOSS_PRECISION_FLOAT;
        c.m = &glossy;
        c.fn = FN_SAMPLE;
        const double floor_err = float_floor(&specular, &in, n);
        printf("| (floor: any float evaluation, specular lobe alone) | | | | specular | | %9.2e | |\n",
               floor_err);
        if (g_csv)
            fprintf(g_csv, "floor,-,-,-,specular,,%.4e,\n", floor_err);
        c.lobes = PGLOSS_LOBE_ALL;
        row("both", &c, "batch", "float", "auto");
        c.m = &diffuse;
        row("diffuse", &c, "batch", "float", "auto");
        c.m = &specular;
        row("specular", &c, "batch", "float", "auto");
    }

    printf("\nBatch size (float eval_pdf, best ISA; median of %d runs): ns per element\n\n| n | ns/elem |\n|---:|---:|\n",
           g_reps);
    const size_t sizes[] = {1, 16, 256, 4096, 65536, 1u << 20};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) {
        ctx c = {&glossy, PGLOSS_LOBE_ALL, &in, sizes[k], FN_EVAL_PDF, 0, {PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO, PGLOSS_FLOAT32}};
        const double t = time_median(run_path, &c) / (double)sizes[k] * 1e9;
        printf("| %zu | %.2f |\n", sizes[k], t);
        if (g_csv)
            fprintf(g_csv, "eval_pdf,batch-n=%zu,float,auto,both,%.4f,,\n", sizes[k], t);
    }

    const size_t np = quick ? 4096 : 65536;
    printf("\nPerceptual conversions (scalar, double; %zu paints; median of %d runs; reference: long double "
           "formulas):\n", np, g_reps);
    perceptual_table(np);
    if (g_csv)
        fclose(g_csv);
    return 0;
}
