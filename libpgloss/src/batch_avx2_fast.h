// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* AVX2 + FMA primitives of the FAST tier's eval/pdf block (batch_fast_block.h): 8 lanes,
 * vrcpps / vrsqrtps estimates (relative error <= 1.5·2^-12) refined by one Newton step (then
 * about 2e-7), masks as all-ones lanes, and the power of two of exp2 built in the exponent
 * bits. */
#ifndef PGLOSS_BATCH_AVX2_FAST_H
#define PGLOSS_BATCH_AVX2_FAST_H

#include <immintrin.h>

#define PGLOSS_VW 8
typedef __m256 pgloss__v;
typedef __m256 pgloss__m;
#define V1(x) _mm256_set1_ps(x)
#define VZERO() _mm256_setzero_ps()
#define VLOAD(p) _mm256_loadu_ps(p)
#define VSTORE(p, v) _mm256_storeu_ps(p, v)
#define VADD _mm256_add_ps
#define VSUB _mm256_sub_ps
#define VMUL _mm256_mul_ps
#define VMAX _mm256_max_ps
#define VMIN _mm256_min_ps
#define VFMADD _mm256_fmadd_ps
#define VFNMADD _mm256_fnmadd_ps
#define VKEEP(m, v) _mm256_and_ps(m, v) /* v where m, else 0 */
#define VRSQRT_EST _mm256_rsqrt_ps
#define VRCP_EST _mm256_rcp_ps
#define VRCP_EST_BITS 11 /* relative error <= 1.5·2^-12 */
/* g - floor(g), and p · 2^floor(g) for g >= -127 (v_exp2_neg clamps g there): the float
 * whose biased exponent is floor(g) + 127, which is 0 (so the product is 0) at -127. */
#define VFRAC(g) _mm256_sub_ps(g, _mm256_floor_ps(g))
#define VSCALE_FLOOR(p, g, frac)                                                                   \
    _mm256_mul_ps(p, _mm256_castsi256_ps(_mm256_slli_epi32(                                        \
                         _mm256_add_epi32(_mm256_cvtps_epi32(_mm256_sub_ps(g, frac)),              \
                                          _mm256_set1_epi32(127)),                                 \
                         23)))
/* a > 0 and b > 0, for floats that are not NaN: on the bits, a positive float is a positive
 * integer and -0 or a negative one is negative. */
#define VBOTH_POSITIVE(a, b)                                                                       \
    _mm256_castsi256_ps(_mm256_cmpgt_epi32(                                                        \
        _mm256_min_epi32(_mm256_castps_si256(a), _mm256_castps_si256(b)), _mm256_setzero_si256()))
/* max(a, b) of floats where b > 0 and a is not NaN, on the bits (a negative a, -0 included,
 * is a negative integer). */
#define VMAX_POS(a, b)                                                                             \
    _mm256_castsi256_ps(_mm256_max_epi32(_mm256_castps_si256(a), _mm256_castps_si256(b)))
#define VADD_KEEP(m, a, b) _mm256_and_ps(m, _mm256_add_ps(a, b)) /* a + b where m, else 0 */

/* Whether every squared length of two blocks lies in [lo, hi] (positive normals): on the
 * bits, as signed integers, so that NaN and Inf fail too. */
PGLOSS_INLINE_FN int v_all_in(pgloss__v a, pgloss__v b, float lo, float hi)
{
    const __m256i ia = _mm256_castps_si256(a), ib = _mm256_castps_si256(b);
    const __m256i mn = _mm256_min_epi32(ia, ib), mx = _mm256_max_epi32(ia, ib);
    const __m256i bad = _mm256_or_si256(
        _mm256_cmpgt_epi32(_mm256_castps_si256(V1(lo)), mn),
        _mm256_cmpgt_epi32(mx, _mm256_castps_si256(V1(hi))));
    return _mm256_testz_si256(bad, bad);
}

#endif
