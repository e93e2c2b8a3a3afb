// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The vectorised loops of the batched perceptual functions (pgloss/perceptual_batch.h): the
 * per-element formulas of perceptual_d.h — the scalar functions' code — over one chunk of
 * contiguous double columns. Compiled once per ISA (libpgloss/CMakeLists.txt, PGLOSS_ISA);
 * perceptual_batch.c gathers the chunks and picks the ISA. Statuses are kept as doubles in
 * the loop (what GCC vectorises next to double arithmetic) and converted after it. */
#include "perceptual_batch_isa.h"
#include "perceptual_d.h"

#ifndef PGLOSS_ISA
#error "PGLOSS_ISA must name the instruction set this file is compiled for"
#endif

#define PGLOSS__CAT2(a, b) a##_##b
#define PGLOSS__NAME2(fn, isa) PGLOSS__CAT2(fn, isa)
#define LOOP_FN(name) PGLOSS__NAME2(pgloss__##name##_loop, PGLOSS_ISA)

static void statuses_out(size_t m, const double *sd, signed char *st)
{
    for (size_t i = 0; i < m; ++i)
        st[i] = (signed char)(int)sd[i];
}

/* The columns as restrict pointers, and a matrix in nine locals that no store can alias. */
#define IN(k) const double *restrict x##k = in[k]
#define OUT(k) double *restrict y##k = out[k]
#define MATRIX_LOCAL(Mk, M)                                                                        \
    const double Mk[9] = {M[0], M[1], M[2], M[3], M[4], M[5], M[6], M[7], M[8]}

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

void LOOP_FN(gloss_from_physical)(size_t m, const double *const *in, double *const *out,
                                  const pgloss__pargs *a, signed char *st)
{
    (void)a;
    IN(0); IN(1); IN(2); OUT(0); OUT(1); OUT(2);
    double sd[PGLOSS__PCHUNK];
    /* A texture's paints pass every check: such a chunk skips them and the cube roots'
     * scaling (the same bits, perceptual_d.h). */
    if (gloss_chunk_plain(m, x0, x1, x2, sd))
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__gloss_from_physical_k(x0[i], x1[i], x2[i], &y0[i], &y1[i], &y2[i], 1);
    else
        for (size_t i = 0; i < m; ++i)
            sd[i] = pgloss__gloss_from_physical_k(x0[i], x1[i], x2[i], &y0[i], &y1[i], &y2[i], 0);
    statuses_out(m, sd, st);
}

void LOOP_FN(physical_from_gloss)(size_t m, const double *const *in, double *const *out,
                                  const pgloss__pargs *a, signed char *st)
{
    (void)a;
    IN(0); IN(1); IN(2); OUT(0); OUT(1); OUT(2);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__physical_from_gloss_k(x0[i], x1[i], x2[i], &y0[i], &y1[i], &y2[i]);
    statuses_out(m, sd, st);
}

void LOOP_FN(envelope_contrast)(size_t m, const double *const *in, double *const *out,
                                const pgloss__pargs *a, signed char *st)
{
    (void)a;
    IN(0); OUT(0);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__envelope_k(x0[i], &y0[i]);
    statuses_out(m, sd, st);
}

void LOOP_FN(match_gloss)(size_t m, const double *const *in, double *const *out,
                          const pgloss__pargs *a, signed char *st)
{
    (void)a;
    IN(0); IN(1); IN(2); OUT(0); OUT(1);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__match_gloss_k(x0[i], x1[i], x2[i], &y0[i], &y1[i]);
    statuses_out(m, sd, st);
}

void LOOP_FN(check_physical)(size_t m, const double *const *in, double *const *out,
                             const pgloss__pargs *a, signed char *st)
{
    (void)out;
    IN(0); IN(1); IN(2); IN(3); IN(4); IN(5);
    const double norm_ok = a->norm_ok;
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__check_physical_k(x0[i], x1[i], x2[i], x3[i], x4[i], x5[i], norm_ok);
    statuses_out(m, sd, st);
}

void LOOP_FN(check_perceptual)(size_t m, const double *const *in, double *const *out,
                               const pgloss__pargs *a, signed char *st)
{
    (void)out;
    IN(0); IN(1); IN(2); IN(3); IN(4);
    MATRIX_LOCAL(Mk, a->M);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__check_perceptual_k(x0[i], x1[i], x2[i], x3[i], x4[i], Mk);
    statuses_out(m, sd, st);
}

void LOOP_FN(physical_from_perceptual)(size_t m, const double *const *in, double *const *out,
                                       const pgloss__pargs *a, signed char *st)
{
    IN(0); IN(1); IN(2); IN(3); IN(4); OUT(0); OUT(1); OUT(2); OUT(3); OUT(4); OUT(5);
    MATRIX_LOCAL(Mk, a->M);
    double sd[PGLOSS__PCHUNK], pre[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i) {
        sd[i] = pgloss__physical_from_perceptual_k(x0[i], x1[i], x2[i], x3[i], x4[i], Mk, &y0[i],
                                                   &y1[i], &y2[i], &y3[i], &y4[i], &pre[i]);
        y5[i] = y4[i]; /* isotropic: αy = αx */
    }
    /* an unknown normalisation: the scalar function's NORMALIZATION, after its input checks */
    if (!(a->norm_ok > 0.0))
        for (size_t i = 0; i < m; ++i)
            if (!(pre[i] < 0.0)) {
                sd[i] = (double)PGLOSS_ERR_NORMALIZATION;
                y0[i] = y1[i] = y2[i] = y3[i] = y4[i] = y5[i] = 0.0;
            }
    statuses_out(m, sd, st);
}

void LOOP_FN(perceptual_from_physical)(size_t m, const double *const *in, double *const *out,
                                       const pgloss__pargs *a, signed char *st)
{
    IN(0); IN(1); IN(2); IN(3); IN(4); IN(5); OUT(0); OUT(1); OUT(2); OUT(3); OUT(4);
    MATRIX_LOCAL(Mk, a->M);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__perceptual_from_physical_k(x0[i], x1[i], x2[i], x3[i], x4[i], x5[i], Mk,
                                                   &y0[i], &y1[i], &y2[i], &y3[i], &y4[i]);
    statuses_out(m, sd, st);
}

void LOOP_FN(rgb_from_lab)(size_t m, const double *const *in, double *const *out,
                           const pgloss__pargs *a, signed char *st)
{
    IN(0); IN(1); IN(2); OUT(0); OUT(1); OUT(2);
    MATRIX_LOCAL(Mk, a->M);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i)
        sd[i] = pgloss__rgb_from_lab_k(x0[i], x1[i], x2[i], Mk, &y0[i], &y1[i], &y2[i]);
    statuses_out(m, sd, st);
}

void LOOP_FN(lab_from_rgb)(size_t m, const double *const *in, double *const *out,
                           const pgloss__pargs *a, signed char *st)
{
    IN(0); IN(1); IN(2); OUT(0); OUT(1); OUT(2);
    MATRIX_LOCAL(Mk, a->M);
    double sd[PGLOSS__PCHUNK];
    for (size_t i = 0; i < m; ++i) {
        double y;
        sd[i] = pgloss__lab_from_rgb_k(x0[i], x1[i], x2[i], Mk, &y0[i], &y1[i], &y2[i], &y);
    }
    statuses_out(m, sd, st);
}
