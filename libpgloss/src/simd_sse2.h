// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The SSE2 helper of the float lobe (pgloss/detail/lobe.h): 4 lanes, masks as all-ones lanes,
 * selects by bitwise logic (SSE2 has no blend), rcpps / rsqrtps estimates (12 bits) for the
 * FAST tier, no FMA. The interface is pgloss/detail/simd_scalar.h's. Not installed. */
#ifndef PGLOSS_SIMD_SSE2_H
#define PGLOSS_SIMD_SSE2_H

#include <emmintrin.h>

typedef int32_t pgloss__i4 __attribute__((vector_size(16)));
typedef double pgloss__d4 __attribute__((vector_size(32)));

static inline __m128 pgloss__sel4(pgloss__i4 m, __m128 a, __m128 b)
{
    return (__m128)(((pgloss__i4)a & m) | ((pgloss__i4)b & ~m));
}
static inline pgloss__i4 pgloss__imax4(pgloss__i4 a, pgloss__i4 b)
{
    const pgloss__i4 m = a > b;
    return (a & m) | (b & ~m);
}
static inline __m128 pgloss__floor4(__m128 x) /* |x| < 2^31 */
{
    const __m128 t = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
    return pgloss__sel4(t > x, t - 1.0f, t);
}

#endif /* PGLOSS_SIMD_SSE2_H */

#define PGLOSS_K(name) pgloss__v_##name
#define PV_LANES 4
#define pv_f __m128
#define pv_i pgloss__i4
#define pv_m pgloss__i4
#define pv_d pgloss__d4
#define pv_f1(x) _mm_set1_ps(x)
#define pv_i1(x) ((pgloss__i4)_mm_set1_epi32(x))
#define pv_sqrt _mm_sqrt_ps
#define pv_min _mm_min_ps
#define pv_max _mm_max_ps
#define pv_imax pgloss__imax4
#define pv_abs(a) ((__m128)((pgloss__i4)(a) & 0x7fffffff))
#define pv_lt(a, b) ((a) < (b))
#define pv_le(a, b) ((a) <= (b))
#define pv_gt(a, b) ((a) > (b))
#define pv_ge(a, b) ((a) >= (b))
#define pv_ieq(a, b) ((a) == (b))
#define pv_and(a, b) ((a) & (b))
#define pv_or(a, b) ((a) | (b))
#define pv_not(a) (~(a))
#define pv_sel pgloss__sel4
#define pv_seli(m, a, b) (((a) & (m)) | ((b) & ~(m)))
#define pv_all(m) (_mm_movemask_ps((__m128)(m)) == 0xf)
#define pv_any(m) (_mm_movemask_ps((__m128)(m)) != 0)
#define pv_bits(a) ((pgloss__i4)(a))
#define pv_from_bits(a) ((__m128)(a))
#define pv_trunc_i(a) ((pgloss__i4)_mm_cvttps_epi32(a))
#define pv_cvt_f(a) _mm_cvtepi32_ps((__m128i)(a))
#define pv_d_of(a) __builtin_convertvector(a, pgloss__d4)
#define pv_f_of(a) __builtin_convertvector(a, __m128)
#define pv_rcp_est _mm_rcp_ps
#define pv_rsqrt_est _mm_rsqrt_ps
#define PV_RCP_STEPS 1
#define PV_RSQRT_STEPS 1
#define pv_fma(a, b, c) ((a) * (b) + (c))
#define pv_fnma(a, b, c) ((c) - (a) * (b))
#define pv_floor pgloss__floor4
#define pv_m1(b) ((pgloss__i4)_mm_set1_epi32(-(int)((b) != 0)))
#define pv_count(m) __builtin_popcount((unsigned)_mm_movemask_ps((__m128)(m)))
#define pv_load _mm_loadu_ps
#define pv_store _mm_storeu_ps
#define pv_store_i(p, a) _mm_storeu_si128((__m128i *)(p), (__m128i)(a))
