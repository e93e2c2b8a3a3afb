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

/* Per-call constants of the loops, derived from the material and the active lobes. */
typedef struct pgloss__batch_consts {
    pgloss_inl_consts lobe;           /* what the inline functions take (pgloss/inline.h) */
    float alpha_x, alpha_y;           /* for the sampler */
    float inv_ax2_log2, inv_ay2_log2; /* log2(e)/α²: eq. 2's exponent in base 2 (FAST blocks) */
    int may_overflow;       /* f or pdf can exceed FLT_MAX/2 at some direction (FAST blocks) */
} pgloss__batch_consts;
struct pgloss__consts_d;

/* The loops, over n contiguous elements; f.r == NULL / pdf == NULL: output not wanted.
 * eval_pdf returns the number of invalid elements met (for one material: invalid directions,
 * wo and wi counted separately). One material: k, with `active` its active lobes; per
 * element: the materials, with `active` the call's mask & PGLOSS_LOBE_ALL. The double loops
 * take one of k (NULL) and pa (NULL). */
typedef size_t (*pgloss__eval_pdf_fn)(const pgloss__batch_consts *k, unsigned active, int norm,
                                      size_t n, pgloss__vec3_f wo, pgloss__vec3_f wi,
                                      pgloss__rgb_out_f f, float *pdf);
typedef void (*pgloss__sample_fn)(const pgloss__batch_consts *k, unsigned active, int norm,
                                  size_t n, pgloss__vec3_f wo, const float *u0,
                                  const float *u1, const float *u2, pgloss__vec3_out_f wi,
                                  float *pdf, pgloss__rgb_out_f weight, unsigned char *lobe);
typedef size_t (*pgloss__eval_pdf_materials_fn)(const pgloss__materials_f *, unsigned, size_t,
                                                pgloss__vec3_f, pgloss__vec3_f,
                                                pgloss__rgb_out_f, float *);
typedef void (*pgloss__sample_materials_fn)(const pgloss__materials_f *, unsigned, size_t,
                                            pgloss__vec3_f, const float *, const float *,
                                            const float *, pgloss__vec3_out_f, float *,
                                            pgloss__rgb_out_f, unsigned char *);
typedef size_t (*pgloss__eval_pdf_d_fn)(const struct pgloss__consts_d *,
                                        const pgloss__materials_d *, unsigned, int, size_t,
                                        pgloss__vec3_d, pgloss__vec3_d, pgloss__rgb_out_d,
                                        double *);
typedef void (*pgloss__sample_d_fn)(const struct pgloss__consts_d *, const pgloss__materials_d *,
                                    unsigned, int, size_t, pgloss__vec3_d, const double *,
                                    const double *, const double *, pgloss__vec3_out_d,
                                    double *, pgloss__rgb_out_d, unsigned char *);

/* Every loop of one ISA: what dispatch.c hands the front ends. */
typedef struct pgloss__loops {
    pgloss__eval_pdf_fn eval_pdf[2]; /* [FAST tier] */
    pgloss__sample_fn sample[2];
    pgloss__eval_pdf_materials_fn eval_pdf_materials;
    pgloss__sample_materials_fn sample_materials;
    pgloss__eval_pdf_d_fn eval_pdf_d;
    pgloss__sample_d_fn sample_d;
#define PGLOSS__LOOP_FIELD(name) pgloss__perceptual_loop name;
    PGLOSS__PERCEPTUAL_LOOPS(PGLOSS__LOOP_FIELD)
#undef PGLOSS__LOOP_FIELD
} pgloss__loops;

/* The one dispatcher: the options of a call resolved (NULL: the defaults), or NULL if they
 * are invalid (an unknown tier or scalar type, an ISA this build or CPU lacks). *opt_out
 * receives the options with AUTO resolved. */
const pgloss__loops *pgloss__dispatch(const pgloss_batch_options *opt,
                                      pgloss_batch_options *opt_out);

/* Whether a float material parameter set passes pgloss_material_init's checks: finite (for a
 * float, |v| <= FLT_MAX), ρ >= 0, α > 0. */
PGLOSS_INLINE_FN int pgloss__material_valid_f(float r, float g, float b, float s, float ax,
                                               float ay)
{
    const int finite = pgloss_inl_finite(r) & pgloss_inl_finite(g) & pgloss_inl_finite(b) &
                       pgloss_inl_finite(s) & pgloss_inl_finite(ax) & pgloss_inl_finite(ay);
    return finite & (r >= 0.0f) & (g >= 0.0f) & (b >= 0.0f) & (s >= 0.0f) & (ax > 0.0f) &
           (ay > 0.0f);
}

/* Element j of a float batch's sample outputs from the scalar pgloss_sample's record (the
 * reference tier of both batch families); lobe may be NULL. */
PGLOSS_INLINE_FN void pgloss__put_sample_record(const pgloss_sample_record *s, size_t j,
                                                pgloss__vec3_out_f wi, float *pdf,
                                                pgloss__rgb_out_f weight, unsigned char *lobe)
{
    wi.x[j] = s->wi.x;
    wi.y[j] = s->wi.y;
    wi.z[j] = s->wi.z;
    pdf[j] = s->pdf;
    weight.r[j] = s->weight.r;
    weight.g[j] = s->weight.g;
    weight.b[j] = s->weight.b;
    if (lobe)
        lobe[j] = (unsigned char)s->lobe;
}

#endif
