// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Renderer-style benchmark of the per-shading-point paths (BENCHMARKS.md, "One shading point").
 *
 * Each call gets its own directions and a material picked from a table of 8 by a random index,
 * as in a path tracer. Two loop forms:
 *   throughput  independent calls, which an out-of-order core overlaps;
 *   latency     each call's input depends on the previous call's output, as along one path:
 *               eval_pdf's wo.z takes + 0·pdf of the previous call (a multiply and an add,
 *               which the compiler may not drop; the "chain only" row measures them), and
 *               sample's wo is the previous sample's wi (z made positive).
 * Paths: pgloss/inline.h, the library's scalar calls, the batch at n = 1 and n = 16 (16
 * independent paths in lockstep for latency; ns per element), and a plain float
 * transcription of eq. 2 with Walter's pdf and sampling using libm (expf, logf, sincosf).
 * Errors: max relative error against a long-double transcription of the same formulas on the
 * regular range (specular exponent tan²δ/α² <= 10, cosines >= 0.05); for sample, pdf and
 * weight at the returned wi, and the largest deviation of wi from the long-double sample.
 * Measurements of all paths are interleaved, repetition by repetition; the median of the
 * thread's CPU time is shown (the host is shared).
 * Built twice (bench/CMakeLists.txt): -O2 -march=x86-64-v3 and plain -O2.
 *   bench_inline [--quick] */
#define _GNU_SOURCE
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pgloss/pgloss.h"
#include "pgloss/inline.h"

#ifndef BENCH_FLAGS
#define BENCH_FLAGS "?"
#endif
#define N 4096   /* inputs per pass: fits in L1/L2, like a renderer's working set */
#define NMAT 8
#define PI_L 3.141592653589793238462643383279502884L

static pgloss_material g_mat[NMAT];
static pgloss_vec3 g_wo[N], g_wi[N];
static float g_u[N][3];
static unsigned g_idx[N];
static volatile float g_sink;

