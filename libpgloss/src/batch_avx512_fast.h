// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* AVX-512 primitives of the FAST tier's eval/pdf block (batch_fast_block.h): 16 lanes,
 * vrcp14ps / vrsqrt14ps estimates (relative error <= 2^-14) refined by one Newton step,
 * vreduceps and vscalefps for exp2, and masked adds. */
#ifndef PGLOSS_BATCH_AVX512_FAST_H
#define PGLOSS_BATCH_AVX512_FAST_H

#include <immintrin.h>

#define PGLOSS_VW 16
typedef __m512 pgloss__v;
typedef __mmask16 pgloss__m;
#define V1(x) _mm512_set1_ps(x)
#define VZERO() _mm512_setzero_ps()
#define VLOAD(p) _mm512_loadu_ps(p)
#define VSTORE(p, v) _mm512_storeu_ps(p, v)
#define VADD _mm512_add_ps
#define VSUB _mm512_sub_ps
#define VMUL _mm512_mul_ps
#define VMAX _mm512_max_ps
#define VMIN _mm512_min_ps
#define VFMADD _mm512_fmadd_ps
#define VFNMADD _mm512_fnmadd_ps
#define VKEEP(m, v) _mm512_maskz_mov_ps(m, v) /* v where m, else 0 */
#define VRSQRT_EST _mm512_rsqrt14_ps
#define VRCP_EST _mm512_rcp14_ps
#define VRCP_EST_BITS 14
/* g - floor(g), and p · 2^floor(g) for g >= -127 (v_exp2_neg clamps g there), 0 at
 * floor(g) = -127: scalef would give a subnormal there. */
#define VFRAC(g) _mm512_reduce_ps(g, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define VSCALE_FLOOR(p, g, frac)                                                                   \
    _mm512_maskz_scalef_ps(_mm512_cmp_ps_mask(g, V1(-126.0f), _CMP_GE_OQ), p, g)
/* a > 0 and b > 0, for floats that are not NaN: on the bits, a positive float is a positive
 * integer and -0 or a negative one is negative (integer ops leave the FP multiply pipes free). */
#define VBOTH_POSITIVE(a, b)                                                                       \
    _mm512_cmp_epi32_mask(_mm512_min_epi32(_mm512_castps_si512(a), _mm512_castps_si512(b)),       \
                          _mm512_setzero_si512(), _MM_CMPINT_GT)
/* max(a, b) of floats where b > 0 and a is not NaN, on the bits (a negative a, -0 included,
 * is a negative integer): on the integer pipes, leaving the FP multiply pipes free. */
#define VMAX_POS(a, b)                                                                             \
    _mm512_castsi512_ps(_mm512_max_epi32(_mm512_castps_si512(a), _mm512_castps_si512(b)))
#define VADD_KEEP(m, a, b) _mm512_maskz_add_ps(m, a, b) /* a + b where m, else 0 */

/* Whether every squared length of two blocks lies in [lo, hi] (positive normals): on the
 * bits, as signed integers, so that NaN and Inf fail too. */
PGLOSS_INLINE_FN int v_all_in(pgloss__v a, pgloss__v b, float lo, float hi)
{
    const __m512i ia = _mm512_castps_si512(a), ib = _mm512_castps_si512(b);
    const __m512i mn = _mm512_min_epi32(ia, ib), mx = _mm512_max_epi32(ia, ib);
    const __mmask16 ok = _mm512_cmp_epi32_mask(mn, _mm512_castps_si512(V1(lo)), _MM_CMPINT_GE) &
                         _mm512_cmp_epi32_mask(mx, _mm512_castps_si512(V1(hi)), _MM_CMPINT_LE);
    return ok == 0xFFFF;
}

#endif
