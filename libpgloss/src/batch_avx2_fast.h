/* The FAST tier's eval/pdf loop on AVX2 + FMA, in intrinsics: the twin of
 * batch_avx512_fast.h on 8 lanes. vrcpps / vrsqrtps estimates (relative error <= 1.5·2^-12)
 * refined by one Newton step (then about 2e-7), FMA, and 2^n built in the exponent bits.
 * Included by batch_isa.c only when it is compiled for AVX2 and the FAST tier.
 * Blocks of 8 whose directions all have squared lengths in [2^-100, 2^100] take this path;
 * any other block, and the tail, take the generic loop. */
#ifndef PGLOSS_BATCH_AVX2_FAST_H
#define PGLOSS_BATCH_AVX2_FAST_H

#include <immintrin.h>

#define PGLOSS_VW 8

#define V1(x) _mm256_set1_ps(x)

PGLOSS_INLINE __m256 v_rsqrt(__m256 x)
{
    const __m256 y = _mm256_rsqrt_ps(x);
    const __m256 hxy = _mm256_mul_ps(_mm256_mul_ps(V1(0.5f), x), y);
    return _mm256_mul_ps(y, _mm256_fnmadd_ps(hxy, y, V1(1.5f)));
}

PGLOSS_INLINE __m256 v_rcp(__m256 x)
{
    const __m256 r = _mm256_rcp_ps(x);
    return _mm256_mul_ps(r, _mm256_fnmadd_ps(x, r, V1(2.0f)));
}

