// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/perceptual.h — the perceptually uniform gloss space of the paper.
 *
 *   L  CIELAB lightness L* in [0, 100] of the diffuse reflectance (§4)
 *   c  contrast gloss,                    c = cbrt(ρs + ρd/2) - cbrt(ρd/2)         (eq. 4)
 *   d  distinctness-of-image gloss,       d = 1 - α                                (eq. 3)
 *   D  gloss difference,                  D = sqrt(Δc² + (1.78 Δd)²)                (eq. 5)
 * and the inverse mapping: ρd = f⁻¹(L) (eq. 6), ρs = (c + cbrt(ρd/2))³ - ρd/2 (eq. 7),
 * α = 1 - d (eq. 8), where f⁻¹ is the CIE 1976 inverse lightness function (the paper's f
 * normalised to [0, 1]; here L is in CIELAB's usual [0, 100]).
 *
 * All functions are in double: they run once per material, not per sample. Every
 * function returns a status; on an error the outputs are 0 unless stated otherwise.
 * No finite input gives a NaN or Inf output: where a finite input would overflow double
 * (L* > 6.6e104, c > ~5e102 in eq. 7, ρs + ρd/2 > DBL_MAX, differences beyond DBL_MAX in
 * eq. 5, ...) the function returns PGLOSS_ERR_NONFINITE with the fallback outputs.
 * For a coloured diffuse, ρd in eqs. 4, 6, 7 is its luminance Y (the CIE Y of the colour:
 * Rec. 709 weights for Rec. 709 RGB, the same Y whichever working colour space ρd is in).
 */
#ifndef PGLOSS_PERCEPTUAL_H
#define PGLOSS_PERCEPTUAL_H

#include <stddef.h>
#include "pgloss/brdf.h"
#include "pgloss/color.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CIE 1976: ε = 216/24389, κ = 24389/27 (the exact rational forms, not 0.008856 / 903.3). */
#define PGLOSS_CIE_EPSILON (216.0 / 24389.0)
#define PGLOSS_CIE_KAPPA (24389.0 / 27.0)
/* Weight of the d axis in the gloss distance (eq. 5). */
#define PGLOSS_D_WEIGHT 1.78
/* α above this is outside what the paper trusts (§4: "should not be much larger than 0.2"). */
#define PGLOSS_ALPHA_TRUSTED_MAX 0.2
/* Slack for the energy/envelope comparisons, so that parameters produced by rounding
 * exactly onto the boundary (e.g. ρd + ρs = 1) are accepted. */
#define PGLOSS_BOUNDARY_TOLERANCE 1e-12

/* The paper's five-parameter colour/gloss description (Fig. 13). */
typedef struct pgloss_perceptual {
    double L;     /* CIELAB L*, [0, 100] */
    double a;     /* CIELAB a* */
    double b;     /* CIELAB b* */
    double c;     /* contrast gloss, >= 0 */
    double d;     /* distinctness-of-image gloss, < 1 */
} pgloss_perceptual;

/* L* from the luminance factor Y (Yn = 1): L = κY if Y <= ε, else 116 cbrt(Y) - 16.
 * Y >= 0 (Y > 1 gives L > 100). Errors: NULL, NONFINITE, NEGATIVE. */
PGLOSS_API pgloss_status pgloss_lightness_from_luminance(double Y, double *L);

/* Y from L*: Y = L/κ if L <= κε (= 8), else ((L + 16)/116)³. L >= 0 (L > 100 gives Y > 1).
 * Errors: NULL, NONFINITE (also for finite L above ~6.6e104, where Y would overflow; Y = 0),
 * LIGHTNESS (L < 0). */
PGLOSS_API pgloss_status pgloss_luminance_from_lightness(double L, double *Y);

/* Eq. 4, computed without cancellation as ρs / (A² + AB + B²), A = cbrt(ρs + ρd/2),
 * B = cbrt(ρd/2). Errors: NULL, NONFINITE, NEGATIVE. */
PGLOSS_API pgloss_status pgloss_contrast_gloss(double rho_d, double rho_s, double *c);

/* Eq. 7, computed as c (c² + 3cB + 3B²), B = cbrt(ρd/2). Errors: NULL, NONFINITE, NEGATIVE. */
PGLOSS_API pgloss_status pgloss_specular_from_contrast(double rho_d, double c, double *rho_s);

/* Eqs. 3, 4 and L* of ρd, for an achromatic paint. Errors: NULL, NONFINITE (also when
 * ρs + ρd/2 overflows, as in pgloss_contrast_gloss), NEGATIVE, ALPHA (α <= 0); warning
 * ALPHA_UNTRUSTED (α > 0.2). */
PGLOSS_API pgloss_status pgloss_gloss_from_physical(double rho_d, double rho_s, double alpha,
                                         double *L, double *c, double *d);

/* Eqs. 6, 7, 8. Errors: NULL, NONFINITE (also for a finite c so large that ρs overflows),
 * LIGHTNESS (L outside [0, 100]), NEGATIVE (c < 0), ALPHA (d >= 1); warning ALPHA_UNTRUSTED
 * (d < 0.8). No envelope check here (see pgloss_check_perceptual). */
PGLOSS_API pgloss_status pgloss_physical_from_gloss(double L, double c, double d,
                                         double *rho_d, double *rho_s, double *alpha);

/* Eq. 5 between the paints (c1, d1) and (c2, d2). The status is the verdict on the two paints,
 * the one pgloss_physical_from_gloss gives on c and d: NEGATIVE (c < 0), ALPHA (d >= 1: α =
 * 1 − d <= 0, no lobe), paint 1 before paint 2, then the warning ALPHA_UNTRUSTED (d < 0.8).
 * D is written for any finite points, with NEGATIVE and ALPHA too (a distance in the plane,
 * e.g. between the unclipped points of pgloss_isogloss_contour). Errors: NULL, NONFINITE
 * (an input, or D beyond DBL_MAX: D = 0), NEGATIVE, ALPHA. */
PGLOSS_API pgloss_status pgloss_gloss_distance(double c1, double d1, double c2, double d2, double *D);

/* Envelope of gloss space (Fig. 10): the largest c at lightness L under energy conservation
 * ρd + ρs <= 1, i.e. cbrt(1 - ρd/2) - cbrt(ρd/2) with ρd = f⁻¹(L). Errors: NULL, NONFINITE,
 * LIGHTNESS. */
PGLOSS_API pgloss_status pgloss_envelope_contrast(double L, double *c_max);

/*
 * Gloss matching across lightness (§5.2, Fig. 12): keeps c (and so d) of (ρd, ρs) and moves
 * the paint to lightness L_target: ρd' = f⁻¹(L_target), ρs' from eq. 7.
 * Errors: NULL, NONFINITE, NEGATIVE, LIGHTNESS; ENVELOPE if ρd' + ρs' > 1 — then the outputs
 * are still the (finite) matched values, so that a caller can show how far outside they are.
 */
PGLOSS_API pgloss_status pgloss_match_gloss(double rho_d, double rho_s, double L_target,
                                 double *rho_d_out, double *rho_s_out);

/*
 * Isogloss contour (§5.1, Fig. 11): n points at gloss distance D from (c0, d0),
 * c_k = c0 + D cos θk, d_k = d0 + (D / 1.78) sin θk, θk = 2πk/n, k = 0..n-1.
 * Points are not clipped to the valid region (check them with pgloss_check_perceptual).
 * Errors: NULL, NONFINITE, NEGATIVE (D < 0), ARGUMENT (n == 0).
 */
PGLOSS_API pgloss_status pgloss_isogloss_contour(double c0, double d0, double D, size_t n,
                                      double *c, double *d);

/*
 * Is p inside the paper's model? Returns the first reason it is not, checked in this order:
 * NULL, NONFINITE (also |value| > FLT_MAX, as pgloss_material_init), NEGATIVE, ALPHA,
 * NORMALIZATION, ENERGY (max over channels of ρd + ρs > 1),
 * then the warning ALPHA_UNTRUSTED (max(αx, αy) > 0.2); PGLOSS_OK otherwise.
 */
PGLOSS_API pgloss_status pgloss_check_physical(const pgloss_physical *p);

/*
 * Is q inside the model? First reason, in this order: NULL, NONFINITE (also α = 1 − d above
 * FLT_MAX, which no material holds), LIGHTNESS, NEGATIVE
 * (c < 0), ALPHA (d >= 1), GAMUT (L*a*b* has no non-negative linear Rec. 709 RGB),
 * ENVELOPE (c > envelope at L), ENERGY (a colour channel of ρd plus ρs exceeds 1, possible
 * for saturated colours inside the luminance envelope), warning ALPHA_UNTRUSTED (d < 0.8).
 */
PGLOSS_API pgloss_status pgloss_check_perceptual(const pgloss_perceptual *q);

/*
 * Fig. 13's colour/gloss description → physical parameters: CIELAB (D65) → XYZ → linear
 * Rec. 709 ρd; ρs from eq. 7 with the luminance Y = f⁻¹(L); α = αx = αy = 1 - d.
 * Errors as pgloss_physical_from_gloss, plus NORMALIZATION and GAMUT (negative RGB: the
 * exact, negative values are still written). Warning ALPHA_UNTRUSTED.
 */
PGLOSS_API pgloss_status pgloss_physical_from_perceptual(const pgloss_perceptual *q,
                                              pgloss_normalization normalization,
                                              pgloss_physical *p);

/*
 * The inverse: L*a*b* of ρd, c from eq. 4 with Y = luminance(ρd), d = 1 - α where
 * α = sqrt(αx αy) (the geometric mean: an extension for anisotropic lobes, which the paper
 * did not study). Errors: NULL, NONFINITE, NEGATIVE, ALPHA; warning ALPHA_UNTRUSTED when
 * max(αx, αy) > 0.2 — the same test as pgloss_check_physical, not the geometric mean (a lobe
 * is outside the trusted range as soon as one of its spreads is), so d >= 0.8 may come with
 * the warning for an anisotropic lobe.
 */
PGLOSS_API pgloss_status pgloss_perceptual_from_physical(const pgloss_physical *p, pgloss_perceptual *q);

/*
 * The three functions above in a working colour space (color.h): ρd is linear RGB of `space`,
 * and GAMUT / ENERGY are decided in that space. ρs, c and L* use the luminance Y, which is
 * the same in every space. Errors as the functions without _ex, plus ARGUMENT (unknown
 * space; checked right after NULL). The functions without _ex are these with
 * PGLOSS_COLOR_SPACE_LINEAR_REC709.
 */
PGLOSS_API pgloss_status pgloss_check_perceptual_ex(const pgloss_perceptual *q, pgloss_color_space space);
PGLOSS_API pgloss_status pgloss_physical_from_perceptual_ex(const pgloss_perceptual *q,
                                                 pgloss_normalization normalization,
                                                 pgloss_color_space space, pgloss_physical *p);
PGLOSS_API pgloss_status pgloss_perceptual_from_physical_ex(const pgloss_physical *p, pgloss_color_space space,
                                                 pgloss_perceptual *q);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_PERCEPTUAL_H */
