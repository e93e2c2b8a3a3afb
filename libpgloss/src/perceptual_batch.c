// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The batched perceptual and colour functions (pgloss/perceptual_batch.h): argument checks,
 * then one driver (run) over chunks: the strided inputs as contiguous columns (strided.h),
 * the function's loop of perceptual_batch_isa.c on the best ISA of the running CPU (the
 * scalar functions' per-element code, perceptual_d.h, so element j gets the scalar
 * function's status and outputs bit for bit), the outputs written back. Every input of a
 * chunk is read before its outputs are written, so an output may be its input array. */
#include "batch_internal.h"
#include "internal.h"
#include "perceptual_d.h"
#include "pgloss/perceptual_batch.h"
#include "strided.h"

#define C PGLOSS__PCHUNK

/* One call: its loop and columns. An input whose pointer is NULL is the one before it
 * (alpha_y NULL: isotropic); an output whose pointer is NULL is not written. */
typedef struct pcall {
    pgloss__perceptual_loop loop;
    pgloss__pargs args;
    int n_in, n_out;
    pgloss_strided in[6];
    pgloss_strided_out out[6];
} pcall;

/* The returned status: first error, else first warning, else OK. The common case (no error)
 * is a min/max pass over a chunk's statuses; the first error or warning is searched for only
 * when there is one. */
typedef struct summary {
    pgloss_status error, warning;
} summary;

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

static pgloss_status run(size_t n, const pcall *c, signed char *status)
{
    summary s = {PGLOSS_OK, PGLOSS_OK};
    double in[6][C], out[6][C];
    signed char buf[C];
    for (size_t base = 0; base < n; base += C) {
        const size_t m = n - base < C ? n - base : C;
        const double *ic[6];
        double *oc[6] = {out[0], out[1], out[2], out[3], out[4], out[5]};
        for (int k = 0; k < c->n_in; ++k)
            ic[k] = c->in[k].ptr ? pgloss__gather(c->in[k].ptr, c->in[k].stride, 8, base, m, in[k])
                                 : ic[k - 1];
        signed char *st = status ? status + base : buf;
        c->loop(m, ic, oc, &c->args, st);
        for (int k = 0; k < c->n_out; ++k)
            if (c->out[k].ptr)
                pgloss__scatter(c->out[k].ptr, c->out[k].stride, 8, base, m, out[k]);
        if (s.error == PGLOSS_OK)
            note_chunk(&s, m, st);
    }
    return s.error != PGLOSS_OK ? s.error : s.warning;
}

/* The common checks, in the documented order: a required pointer (the inputs but the ones
 * that may be NULL, the outputs but alpha_y), the colour space, the outputs' strides. */
static pgloss_status check(size_t n, const pcall *c, int optional_in, int optional_out,
                           int space_ok)
{
    for (int k = 0; k < c->n_in; ++k)
        if (!c->in[k].ptr && k != optional_in)
            return PGLOSS_ERR_NULL;
    for (int k = 0; k < c->n_out; ++k)
        if (!c->out[k].ptr && k != optional_out)
            return PGLOSS_ERR_NULL;
    if (!space_ok)
        return PGLOSS_ERR_ARGUMENT;
    for (int k = 0; k < c->n_out; ++k)
        if (c->out[k].ptr && c->out[k].stride == 0 && n > 1)
            return PGLOSS_ERR_ARGUMENT;
    return PGLOSS_OK;
}

static const pgloss__loops *loops(void)
{
    return pgloss__dispatch(NULL, NULL);
}

static pgloss_strided in_of(pgloss_strided3 s, int c)
{
    const pgloss_strided r = {s.ptr[c], s.stride};
    return r;
}
static pgloss_strided_out out_of(pgloss_strided3_out s, int c)
{
    const pgloss_strided_out r = {s.ptr[c], s.stride};
    return r;
}

