// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss/batch.h: the BRDF of n direction pairs in one call, (n, 3) float rows, with a status
 * per element; each element agrees with the scalar pgloss_eval_pdf. */
#include <math.h>
#include <stdio.h>

#include <pgloss/pgloss.h>

enum { N = 4 };

int main(void)
{
    const pgloss_physical p = {{0.193, 0.193, 0.193}, 0.066, 0.07, 0.07, PGLOSS_NORM_WARD};
    pgloss_material m;
    if (pgloss_material_init(&m, &p) != PGLOSS_OK)
        return 1;

    float wo[N][3] = {{0, 0.5f, 1}, {0.3f, 0, 1}, {0, 0, 1}, {0.2f, 0.1f, 1}};
    float wi[N][3] = {{0, -0.5f, 1}, {-0.3f, 0.1f, 1}, {0, 0, 0}, {-0.1f, 0.2f, 1}}; /* [2]: no direction */
    float f[N][3], pdf[N];
    signed char status[N];
    const pgloss_status st = pgloss_eval_pdf_batch(
        NULL, &m, NULL, PGLOSS_LOBE_ALL, N,                     /* NULL options: FLOAT, AUTO, float32 */
        pgloss_strided3_rows(wo, sizeof(float)), pgloss_strided3_rows(wi, sizeof(float)),
        pgloss_strided3_out_rows(f, sizeof(float)), pgloss_strided_out_of(pdf, sizeof(float)),
        status);
    printf("call: %s\n", pgloss_status_name(st)); /* the first invalid element's status */
    if (st != PGLOSS_ERR_DIRECTION)
        return 1;

    for (int j = 0; j < N; ++j) {
        const pgloss_vec3 o = {wo[j][0], wo[j][1], wo[j][2]}, i = {wi[j][0], wi[j][1], wi[j][2]};
        pgloss_rgb fs;
        float ps;
        const pgloss_status sj = pgloss_eval_pdf(&m, o, i, PGLOSS_LOBE_ALL, &fs, &ps);
        if (sj != status[j])
            return 1;
        /* The FLOAT tier agrees with the scalar reference to a few float ulps. */
        if (fabsf(f[j][0] - fs.r) > 1e-5f * fs.r || fabsf(pdf[j] - ps) > 1e-5f * ps)
            return 1;
        printf("%d: %-20s f %.4f  pdf %.4f\n", j, pgloss_status_name(sj), f[j][0], pdf[j]);
    }
    return 0;
}
