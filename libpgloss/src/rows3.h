// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* (n, 3) float32 and float64 rows (x y z x y z …, any alignment) to three contiguous columns
 * and back, for batch_isa.c and batch.c: numpy's channel-last arrays reach the batches as such
 * rows, and a strided copy of one value at a time costs as much as the lobe. Float: AVX2 (also
 * in the AVX-512 file) de-interleaves 8 rows from 3 loads by blends and one lane permute per
 * column, SSE2 4 rows by shuffles. Double: SSE2, 2 rows from 3 loads by shuffles. Other
 * targets copy element by element. A pure copy: no value changes. Not installed. */
#ifndef PGLOSS_ROWS3_H
#define PGLOSS_ROWS3_H

#include <stddef.h>
#include <string.h>
#if defined(__AVX2__)
#include <immintrin.h>
#define PGLOSS__ROWS 8
#elif defined(__SSE2__)
#include <emmintrin.h>
#define PGLOSS__ROWS 4
#else
#define PGLOSS__ROWS 1
#endif

/* Rows [j, n) of `size`-byte values, one at a time: the tails the vector loops leave. */
static inline void pgloss__rows3_tail_in(const char *p, size_t size, size_t j, size_t n, void *x,
                                         void *y, void *z)
{
    for (; j < n; ++j, p += 3 * size) {
        memcpy((char *)x + j * size, p, size);
        memcpy((char *)y + j * size, p + size, size);
        memcpy((char *)z + j * size, p + 2 * size, size);
    }
}

static inline void pgloss__rows3_tail_out(const void *x, const void *y, const void *z,
                                          size_t size, size_t j, size_t n, char *p)
{
    for (; j < n; ++j, p += 3 * size) {
        memcpy(p, (const char *)x + j * size, size);
        memcpy(p + size, (const char *)y + j * size, size);
        memcpy(p + 2 * size, (const char *)z + j * size, size);
    }
}

/* Rows [0, n) at `rows` (byte pointer) into x, y, z. */
static inline void pgloss__rows3_to_columns(const void *rows, size_t n, float *x, float *y,
                                            float *z)
{
    const char *p = (const char *)rows;
    size_t j = 0;
#if defined(__AVX2__)
    /* Blend each column's 8 values into one register (the lane order a rotation), then
     * permute them into place: x = 0 3 6 9 …, y = 1 4 7 …, z = 2 5 8 … of the 24 floats. */
    const __m256i px = _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
    const __m256i py = _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6);
    const __m256i pz = _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7);
    for (; j + 8 <= n; j += 8, p += 96) {
        const __m256 a = _mm256_loadu_ps((const float *)p);
        const __m256 b = _mm256_loadu_ps((const float *)(p + 32));
        const __m256 c = _mm256_loadu_ps((const float *)(p + 64));
        const __m256 tx = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x92), c, 0x24);
        const __m256 ty = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x24), c, 0x49);
        const __m256 tz = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x49), c, 0x92);
        _mm256_storeu_ps(x + j, _mm256_permutevar8x32_ps(tx, px));
        _mm256_storeu_ps(y + j, _mm256_permutevar8x32_ps(ty, py));
        _mm256_storeu_ps(z + j, _mm256_permutevar8x32_ps(tz, pz));
    }
#elif defined(__SSE2__)
    for (; j + 4 <= n; j += 4, p += 48) {
        const __m128 a = _mm_loadu_ps((const float *)p);
        const __m128 b = _mm_loadu_ps((const float *)(p + 16));
        const __m128 c = _mm_loadu_ps((const float *)(p + 32));
        const __m128 bc = _mm_shuffle_ps(b, c, _MM_SHUFFLE(1, 0, 3, 2)); /* b2 b3 c0 c1 */
        _mm_storeu_ps(x + j, _mm_shuffle_ps(a, bc, _MM_SHUFFLE(3, 0, 3, 0)));
        _mm_storeu_ps(y + j, _mm_shuffle_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 1, 1)),
                                            _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 2, 3, 3)),
                                            _MM_SHUFFLE(2, 0, 2, 0)));
        _mm_storeu_ps(z + j, _mm_shuffle_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 1, 2, 2)),
                                            _mm_shuffle_ps(c, c, _MM_SHUFFLE(3, 3, 0, 0)),
                                            _MM_SHUFFLE(2, 0, 2, 0)));
    }
#endif
    pgloss__rows3_tail_in(p, 4, j, n, x, y, z);
}

