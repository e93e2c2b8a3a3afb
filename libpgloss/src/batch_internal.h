// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The batched paths, shared between the front ends (batch.c, perceptual_batch.c: arguments,
 * strided arrays, statuses), the dispatcher (dispatch.c) and the loops (batch_isa.c,
 * batch_d_isa.c, perceptual_batch_isa.c, compiled once per ISA). The loops take contiguous
 * columns (the front ends gather strided arrays into them). Not installed. */
#ifndef PGLOSS_BATCH_INTERNAL_H
#define PGLOSS_BATCH_INTERNAL_H

#include <stddef.h>
#include "pgloss/batch.h"
#include "pgloss/inline.h"
#include "perceptual_batch_isa.h"

/* Contiguous columns of the loops: directions and RGB values, read or written. */
typedef struct pgloss__vec3_f { const float *x, *y, *z; } pgloss__vec3_f;
typedef struct pgloss__vec3_out_f { float *x, *y, *z; } pgloss__vec3_out_f;
typedef struct pgloss__rgb_out_f { float *r, *g, *b; } pgloss__rgb_out_f;
typedef struct pgloss__vec3_d { const double *x, *y, *z; } pgloss__vec3_d;
typedef struct pgloss__vec3_out_d { double *x, *y, *z; } pgloss__vec3_out_d;
typedef struct pgloss__rgb_out_d { double *r, *g, *b; } pgloss__rgb_out_d;
/* Per-element materials as columns (alpha_y never NULL here). */
typedef struct pgloss__materials_f {
    const float *rho_d_r, *rho_d_g, *rho_d_b, *rho_s, *alpha_x, *alpha_y;
    pgloss_normalization normalization;
} pgloss__materials_f;
typedef struct pgloss__materials_d {
    const double *rho_d_r, *rho_d_g, *rho_d_b, *rho_s, *alpha_x, *alpha_y;
    pgloss_normalization normalization;
} pgloss__materials_d;

/* LOOP(lobes, normalisation) with both as compile-time constants, chosen from the run-time
 * `active` and `norm` (the float and the double loops): absent lobes and unused
 * normalisations compile away. */
#define PGLOSS__BY_NORM(LOOP, A, norm)                                                             \
    ((norm) == PGLOSS_NORM_WARD_DUR                                                                \
         ? LOOP(A, PGLOSS_NORM_WARD_DUR)                                                           \
         : ((norm) == PGLOSS_NORM_BOUNDED ? LOOP(A, PGLOSS_NORM_BOUNDED)                           \
                                          : LOOP(A, PGLOSS_NORM_WARD)))
#define PGLOSS__BY_LOBES(LOOP, active, norm)                                                       \
    ((active) == PGLOSS_LOBE_DIFFUSE    ? LOOP(PGLOSS_LOBE_DIFFUSE, PGLOSS_NORM_WARD)              \
     : (active) == PGLOSS_LOBE_SPECULAR ? PGLOSS__BY_NORM(LOOP, PGLOSS_LOBE_SPECULAR, norm)       \
     : (active) == PGLOSS_LOBE_ALL      ? PGLOSS__BY_NORM(LOOP, PGLOSS_LOBE_ALL, norm)            \
                                        : LOOP(PGLOSS_LOBE_NONE, PGLOSS_NORM_WARD))

/* X(lobes, normalisation) for every pair PGLOSS__BY_LOBES chooses among: the loops define one
 * out-of-line function per pair with it (one function holding every specialisation inlined
 * made GCC's superlinear passes and the sanitizers take minutes per object). */
#define PGLOSS__EACH_LOBES(X)                                                                      \
    X(PGLOSS_LOBE_DIFFUSE, PGLOSS_NORM_WARD)                                                       \
    X(PGLOSS_LOBE_SPECULAR, PGLOSS_NORM_WARD)                                                      \
    X(PGLOSS_LOBE_SPECULAR, PGLOSS_NORM_WARD_DUR)                                                  \
    X(PGLOSS_LOBE_SPECULAR, PGLOSS_NORM_BOUNDED)                                                   \
    X(PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD)                                                           \
    X(PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD_DUR)                                                       \
    X(PGLOSS_LOBE_ALL, PGLOSS_NORM_BOUNDED)                                                        \
    X(PGLOSS_LOBE_NONE, PGLOSS_NORM_WARD)

