// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// <pgloss_perceptual_bsdf> for genglsl: Fig. 13's five parameters → (ρd, ρs, α) with
// pgloss_physical_from_perceptual_ex (glsl/pgloss.glsl), then <pgloss_bsdf>.
#include "mx_pgloss_bsdf.glsl"

void mx_pgloss_perceptual_bsdf(ClosureData closureData, float weight, float lightness, float a, float b,
                               float c, float d, int normalization, int color_space, vec3 N,
                               inout BSDF bsdf)
{
    pgloss_physical p;
    int st = pgloss_physical_from_perceptual_ex(pgloss_perceptual(lightness, a, b, c, d), normalization,
                                                color_space, p);
    if (st < 0 && st != PGLOSS_ERR_GAMUT)
    {
        bsdf.throughput = vec3(0.0);
        return;   // black, as the C core's material for invalid parameters
    }
    // Out of gamut: clamp the colour to the working space, as renderers do.
    mx_pgloss_bsdf(closureData, weight, max(p.rho_d, vec3(0.0)), p.rho_s, p.alpha_x, normalization, N, bsdf);
}
