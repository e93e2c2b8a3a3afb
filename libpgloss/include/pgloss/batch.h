// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/batch.h — the BRDF of pgloss/brdf.h over n elements in one call: two entry points,
 * pgloss_eval_pdf_batch and pgloss_sample_batch.
 *
 * Arrays are strided, as Embree's buffers (byteStride): an array is a base pointer per
 * component and one byte stride, so that (n, 3) rows (AoS), three columns (SoA) and one value
 * for every element (stride 0, numpy's broadcasting) all pass without a copy. The scalar
 * type of every floating-point array of a call (directions, random numbers, outputs,
 * per-element materials) is the options' scalar type: float32 (the default) or float64.
 * The material is one pgloss_material for every element, or one parameter set per element
 * (pgloss_physical_array).
 *
 * Semantics are those of the scalar functions of pgloss/brdf.h, element by element
 * (normalisation of inputs, one-sided BRDF, rejected samples, lobe masks), with element j's
 * per-element material checked as pgloss_material_init checks it (NONFINITE — NaN, Inf,
 * |v| > FLT_MAX —, NEGATIVE, ALPHA in that order; energy is not checked) and derived as it
 * derives its constants (the α floor, 1/α, eq. 2's constant, the lobe selection) in the
 * call's scalar type: float32 parameters give pgloss_material_init's material bit for bit,
 * float64 ones are used as they are, not rounded to float (so that a float64 call is the
 * double reference on double parameters; one pgloss_material in a float64 call is widened
 * exactly). An element whose material or inputs are invalid gets that status and 0 outputs
 * (a sample's wi = (0, 0, 1), lobe NONE); the others are computed normally.
 *
 * Returned status: PGLOSS_OK if every element is valid, else the status of the first invalid
 * element (the lowest index). Errors of the whole call (nothing written, status included):
 * PGLOSS_ERR_ARGUMENT for invalid options, for m and ms both given, or for an output with
 * stride 0 and n > 1; PGLOSS_ERR_NULL for a missing required pointer when n > 0;
 * PGLOSS_ERR_NORMALIZATION for an unknown ms->normalization. n == 0 is PGLOSS_OK.
 *
 * Accuracy (docs/kernels.md; BENCHMARKS.md measures it): float32 FLOAT agrees with the scalar
 * double reference within a few float ulps times the conditioning of exp and of the half
 * vector (docs/kernels.md, step 3), and is bit-identical across instruction sets and between
 * one material per element and one per call; FAST trades a few more ulps for speed; REFERENCE
 * runs the scalar functions. float64 runs the double lobe in every tier: within 1e-12
 * relative of the scalar reference times exp's conditioning (the shared vectors' double
 * tolerance); outputs at most FLT_MAX as in every precision.
 *
 * Arrays may be of any alignment. Inputs and outputs must not overlap.
 */
#ifndef PGLOSS_BATCH_H
#define PGLOSS_BATCH_H

#include <stddef.h>
#include "pgloss/brdf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- strided arrays -------------------------------------------------------------------- */

/* The scalar type of a call's floating-point arrays. */
typedef enum pgloss_scalar_type {
    PGLOSS_FLOAT32 = 0, /* float */
    PGLOSS_FLOAT64 = 1  /* double */
} pgloss_scalar_type;

/* One value per element, read: element j at (const char *)ptr + j * stride. */
typedef struct pgloss_strided { const void *ptr; ptrdiff_t stride; } pgloss_strided;
/* One value per element, written: element j at (char *)ptr + j * stride. */
typedef struct pgloss_strided_out { void *ptr; ptrdiff_t stride; } pgloss_strided_out;
/* Three values per element, read: component c of element j at (const char *)ptr[c] + j * stride. */
typedef struct pgloss_strided3 { const void *ptr[3]; ptrdiff_t stride; } pgloss_strided3;
/* Three values per element, written: component c of element j at (char *)ptr[c] + j * stride. */
typedef struct pgloss_strided3_out { void *ptr[3]; ptrdiff_t stride; } pgloss_strided3_out;

/* Constructors for the common layouts (size: sizeof the scalar type). Stride 0 broadcasts. */
static inline pgloss_strided pgloss_strided_of(const void *p, ptrdiff_t stride)
{
    pgloss_strided s;
    s.ptr = p;
    s.stride = stride;
    return s;
}
static inline pgloss_strided_out pgloss_strided_out_of(void *p, ptrdiff_t stride)
{
    pgloss_strided_out s;
    s.ptr = p;
    s.stride = stride;
    return s;
}
/* Three columns (SoA) of elements of `size` bytes. */
static inline pgloss_strided3 pgloss_strided3_soa(const void *x, const void *y, const void *z,
                                                  size_t size)
{
    pgloss_strided3 s;
    s.ptr[0] = x;
    s.ptr[1] = y;
    s.ptr[2] = z;
    s.stride = (ptrdiff_t)size;
    return s;
}
static inline pgloss_strided3_out pgloss_strided3_out_soa(void *x, void *y, void *z, size_t size)
{
    pgloss_strided3_out s;
    s.ptr[0] = x;
    s.ptr[1] = y;
    s.ptr[2] = z;
    s.stride = (ptrdiff_t)size;
    return s;
}
/* Rows of three (an (n, 3) array, AoS) of elements of `size` bytes. */
static inline pgloss_strided3 pgloss_strided3_rows(const void *p, size_t size)
{
    return pgloss_strided3_soa(p, (const char *)p + size, (const char *)p + 2 * size, 3 * size);
}
static inline pgloss_strided3_out pgloss_strided3_out_rows(void *p, size_t size)
{
    return pgloss_strided3_out_soa(p, (char *)p + size, (char *)p + 2 * size, 3 * size);
}

/* n physical parameter sets (pgloss_physical, one per element), read, in the call's scalar
 * type (the perceptual batches: float64). alpha_y.ptr NULL: isotropic, αy = αx. */
typedef struct pgloss_physical_array {
    pgloss_strided3 rho_d; /* diffuse reflectance, linear RGB */
    pgloss_strided rho_s;  /* specular energy */
    pgloss_strided alpha_x, alpha_y;
    pgloss_normalization normalization; /* one for every element */
} pgloss_physical_array;

/* ---- options ----------------------------------------------------------------------------- */

/* How the BRDF batches compute float32 arrays (errors: docs/kernels.md and BENCHMARKS.md):
 *   FLOAT      the float lobe of pgloss/inline.h: IEEE division and square root, an exp within
 *              2 ulp (the default);
 *   FAST       the same lobe with reciprocal and rsqrt estimates refined by Newton steps, a
 *              degree-5 exp2 and multiply-adds fused where the ISA has FMA;
 *   REFERENCE  the scalar functions (double arithmetic) element by element.
 * float64 arrays run the double lobe in every tier. */
typedef enum pgloss_precision {
    PGLOSS_PRECISION_FLOAT = 0,
    PGLOSS_PRECISION_FAST = 1,
    PGLOSS_PRECISION_REFERENCE = 2
} pgloss_precision;

/* Instruction sets of the batched loops. AUTO picks the best one the running CPU supports
 * (pgloss_isa_best). BASELINE is the build's target without extensions (SSE2 on x86-64);
 * AVX2 means AVX2 + FMA, AVX512 means AVX-512 F/VL/DQ/BW. */
typedef enum pgloss_isa {
    PGLOSS_ISA_AUTO = 0,
    PGLOSS_ISA_BASELINE = 1,
    PGLOSS_ISA_AVX2 = 2,
    PGLOSS_ISA_AVX512 = 3
} pgloss_isa;

/* Options of a batched call; all zeros (or a NULL pointer) are the defaults. */
typedef struct pgloss_batch_options {
    pgloss_precision precision; /* accuracy tier: FLOAT */
    pgloss_isa isa;             /* AUTO */
    pgloss_scalar_type scalar;  /* FLOAT32 */
} pgloss_batch_options;

/* 1 if this build has loops for isa and the running CPU can execute them (AUTO: 1). */
PGLOSS_API int pgloss_isa_supported(pgloss_isa isa);
/* What PGLOSS_ISA_AUTO resolves to on the running CPU. */
PGLOSS_API pgloss_isa pgloss_isa_best(void);
/* "auto", "baseline", "avx2", "avx512"; "unknown" otherwise. */
PGLOSS_API const char *pgloss_isa_name(pgloss_isa isa);

/* ---- the batches ------------------------------------------------------------------------- */

/*
 * f (no cosine) and pdf of n pairs (wo, wi), as pgloss_eval_pdf.
 *   options  NULL: FLOAT tier, AUTO, float32.
 *   m, ms    exactly one non-NULL: one material for every element, or one per element.
 *   f        f.ptr[0] NULL: f not wanted (f.ptr[1], f.ptr[2] ignored);
 *   pdf      pdf.ptr NULL: pdf not wanted; not both.
 *   status   NULL, or n signed chars: element j's pgloss_status.
 */
PGLOSS_API pgloss_status pgloss_eval_pdf_batch(const pgloss_batch_options *options,
                                               const pgloss_material *m,
                                               const pgloss_physical_array *ms, unsigned lobes,
                                               size_t n, pgloss_strided3 wo, pgloss_strided3 wi,
                                               pgloss_strided3_out f, pgloss_strided_out pdf,
                                               signed char *status);

/*
 * n samples of wi given wo, as pgloss_sample, from the random numbers u (three per element;
 * float64 numbers are clamped to [0, 1 - 2^-24] as float32 ones are, so that both draw the
 * same directions). wi, pdf and weight are required; lobe (NULL: not written) receives the
 * pgloss_lobe chosen per element; options, m, ms and status as pgloss_eval_pdf_batch.
 */
PGLOSS_API pgloss_status pgloss_sample_batch(const pgloss_batch_options *options,
                                             const pgloss_material *m,
                                             const pgloss_physical_array *ms, unsigned lobes,
                                             size_t n, pgloss_strided3 wo, pgloss_strided3 u,
                                             pgloss_strided3_out wi, pgloss_strided_out pdf,
                                             pgloss_strided3_out weight, unsigned char *lobe,
                                             signed char *status);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BATCH_H */
