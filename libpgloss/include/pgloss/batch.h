// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/batch.h — batched entry points over structure-of-arrays inputs.
 *
 * Same semantics as the scalar functions of pgloss/brdf.h (normalisation of inputs,
 * one-sided BRDF, rejected samples, lobe masks), element by element, in float
 * arithmetic: the per-point functions of pgloss/inline.h over the arrays, which the compiler
 * vectorises. They agree with the scalar reference within a few float ulps times the
 * conditioning of exp (tests assert it).
 *
 * The functions below run the float tier on the best instruction set of the running CPU;
 * the *_ex forms choose the tier and the instruction set explicitly (pgloss_batch_options).
 *
 * Arrays may be any alignment. Input and output arrays must not overlap.
 * The status is PGLOSS_OK if every element was valid, else the error of the first
 * invalid element (PGLOSS_ERR_DIRECTION, PGLOSS_ERR_RANDOM); invalid elements get 0
 * outputs and the others are computed normally.
 */
#ifndef PGLOSS_BATCH_H
#define PGLOSS_BATCH_H

#include <stddef.h>
#include "pgloss/brdf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* n directions as three arrays (read-only). */
typedef struct pgloss_vec3_array { const float *x, *y, *z; } pgloss_vec3_array;
/* n directions as three arrays (written). */
typedef struct pgloss_vec3_out { float *x, *y, *z; } pgloss_vec3_out;
/* n RGB values as three arrays (written). */
typedef struct pgloss_rgb_out { float *r, *g, *b; } pgloss_rgb_out;

PGLOSS_API pgloss_status pgloss_eval_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f);

PGLOSS_API pgloss_status pgloss_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                               pgloss_vec3_array wo, pgloss_vec3_array wi, float *pdf);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array wo, pgloss_vec3_array wi,
                                    pgloss_rgb_out f, float *pdf);

/* u0, u1, u2: the three random numbers of pgloss_sample, one array each.
 * lobe may be NULL; otherwise it receives the pgloss_lobe chosen per element. */
PGLOSS_API pgloss_status pgloss_sample_batch(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array wo, const float *u0, const float *u1,
                                  const float *u2, pgloss_vec3_out wi, float *pdf,
                                  pgloss_rgb_out weight, unsigned char *lobe);

/* ---- accuracy tiers and instruction sets --------------------------------------------- */

/* How the batched loops compute (errors on the regular range and against the shared vectors:
 * docs/kernels.md and BENCHMARKS.md):
 *   FLOAT      the float lobe of pgloss/inline.h: IEEE division and square root, an exp within
 *              2 ulp (the default);
 *   FAST       on AVX2 and AVX-512, blocks of unit directions in intrinsics with hardware
 *              reciprocal and rsqrt estimates and a degree-5 exp2, no division or square root;
 *              elsewhere (other ISAs, tails, other directions, the sampler's directions) FLOAT;
 *   REFERENCE  the scalar functions (double arithmetic) element by element. */
typedef enum pgloss_precision {
    PGLOSS_PRECISION_FLOAT = 0,
    PGLOSS_PRECISION_FAST = 1,
    PGLOSS_PRECISION_REFERENCE = 2
} pgloss_precision;

/* Instruction sets of the FLOAT and FAST loops. AUTO picks the best one the running CPU
 * supports (pgloss_isa_best). BASELINE is the build's target without extensions (SSE2 on
 * x86-64); AVX2 means AVX2 + FMA, AVX512 means AVX-512 F/VL/DQ/BW. FLOAT-tier results are
 * bit-identical across instruction sets (no FMA contraction); FAST-tier results may
 * differ by its stated error. */
typedef enum pgloss_isa {
    PGLOSS_ISA_AUTO = 0,
    PGLOSS_ISA_BASELINE = 1,
    PGLOSS_ISA_AVX2 = 2,
    PGLOSS_ISA_AVX512 = 3
} pgloss_isa;

typedef struct pgloss_batch_options {
    pgloss_precision precision;
    pgloss_isa isa;
} pgloss_batch_options;

/* 1 if this build has loops for isa and the running CPU can execute them (AUTO: 1). */
PGLOSS_API int pgloss_isa_supported(pgloss_isa isa);
/* What PGLOSS_ISA_AUTO resolves to on the running CPU. */
PGLOSS_API pgloss_isa pgloss_isa_best(void);
/* "auto", "baseline", "avx2", "avx512"; "unknown" otherwise. */
PGLOSS_API const char *pgloss_isa_name(pgloss_isa isa);

/*
 * pgloss_eval_pdf_batch with explicit options (NULL: the defaults, FLOAT on AUTO). Either
 * output may be omitted: f.r == NULL (then f.g and f.b are ignored) or pdf == NULL, not
 * both. PGLOSS_ERR_ARGUMENT (nothing written) for an unknown precision or isa, or an isa
 * that pgloss_isa_supported denies.
 */
PGLOSS_API pgloss_status pgloss_eval_pdf_batch_ex(const pgloss_batch_options *options,
                                       const pgloss_material *m, unsigned lobes, size_t n,
                                       pgloss_vec3_array wo, pgloss_vec3_array wi,
                                       pgloss_rgb_out f, float *pdf);

/* pgloss_sample_batch with explicit options, as pgloss_eval_pdf_batch_ex. */
PGLOSS_API pgloss_status pgloss_sample_batch_ex(const pgloss_batch_options *options,
                                     const pgloss_material *m, unsigned lobes, size_t n,
                                     pgloss_vec3_array wo, const float *u0, const float *u1,
                                     const float *u2, pgloss_vec3_out wi, float *pdf,
                                     pgloss_rgb_out weight, unsigned char *lobe);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BATCH_H */