/* Columns x, y, z [0, n) into rows [0, n) at `rows` (byte pointer). */
static inline void pgloss__columns_to_rows3(const float *x, const float *y, const float *z,
                                            size_t n, void *rows)
{
    char *p = (char *)rows;
    size_t j = 0;
#if defined(__AVX2__)
    /* The inverse of the above: each column permuted back (the same rotations), then blended. */
    const __m256i px = _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
    const __m256i py = _mm256_setr_epi32(5, 0, 3, 6, 1, 4, 7, 2);
    const __m256i pz = _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7);
    for (; j + 8 <= n; j += 8, p += 96) {
        const __m256 tx = _mm256_permutevar8x32_ps(_mm256_loadu_ps(x + j), px);
        const __m256 ty = _mm256_permutevar8x32_ps(_mm256_loadu_ps(y + j), py);
        const __m256 tz = _mm256_permutevar8x32_ps(_mm256_loadu_ps(z + j), pz);
        _mm256_storeu_ps((float *)p, _mm256_blend_ps(_mm256_blend_ps(tx, ty, 0x92), tz, 0x24));
        _mm256_storeu_ps((float *)(p + 32),
                         _mm256_blend_ps(_mm256_blend_ps(tx, ty, 0x24), tz, 0x49));
        _mm256_storeu_ps((float *)(p + 64),
                         _mm256_blend_ps(_mm256_blend_ps(tx, ty, 0x49), tz, 0x92));
    }
#elif defined(__SSE2__)
    for (; j + 4 <= n; j += 4, p += 48) {
        const __m128 vx = _mm_loadu_ps(x + j), vy = _mm_loadu_ps(y + j), vz = _mm_loadu_ps(z + j);
        _mm_storeu_ps((float *)p, _mm_shuffle_ps(_mm_shuffle_ps(vx, vy, _MM_SHUFFLE(1, 0, 1, 0)),
                                                 _mm_shuffle_ps(vz, vx, _MM_SHUFFLE(1, 1, 0, 0)),
                                                 _MM_SHUFFLE(2, 0, 2, 0)));
        _mm_storeu_ps((float *)(p + 16),
                      _mm_shuffle_ps(_mm_shuffle_ps(vy, vz, _MM_SHUFFLE(1, 1, 1, 1)),
                                     _mm_shuffle_ps(vx, vy, _MM_SHUFFLE(2, 2, 2, 2)),
                                     _MM_SHUFFLE(2, 0, 2, 0)));
        _mm_storeu_ps((float *)(p + 32),
                      _mm_shuffle_ps(_mm_shuffle_ps(vz, vx, _MM_SHUFFLE(3, 3, 2, 2)),
                                     _mm_shuffle_ps(vy, vz, _MM_SHUFFLE(3, 3, 3, 3)),
                                     _MM_SHUFFLE(2, 0, 2, 0)));
    }
#endif
    pgloss__rows3_tail_out(x, y, z, 4, j, n, p);
}

/* Float64 rows [0, n) at `rows` (byte pointer) into x, y, z: rows j, j + 1 are the loads
 * a = (x0 y0), b = (z0 x1), c = (y1 z1). */
static inline void pgloss__rows3d_to_columns(const void *rows, size_t n, double *x, double *y,
                                             double *z)
{
    const char *p = (const char *)rows;
    size_t j = 0;
#if defined(__SSE2__)
    for (; j + 2 <= n; j += 2, p += 48) {
        const __m128d a = _mm_loadu_pd((const double *)p);
        const __m128d b = _mm_loadu_pd((const double *)(p + 16));
        const __m128d c = _mm_loadu_pd((const double *)(p + 32));
        _mm_storeu_pd(x + j, _mm_shuffle_pd(a, b, 2)); /* a0 b1 */
        _mm_storeu_pd(y + j, _mm_shuffle_pd(a, c, 1)); /* a1 c0 */
        _mm_storeu_pd(z + j, _mm_shuffle_pd(b, c, 2)); /* b0 c1 */
    }
#endif
    pgloss__rows3_tail_in(p, 8, j, n, x, y, z);
}

/* Columns x, y, z [0, n) into float64 rows [0, n) at `rows` (byte pointer). */
static inline void pgloss__columns_to_rows3d(const double *x, const double *y, const double *z,
                                             size_t n, void *rows)
{
    char *p = (char *)rows;
    size_t j = 0;
#if defined(__SSE2__)
    for (; j + 2 <= n; j += 2, p += 48) {
        const __m128d vx = _mm_loadu_pd(x + j), vy = _mm_loadu_pd(y + j), vz = _mm_loadu_pd(z + j);
        _mm_storeu_pd((double *)p, _mm_unpacklo_pd(vx, vy));              /* x0 y0 */
        _mm_storeu_pd((double *)(p + 16), _mm_shuffle_pd(vz, vx, 2));     /* z0 x1 */
        _mm_storeu_pd((double *)(p + 32), _mm_unpackhi_pd(vy, vz));       /* y1 z1 */
    }
#endif
    pgloss__rows3_tail_out(x, y, z, 8, j, n, p);
}

#endif
