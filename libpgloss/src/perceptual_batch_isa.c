// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The vectorised loops of the batched perceptual functions (pgloss/perceptual_batch.h):
 * the per-element formulas of perceptual_d.h — the scalar functions' code — over SoA double
 * arrays. Compiled once per ISA (libpgloss/CMakeLists.txt, PGLOSS_ISA); perceptual_batch.c
 * picks one at run time and summarises the statuses.
 *
 * Each chunk is computed into stack arrays first (statuses as doubles: what GCC vectorises
 * next to double arithmetic) and then copied out: the hot loop then stores to nothing the
 * inputs could alias (an output may be the very same array as an input), and the copy loops
 * are plain. */
#include "perceptual_batch_isa.h"
#include "perceptual_d.h"

#ifndef PGLOSS_ISA
#error "PGLOSS_ISA must name the instruction set this file is compiled for"
#endif

#define PGLOSS__CAT2(a, b) a##_##b
#define PGLOSS__NAME2(fn, isa) PGLOSS__CAT2(fn, isa)
#define GLOSS_FN PGLOSS__NAME2(pgloss__gloss_from_physical_loop, PGLOSS_ISA)
#define PHYSICAL_FN PGLOSS__NAME2(pgloss__physical_from_perceptual_loop, PGLOSS_ISA)
#define FROM_GLOSS_FN PGLOSS__NAME2(pgloss__physical_from_gloss_loop, PGLOSS_ISA)
#define ENVELOPE_FN PGLOSS__NAME2(pgloss__envelope_contrast_loop, PGLOSS_ISA)
#define MATCH_FN PGLOSS__NAME2(pgloss__match_gloss_loop, PGLOSS_ISA)
#define CHECK_PHYSICAL_FN PGLOSS__NAME2(pgloss__check_physical_loop, PGLOSS_ISA)
#define CHECK_PERCEPTUAL_FN PGLOSS__NAME2(pgloss__check_perceptual_loop, PGLOSS_ISA)
#define TO_PERCEPTUAL_FN PGLOSS__NAME2(pgloss__perceptual_from_physical_loop, PGLOSS_ISA)
#define RGB_FN PGLOSS__NAME2(pgloss__rgb_from_lab_loop, PGLOSS_ISA)
#define LAB_FN PGLOSS__NAME2(pgloss__lab_from_rgb_loop, PGLOSS_ISA)

#define CHUNK 256

static void statuses_out(size_t m, const double *sd, signed char *st)
{
    for (size_t i = 0; i < m; ++i)
        st[i] = (signed char)(int)sd[i];
}

static void copy_out(size_t m, const double *src, double *dst)
{
    memcpy(dst, src, m * sizeof *dst);
}

/* 1 if every element of the chunk passes pgloss__gloss_plain_d. The flags go through a
 * buffer and are then ANDed as integers: both loops vectorise, where a reduction of doubles,
 * or one fused with the comparisons, does not. */
static int gloss_chunk_plain(size_t m, const double *rho_d, const double *rho_s,
                             const double *alpha, double *flag)
{
    for (size_t i = 0; i < m; ++i)
        flag[i] = pgloss__gloss_plain_d(rho_d[i], rho_s[i], alpha[i]);
    uint64_t all = ~(uint64_t)0;
    for (size_t i = 0; i < m; ++i)
        all &= pgloss__bits_d(flag[i]);
    return all != 0;
}

void GLOSS_FN(size_t n, const double *rho_d, const double *rho_s, const double *alpha, double *L,
              double *c, double *d, signed char *st)
{
    double oL[CHUNK], oc[CHUNK], od[CHUNK], sd[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *a = rho_d + base, *b = rho_s + base, *al = alpha + base;
        /* A texture's paints pass every check: such a chunk skips them and the cube roots'
         * scaling (the same bits, perceptual_d.h). */
        if (gloss_chunk_plain(m, a, b, al, sd))
            for (size_t i = 0; i < m; ++i)
                sd[i] = pgloss__gloss_from_physical_k(a[i], b[i], al[i], &oL[i], &oc[i], &od[i], 1);
        else
            for (size_t i = 0; i < m; ++i)
                sd[i] = pgloss__gloss_from_physical_k(a[i], b[i], al[i], &oL[i], &oc[i], &od[i], 0);
        copy_out(m, oL, L + base);
        copy_out(m, oc, c + base);
        copy_out(m, od, d + base);
        statuses_out(m, sd, st + base);
    }
}

/* A matrix into nine locals: constants of the loop, which no store can alias. */
#define MATRIX_LOCAL(Mk, M)                                                                        \
    const double Mk[9] = {M[0], M[1], M[2], M[3], M[4], M[5], M[6], M[7], M[8]}

void PHYSICAL_FN(size_t n, pgloss_perceptual_array q, const double *M, pgloss_physical_out p,
                 signed char *st)
{
    double r[CHUNK], g[CHUNK], b[CHUNK], s[CHUNK], al[CHUNK], sd[CHUNK];
    MATRIX_LOCAL(Mk, M);
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *qL = q.L + base, *qa = q.a + base, *qb = q.b + base, *qc = q.c + base,
                     *qd = q.d + base;
        for (size_t i = 0; i < m; ++i) {
            double pre;
            sd[i] = pgloss__physical_from_perceptual_k(qL[i], qa[i], qb[i], qc[i], qd[i], Mk,
                                                       &r[i], &g[i], &b[i], &s[i], &al[i], &pre);
        }
        copy_out(m, r, p.rho_d_r + base);
        copy_out(m, g, p.rho_d_g + base);
        copy_out(m, b, p.rho_d_b + base);
        copy_out(m, s, p.rho_s + base);
        copy_out(m, al, p.alpha_x + base);
        if (p.alpha_y)
            copy_out(m, al, p.alpha_y + base);
        statuses_out(m, sd, st + base);
    }
}

