// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/perceptual_batch.h — the perceptual and colour functions of pgloss/perceptual.h
 * and pgloss/color.h over n elements (a texture of paints), with a status per element.
 *
 * Arrays are float64 strided arrays (pgloss/batch.h: a base pointer and a byte stride per
 * array, stride 0 for one value for every element). The colour space is an argument
 * (PGLOSS_COLOR_SPACE_LINEAR_REC709 is what the functions without _ex of perceptual.h use).
 *
 * Element j gets exactly what the scalar function returns for element j: the same status and
 * the same outputs, bit for bit (each loop runs the scalar function's per-element code,
 * vectorised, on the best ISA of the running CPU: docs/kernels.md), so the scalar functions'
 * error against the shared vectors (relative 1e-12, tests/vectors) is theirs too. That
 * includes the documented outputs of a failed element: 0, except the exact values of a GAMUT
 * element (rgb_from_lab, physical_from_perceptual) and the matched values of an ENVELOPE
 * element (match_gloss).
 *
 * status (may be NULL): n signed chars, element j's pgloss_status.
 * Returned status: the first error (< 0) in index order if any element has one, else the
 * first warning (PGLOSS_WARN_ALPHA_UNTRUSTED) if any, else PGLOSS_OK. So a return >= 0 means
 * every output is usable. Errors of the whole call (nothing written, status included), with
 * n > 0: a required pointer that is NULL (PGLOSS_ERR_NULL); an unknown colour space, or an
 * output with stride 0 and n > 1 (PGLOSS_ERR_ARGUMENT). An unknown normalization
 * (check_physical, physical_from_perceptual) is each element's status, in the scalar
 * function's order (after the checks of its inputs that come first there). n == 0 is OK.
 *
 * An output may be the very same array as an input (in place, element by element); other
 * overlaps are not allowed.
 */
#ifndef PGLOSS_PERCEPTUAL_BATCH_H
#define PGLOSS_PERCEPTUAL_BATCH_H

#include <stddef.h>
#include "pgloss/batch.h"
#include "pgloss/perceptual.h"

#ifdef __cplusplus
extern "C" {
#endif

/* n five-parameter descriptions (pgloss_perceptual, Fig. 13), each field an array of its own
 * (its own stride: a field of one value for every element has stride 0); read / written. */
typedef struct pgloss_perceptual_array {
    pgloss_strided L, a, b, c, d;
} pgloss_perceptual_array;
typedef struct pgloss_perceptual_array_out {
    pgloss_strided_out L, a, b, c, d;
} pgloss_perceptual_array_out;
/* n physical parameter sets, written (pgloss_physical_array is the input form); alpha_y.ptr
 * NULL: not written. */
typedef struct pgloss_physical_array_out {
    pgloss_strided3_out rho_d;
    pgloss_strided_out rho_s;
    pgloss_strided_out alpha_x, alpha_y;
} pgloss_physical_array_out;

/* pgloss_gloss_from_physical (eqs. 3, 4, L* of ρd). */
PGLOSS_API pgloss_status pgloss_gloss_from_physical_batch(size_t n, pgloss_strided rho_d,
                                                          pgloss_strided rho_s,
                                                          pgloss_strided alpha,
                                                          pgloss_strided_out L,
                                                          pgloss_strided_out c,
                                                          pgloss_strided_out d,
                                                          signed char *status);

/* pgloss_physical_from_gloss (eqs. 6, 7, 8). */
PGLOSS_API pgloss_status pgloss_physical_from_gloss_batch(size_t n, pgloss_strided L,
                                                          pgloss_strided c, pgloss_strided d,
                                                          pgloss_strided_out rho_d,
                                                          pgloss_strided_out rho_s,
                                                          pgloss_strided_out alpha,
                                                          signed char *status);

/* pgloss_envelope_contrast (Fig. 10). */
PGLOSS_API pgloss_status pgloss_envelope_contrast_batch(size_t n, pgloss_strided L,
                                                        pgloss_strided_out c_max,
                                                        signed char *status);

/* pgloss_match_gloss (§5.2, Fig. 12). */
PGLOSS_API pgloss_status pgloss_match_gloss_batch(size_t n, pgloss_strided rho_d,
                                                  pgloss_strided rho_s, pgloss_strided L_target,
                                                  pgloss_strided_out rho_d_out,
                                                  pgloss_strided_out rho_s_out,
                                                  signed char *status);

/* pgloss_check_physical (p->normalization for every element). Statuses only: status may
 * still be NULL (then only the returned status is of use). */
PGLOSS_API pgloss_status pgloss_check_physical_batch(size_t n, const pgloss_physical_array *p,
                                                     signed char *status);

/* pgloss_check_perceptual_ex. */
PGLOSS_API pgloss_status pgloss_check_perceptual_batch(size_t n,
                                                       const pgloss_perceptual_array *q,
                                                       pgloss_color_space space,
                                                       signed char *status);

/* pgloss_physical_from_perceptual_ex (Fig. 13 → eq. 2's parameters, with the validity of
 * pgloss_physical_from_perceptual; for the full model check, pgloss_check_perceptual). */
PGLOSS_API pgloss_status pgloss_physical_from_perceptual_batch(
    size_t n, const pgloss_perceptual_array *q, pgloss_normalization normalization,
    pgloss_color_space space, const pgloss_physical_array_out *p, signed char *status);

/* pgloss_perceptual_from_physical_ex (p->normalization is not used). */
PGLOSS_API pgloss_status pgloss_perceptual_from_physical_batch(
    size_t n, const pgloss_physical_array *p, pgloss_color_space space,
    const pgloss_perceptual_array_out *q, signed char *status);

/* pgloss_rgb_from_lab_ex and pgloss_lab_from_rgb_ex. */
PGLOSS_API pgloss_status pgloss_rgb_from_lab_batch(size_t n, pgloss_strided3 lab,
                                                   pgloss_color_space space,
                                                   pgloss_strided3_out rgb, signed char *status);
PGLOSS_API pgloss_status pgloss_lab_from_rgb_batch(size_t n, pgloss_strided3 rgb,
                                                   pgloss_color_space space,
                                                   pgloss_strided3_out lab, signed char *status);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_PERCEPTUAL_BATCH_H */