/* exp(x) for x <= 0 (0 below ln FLT_MIN), as pgloss__exp_neg_fast. */
PGLOSS_INLINE __m256 v_exp_neg(__m256 x)
{
    const __m256 xc = _mm256_max_ps(x, V1(-87.33654f));
    const __m256 n = _mm256_round_ps(_mm256_mul_ps(xc, V1(1.44269504088896341f)),
                                     _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    __m256 r = _mm256_fnmadd_ps(n, V1(0.693145751953125f), xc);
    r = _mm256_fnmadd_ps(n, V1(1.428606765330187e-06f), r);
    __m256 p = V1(1.0f / 120.0f);
    p = _mm256_fmadd_ps(p, r, V1(1.0f / 24.0f));
    p = _mm256_fmadd_ps(p, r, V1(1.0f / 6.0f));
    p = _mm256_fmadd_ps(p, r, V1(0.5f));
    p = _mm256_fmadd_ps(p, r, V1(1.0f));
    p = _mm256_fmadd_ps(p, r, V1(1.0f));
    /* n in [-126, 0]: 2^n is a normal float with biased exponent n + 127. */
    const __m256 scale = _mm256_castsi256_ps(
        _mm256_slli_epi32(_mm256_add_epi32(_mm256_cvtps_epi32(n), _mm256_set1_epi32(127)), 23));
    const __m256 keep = _mm256_cmp_ps(x, V1(-87.33654f), _CMP_GE_OQ);
    return _mm256_and_ps(keep, _mm256_mul_ps(p, scale));
}

PGLOSS_INLINE int v_eval_pdf_block(const pgloss__batch_consts *restrict k, const unsigned active,
                                   const int norm, const float *ox_, const float *oy_,
                                   const float *oz_, const float *ix_, const float *iy_,
                                   const float *iz_, float *fr_, float *fg_, float *fb_,
                                   float *pdf_, const int want_f, const int want_p)
{
    __m256 ox = _mm256_loadu_ps(ox_), oy = _mm256_loadu_ps(oy_), oz = _mm256_loadu_ps(oz_);
    __m256 ix = _mm256_loadu_ps(ix_), iy = _mm256_loadu_ps(iy_), iz = _mm256_loadu_ps(iz_);
    const __m256 lo2 = _mm256_fmadd_ps(ox, ox, _mm256_fmadd_ps(oy, oy, _mm256_mul_ps(oz, oz)));
    const __m256 li2 = _mm256_fmadd_ps(ix, ix, _mm256_fmadd_ps(iy, iy, _mm256_mul_ps(iz, iz)));
    const __m256 safe = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(lo2, V1(0x1p-100f), _CMP_GE_OQ),
                      _mm256_cmp_ps(lo2, V1(0x1p100f), _CMP_LE_OQ)),
        _mm256_and_ps(_mm256_cmp_ps(li2, V1(0x1p-100f), _CMP_GE_OQ),
                      _mm256_cmp_ps(li2, V1(0x1p100f), _CMP_LE_OQ)));
    if (_mm256_movemask_ps(safe) != 0xFF)
        return 0;
    const __m256 no = v_rsqrt(lo2), ni = v_rsqrt(li2);
    ox = _mm256_mul_ps(ox, no);
    oy = _mm256_mul_ps(oy, no);
    oz = _mm256_mul_ps(oz, no);
    ix = _mm256_mul_ps(ix, ni);
    iy = _mm256_mul_ps(iy, ni);
    iz = _mm256_mul_ps(iz, ni);
    const __m256 upper = _mm256_and_ps(_mm256_cmp_ps(oz, _mm256_setzero_ps(), _CMP_GT_OQ),
                                       _mm256_cmp_ps(iz, _mm256_setzero_ps(), _CMP_GT_OQ));
    __m256 fr = _mm256_setzero_ps(), fg = fr, fb = fr, p = fr;
    if (active & PGLOSS_LOBE_DIFFUSE) {
        fr = V1(k->fd[0]);
        fg = V1(k->fd[1]);
        fb = V1(k->fd[2]);
        if (want_p)
            p = _mm256_mul_ps(V1(k->pd * PGLOSS_INV_PI_F), iz);
    }
    if (active & PGLOSS_LOBE_SPECULAR) {
        const __m256 hx = _mm256_add_ps(ox, ix), hy = _mm256_add_ps(oy, iy),
                     hz = _mm256_add_ps(oz, iz);
        const __m256 ex = _mm256_mul_ps(hx, V1(k->inv_ax)), ey = _mm256_mul_ps(hy, V1(k->inv_ay));
        const __m256 hz2 = _mm256_max_ps(_mm256_mul_ps(hz, hz), V1(FLT_MIN));
        const __m256 t2 = _mm256_fmadd_ps(ex, ex, _mm256_mul_ps(ey, ey));
        const __m256 e =
            v_exp_neg(_mm256_sub_ps(_mm256_setzero_ps(), _mm256_mul_ps(t2, v_rcp(hz2))));
        const __m256 ci = _mm256_max_ps(iz, V1(COS_MIN_F)), co = _mm256_max_ps(oz, V1(COS_MIN_F));
        const __m256 hzc = _mm256_add_ps(ci, co);
        const __m256 hh = _mm256_fmadd_ps(hx, hx, _mm256_fmadd_ps(hy, hy, _mm256_mul_ps(hz, hz)));
        const __m256 inv_hzc = v_rcp(hzc);
        const __m256 inv_hzc2 = _mm256_mul_ps(inv_hzc, inv_hzc);
        __m256 nn = _mm256_setzero_ps();
        if (!want_f)
            ; /* the pdf does not depend on the normalisation */
        else if (norm == PGLOSS_NORM_WARD_DUR)
            nn = v_rcp(_mm256_mul_ps(ci, co));
        else if (norm == PGLOSS_NORM_BOUNDED)
            nn = _mm256_mul_ps(hh, _mm256_mul_ps(inv_hzc2, inv_hzc2));
        else
            nn = v_rsqrt(_mm256_mul_ps(ci, co));
        if (want_f) {
            const __m256 fs = _mm256_mul_ps(_mm256_mul_ps(V1(k->spec_scale), e), nn);
            fr = _mm256_add_ps(fr, fs);
            fg = _mm256_add_ps(fg, fs);
            fb = _mm256_add_ps(fb, fs);
        }
        if (want_p) {
            const __m256 ps = _mm256_mul_ps(V1(k->ps * k->pdf2), _mm256_mul_ps(e, hh));
            p = _mm256_fmadd_ps(ps, _mm256_mul_ps(inv_hzc2, inv_hzc), p);
        }
    }
    /* min(·, FLT_MAX) also turns an overflow to Inf into FLT_MAX (vminps returns its second
     * operand only for NaN, which finite input cannot produce here). */
    if (want_f) {
        _mm256_storeu_ps(fr_, _mm256_and_ps(upper, _mm256_min_ps(fr, V1(FLT_MAX))));
        _mm256_storeu_ps(fg_, _mm256_and_ps(upper, _mm256_min_ps(fg, V1(FLT_MAX))));
        _mm256_storeu_ps(fb_, _mm256_and_ps(upper, _mm256_min_ps(fb, V1(FLT_MAX))));
    }
    if (want_p)
        _mm256_storeu_ps(pdf_, _mm256_and_ps(upper, _mm256_min_ps(p, V1(FLT_MAX))));
    return 1;
}

#undef V1
#endif