#if defined(__GNUC__) || defined(__clang__)
#define PGLOSS__NOINLINE __attribute__((noinline))
#else
#define PGLOSS__NOINLINE
#endif

/* A float call as the loops take it. */
typedef struct pgloss__call_f {
    const pgloss_material *m;      /* one material, or NULL: */
    const pgloss__materials_f *ms; /* one per element */
    unsigned active;               /* m: lobes & m->lobes; ms: the call's lobes (each element
                                      narrows them to those it has) */
    int norm;
    int clamp; /* whether outputs can exceed FLT_MAX (per element: always) */
} pgloss__call_f;
struct pgloss__consts_d;

/* The loops, over n contiguous elements; f.r == NULL / pdf == NULL: output not wanted. They
 * return the number of invalid elements met (0 exactly when every element is valid). The
 * double loops take one of k (NULL) and pa (NULL). */
typedef size_t (*pgloss__eval_pdf_fn)(const pgloss__call_f *c, size_t n, pgloss__vec3_f wo,
                                      pgloss__vec3_f wi, pgloss__rgb_out_f f, float *pdf);
typedef size_t (*pgloss__sample_fn)(const pgloss__call_f *c, size_t n, pgloss__vec3_f wo,
                                    const float *u0, const float *u1, const float *u2,
                                    pgloss__vec3_out_f wi, float *pdf, pgloss__rgb_out_f weight,
                                    unsigned char *lobe);
typedef size_t (*pgloss__eval_pdf_d_fn)(const struct pgloss__consts_d *,
                                        const pgloss__materials_d *, unsigned, int, size_t,
                                        pgloss__vec3_d, pgloss__vec3_d, pgloss__rgb_out_d,
                                        double *);
typedef size_t (*pgloss__sample_d_fn)(const struct pgloss__consts_d *, const pgloss__materials_d *,
                                    unsigned, int, size_t, pgloss__vec3_d, const double *,
                                    const double *, const double *, pgloss__vec3_out_d,
                                    double *, pgloss__rgb_out_d, unsigned char *);

/* (n, 3) float32 rows (byte stride 12, any alignment) to n contiguous x, y, z, and back
 * (rows3.h): compiled per ISA, so that the front ends' gathers and scatters of the common
 * channel-last layout run as wide as the loops. */
typedef void (*pgloss__rows_in_fn)(const void *rows, size_t n, float *x, float *y, float *z);
typedef void (*pgloss__rows_out_fn)(const float *x, const float *y, const float *z, size_t n,
                                    void *rows);

/* Every loop of one ISA: what dispatch.c hands the front ends. */
typedef struct pgloss__loops {
    pgloss__eval_pdf_fn eval_pdf[2]; /* [FAST tier] */
    pgloss__sample_fn sample[2];
    pgloss__eval_pdf_d_fn eval_pdf_d;
    pgloss__sample_d_fn sample_d;
    pgloss__rows_in_fn rows_in;
    pgloss__rows_out_fn rows_out;
#define PGLOSS__LOOP_FIELD(name) pgloss__perceptual_loop name;
    PGLOSS__PERCEPTUAL_LOOPS(PGLOSS__LOOP_FIELD)
#undef PGLOSS__LOOP_FIELD
} pgloss__loops;

/* The one dispatcher: the options of a call resolved (NULL: the defaults), or NULL if they
 * are invalid (an unknown tier or scalar type, an ISA this build or CPU lacks). *opt_out
 * receives the options with AUTO resolved. */
const pgloss__loops *pgloss__dispatch(const pgloss_batch_options *opt,
                                      pgloss_batch_options *opt_out);

#endif
