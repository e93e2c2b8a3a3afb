// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The wall clock and the median's comparison, shared by the benchmark programs (bench_core.c,
 * bench_texture.c). Include after defining _POSIX_C_SOURCE (clock_gettime). */
#ifndef PGLOSS_BENCH_CLOCK_H
#define PGLOSS_BENCH_CLOCK_H

#include <time.h>

static inline double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* qsort's comparison for doubles (the median of repeated timings). */
static inline int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#endif
