// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* A C program that uses an installed or embedded pgloss, as a renderer would
 * (scripts/test-package.sh builds it through find_package, pkg-config and add_subdirectory).
 * The expected values are the paper's formulas written out here, not pgloss's output:
 * eq. 3 (d = 1 - α), eq. 4 (c = cbrt(ρs + ρd/2) - cbrt(ρd/2)), CIE L* = 116 cbrt(Y) - 16, and a
 * Lambertian BRDF ρd/π (eq. 2 without its specular term) through the batched path. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <pgloss/pgloss.h>

static int failures;

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "consumer.c: FAILED %s\n", what);
        ++failures;
    }
}

int main(void)
{
    check(strcmp(pgloss_version(), PGLOSS_VERSION_STRING) == 0,
          "pgloss_version() is the version of the headers");
    char expect[32];
    snprintf(expect, sizeof expect, "%d.%d.%d", PGLOSS_VERSION_MAJOR, PGLOSS_VERSION_MINOR,
             PGLOSS_VERSION_PATCH);
    check(strcmp(expect, PGLOSS_VERSION_STRING) == 0, "PGLOSS_VERSION_STRING = MAJOR.MINOR.PATCH");

    /* Experiment 2's white paint: ρd = 0.767, ρs = 0.099, α = 0.04. */
    const double rd = 0.767, rs = 0.099, alpha = 0.04;
    double L, c, d;
    check(pgloss_gloss_from_physical(rd, rs, alpha, &L, &c, &d) == PGLOSS_OK, "gloss_from_physical status");
    check(fabs(c - (cbrt(rs + rd / 2) - cbrt(rd / 2))) < 1e-12, "eq. 4: contrast gloss c");
    check(fabs(d - (1 - alpha)) < 1e-12, "eq. 3: DOI gloss d = 1 - alpha");
    check(fabs(L - (116 * cbrt(rd) - 16)) < 1e-9, "L* of rho_d");

    /* A matte paint through the batched (run-time ISA) path: f = ρd/π for every wi above. */
    pgloss_physical p = {{0.5, 0.25, 0.125}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD};
    pgloss_material m;
    check(pgloss_material_init(&m, &p) == PGLOSS_OK, "material_init status");
    enum { N = 37 };
    float ox[N], oy[N], oz[N], ix[N], iy[N], iz[N], fr[N], fg[N], fb[N];
    for (int k = 0; k < N; ++k) {
        const float t = 0.04f * (float)k;
        ox[k] = 0.0f; oy[k] = sinf(t); oz[k] = cosf(t);
        ix[k] = sinf(t); iy[k] = 0.0f; iz[k] = cosf(t);
    }
    const pgloss_strided3 wo = pgloss_strided3_soa(ox, oy, oz, sizeof(float));
    const pgloss_strided3 wi = pgloss_strided3_soa(ix, iy, iz, sizeof(float));
    const pgloss_strided3_out f = pgloss_strided3_out_soa(fr, fg, fb, sizeof(float));
    const pgloss_strided_out no_pdf = {NULL, 0};
    check(pgloss_eval_pdf_batch(NULL, &m, NULL, PGLOSS_LOBE_ALL, N, wo, wi, f, no_pdf, NULL) == PGLOSS_OK,
          "eval_pdf_batch status");
    const double pi = 3.14159265358979323846;
    for (int k = 0; k < N; ++k) {
        check(fabs(fr[k] - 0.5 / pi) < 1e-6 && fabs(fg[k] - 0.25 / pi) < 1e-6 &&
              fabs(fb[k] - 0.125 / pi) < 1e-6, "eval_pdf_batch: Lambertian rho_d / pi");
    }
    check(strcmp(pgloss_status_name(PGLOSS_ERR_ENERGY), "PGLOSS_ERR_ENERGY") == 0, "status_name");

    if (failures) return 1;
    printf("consumer.c: pgloss %s (%s), c = %.6f, d = %.2f, L* = %.3f, batch on %s: OK\n",
           pgloss_version(),
#ifdef PGLOSS_STATIC
           "static",
#else
           "shared",
#endif
           c, d, L, pgloss_isa_name(pgloss_isa_best()));
    return 0;
}
