// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/batch_materials.h — batched BRDF entry points with one material per element
 * (a texture of paints), in float; and the float64 (double) batch path, with one material
 * for the whole batch or one per element.
 *
 * Semantics are those of pgloss/batch.h element by element, with element j's material
 * built as pgloss_material_init builds it from element j of the arrays: the same checks
 * (NONFINITE — NaN, Inf, |v| > FLT_MAX —, NEGATIVE ρd or ρs, ALPHA αx or αy <= 0, in that
 * order), the same α floor (PGLOSS_ALPHA_MIN) and the same derived constants, computed
 * inside the batched loop (pgloss_inl_material_derive in pgloss/inline.h is the one formula for
 * them; pgloss_material_init calls it too). Energy (ρd + ρs > 1) is not rejected, as in
 * pgloss_material_init. An element whose material is invalid gets that status and 0 outputs
 * (a sample's wi = (0, 0, 1)); its directions are then not examined. Otherwise the element's
 * status is the one pgloss_eval_pdf / pgloss_sample would return (DIRECTION, RANDOM, OK).
 *
 * Returned status: PGLOSS_OK if every element is valid, else the status of the first invalid
 * element (the lowest index). PGLOSS_ERR_NULL (nothing written) for a missing required
 * array when n > 0; PGLOSS_ERR_NORMALIZATION (nothing written) for an unknown
 * normalization; PGLOSS_ERR_ARGUMENT (nothing written) for invalid options.
 *
 * status (the _ex forms; may be NULL): n signed chars, element j's pgloss_status (every
 * pgloss_status value fits a signed char).
 *
 * Accuracy. Float, per element: FLOAT-tier results are bit-identical to pgloss_eval_pdf_batch_ex
 * / pgloss_sample_batch_ex called with element j's pgloss_material (the tests assert it, on
 * every ISA). FAST runs the FLOAT code for per-element materials; REFERENCE runs the scalar
 * functions element by element.
 * Double (the _d functions): every tier runs the double loops (options select the ISA; the
 * precision is validated but the double lobe is already the reference formula: the per-point
 * code of the scalar pgloss_eval_pdf, shared with brdf.c). On AVX2 and AVX-512 those loops
 * fuse the formula's multiply-adds (FMA), so their bits differ from the baseline ISA's within
 * the bound below; per element and one material per call still agree bit for bit on each
 * ISA. f and pdf agree with the scalar
 * double reference within 1e-12 relative times the conditioning of exp (the shared vectors'
 * double tolerance); samples within the same bound, wi within 1e-12 absolute. Outputs are
 * clamped to at most FLT_MAX as in every precision (brdf.h), and tails of the lobe go on into
 * the subnormals rather than stopping at float's range.
 *
 * Arrays may be any alignment. Input and output arrays must not overlap.
 */
#ifndef PGLOSS_BATCH_MATERIALS_H
#define PGLOSS_BATCH_MATERIALS_H

#include <stddef.h>
#include "pgloss/batch.h"

#ifdef __cplusplus
extern "C" {
#endif

/* n materials as SoA float arrays, one value per element (the float batch path). alpha_y
 * may be NULL: isotropic, αy = αx. normalization is shared by all elements. */
typedef struct pgloss_material_array {
    const float *rho_d_r, *rho_d_g, *rho_d_b; /* diffuse reflectance, linear RGB */
    const float *rho_s;                       /* specular energy */
    const float *alpha_x, *alpha_y;           /* lobe spreads (alpha_y NULL: = alpha_x) */
    pgloss_normalization normalization;
} pgloss_material_array;

/* n physical parameter sets as SoA double arrays (pgloss_physical, one per element): the
 * materials of the double batch path, and the input/output of the batched perceptual
 * functions (pgloss/perceptual_batch.h). alpha_y may be NULL where read: isotropic. */
typedef struct pgloss_physical_array {
    const double *rho_d_r, *rho_d_g, *rho_d_b;
    const double *rho_s;
    const double *alpha_x, *alpha_y;
    pgloss_normalization normalization;
} pgloss_physical_array;

/* double counterparts of pgloss_vec3_array, pgloss_vec3_out, pgloss_rgb_out */
typedef struct pgloss_vec3_array_d { const double *x, *y, *z; } pgloss_vec3_array_d;
typedef struct pgloss_vec3_out_d { double *x, *y, *z; } pgloss_vec3_out_d;
typedef struct pgloss_rgb_out_d { double *r, *g, *b; } pgloss_rgb_out_d;

/* ---- float, one material per element --------------------------------------------------- */

PGLOSS_API pgloss_status pgloss_eval_batch_materials(const pgloss_material_array *m,
                                                     unsigned lobes, size_t n,
                                                     pgloss_vec3_array wo, pgloss_vec3_array wi,
                                                     pgloss_rgb_out f);

PGLOSS_API pgloss_status pgloss_pdf_batch_materials(const pgloss_material_array *m,
                                                    unsigned lobes, size_t n,
                                                    pgloss_vec3_array wo, pgloss_vec3_array wi,
                                                    float *pdf);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch_materials(const pgloss_material_array *m,
                                                         unsigned lobes, size_t n,
                                                         pgloss_vec3_array wo,
                                                         pgloss_vec3_array wi, pgloss_rgb_out f,
                                                         float *pdf);

PGLOSS_API pgloss_status pgloss_sample_batch_materials(const pgloss_material_array *m,
                                                       unsigned lobes, size_t n,
                                                       pgloss_vec3_array wo, const float *u0,
                                                       const float *u1, const float *u2,
                                                       pgloss_vec3_out wi, float *pdf,
                                                       pgloss_rgb_out weight,
                                                       unsigned char *lobe);

/* With options (NULL: FLOAT on AUTO) and the per-element status array (NULL: not written).
 * Either f (f.r == NULL) or pdf may be omitted, not both. */
PGLOSS_API pgloss_status pgloss_eval_pdf_batch_materials_ex(
    const pgloss_batch_options *options, const pgloss_material_array *m, unsigned lobes,
    size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f, float *pdf,
    signed char *status);

PGLOSS_API pgloss_status pgloss_sample_batch_materials_ex(
    const pgloss_batch_options *options, const pgloss_material_array *m, unsigned lobes,
    size_t n, pgloss_vec3_array wo, const float *u0, const float *u1, const float *u2,
    pgloss_vec3_out wi, float *pdf, pgloss_rgb_out weight, unsigned char *lobe,
    signed char *status);

/* ---- double, one material for the batch ------------------------------------------------ */
/* m's parameters (floats) are widened exactly; its derived constants are recomputed in
 * double. Random numbers are clamped to [0, 1 - 2^-24] as in pgloss_sample (NaN:
 * PGLOSS_ERR_RANDOM), so that every precision draws the same directions. */

PGLOSS_API pgloss_status pgloss_eval_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                             pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                             pgloss_rgb_out_d f);

