// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* A paint from its perceptual description (Fig. 13) to a material, then the BRDF (eq. 2):
 * eval, pdf and one importance sample; the verdicts of the validity checks. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <pgloss/pgloss.h>

static void require(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "paint.c: %s\n", what);
        exit(1);
    }
}

int main(void)
{
    /* The paper's Fig. 14 red paint: L*, a*, b*, contrast gloss c, distinctness-of-image gloss d. */
    const pgloss_perceptual red = {35.0, 45.0, 25.0, 0.06, 0.95};
    pgloss_physical p;
    pgloss_status st = pgloss_physical_from_perceptual(&red, PGLOSS_NORM_WARD, &p); /* eqs. 6-8 */
    require(st == PGLOSS_OK, pgloss_status_string(st));
    printf("rho_d %.4f %.4f %.4f  rho_s %.4f  alpha %.2f\n", p.rho_d[0], p.rho_d[1], p.rho_d[2],
           p.rho_s, p.alpha_x);

    pgloss_material m;
    st = pgloss_material_init(&m, &p);
    require(st == PGLOSS_OK, pgloss_status_string(st));

    /* Shading frame: normal +z, wo towards the viewer, wi towards the light (any length). */
    const pgloss_vec3 wo = {0.0f, 0.5f, 1.0f}, wi = {0.0f, -0.5f, 1.0f}; /* the mirror pair */
    pgloss_rgb f;
    float pdf;
    st = pgloss_eval_pdf(&m, wo, wi, PGLOSS_LOBE_ALL, &f, &pdf);
    require(st == PGLOSS_OK, pgloss_status_string(st));
    printf("f %.3f %.3f %.3f  pdf %.3f\n", f.r, f.g, f.b, pdf);

    /* One sample from three uniform numbers; pdf 0 would mark a rejected sample. */
    const float u[3] = {0.25f, 0.5f, 0.75f};
    pgloss_sample_record s;
    st = pgloss_sample(&m, wo, u, PGLOSS_LOBE_ALL, &s);
    require(st == PGLOSS_OK && s.pdf > 0.0f, "sample");
    float pdf_again;
    pgloss_pdf(&m, wo, s.wi, PGLOSS_LOBE_ALL, &pdf_again);
    require(fabsf(pdf_again - s.pdf) <= 1e-5f * s.pdf, "the sample's pdf is pgloss_pdf's");
    printf("sampled the %s lobe\n", s.lobe == PGLOSS_LOBE_SPECULAR ? "specular" : "diffuse");

    /* Experiment 1's grey paint in gloss space (eqs. 3-4) and its distance to another (eq. 5). */
    double L, c, d, D;
    st = pgloss_gloss_from_physical(0.193, 0.066, 0.07, &L, &c, &d);
    require(st == PGLOSS_OK, pgloss_status_string(st));
    pgloss_gloss_distance(c, d, 0.1, 0.9, &D);
    printf("L* %.2f  c %.4f  d %.2f  D to (0.1, 0.9) %.4f\n", L, c, d, D);

    /* Outside the model: the status says why; the outputs are still finite. */
    const pgloss_physical too_bright = {{0.767, 0.767, 0.767}, 0.3, 0.04, 0.04, PGLOSS_NORM_WARD};
    st = pgloss_check_physical(&too_bright);
    require(st == PGLOSS_ERR_ENERGY, "energy");
    printf("%s: %s\n", pgloss_status_name(st), pgloss_status_string(st));
    const pgloss_perceptual untrusted = {50.0, 0.0, 0.0, 0.05, 0.7};
    st = pgloss_check_perceptual(&untrusted);
    require(st == PGLOSS_WARN_ALPHA_UNTRUSTED && st > 0, "warning");
    printf("%s\n", pgloss_status_name(st));
    return 0;
}
