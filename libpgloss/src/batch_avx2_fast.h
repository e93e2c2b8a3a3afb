/* AVX2 + FMA primitives of the FAST tier's eval/pdf block (batch_fast_block.h): 8 lanes,
 * vrcpps / vrsqrtps estimates (relative error <= 1.5·2^-12) refined by one Newton step (then
 * about 2e-7), masks as all-ones lanes, and 2^n built in the exponent bits. */
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
#define VCMP(a, b, op) _mm256_cmp_ps(a, b, op)
#define MAND(a, b) _mm256_and_ps(a, b)
#define MALL(m) (_mm256_movemask_ps(m) == 0xFF)
#define VKEEP(m, v) _mm256_and_ps(m, v) /* v where m, else 0 */
#define VRSQRT_EST _mm256_rsqrt_ps
#define VRCP_EST _mm256_rcp_ps
#define VROUND(v) _mm256_round_ps(v, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)
/* p · 2^n for integral n in [-126, 0]: 2^n is the normal float with biased exponent n + 127. */
#define VSCALE2(p, n)                                                                              \
    _mm256_mul_ps(p, _mm256_castsi256_ps(_mm256_slli_epi32(                                        \
                         _mm256_add_epi32(_mm256_cvtps_epi32(n), _mm256_set1_epi32(127)), 23)))

#endif
