// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The AVX2 + FMA helper of the float lobe (pgloss/detail/lobe.h): 8 lanes, masks as all-ones
 * lanes, blends, vrcpps / vrsqrtps estimates (12 bits) and FMA for the FAST tier. The
 * interface is pgloss/detail/simd_scalar.h's. Not installed. */
#ifndef PGLOSS_SIMD_AVX2_H
#define PGLOSS_SIMD_AVX2_H

#include <immintrin.h>

typedef int32_t pgloss__i8 __attribute__((vector_size(32)));
typedef double pgloss__d8 __attribute__((vector_size(64)));

/* The first m < 8 floats at p, the other lanes `fill`: one masked load, where a copy through
 * the stack would stall on store-to-load forwarding (the batch's last block, and n = 1). */
static inline __m256 pgloss__load_part8(const float *p, size_t m, float fill)
{
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i in = _mm256_cmpgt_epi32(_mm256_set1_epi32((int)m), lane);
    return _mm256_blendv_ps(_mm256_set1_ps(fill), _mm256_maskload_ps(p, in), _mm256_castsi256_ps(in));
}

#endif /* PGLOSS_SIMD_AVX2_H */

#define PGLOSS_K(name) pgloss__v_##name
#define PV_LANES 8
#define pv_f __m256
#define pv_i pgloss__i8
#define pv_m pgloss__i8
#define pv_d pgloss__d8
#define pv_f1(x) _mm256_set1_ps(x)
#define pv_i1(x) ((pgloss__i8)_mm256_set1_epi32(x))
#define pv_sqrt _mm256_sqrt_ps
#define pv_min _mm256_min_ps
#define pv_max _mm256_max_ps
#define pv_imax(a, b) ((pgloss__i8)_mm256_max_epi32((__m256i)(a), (__m256i)(b)))
#define pv_abs(a) ((__m256)((pgloss__i8)(a) & 0x7fffffff))
#define pv_lt(a, b) ((a) < (b))
#define pv_le(a, b) ((a) <= (b))
#define pv_gt(a, b) ((a) > (b))
#define pv_ge(a, b) ((a) >= (b))
#define pv_ieq(a, b) ((a) == (b))
#define pv_and(a, b) ((a) & (b))
#define pv_or(a, b) ((a) | (b))
#define pv_not(a) (~(a))
#define pv_sel(m, a, b) _mm256_blendv_ps(b, a, (__m256)(m))
#define pv_seli(m, a, b) ((pgloss__i8)_mm256_blendv_ps((__m256)(b), (__m256)(a), (__m256)(m)))
#define pv_all(m) (_mm256_movemask_ps((__m256)(m)) == 0xff)
#define pv_any(m) (_mm256_movemask_ps((__m256)(m)) != 0)
#define pv_bits(a) ((pgloss__i8)(a))
#define pv_from_bits(a) ((__m256)(a))
#define pv_trunc_i(a) ((pgloss__i8)_mm256_cvttps_epi32(a))
#define pv_cvt_f(a) _mm256_cvtepi32_ps((__m256i)(a))
#define pv_d_of(a) __builtin_convertvector(a, pgloss__d8)
#define pv_f_of(a) __builtin_convertvector(a, __m256)
#define pv_rcp_est _mm256_rcp_ps
#define pv_rsqrt_est _mm256_rsqrt_ps
#define PV_RCP_STEPS 1
#define PV_RSQRT_STEPS 1
#define pv_fma _mm256_fmadd_ps
#define pv_fnma _mm256_fnmadd_ps
#define pv_floor _mm256_floor_ps
#define pv_m1(b) ((pgloss__i8)_mm256_set1_epi32(-(int)((b) != 0)))
#define pv_count(m) __builtin_popcount((unsigned)_mm256_movemask_ps((__m256)(m)))
#define pv_load _mm256_loadu_ps
#define pv_load_part pgloss__load_part8
#define pv_store _mm256_storeu_ps
#define pv_store_i(p, a) _mm256_storeu_si256((__m256i *)(p), (__m256i)(a))
