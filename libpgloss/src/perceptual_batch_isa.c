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

void PHYSICAL_FN(size_t n, pgloss_perceptual_array q, const double *M, pgloss_physical_out p,
                 signed char *st)
{
    double r[CHUNK], g[CHUNK], b[CHUNK], s[CHUNK], al[CHUNK], sd[CHUNK];
    const double m0 = M[0], m1 = M[1], m2 = M[2], m3 = M[3], m4 = M[4], m5 = M[5], m6 = M[6],
                 m7 = M[7], m8 = M[8];
    const double Mk[9] = {m0, m1, m2, m3, m4, m5, m6, m7, m8};
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
