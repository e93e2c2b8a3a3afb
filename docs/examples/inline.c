// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss/inline.h: the BRDF at one shading point, header-only (no library call); the material
 * is made once by the library's pgloss_material_init. The results agree with pgloss_eval_pdf
 * within the FLOAT tier's error. */
#include <math.h>
#include <stdio.h>

#include <pgloss/inline.h>
#include <pgloss/pgloss.h>

int main(void)
{
    const pgloss_physical p = {{0.767, 0.767, 0.767}, 0.099, 0.04, 0.04, PGLOSS_NORM_WARD};
    pgloss_material m;
    if (pgloss_material_init(&m, &p) != PGLOSS_OK) /* once per material, in the library */
        return 1;

    /* Per shading point, inlined: */
    const pgloss_vec3 wo = {0.2f, 0.4f, 1.0f}, wi = {-0.2f, -0.35f, 1.0f};
    pgloss_rgb f;
    float pdf;
    if (pgloss_eval_pdf_inline(&m, wo, wi, PGLOSS_LOBE_ALL, &f, &pdf) != PGLOSS_OK)
        return 1;

    pgloss_rgb f_ref;
    float pdf_ref;
    pgloss_eval_pdf(&m, wo, wi, PGLOSS_LOBE_ALL, &f_ref, &pdf_ref);
    if (fabsf(f.r - f_ref.r) > 1e-5f * f_ref.r || fabsf(pdf - pdf_ref) > 1e-5f * pdf_ref)
        return 1;
    printf("f %.3f  pdf %.3f\n", f.r, pdf);

    const float u[3] = {0.1f, 0.6f, 0.3f};
    pgloss_sample_record s;
    if (pgloss_sample_inline(&m, wo, u, PGLOSS_LOBE_ALL, &s) != PGLOSS_OK || s.pdf <= 0.0f)
        return 1;
    float pdf_at;
    pgloss_pdf_inline(&m, wo, s.wi, PGLOSS_LOBE_ALL, &pdf_at);
    if (fabsf(pdf_at - s.pdf) > 1e-5f * s.pdf)
        return 1;
    printf("sampled the %s lobe, weight %.3f\n",
           s.lobe == PGLOSS_LOBE_SPECULAR ? "specular" : "diffuse", s.weight.r);
    return 0;
}