void FROM_GLOSS_FN(size_t n, const double *L, const double *c, const double *d, double *rho_d,
                   double *rho_s, double *alpha, signed char *st)
{
    double o0[CHUNK], o1[CHUNK], o2[CHUNK], sd[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *x0 = L + base, *x1 = c + base, *x2 = d + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__physical_from_gloss_k(x0[i], x1[i], x2[i], &o0[i], &o1[i], &o2[i]);
        copy_out(m, o0, rho_d + base);
        copy_out(m, o1, rho_s + base);
        copy_out(m, o2, alpha + base);
        statuses_out(m, sd, st + base);
    }
}

void ENVELOPE_FN(size_t n, const double *L, double *c_max, signed char *st)
{
    double o0[CHUNK], sd[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *x0 = L + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__envelope_k(x0[i], &o0[i]);
        copy_out(m, o0, c_max + base);
        statuses_out(m, sd, st + base);
    }
}

void MATCH_FN(size_t n, const double *rho_d, const double *rho_s, const double *L_target,
              double *rho_d_out, double *rho_s_out, signed char *st)
{
    double o0[CHUNK], o1[CHUNK], sd[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *x0 = rho_d + base, *x1 = rho_s + base, *x2 = L_target + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__match_gloss_k(x0[i], x1[i], x2[i], &o0[i], &o1[i]);
        copy_out(m, o0, rho_d_out + base);
        copy_out(m, o1, rho_s_out + base);
        statuses_out(m, sd, st + base);
    }
}

void CHECK_PHYSICAL_FN(size_t n, pgloss_physical_array p, double norm_ok, signed char *st)
{
    double sd[CHUNK];
    const double *ay_all = p.alpha_y ? p.alpha_y : p.alpha_x; /* NULL: isotropic */
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *r = p.rho_d_r + base, *g = p.rho_d_g + base, *b = p.rho_d_b + base,
                     *s = p.rho_s + base, *ax = p.alpha_x + base, *ay = ay_all + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__check_physical_k(r[i], g[i], b[i], s[i], ax[i], ay[i], norm_ok);
        statuses_out(m, sd, st + base);
    }
}

void CHECK_PERCEPTUAL_FN(size_t n, pgloss_perceptual_array q, const double *M, signed char *st)
{
    double sd[CHUNK];
    MATRIX_LOCAL(Mk, M);
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *qL = q.L + base, *qa = q.a + base, *qb = q.b + base, *qc = q.c + base,
                     *qd = q.d + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__check_perceptual_k(qL[i], qa[i], qb[i], qc[i], qd[i], Mk);
        statuses_out(m, sd, st + base);
    }
}

void TO_PERCEPTUAL_FN(size_t n, pgloss_physical_array p, const double *Mx, pgloss_perceptual_out q,
                      signed char *st)
{
    double oL[CHUNK], oa[CHUNK], ob[CHUNK], oc[CHUNK], od[CHUNK], sd[CHUNK];
    MATRIX_LOCAL(Mk, Mx);
    const double *ay_all = p.alpha_y ? p.alpha_y : p.alpha_x; /* NULL: isotropic */
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *r = p.rho_d_r + base, *g = p.rho_d_g + base, *b = p.rho_d_b + base,
                     *s = p.rho_s + base, *ax = p.alpha_x + base, *ay = ay_all + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__perceptual_from_physical_k(r[i], g[i], b[i], s[i], ax[i], ay[i], Mk,
                                                       &oL[i], &oa[i], &ob[i], &oc[i], &od[i]);
        copy_out(m, oL, q.L + base);
        copy_out(m, oa, q.a + base);
        copy_out(m, ob, q.b + base);
        copy_out(m, oc, q.c + base);
        copy_out(m, od, q.d + base);
        statuses_out(m, sd, st + base);
    }
}

void RGB_FN(size_t n, pgloss_lab_array lab, const double *M, pgloss_rgb_out_d rgb, signed char *st)
{
    double o0[CHUNK], o1[CHUNK], o2[CHUNK], sd[CHUNK];
    MATRIX_LOCAL(Mk, M);
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *x0 = lab.L + base, *x1 = lab.a + base, *x2 = lab.b + base;
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__rgb_from_lab_k(x0[i], x1[i], x2[i], Mk, &o0[i], &o1[i], &o2[i]);
        copy_out(m, o0, rgb.r + base);
        copy_out(m, o1, rgb.g + base);
        copy_out(m, o2, rgb.b + base);
        statuses_out(m, sd, st + base);
    }
}

void LAB_FN(size_t n, pgloss_rgb_array_d rgb, const double *Mx, pgloss_lab_out lab,
            signed char *st)
{
    double o0[CHUNK], o1[CHUNK], o2[CHUNK], sd[CHUNK];
    MATRIX_LOCAL(Mk, Mx);
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        const double *x0 = rgb.r + base, *x1 = rgb.g + base, *x2 = rgb.b + base;
        for (size_t i = 0; i < m; ++i) {
            double y;
            sd[i] = pgloss__lab_from_rgb_k(x0[i], x1[i], x2[i], Mk, &o0[i], &o1[i], &o2[i], &y);
        }
        copy_out(m, o0, lab.L + base);
        copy_out(m, o1, lab.a + base);
        copy_out(m, o2, lab.b + base);
        statuses_out(m, sd, st + base);
    }
}
