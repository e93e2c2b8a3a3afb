/* AVX-512 primitives of the FAST tier's eval/pdf block (batch_fast_block.h): 16 lanes,
 * vrcp14ps / vrsqrt14ps estimates (relative error <= 2^-14) refined by one Newton step,
 * and vscalefps for the power of two of exp. */
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
#define VCMP(a, b, op) _mm512_cmp_ps_mask(a, b, op)
#define MAND(a, b) ((pgloss__m)((a) & (b)))
#define MALL(m) ((m) == 0xFFFF)
#define VKEEP(m, v) _mm512_maskz_mov_ps(m, v) /* v where m, else 0 */
#define VRSQRT_EST _mm512_rsqrt14_ps
#define VRCP_EST _mm512_rcp14_ps
#define VROUND(v) _mm512_roundscale_ps(v, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)
/* p · 2^n for integral n in [-126, 0]. */
#define VSCALE2(p, n) _mm512_scalef_ps(p, n)

#endif