static double now_s(void)
{
    struct timespec t;
    /* CPU time of this thread: the host is shared, and time spent descheduled is not ours. */
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t g_rng = 0x9E3779B97F4A7C15ull;
static float rnd(void)
{
    g_rng ^= g_rng << 13;
    g_rng ^= g_rng >> 7;
    g_rng ^= g_rng << 17;
    return (float)(g_rng >> 40) * 0x1p-24f;
}

static pgloss_vec3 hemisphere(float cmin)
{
    const float c = cmin + (1.0f - cmin) * rnd(), p = 6.2831853f * rnd();
    const float s = sqrtf(1.0f - c * c);
    const pgloss_vec3 v = {s * cosf(p), s * sinf(p), c};
    return v;
}

/* ---- a plain float transcription of eq. 2 and Walter 2005 (libm), isotropic α ---------- */

static inline void plain_eval_pdf(const pgloss_material *m, pgloss_vec3 o, pgloss_vec3 i,
                                  pgloss_rgb *f, float *pdf)
{
    const float a = m->alpha_x, ps = m->weight_specular / (m->weight_diffuse + m->weight_specular);
    float hx = o.x + i.x, hy = o.y + i.y, hz = o.z + i.z;
    const float hl = 1.0f / sqrtf(hx * hx + hy * hy + hz * hz);
    hx *= hl, hy *= hl, hz *= hl;
    const float e = expf(-(hx * hx + hy * hy) / (hz * hz * a * a));
    const float fs = m->rho_s * e / (4.0f * (float)M_PI * a * a * sqrtf(o.z * i.z));
    const int up = o.z > 0.0f && i.z > 0.0f;
    f->r = up ? m->rho_d[0] / (float)M_PI + fs : 0.0f;
    f->g = up ? m->rho_d[1] / (float)M_PI + fs : 0.0f;
    f->b = up ? m->rho_d[2] / (float)M_PI + fs : 0.0f;
    const float oh = o.x * hx + o.y * hy + o.z * hz;
    *pdf = up ? (1.0f - ps) * i.z / (float)M_PI +
                    ps * e / (4.0f * (float)M_PI * a * a * oh * hz * hz * hz)
              : 0.0f;
}

static inline void plain_sample(const pgloss_material *m, pgloss_vec3 o, const float u[3],
                                pgloss_sample_record *s)
{
    const float ps = m->weight_specular / (m->weight_diffuse + m->weight_specular);
    pgloss_vec3 w;
    if (u[0] < ps) {
        const float t = sqrtf(-logf(1.0f - u[1])) * m->alpha_x;
        float sn, cs;
        sincosf(6.2831853f * u[2], &sn, &cs);
        const float hl = 1.0f / sqrtf(t * t + 1.0f);
        const float hx = t * cs * hl, hy = t * sn * hl, hz = hl;
        const float oh = o.x * hx + o.y * hy + o.z * hz;
        w.x = 2.0f * oh * hx - o.x, w.y = 2.0f * oh * hy - o.y, w.z = 2.0f * oh * hz - o.z;
    } else {
        const float r = sqrtf(u[1]);
        float sn, cs;
        sincosf(6.2831853f * u[2], &sn, &cs);
        w.x = r * cs, w.y = r * sn, w.z = sqrtf(fmaxf(0.0f, 1.0f - u[1]));
    }
    s->wi = w;
    s->lobe = u[0] < ps ? PGLOSS_LOBE_SPECULAR : PGLOSS_LOBE_DIFFUSE;
    pgloss_rgb f;
    plain_eval_pdf(m, o, w, &f, &s->pdf);
    const float k = s->pdf > 0.0f ? w.z / s->pdf : 0.0f;
    s->weight.r = f.r * k, s->weight.g = f.g * k, s->weight.b = f.b * k;
}

/* ---- the loops -------------------------------------------------------------------------- */

enum { P_INLINE, P_SCALAR, P_BATCH1, P_BATCH16, P_PLAIN, P_CHAIN, NPATH };
static const char *path_name[NPATH] = {"inline (pgloss/inline.h)", "scalar library call",
                                       "batch, n = 1", "batch, n = 16 (per element)",
                                       "plain eq. 2 (float, libm)", "chain only (no call)"};

static inline __attribute__((always_inline)) void call_eval_pdf(int path, const pgloss_material *m, pgloss_vec3 o, pgloss_vec3 i,
                                 pgloss_rgb *f, float *p)
{
    switch (path) {
    case P_INLINE: pgloss_eval_pdf_inline(m, o, i, PGLOSS_LOBE_ALL, f, p); break;
    case P_SCALAR: pgloss_eval_pdf(m, o, i, PGLOSS_LOBE_ALL, f, p); break;
    case P_BATCH1: {
        pgloss_eval_pdf_batch(NULL, m, NULL, PGLOSS_LOBE_ALL, 1, pgloss_strided3_rows(&o, sizeof(float)),
                              pgloss_strided3_rows(&i, sizeof(float)), pgloss_strided3_out_rows(f, sizeof(float)),
                              pgloss_strided_out_of(p, sizeof(float)), NULL);
        break;
    }
    case P_PLAIN: plain_eval_pdf(m, o, i, f, p); break;
    default: f->r = f->g = f->b = 0.0f; *p = o.z; break;
    }
}

static inline __attribute__((always_inline)) void call_sample(int path, const pgloss_material *m, pgloss_vec3 o, const float u[3],
                               pgloss_sample_record *s)
{
    switch (path) {
    case P_INLINE: pgloss_sample_inline(m, o, u, PGLOSS_LOBE_ALL, s); break;
    case P_SCALAR: pgloss_sample(m, o, u, PGLOSS_LOBE_ALL, s); break;
    case P_BATCH1: {
        pgloss_sample_batch(NULL, m, NULL, PGLOSS_LOBE_ALL, 1, pgloss_strided3_rows(&o, sizeof(float)),
                            pgloss_strided3_rows(u, sizeof(float)), pgloss_strided3_out_rows(&s->wi, sizeof(float)),
                            pgloss_strided_out_of(&s->pdf, sizeof(float)),
                            pgloss_strided3_out_rows(&s->weight, sizeof(float)), NULL, NULL);
        break;
    }
    case P_PLAIN: plain_sample(m, o, u, s); break;
    default: s->wi = o; s->pdf = 1.0f; break;
    }
}

/* The batch at n = 16: one material per call (a renderer sorts hits by material to batch);
 * for latency, 16 paths in lockstep. */
static float batch16(int sample, int latency)
{
    float acc = 0.0f;
    float ox[16], oy[16], oz[16], ix[16], iy[16], iz[16], u0[16], u1[16], u2[16];
    float fr[16], fg[16], fb[16], p[16] = {0}, wx[16], wy[16], wz[16];
    for (int j = 0; j < 16; ++j)
        ox[j] = g_wo[j].x, oy[j] = g_wo[j].y, oz[j] = g_wo[j].z;
    for (int b = 0; b < N; b += 16) {
        const pgloss_material *m = &g_mat[g_idx[b]];
        for (int j = 0; j < 16; ++j) {
            if (!(latency && sample)) {
                ox[j] = g_wo[b + j].x, oy[j] = g_wo[b + j].y, oz[j] = g_wo[b + j].z;
                if (latency)
                    oz[j] += 0.0f * p[j];
            }
            ix[j] = g_wi[b + j].x, iy[j] = g_wi[b + j].y, iz[j] = g_wi[b + j].z;
            u0[j] = g_u[b + j][0], u1[j] = g_u[b + j][1], u2[j] = g_u[b + j][2];
        }
        const size_t F = sizeof(float);
        const pgloss_strided3 ao = pgloss_strided3_soa(ox, oy, oz, F), ai = pgloss_strided3_soa(ix, iy, iz, F);
        const pgloss_strided3_out fo = pgloss_strided3_out_soa(fr, fg, fb, F);
        const pgloss_strided_out po = pgloss_strided_out_of(p, F);
        if (sample) {
            pgloss_sample_batch(NULL, m, NULL, PGLOSS_LOBE_ALL, 16, ao, pgloss_strided3_soa(u0, u1, u2, F),
                                pgloss_strided3_out_soa(wx, wy, wz, F), po, fo, NULL, NULL);
            if (latency)
                for (int j = 0; j < 16; ++j)
                    ox[j] = wx[j], oy[j] = wy[j], oz[j] = fabsf(wz[j]);
        } else {
            pgloss_eval_pdf_batch(NULL, m, NULL, PGLOSS_LOBE_ALL, 16, ao, ai, fo, po, NULL);
        }
        acc += fr[0] + p[15];
    }
    return acc;
}

/* One pass over the N inputs; returns something that depends on every output. Inlined with
 * constant arguments (pass below), so that each loop is specialised for its path. */
static inline __attribute__((always_inline)) float pass_of(const int path, const int sample,
                                                           const int latency)
{
    float acc = 0.0f;
    if (!sample) {
        float prev = 0.0f;
        for (int j = 0; j < N; ++j) {
            pgloss_vec3 o = g_wo[j];
            if (latency)
                o.z += 0.0f * prev;
            pgloss_rgb f;
            float p;
            call_eval_pdf(path, &g_mat[g_idx[j]], o, g_wi[j], &f, &p);
            prev = p;
            acc += f.g + p;
        }
    } else {
        pgloss_vec3 o = g_wo[0];
        for (int j = 0; j < N; ++j) {
            pgloss_sample_record s;
            call_sample(path, &g_mat[g_idx[j]], latency ? o : g_wo[j], g_u[j], &s);
            o.x = s.wi.x, o.y = s.wi.y, o.z = fabsf(s.wi.z);
            acc += s.weight.g + s.pdf;
        }
    }
    return acc;
}

#define PASS_LOOPS(P)                                                                              \
    (sample ? (latency ? pass_of(P, 1, 1) : pass_of(P, 1, 0))                                      \
            : (latency ? pass_of(P, 0, 1) : pass_of(P, 0, 0)))
static __attribute__((noinline)) float pass(int path, int sample, int latency)
{
    switch (path) {
    case P_INLINE: return PASS_LOOPS(P_INLINE);
    case P_SCALAR: return PASS_LOOPS(P_SCALAR);
    case P_BATCH1: return PASS_LOOPS(P_BATCH1);
    case P_BATCH16: return batch16(sample, latency);
    case P_PLAIN: return PASS_LOOPS(P_PLAIN);
    default: return PASS_LOOPS(P_CHAIN);
    }
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* ---- errors against long double --------------------------------------------------------- */

typedef struct { long double f[3], pdf, x; } ref_out;

static void ref_eval_pdf(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi, ref_out *r)
{
    const long double lo = sqrtl((long double)wo.x * wo.x + (long double)wo.y * wo.y + (long double)wo.z * wo.z);
    const long double li = sqrtl((long double)wi.x * wi.x + (long double)wi.y * wi.y + (long double)wi.z * wi.z);
    const long double o[3] = {wo.x / lo, wo.y / lo, wo.z / lo}, i[3] = {wi.x / li, wi.y / li, wi.z / li};
    long double h[3] = {o[0] + i[0], o[1] + i[1], o[2] + i[2]};
    const long double hl = sqrtl(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (int k = 0; k < 3; ++k)
        h[k] /= hl;
    const long double ax = m->alpha_x, ay = m->alpha_y;
    r->x = ((h[0] / ax) * (h[0] / ax) + (h[1] / ay) * (h[1] / ay)) / (h[2] * h[2]);
    const long double e = expl(-r->x);
    const long double fs = (long double)m->rho_s * e / (4 * PI_L * ax * ay * sqrtl(i[2] * o[2]));
    const long double wd = PGLOSS_LUMA_R * (long double)m->rho_d[0] + PGLOSS_LUMA_G * (long double)m->rho_d[1] +
                           PGLOSS_LUMA_B * (long double)m->rho_d[2];
    const long double ps = m->rho_s / (wd + m->rho_s);
    for (int k = 0; k < 3; ++k)
        r->f[k] = m->rho_d[k] / PI_L + fs;
    const long double oh = o[0] * h[0] + o[1] * h[1] + o[2] * h[2];
    r->pdf = (1 - ps) * i[2] / PI_L + ps * e / (4 * PI_L * ax * ay * oh * h[2] * h[2] * h[2]);
}

static double rel(double got, long double want) { return (double)fabsl((got - want) / want); }

static void errors(int path, double err_eval[2], double err_sample[3])
{
    err_eval[0] = err_eval[1] = err_sample[0] = err_sample[1] = err_sample[2] = 0.0;
    for (int j = 0; j < N; ++j) {
        const pgloss_material *m = &g_mat[g_idx[j]];
        ref_out r;
        pgloss_rgb f;
        float p;
        ref_eval_pdf(m, g_wo[j], g_wi[j], &r);
        call_eval_pdf(path, m, g_wo[j], g_wi[j], &f, &p);
        if (r.x <= 10.0L && g_wi[j].z >= 0.05f) {
            err_eval[0] = fmax(err_eval[0], fmax(rel(f.r, r.f[0]), rel(f.b, r.f[2])));
            err_eval[1] = fmax(err_eval[1], rel(p, r.pdf));
        }
        pgloss_sample_record s;
        call_sample(path, m, g_wo[j], g_u[j], &s);
        pgloss_sample_record sl; /* the library's sample (double inside) as the direction reference */
        pgloss_sample(m, g_wo[j], g_u[j], PGLOSS_LOBE_ALL, &sl);
        if (!(s.pdf > 0.0f) || !(sl.pdf > 0.0f) || s.wi.z < 0.05f)
            continue;
        ref_eval_pdf(m, g_wo[j], s.wi, &r);
        if (r.x > 10.0L)
            continue;
        err_sample[0] = fmax(err_sample[0], rel(s.pdf, r.pdf));
        const long double wr = r.f[0] * (s.wi.z / sqrtl((long double)s.wi.x * s.wi.x + (long double)s.wi.y * s.wi.y +
                                                        (long double)s.wi.z * s.wi.z)) / r.pdf;
        err_sample[1] = fmax(err_sample[1], rel(s.weight.r, wr));
        if (path != P_PLAIN) /* the plain sampler maps (u1, u2) differently */
            err_sample[2] = fmax(err_sample[2], fmax(fabs(s.wi.x - sl.wi.x), fmax(fabs(s.wi.y - sl.wi.y), fabs(s.wi.z - sl.wi.z))));
    }
}

int main(int argc, char **argv)
{
    const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    for (int k = 0; k < NMAT; ++k) { /* glossy paints of the paper's range, eq. 2's normalisation */
        const double rd = 0.05 + 0.1 * k, rs = 0.02 + 0.012 * k, a = 0.03 + 0.03 * k;
        const pgloss_physical ph = {{rd, 0.8 * rd, 0.6 * rd}, rs, a, a, PGLOSS_NORM_WARD};
        if (pgloss_material_init(&g_mat[k], &ph) != PGLOSS_OK)
            return 1;
    }
    for (int j = 0; j < N; ++j) {
        g_wo[j] = hemisphere(0.05f);
        g_idx[j] = (unsigned)(rnd() * NMAT) & (NMAT - 1);
        g_u[j][0] = rnd(), g_u[j][1] = rnd(), g_u[j][2] = rnd();
        /* wi as a renderer meets it: sampled from the BRDF (the lobe's region), or a light. */
        if (j & 1) {
            pgloss_sample_record s;
            pgloss_sample(&g_mat[g_idx[j]], g_wo[j], g_u[j], PGLOSS_LOBE_ALL, &s);
            g_wi[j] = s.pdf > 0.0f ? s.wi : hemisphere(0.05f);
        } else {
            g_wi[j] = hemisphere(0.05f);
        }
    }
    const int reps = quick ? 5 : 31;
    const int passes = quick ? 20 : 100;
    static double t[2][2][NPATH][64]; /* [sample][latency][path][rep] */
    for (int r = 0; r < reps; ++r)
        for (int sample = 0; sample < 2; ++sample)
            for (int lat = 0; lat < 2; ++lat)
                for (int path = 0; path < NPATH; ++path) {
                    const int np = path == P_SCALAR || path == P_BATCH1 ? passes / 4 : passes;
                    float acc = 0.0f;
                    const double t0 = now_s();
                    for (int q = 0; q < np; ++q)
                        acc += pass(path, sample, lat);
                    t[sample][lat][path][r] = (now_s() - t0) / ((double)np * N) * 1e9;
                    g_sink = acc;
                }
    printf("Compiled with %s; %d materials (eq. 2, both lobes) picked at random; %d inputs; "
           "median of %d interleaved repetitions; ns per call.\n\n", BENCH_FLAGS, NMAT, N, reps);
    printf("| path | eval_pdf thr. | eval_pdf lat. | sample thr. | sample lat. | eval_pdf max rel err f / pdf | sample max rel err pdf / weight, max abs dev wi |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (int path = 0; path < NPATH; ++path) {
        double med[2][2];
        for (int s = 0; s < 2; ++s)
            for (int l = 0; l < 2; ++l) {
                qsort(t[s][l][path], (size_t)reps, sizeof(double), cmp_double);
                med[s][l] = t[s][l][path][reps / 2];
            }
        double ee[2], es[3];
        if (path == P_CHAIN || path == P_BATCH16) {
            printf("| %s | %.2f | %.2f | %.2f | %.2f | %s | %s |\n", path_name[path], med[0][0],
                   med[0][1], med[1][0], med[1][1], path == P_CHAIN ? "-" : "as batch, n = 1",
                   path == P_CHAIN ? "-" : "as batch, n = 1");
            continue;
        }
        errors(path, ee, es);
        char dev[32] = "-";
        if (path != P_PLAIN)
            snprintf(dev, sizeof dev, "%.1e", es[2]);
        printf("| %s | %.2f | %.2f | %.2f | %.2f | %.1e / %.1e | %.1e / %.1e, %s |\n", path_name[path],
               med[0][0], med[0][1], med[1][0], med[1][1], ee[0], ee[1], es[0], es[1], dev);
    }
    return 0;
}
