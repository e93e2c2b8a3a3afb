// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/color.h — CIELAB ↔ linear RGB (Rec. 709 by default, or another working colour
 * space), for the colour part of Fig. 13.
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

/*
 * Working colour spaces: the linear RGB that ρd is expressed in. CIELAB stays relative to D65
 * in every space. A space whose white is not D65 (ACEScg: the ACES white (0.32168, 0.33767))
 * is reached from D65 by a Bradford chromatic adaptation, so neutral L*a*b* still maps to
 * R = G = B = Y. The luminance Y (the CIE Y of the colour) does not depend on the working
 * space, so L* and the contrast gloss c (eqs. 4, 7) are the same whichever space is chosen;
 * only the RGB of ρd, and with it the gamut and per-channel energy checks, change.
 */
typedef enum pgloss_color_space {
    PGLOSS_COLOR_SPACE_LINEAR_REC709 = 0,     /* sRGB / Rec. 709 primaries, D65 (the default) */
    PGLOSS_COLOR_SPACE_ACESCG = 1,            /* ACES AP1 primaries, ACES white (Bradford from D65) */
    PGLOSS_COLOR_SPACE_LINEAR_DISPLAY_P3 = 2, /* Display P3 (DCI-P3 primaries), D65 */
    PGLOSS_COLOR_SPACE_LINEAR_REC2020 = 3     /* ITU-R BT.2020 primaries, D65 */
} pgloss_color_space;

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

/* The same three in a working space. Errors as above, plus ARGUMENT (unknown space; checked
 * right after NULL). pgloss_rgb_from_lab(lab, rgb) is
 * pgloss_rgb_from_lab_ex(lab, PGLOSS_COLOR_SPACE_LINEAR_REC709, rgb), and so on. */
PGLOSS_API pgloss_status pgloss_rgb_from_lab_ex(const double lab[3], pgloss_color_space space, double rgb[3]);
PGLOSS_API pgloss_status pgloss_lab_from_rgb_ex(const double rgb[3], pgloss_color_space space, double lab[3]);
PGLOSS_API pgloss_status pgloss_luminance_ex(const double rgb[3], pgloss_color_space space, double *Y);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_COLOR_H */
