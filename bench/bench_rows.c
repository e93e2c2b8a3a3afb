// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The BRDF batch's front end on 2^20 pairs (2^16 with --quick): pgloss_eval_pdf_batch, float32,
 * one material, on (n, 3) rows (the layout numpy's channel-last arrays and the Python binding
 * pass) and on SoA columns, each with and without a status array. Prints a Markdown table: the
 * min over 15 alternating calls (5 with --quick) of the thread's CPU time (robust to a shared
 * host's descheduling), and each layout's time over the columns without statuses.
 *     bench_rows [--quick] */
#define _POSIX_C_SOURCE 200809L
#include <pgloss/batch.h>
#include <pgloss/brdf.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

int main(int argc, char **argv)
{
    const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    const size_t n = (size_t)1 << (quick ? 16 : 20);
    const int reps = quick ? 5 : 15;
    float *wo = malloc(n * 12), *wi = malloc(n * 12), *f = malloc(n * 12), *pdf = malloc(n * 4);
    float *col[6], *fc[3];
    for (int k = 0; k < 6; ++k)
        col[k] = malloc(n * 4);
    for (int k = 0; k < 3; ++k)
        fc[k] = malloc(n * 4);
    signed char *st = malloc(n);
    srand(1);
    for (size_t j = 0; j < n; ++j) {
        for (int k = 0; k < 3; ++k) {
            wo[3 * j + k] = (float)rand() / (float)RAND_MAX - 0.5f;
            wi[3 * j + k] = (float)rand() / (float)RAND_MAX - 0.5f;
        }
        wo[3 * j + 2] = fabsf(wo[3 * j + 2]) + 0.1f; /* above the surface: every element valid */
        wi[3 * j + 2] = fabsf(wi[3 * j + 2]) + 0.1f;
        for (int k = 0; k < 3; ++k) {
            col[k][j] = wo[3 * j + k];
            col[3 + k][j] = wi[3 * j + k];
        }
    }
    const pgloss_physical ph = {{0.3, 0.2, 0.1}, 0.05, 0.1, 0.1, PGLOSS_NORM_WARD};
    pgloss_material m;
    if (pgloss_material_init(&m, &ph) != PGLOSS_OK)
        return 1;
    const char *names[4] = {"rows, status", "rows, no status", "columns, status", "columns, no status"};
    double best[4] = {1e30, 1e30, 1e30, 1e30};
    for (int r = 0; r < reps; ++r)
        for (int v = 0; v < 4; ++v) {
            pgloss_strided3 a, b;
            pgloss_strided3_out fo;
            if (v < 2) {
                a = pgloss_strided3_rows(wo, 4);
                b = pgloss_strided3_rows(wi, 4);
                fo = pgloss_strided3_out_rows(f, 4);
            } else {
                a = pgloss_strided3_soa(col[0], col[1], col[2], 4);
                b = pgloss_strided3_soa(col[3], col[4], col[5], 4);
                fo = pgloss_strided3_out_soa(fc[0], fc[1], fc[2], 4);
            }
            double t = cpu_ms();
            const pgloss_status s = pgloss_eval_pdf_batch(NULL, &m, NULL, PGLOSS_LOBE_ALL, n, a, b, fo,
                                                          pgloss_strided_out_of(pdf, 4),
                                                          v % 2 == 0 ? st : NULL);
            t = cpu_ms() - t;
            if (s != PGLOSS_OK)
                return 1;
            if (t < best[v])
                best[v] = t;
        }
    printf("pgloss_eval_pdf_batch, float32, one material, %zu pairs, ISA %s; the thread's CPU time, "
           "min of %d alternating calls\n\n| layout | ms | ns/pair | / columns, no status |\n|---|---:|---:|---:|\n",
           n, pgloss_isa_name(pgloss_isa_best()), reps);
    for (int v = 0; v < 4; ++v)
        printf("| %s | %.2f | %.2f | %.2f |\n", names[v], best[v], best[v] * 1e6 / (double)n, best[v] / best[3]);
    for (int k = 0; k < 6; ++k)
        free(col[k]);
    for (int k = 0; k < 3; ++k)
        free(fc[k]);
    free(wo), free(wi), free(f), free(pdf), free(st);
    return 0;
}
