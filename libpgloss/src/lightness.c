// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* CIE 1976 lightness L* ↔ luminance factor Y (Yn = 1): the paper's f and f⁻¹ (§4, eq. 6),
 * scaled to CIELAB's [0, 100]. The exact rational constants make the two branches meet
 * continuously at Y = ε, L = κε = 8. */
#include "internal.h"
#include "perceptual_d.h"
#include "pgloss/perceptual.h"

pgloss_status pgloss_lightness_from_luminance(double Y, double *L)
{
    if (!L)
        return PGLOSS_ERR_NULL;
    *L = 0.0;
    if (!isfinite(Y))
        return PGLOSS_ERR_NONFINITE;
    if (Y < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    *L = pgloss__lightness_d(Y);
    return PGLOSS_OK;
}

pgloss_status pgloss_luminance_from_lightness(double L, double *Y)
{
    if (!Y)
        return PGLOSS_ERR_NULL;
    *Y = 0.0;
    if (!isfinite(L))
        return PGLOSS_ERR_NONFINITE;
    if (L < 0.0)
        return PGLOSS_ERR_LIGHTNESS;
    const double y = pgloss__luminance_d(L);
    /* Finite L* above ~6.6e104 would give Y = +Inf: no finite input may produce Inf. */
    if (!isfinite(y))
        return PGLOSS_ERR_NONFINITE;
    *Y = y;
    return PGLOSS_OK;
}
