// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/color.h — CIELAB ↔ linear Rec. 709 RGB, for the colour part of Fig. 13.
 *
 * The white point is D65 as Rec. 709 defines it, by its chromaticity (0.3127, 0.3290):
 * Xn = 0.3127/0.3290, Yn = 1, Zn = 0.3583/0.3290. The RGB ↔ XYZ matrices are derived
 * from the Rec. 709 primaries and that white, so a* = b* = 0 maps to R = G = B = Y exactly
 * (to double rounding), and the luminance of RGB is the Y of CIELAB.
 */
#ifndef PGLOSS_COLOR_H
#define PGLOSS_COLOR_H

#include "pgloss/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Luminance Y of linear Rec. 709 RGB (the second row of the RGB → XYZ matrix). */
#define PGLOSS_LUMA_R 0.21263900587151036
#define PGLOSS_LUMA_G 0.71516867876775593
#define PGLOSS_LUMA_B 0.072192315360733715

/* lab = (L*, a*, b*) → linear Rec. 709 RGB. Errors: NULL, NONFINITE, LIGHTNESS (L outside
 * [0, 100]), GAMUT (a channel < −PGLOSS_BOUNDARY_TOLERANCE: the exact values are still
 * written). A channel in [−PGLOSS_BOUNDARY_TOLERANCE, 0) is rounding on the gamut boundary
 * and is returned as 0 with OK; so no OK result has a negative channel. */
PGLOSS_API pgloss_status pgloss_rgb_from_lab(const double lab[3], double rgb[3]);

/* Linear Rec. 709 RGB → (L*, a*, b*). Errors: NULL, NONFINITE, NEGATIVE. */
PGLOSS_API pgloss_status pgloss_lab_from_rgb(const double rgb[3], double lab[3]);

/* Luminance of linear Rec. 709 RGB. Errors: NULL, NONFINITE. */
PGLOSS_API pgloss_status pgloss_luminance(const double rgb[3], double *Y);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_COLOR_H */
