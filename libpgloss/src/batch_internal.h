// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The batched paths, shared between batch.c (public entry points, validation, ISA and tier
 * dispatch) and batch_isa.c (the loops, compiled once per ISA × tier). Not installed. */
#ifndef PGLOSS_BATCH_INTERNAL_H
#define PGLOSS_BATCH_INTERNAL_H

#include <stddef.h>
#include "pgloss/batch.h"
#include "pgloss/batch_materials.h"
#include "pgloss/inline.h"

/* The options of a batched call (NULL: FLOAT tier, AUTO): 0 if invalid (an unknown precision,
 * or an ISA this build or CPU lacks), else 1 with *prec and *isa (AUTO resolved to the best
 * ISA). The one decision for batch.c and batch_materials.c. */
int pgloss__batch_options_resolve(const pgloss_batch_options *opt, pgloss_precision *prec,
                                  pgloss_isa *isa);

/* Per-call constants of the loops, derived from the material and the active lobes. */
typedef struct pgloss__batch_consts {
    pgloss_inl_consts lobe;           /* what the inline functions take (pgloss/inline.h) */
    float alpha_x, alpha_y;           /* for the sampler */
    float inv_ax2_log2, inv_ay2_log2; /* log2(e)/α²: eq. 2's exponent in base 2 (FAST blocks) */
    int may_overflow;       /* f or pdf can exceed FLT_MAX/2 at some direction (FAST blocks) */
} pgloss__batch_consts;

typedef size_t (*pgloss__eval_pdf_fn)(const pgloss__batch_consts *k, unsigned active, int norm,
                                      size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi,
                                      pgloss_rgb_out f, float *pdf);
typedef void (*pgloss__sample_fn)(const pgloss__batch_consts *k, unsigned active, int norm,
                                  size_t n, pgloss_vec3_array wo, const float *u0,
                                  const float *u1, const float *u2, pgloss_vec3_out wi,
                                  float *pdf, pgloss_rgb_out weight, unsigned char *lobe);

/* One pair of loops per (ISA, tier) built; f.r == NULL / pdf == NULL: output not wanted.
 * eval_pdf returns the number of invalid directions met (wo and wi counted separately). */
#define PGLOSS__DECLARE_KERNELS(isa, tier)                                                        \
    size_t pgloss__eval_pdf_##isa##_##tier(const pgloss__batch_consts *, unsigned, int, size_t,  \
                                           pgloss_vec3_array, pgloss_vec3_array,                 \
                                           pgloss_rgb_out, float *);                             \
    void pgloss__sample_##isa##_##tier(const pgloss__batch_consts *, unsigned, int, size_t,       \
                                       pgloss_vec3_array, const float *, const float *,          \
                                       const float *, pgloss_vec3_out, float *, pgloss_rgb_out,  \
                                       unsigned char *);

/* Per-element materials (pgloss/batch_materials.h): one pair per ISA, FLOAT tier; `active`
 * is the call's mask & PGLOSS_LOBE_ALL, m->alpha_y is never NULL here. eval_pdf returns the
 * number of invalid elements met (materials and directions). */
#define PGLOSS__DECLARE_MATERIAL_KERNELS(isa)                                                     \
    size_t pgloss__eval_pdf_materials_##isa(const pgloss_material_array *, unsigned,     \
                                                    size_t, pgloss_vec3_array, pgloss_vec3_array, \
                                                    pgloss_rgb_out, float *);                     \
    void pgloss__sample_materials_##isa(const pgloss_material_array *, unsigned, size_t,  \
                                                pgloss_vec3_array, const float *, const float *,  \
                                                const float *, pgloss_vec3_out, float *,          \
                                                pgloss_rgb_out, unsigned char *);

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
                                                pgloss_vec3_out wi, float *pdf,
                                                pgloss_rgb_out weight, unsigned char *lobe)
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

PGLOSS__DECLARE_MATERIAL_KERNELS(baseline)
#if defined(PGLOSS_HAVE_AVX2)
PGLOSS__DECLARE_MATERIAL_KERNELS(avx2)
#endif
#if defined(PGLOSS_HAVE_AVX512)
PGLOSS__DECLARE_MATERIAL_KERNELS(avx512)
#endif

/* The double loops (batch_d_isa.c), one pair per ISA: k for one material, or pa (non-NULL)
 * for one per element (pa->alpha_y never NULL here). eval_pdf returns the number of invalid
 * elements. */
struct pgloss__consts_d;
#define PGLOSS__DECLARE_DOUBLE_KERNELS(isa)                                                       \
    size_t pgloss__eval_pdf_batch_d_##isa(const struct pgloss__consts_d *,                        \
                                          const pgloss_physical_array *, unsigned, int, size_t,   \
                                          pgloss_vec3_array_d, pgloss_vec3_array_d,               \
                                          pgloss_rgb_out_d, double *);                            \
    void pgloss__sample_batch_d_##isa(const struct pgloss__consts_d *,                            \
                                      const pgloss_physical_array *, unsigned, int, size_t,       \
                                      pgloss_vec3_array_d, const double *, const double *,        \
                                      const double *, pgloss_vec3_out_d, double *,                \
                                      pgloss_rgb_out_d, unsigned char *);
PGLOSS__DECLARE_DOUBLE_KERNELS(baseline)
#if defined(PGLOSS_HAVE_AVX2)
PGLOSS__DECLARE_DOUBLE_KERNELS(avx2)
#endif
#if defined(PGLOSS_HAVE_AVX512)
PGLOSS__DECLARE_DOUBLE_KERNELS(avx512)
#endif

PGLOSS__DECLARE_KERNELS(baseline, float)
PGLOSS__DECLARE_KERNELS(baseline, fast)
#if defined(PGLOSS_HAVE_AVX2)
PGLOSS__DECLARE_KERNELS(avx2, float)
PGLOSS__DECLARE_KERNELS(avx2, fast)
#endif
#if defined(PGLOSS_HAVE_AVX512)
PGLOSS__DECLARE_KERNELS(avx512, float)
PGLOSS__DECLARE_KERNELS(avx512, fast)
#endif

#endif
