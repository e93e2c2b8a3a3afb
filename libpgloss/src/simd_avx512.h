// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The AVX-512 helper of the float lobe (pgloss/detail/lobe.h): 16 lanes, masks in mask
 * registers, masked blends, vrcp14ps / vrsqrt14ps estimates (14 bits) and FMA for the FAST
 * tier. The interface is pgloss/detail/simd_scalar.h's. Not installed. */
#ifndef PGLOSS_SIMD_AVX512_H
#define PGLOSS_SIMD_AVX512_H

#include <immintrin.h>

typedef int32_t pgloss__i16 __attribute__((vector_size(64)));
typedef double pgloss__d16 __attribute__((vector_size(128)));

#endif /* PGLOSS_SIMD_AVX512_H */

#define PGLOSS_K(name) pgloss__v_##name
#define PV_LANES 16
#define pv_f __m512
#define pv_i pgloss__i16
#define pv_m __mmask16
#define pv_d pgloss__d16
#define pv_f1(x) _mm512_set1_ps(x)
#define pv_i1(x) ((pgloss__i16)_mm512_set1_epi32(x))
#define pv_sqrt _mm512_sqrt_ps
#define pv_min _mm512_min_ps
#define pv_max _mm512_max_ps
#define pv_imax(a, b) ((pgloss__i16)_mm512_max_epi32((__m512i)(a), (__m512i)(b)))
#define pv_abs(a) ((__m512)((pgloss__i16)(a) & 0x7fffffff))
#define pv_lt(a, b) _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ)
#define pv_le(a, b) _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ)
#define pv_gt(a, b) _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ)
#define pv_ge(a, b) _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ)
#define pv_ieq(a, b) _mm512_cmpeq_epi32_mask((__m512i)(a), (__m512i)(b))
#define pv_and(a, b) ((__mmask16)((a) & (b)))
#define pv_or(a, b) ((__mmask16)((a) | (b)))
#define pv_not(a) ((__mmask16)~(a))
#define pv_sel(m, a, b) _mm512_mask_blend_ps(m, b, a)
#define pv_seli(m, a, b) ((pgloss__i16)_mm512_mask_blend_epi32(m, (__m512i)(b), (__m512i)(a)))
#define pv_all(m) ((m) == 0xffff)
#define pv_any(m) ((m) != 0)
#define pv_bits(a) ((pgloss__i16)(a))
#define pv_from_bits(a) ((__m512)(a))
#define pv_trunc_i(a) ((pgloss__i16)_mm512_cvttps_epi32(a))
#define pv_cvt_f(a) _mm512_cvtepi32_ps((__m512i)(a))
#define pv_d_of(a) __builtin_convertvector(a, pgloss__d16)
#define pv_f_of(a) __builtin_convertvector(a, __m512)
#define pv_rcp_est _mm512_rcp14_ps
#define pv_rsqrt_est _mm512_rsqrt14_ps
#define PV_RCP_STEPS 1
#define PV_RSQRT_STEPS 1
#define pv_fma _mm512_fmadd_ps
#define pv_fnma _mm512_fnmadd_ps
#define pv_floor(x) _mm512_roundscale_ps(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)
#define pv_m1(b) ((__mmask16)((b) ? 0xffff : 0))
#define pv_count(m) __builtin_popcount((unsigned)(m))
#define pv_load _mm512_loadu_ps
#define pv_store _mm512_storeu_ps
#define pv_store_i(p, a) _mm512_storeu_si512((void *)(p), (__m512i)(a))
