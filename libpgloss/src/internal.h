// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Internal helpers shared by the scalar (double) paths. Not installed. */
#ifndef PGLOSS_INTERNAL_H
#define PGLOSS_INTERNAL_H

#include <float.h>
#include <stddef.h>
#include <math.h>
#include "pgloss/brdf.h"
#include "pgloss/color.h"

#define PGLOSS_PI 3.14159265358979323846
#define PGLOSS_INV_PI 0.31830988618379067154

/* Normalises v into out (double). The components are floats, so their squares can neither
 * overflow nor underflow in double (3.4e38² · 3 < DBL_MAX, (1.4e-45)² > DBL_MIN): no scaling
 * is needed, and the result is within an ulp of double. Returns 0 for a zero or non-finite
 * vector (out is then set to 0); a NaN or Inf component makes the sum NaN or Inf. */
static inline int pgloss__normalize(pgloss_vec3 v, double out[3])
{
    const double x = v.x, y = v.y, z = v.z;
    const double l2 = x * x + y * y + z * z;
    if (!(l2 > 0.0) || !(l2 <= DBL_MAX)) {
        out[0] = out[1] = out[2] = 0.0;
        return 0;
    }
    const double inv = 1.0 / sqrt(l2);
    out[0] = x * inv; out[1] = y * inv; out[2] = z * inv;
    return 1;
}

/* Rounds a non-negative double to float without overflowing to Inf. */
static inline float pgloss__to_float(double v)
{
    return v < (double)FLT_MAX ? (float)v : FLT_MAX;
}

/* A known pgloss_color_space (an int from another language may hold anything). */
static inline int pgloss__valid_color_space(pgloss_color_space space)
{
    return (int)space >= (int)PGLOSS_COLOR_SPACE_LINEAR_REC709 && (int)space <= (int)PGLOSS_COLOR_SPACE_LINEAR_REC2020;
}

static inline int pgloss__valid_normalization(pgloss_normalization n)
{
    return n == PGLOSS_NORM_WARD || n == PGLOSS_NORM_WARD_DUR || n == PGLOSS_NORM_BOUNDED;
}

static inline double pgloss__luminance3(double r, double g, double b)
{
    return PGLOSS_LUMA_R * r + PGLOSS_LUMA_G * g + PGLOSS_LUMA_B * b;
}

/* f and pdf of the active lobes at unit directions o, i (double). Either output may be NULL. */
void pgloss__eval_pdf_d(const pgloss_material *m, unsigned active, const double o[3],
                        const double i[3], double f[3], double *pdf);

/* f, pdf of the active lobes at directions wo, wi as the caller gave them (any length):
 * PGLOSS_ERR_DIRECTION, with f and pdf 0, for a zero or non-finite direction. Either output
 * may be NULL; *cos_i (cos_i may be NULL) receives wi.z/|wi| for valid directions. */
pgloss_status pgloss__eval_pdf_raw(const pgloss_material *m, unsigned active, pgloss_vec3 wo,
                                   pgloss_vec3 wi, double f[3], double *pdf, double *cos_i);

/* The checks every consumer of pgloss_physical shares, in the documented order: NONFINITE
 * (|v| > limit counts as non-finite: DBL_MAX, or FLT_MAX for a float material), NEGATIVE,
 * ALPHA. PGLOSS_OK if they pass. */
pgloss_status pgloss__check_physical_values(const pgloss_physical *p, double limit);

/* Specular-lobe probability for an active mask, in double. */
double pgloss__specular_probability_d(const pgloss_material *m, unsigned active);

#endif
