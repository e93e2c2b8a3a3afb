// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/perceptual_batch.h — the perceptual and colour functions of pgloss/perceptual.h
 * and pgloss/color.h over SoA double arrays (a texture of paints), with a status per element.
 *
 * Element j gets exactly what the scalar function returns for element j: the same status and
 * the same outputs, bit for bit (each loop runs the scalar function's per-element code,
 * vectorised, on the best ISA of the running CPU, and the scalar functions run the same code:
 * docs/kernels.md), so
 * the scalar functions' error against the shared vectors (relative 1e-12, tests/vectors) is
 * theirs too. That includes the documented outputs of a failed element: 0, except the exact
 * values of a GAMUT element (rgb_from_lab, physical_from_perceptual) and the matched values of
 * an ENVELOPE element (match_gloss). Timings: bench/bench_texture.c.
 *
 * status (may be NULL): n signed chars, element j's pgloss_status.
 * Returned status: the first error (< 0) in index order if any element has one, else the
 * first warning (PGLOSS_WARN_ALPHA_UNTRUSTED) if any, else PGLOSS_OK. So a return >= 0 means
 * every output is usable. Errors of the whole call (nothing is written, status included): with
 * n > 0 a required array that is NULL (PGLOSS_ERR_NULL), an unknown colour space
 * (PGLOSS_ERR_ARGUMENT), and physical_from_perceptual's unknown normalization
 * (PGLOSS_ERR_NORMALIZATION). check_physical takes the normalization per element, in the
 * scalar function's order. n == 0 is OK.
 *
 * Input and output arrays must not overlap, except that an output may be the very same array
 * as an input (in place, element by element).
 */
#ifndef PGLOSS_PERCEPTUAL_BATCH_H
#define PGLOSS_PERCEPTUAL_BATCH_H

#include <stddef.h>
#include "pgloss/batch_materials.h"
#include "pgloss/perceptual.h"

#ifdef __cplusplus
extern "C" {
#endif

/* n five-parameter descriptions (pgloss_perceptual, Fig. 13), read / written. */
typedef struct pgloss_perceptual_array { const double *L, *a, *b, *c, *d; } pgloss_perceptual_array;
typedef struct pgloss_perceptual_out { double *L, *a, *b, *c, *d; } pgloss_perceptual_out;
/* n physical parameter sets, written (pgloss_physical_array is the input form); alpha_y may
 * be NULL where the output is isotropic (physical_from_perceptual): then it is not written. */
typedef struct pgloss_physical_out {
    double *rho_d_r, *rho_d_g, *rho_d_b;
    double *rho_s;
    double *alpha_x, *alpha_y;
} pgloss_physical_out;
/* n CIELAB colours (L*, a*, b*), and n linear RGB colours, as double arrays. */
typedef struct pgloss_lab_array { const double *L, *a, *b; } pgloss_lab_array;
typedef struct pgloss_lab_out { double *L, *a, *b; } pgloss_lab_out;
typedef struct pgloss_rgb_array_d { const double *r, *g, *b; } pgloss_rgb_array_d;

/* pgloss_gloss_from_physical (eqs. 3, 4, L* of ρd), element by element. */
PGLOSS_API pgloss_status pgloss_gloss_from_physical_batch(size_t n, const double *rho_d,
                                                          const double *rho_s,
                                                          const double *alpha, double *L,
                                                          double *c, double *d,
                                                          signed char *status);

/* pgloss_physical_from_gloss (eqs. 6, 7, 8). */
PGLOSS_API pgloss_status pgloss_physical_from_gloss_batch(size_t n, const double *L,
                                                          const double *c, const double *d,
                                                          double *rho_d, double *rho_s,
                                                          double *alpha, signed char *status);

/* pgloss_envelope_contrast (Fig. 10). */
PGLOSS_API pgloss_status pgloss_envelope_contrast_batch(size_t n, const double *L, double *c_max,
                                                        signed char *status);

/* pgloss_match_gloss (§5.2, Fig. 12). */
PGLOSS_API pgloss_status pgloss_match_gloss_batch(size_t n, const double *rho_d,
                                                  const double *rho_s, const double *L_target,
                                                  double *rho_d_out, double *rho_s_out,
                                                  signed char *status);

/* pgloss_check_physical (p->normalization for every element; alpha_y NULL: isotropic).
 * Statuses only: status may still be NULL (then only the returned status is of use). */
PGLOSS_API pgloss_status pgloss_check_physical_batch(size_t n, const pgloss_physical_array *p,
                                                     signed char *status);

/* pgloss_check_perceptual / pgloss_check_perceptual_ex. */
PGLOSS_API pgloss_status pgloss_check_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                                       signed char *status);
PGLOSS_API pgloss_status pgloss_check_perceptual_batch_ex(size_t n, pgloss_perceptual_array q,
                                                          pgloss_color_space space,
                                                          signed char *status);

/* pgloss_physical_from_perceptual / _ex (Fig. 13 → eq. 2's parameters, with the validity
 * of pgloss_physical_from_perceptual; for the full model check, pgloss_check_perceptual). */
PGLOSS_API pgloss_status pgloss_physical_from_perceptual_batch(size_t n, pgloss_perceptual_array q,
                                                               pgloss_normalization normalization,
                                                               pgloss_physical_out p,
                                                               signed char *status);
PGLOSS_API pgloss_status pgloss_physical_from_perceptual_batch_ex(
    size_t n, pgloss_perceptual_array q, pgloss_normalization normalization,
    pgloss_color_space space, pgloss_physical_out p, signed char *status);

/* pgloss_perceptual_from_physical / _ex (p->normalization is not used; alpha_y NULL:
 * isotropic). */
PGLOSS_API pgloss_status pgloss_perceptual_from_physical_batch(size_t n,
                                                               const pgloss_physical_array *p,
                                                               pgloss_perceptual_out q,
                                                               signed char *status);
PGLOSS_API pgloss_status pgloss_perceptual_from_physical_batch_ex(size_t n,
                                                                  const pgloss_physical_array *p,
                                                                  pgloss_color_space space,
                                                                  pgloss_perceptual_out q,
                                                                  signed char *status);

/* pgloss_rgb_from_lab / _ex and pgloss_lab_from_rgb / _ex. */
PGLOSS_API pgloss_status pgloss_rgb_from_lab_batch(size_t n, pgloss_lab_array lab,
                                                   pgloss_rgb_out_d rgb, signed char *status);
PGLOSS_API pgloss_status pgloss_rgb_from_lab_batch_ex(size_t n, pgloss_lab_array lab,
                                                      pgloss_color_space space,
                                                      pgloss_rgb_out_d rgb, signed char *status);
PGLOSS_API pgloss_status pgloss_lab_from_rgb_batch(size_t n, pgloss_rgb_array_d rgb,
                                                   pgloss_lab_out lab, signed char *status);
PGLOSS_API pgloss_status pgloss_lab_from_rgb_batch_ex(size_t n, pgloss_rgb_array_d rgb,
                                                      pgloss_color_space space,
                                                      pgloss_lab_out lab, signed char *status);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_PERCEPTUAL_BATCH_H */
