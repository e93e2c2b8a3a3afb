// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/detail/simd_scalar.h — the one-lane helper of the float lobe (pgloss/detail/lobe.h):
 * pv_f is a float, pv_m an int. With it the lobe is the per-shading-point code of
 * pgloss/inline.h; libpgloss/src/simd_*.h are the same interface over SSE2, AVX2 and AVX-512
 * vectors. Not part of the API: the pv_ names are #undef'd at the end of lobe.h.
 *
 * Every operation here is the IEEE operation its vector counterparts perform (min and max as
 * minps and maxps order their operands), so that the lobe gives the same bits on every helper.
 */
#ifndef PGLOSS_DETAIL_SIMD_SCALAR_H
#define PGLOSS_DETAIL_SIMD_SCALAR_H

#include <math.h>
#include <stdint.h>
#include <string.h>

PGLOSS_INLINE_FN float pgloss_s_from_bits(int32_t b) { float f; memcpy(&f, &b, sizeof f); return f; }
PGLOSS_INLINE_FN int32_t pgloss_s_bits(float f) { int32_t b; memcpy(&b, &f, sizeof b); return b; }
PGLOSS_INLINE_FN float pgloss_s_min(float a, float b) { return a < b ? a : b; }
PGLOSS_INLINE_FN float pgloss_s_max(float a, float b) { return a > b ? a : b; }
PGLOSS_INLINE_FN int32_t pgloss_s_imax(int32_t a, int32_t b) { return a > b ? a : b; }
PGLOSS_INLINE_FN float pgloss_s_abs(float a) { return pgloss_s_from_bits(pgloss_s_bits(a) & 0x7fffffff); }
/* floor for |x| < 2^31 */
PGLOSS_INLINE_FN float pgloss_s_floor(float x)
{
    const float t = (float)(int32_t)x;
    return t > x ? t - 1.0f : t;
}

#endif /* PGLOSS_DETAIL_SIMD_SCALAR_H */

/* The names the lobe uses (defined at every inclusion; lobe.h undefines them). */
#define PGLOSS_K(name) pgloss_inl_##name
#define PV_LANES 1
#define pv_f float
#define pv_i int32_t
#define pv_m int
#define pv_d double
#define pv_f1(x) ((float)(x))
#define pv_i1(x) ((int32_t)(x))
#define pv_sqrt(a) sqrtf(a)
#define pv_min pgloss_s_min
#define pv_max pgloss_s_max
#define pv_imax pgloss_s_imax
#define pv_abs pgloss_s_abs
#define pv_lt(a, b) ((a) < (b))
#define pv_le(a, b) ((a) <= (b))
#define pv_gt(a, b) ((a) > (b))
#define pv_ge(a, b) ((a) >= (b))
#define pv_ieq(a, b) ((a) == (b))
#define pv_and(a, b) ((a) & (b))
#define pv_or(a, b) ((a) | (b))
#define pv_not(a) (!(a))
#define pv_sel(m, a, b) ((m) ? (a) : (b))
#define pv_seli(m, a, b) ((m) ? (a) : (b))
#define pv_all(m) (m)
#define pv_any(m) (m)
#define pv_bits pgloss_s_bits
#define pv_from_bits pgloss_s_from_bits
#define pv_trunc_i(a) ((int32_t)(a))
#define pv_cvt_f(a) ((float)(a))
#define pv_d_of(a) ((double)(a))
#define pv_f_of(a) ((float)(a))
/* the FAST tier's operations (not used by the per-point functions): exact here */
#define pv_rcp_est(a) (1.0f / (a))
#define pv_rsqrt_est(a) (1.0f / sqrtf(a))
#define PV_RCP_STEPS 0
#define PV_RSQRT_STEPS 0
#define pv_fma(a, b, c) ((a) * (b) + (c))
#define pv_fnma(a, b, c) ((c) - (a) * (b))
#define pv_floor pgloss_s_floor
#define pv_m1(b) ((int)((b) != 0))
#define pv_count(m) ((m) != 0)
#define pv_load(p) (*(p))
#define pv_store(p, a) (*(p) = (a))
#define pv_store_i(p, a) (*(p) = (a))