/* Three columns in, three out (gloss space, colour). */
static pgloss_status run3(size_t n, pgloss__perceptual_loop loop, const double *M, int n_out,
                          pgloss_strided x0, pgloss_strided x1, pgloss_strided x2,
                          pgloss_strided_out y0, pgloss_strided_out y1, pgloss_strided_out y2,
                          int space_ok, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    const pcall c = {loop, {M, 0.0}, 3, n_out, {x0, x1, x2}, {y0, y1, y2}};
    const pgloss_status st = check(n, &c, -1, -1, space_ok);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

/* ---- gloss space (eqs. 3–8) --------------------------------------------------------------- */

pgloss_status pgloss_gloss_from_physical_batch(size_t n, pgloss_strided rho_d,
                                               pgloss_strided rho_s, pgloss_strided alpha,
                                               pgloss_strided_out L, pgloss_strided_out c,
                                               pgloss_strided_out d, signed char *status)
{
    return run3(n, loops()->gloss_from_physical, NULL, 3, rho_d, rho_s, alpha, L, c, d, 1,
                status);
}

pgloss_status pgloss_physical_from_gloss_batch(size_t n, pgloss_strided L, pgloss_strided c,
                                               pgloss_strided d, pgloss_strided_out rho_d,
                                               pgloss_strided_out rho_s,
                                               pgloss_strided_out alpha, signed char *status)
{
    return run3(n, loops()->physical_from_gloss, NULL, 3, L, c, d, rho_d, rho_s, alpha, 1,
                status);
}

pgloss_status pgloss_envelope_contrast_batch(size_t n, pgloss_strided L, pgloss_strided_out c_max,
                                             signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    const pcall c = {loops()->envelope_contrast, {NULL, 0.0}, 1, 1, {L}, {c_max}};
    const pgloss_status st = check(n, &c, -1, -1, 1);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

pgloss_status pgloss_match_gloss_batch(size_t n, pgloss_strided rho_d, pgloss_strided rho_s,
                                       pgloss_strided L_target, pgloss_strided_out rho_d_out,
                                       pgloss_strided_out rho_s_out, signed char *status)
{
    const pgloss_strided_out none = {NULL, 0};
    return run3(n, loops()->match_gloss, NULL, 2, rho_d, rho_s, L_target, rho_d_out, rho_s_out,
                none, 1, status);
}

/* ---- parameter sets (Fig. 13) ---------------------------------------------------------------- */

/* ρd r, g, b, ρs, αx, αy as six input columns. */
static void physical_in(const pgloss_physical_array *p, pgloss_strided *in)
{
    for (int k = 0; k < 3; ++k)
        in[k] = in_of(p->rho_d, k);
    in[3] = p->rho_s;
    in[4] = p->alpha_x;
    in[5] = p->alpha_y;
}

static void perceptual_in(const pgloss_perceptual_array *q, pgloss_strided *in)
{
    in[0] = q->L;
    in[1] = q->a;
    in[2] = q->b;
    in[3] = q->c;
    in[4] = q->d;
}

pgloss_status pgloss_check_physical_batch(size_t n, const pgloss_physical_array *p,
                                          signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!p)
        return PGLOSS_ERR_NULL;
    pcall c = {loops()->check_physical, {NULL, pgloss__valid_normalization(p->normalization)},
               6, 0, {{0}}, {{0}}};
    physical_in(p, c.in);
    const pgloss_status st = check(n, &c, 5, -1, 1);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

pgloss_status pgloss_check_perceptual_batch(size_t n, const pgloss_perceptual_array *q,
                                            pgloss_color_space space, signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!q)
        return PGLOSS_ERR_NULL;
    const int space_ok = pgloss__valid_color_space(space);
    pcall c = {loops()->check_perceptual,
               {space_ok ? pgloss__from_xyz_matrix(space) : NULL, 0.0}, 5, 0, {{0}}, {{0}}};
    perceptual_in(q, c.in);
    const pgloss_status st = check(n, &c, -1, -1, space_ok);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

pgloss_status pgloss_physical_from_perceptual_batch(size_t n, const pgloss_perceptual_array *q,
                                                    pgloss_normalization normalization,
                                                    pgloss_color_space space,
                                                    const pgloss_physical_array_out *p,
                                                    signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!q || !p)
        return PGLOSS_ERR_NULL;
    const int space_ok = pgloss__valid_color_space(space);
    pcall c = {loops()->physical_from_perceptual,
               {space_ok ? pgloss__from_xyz_matrix(space) : NULL,
                pgloss__valid_normalization(normalization)},
               5, 6, {{0}}, {{0}}};
    perceptual_in(q, c.in);
    for (int k = 0; k < 3; ++k)
        c.out[k] = out_of(p->rho_d, k);
    c.out[3] = p->rho_s;
    c.out[4] = p->alpha_x;
    c.out[5] = p->alpha_y;
    const pgloss_status st = check(n, &c, -1, 5, space_ok);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

pgloss_status pgloss_perceptual_from_physical_batch(size_t n, const pgloss_physical_array *p,
                                                    pgloss_color_space space,
                                                    const pgloss_perceptual_array_out *q,
                                                    signed char *status)
{
    if (n == 0)
        return PGLOSS_OK;
    if (!p || !q)
        return PGLOSS_ERR_NULL;
    const int space_ok = pgloss__valid_color_space(space);
    pcall c = {loops()->perceptual_from_physical,
               {space_ok ? pgloss__to_xyz_matrix(space) : NULL, 0.0}, 6, 5, {{0}}, {{0}}};
    physical_in(p, c.in);
    c.out[0] = q->L;
    c.out[1] = q->a;
    c.out[2] = q->b;
    c.out[3] = q->c;
    c.out[4] = q->d;
    const pgloss_status st = check(n, &c, 5, -1, space_ok);
    return st != PGLOSS_OK ? st : run(n, &c, status);
}

/* ---- colour ----------------------------------------------------------------------------------- */

pgloss_status pgloss_rgb_from_lab_batch(size_t n, pgloss_strided3 lab, pgloss_color_space space,
                                        pgloss_strided3_out rgb, signed char *status)
{
    const int ok = pgloss__valid_color_space(space);
    return run3(n, loops()->rgb_from_lab, ok ? pgloss__from_xyz_matrix(space) : NULL, 3,
                in_of(lab, 0), in_of(lab, 1), in_of(lab, 2), out_of(rgb, 0), out_of(rgb, 1),
                out_of(rgb, 2), ok, status);
}

pgloss_status pgloss_lab_from_rgb_batch(size_t n, pgloss_strided3 rgb, pgloss_color_space space,
                                        pgloss_strided3_out lab, signed char *status)
{
    const int ok = pgloss__valid_color_space(space);
    return run3(n, loops()->lab_from_rgb, ok ? pgloss__to_xyz_matrix(space) : NULL, 3,
                in_of(rgb, 0), in_of(rgb, 1), in_of(rgb, 2), out_of(lab, 0), out_of(lab, 1),
                out_of(lab, 2), ok, status);
}