PGLOSS_API pgloss_status pgloss_pdf_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                            pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                            double *pdf);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch_d(const pgloss_material *m, unsigned lobes,
                                                 size_t n, pgloss_vec3_array_d wo,
                                                 pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                 double *pdf);

PGLOSS_API pgloss_status pgloss_sample_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                               pgloss_vec3_array_d wo, const double *u0,
                                               const double *u1, const double *u2,
                                               pgloss_vec3_out_d wi, double *pdf,
                                               pgloss_rgb_out_d weight, unsigned char *lobe);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch_d_ex(const pgloss_batch_options *options,
                                                    const pgloss_material *m, unsigned lobes,
                                                    size_t n, pgloss_vec3_array_d wo,
                                                    pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                    double *pdf, signed char *status);

PGLOSS_API pgloss_status pgloss_sample_batch_d_ex(const pgloss_batch_options *options,
                                                  const pgloss_material *m, unsigned lobes,
                                                  size_t n, pgloss_vec3_array_d wo,
                                                  const double *u0, const double *u1,
                                                  const double *u2, pgloss_vec3_out_d wi,
                                                  double *pdf, pgloss_rgb_out_d weight,
                                                  unsigned char *lobe, signed char *status);

/* ---- double, one material per element -------------------------------------------------- */
/* Element j's material is pgloss_physical {ρd, ρs, αx, αy} of the arrays, checked as
 * pgloss_material_init checks it (|v| > FLT_MAX is NONFINITE) but kept in double. */

PGLOSS_API pgloss_status pgloss_eval_batch_materials_d(const pgloss_physical_array *m,
                                                       unsigned lobes, size_t n,
                                                       pgloss_vec3_array_d wo,
                                                       pgloss_vec3_array_d wi,
                                                       pgloss_rgb_out_d f);

PGLOSS_API pgloss_status pgloss_pdf_batch_materials_d(const pgloss_physical_array *m,
                                                      unsigned lobes, size_t n,
                                                      pgloss_vec3_array_d wo,
                                                      pgloss_vec3_array_d wi, double *pdf);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch_materials_d(const pgloss_physical_array *m,
                                                           unsigned lobes, size_t n,
                                                           pgloss_vec3_array_d wo,
                                                           pgloss_vec3_array_d wi,
                                                           pgloss_rgb_out_d f, double *pdf);

PGLOSS_API pgloss_status pgloss_sample_batch_materials_d(const pgloss_physical_array *m,
                                                         unsigned lobes, size_t n,
                                                         pgloss_vec3_array_d wo,
                                                         const double *u0, const double *u1,
                                                         const double *u2, pgloss_vec3_out_d wi,
                                                         double *pdf, pgloss_rgb_out_d weight,
                                                         unsigned char *lobe);

PGLOSS_API pgloss_status pgloss_eval_pdf_batch_materials_d_ex(
    const pgloss_batch_options *options, const pgloss_physical_array *m, unsigned lobes,
    size_t n, pgloss_vec3_array_d wo, pgloss_vec3_array_d wi, pgloss_rgb_out_d f, double *pdf,
    signed char *status);

PGLOSS_API pgloss_status pgloss_sample_batch_materials_d_ex(
    const pgloss_batch_options *options, const pgloss_physical_array *m, unsigned lobes,
    size_t n, pgloss_vec3_array_d wo, const double *u0, const double *u1, const double *u2,
    pgloss_vec3_out_d wi, double *pdf, pgloss_rgb_out_d weight, unsigned char *lobe,
    signed char *status);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BATCH_MATERIALS_H */
