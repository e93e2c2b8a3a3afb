/* The FAST tier's eval/pdf loop on AVX-512, in intrinsics: hardware reciprocal and
 * reciprocal-square-root estimates (vrcp14ps, vrsqrt14ps: relative error <= 2^-14) refined
 * by one Newton step (then within a few float ulps), FMA, and vscalefps for the exponent of
 * exp — no division and no square root, which bound the FLOAT tier on this ISA.
 * Included by batch_isa.c only when it is compiled for AVX-512 and the FAST tier.
 *
 * Blocks of 16 whose directions all have squared lengths in [2^-100, 2^100] (so nothing
 * overflows, underflows or is non-finite) take this path; any other block, and the tail,
 * take the generic loop, which handles every edge as the FLOAT tier does. */
#ifndef PGLOSS_BATCH_AVX512_FAST_H
#define PGLOSS_BATCH_AVX512_FAST_H

#include <immintrin.h>

#define PGLOSS_VW 16

#define V1(x) _mm512_set1_ps(x)

/* 1/sqrt(x), x normal: estimate + one Newton step y (1.5 - 0.5 x y²). */
PGLOSS_INLINE __m512 v_rsqrt(__m512 x)
{
    const __m512 y = _mm512_rsqrt14_ps(x);
    const __m512 hxy = _mm512_mul_ps(_mm512_mul_ps(V1(0.5f), x), y);
    return _mm512_mul_ps(y, _mm512_fnmadd_ps(hxy, y, V1(1.5f)));
}

/* 1/x, x normal: estimate + one Newton step r (2 - x r). */
PGLOSS_INLINE __m512 v_rcp(__m512 x)
{
    const __m512 r = _mm512_rcp14_ps(x);
    return _mm512_mul_ps(r, _mm512_fnmadd_ps(x, r, V1(2.0f)));
}

/* exp(x) for x <= 0 (0 below ln FLT_MIN): the reduction and degree-5 polynomial of
 * pgloss__exp_neg_fast, with the power of two applied by vscalefps. */
PGLOSS_INLINE __m512 v_exp_neg(__m512 x)
{
    const __m512 xc = _mm512_max_ps(x, V1(-87.33654f));
    const __m512 n = _mm512_roundscale_ps(_mm512_mul_ps(xc, V1(1.44269504088896341f)),
                                          _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    __m512 r = _mm512_fnmadd_ps(n, V1(0.693145751953125f), xc);
    r = _mm512_fnmadd_ps(n, V1(1.428606765330187e-06f), r);
    __m512 p = V1(1.0f / 120.0f);
    p = _mm512_fmadd_ps(p, r, V1(1.0f / 24.0f));
    p = _mm512_fmadd_ps(p, r, V1(1.0f / 6.0f));
    p = _mm512_fmadd_ps(p, r, V1(0.5f));
    p = _mm512_fmadd_ps(p, r, V1(1.0f));
    p = _mm512_fmadd_ps(p, r, V1(1.0f));
    const __mmask16 under = _mm512_cmp_ps_mask(x, V1(-87.33654f), _CMP_LT_OQ);
    return _mm512_maskz_mov_ps((__mmask16)~under, _mm512_scalef_ps(p, n));
}

/* PGLOSS_VW = 16 evaluations at j; returns 0 (nothing written) if the block needs the generic path. */
PGLOSS_INLINE int v_eval_pdf_block(const pgloss__batch_consts *restrict k, const unsigned active,
                               const int norm, const float *ox_, const float *oy_,
                               const float *oz_, const float *ix_, const float *iy_,
                               const float *iz_, float *fr_, float *fg_, float *fb_, float *pdf_,
                               const int want_f, const int want_p)
{
    __m512 ox = _mm512_loadu_ps(ox_), oy = _mm512_loadu_ps(oy_), oz = _mm512_loadu_ps(oz_);
    __m512 ix = _mm512_loadu_ps(ix_), iy = _mm512_loadu_ps(iy_), iz = _mm512_loadu_ps(iz_);
    const __m512 lo2 = _mm512_fmadd_ps(ox, ox, _mm512_fmadd_ps(oy, oy, _mm512_mul_ps(oz, oz)));
    const __m512 li2 = _mm512_fmadd_ps(ix, ix, _mm512_fmadd_ps(iy, iy, _mm512_mul_ps(iz, iz)));
    const __mmask16 safe =
        _mm512_cmp_ps_mask(lo2, V1(0x1p-100f), _CMP_GE_OQ) &
        _mm512_cmp_ps_mask(lo2, V1(0x1p100f), _CMP_LE_OQ) &
        _mm512_cmp_ps_mask(li2, V1(0x1p-100f), _CMP_GE_OQ) &
        _mm512_cmp_ps_mask(li2, V1(0x1p100f), _CMP_LE_OQ);
    if (safe != 0xFFFF)
        return 0;
    const __m512 no = v_rsqrt(lo2), ni = v_rsqrt(li2);
    ox = _mm512_mul_ps(ox, no);
    oy = _mm512_mul_ps(oy, no);
    oz = _mm512_mul_ps(oz, no);
    ix = _mm512_mul_ps(ix, ni);
    iy = _mm512_mul_ps(iy, ni);
    iz = _mm512_mul_ps(iz, ni);
    const __mmask16 upper = _mm512_cmp_ps_mask(oz, _mm512_setzero_ps(), _CMP_GT_OQ) &
                            _mm512_cmp_ps_mask(iz, _mm512_setzero_ps(), _CMP_GT_OQ);
    __m512 fr = _mm512_setzero_ps(), fg = fr, fb = fr, p = fr;
    if (active & PGLOSS_LOBE_DIFFUSE) {
        fr = V1(k->fd[0]);
        fg = V1(k->fd[1]);
        fb = V1(k->fd[2]);
        if (want_p)
            p = _mm512_mul_ps(V1(k->pd * PGLOSS_INV_PI_F), iz);
    }
    if (active & PGLOSS_LOBE_SPECULAR) {
        const __m512 hx = _mm512_add_ps(ox, ix), hy = _mm512_add_ps(oy, iy),
                     hz = _mm512_add_ps(oz, iz);
        const __m512 ex = _mm512_mul_ps(hx, V1(k->inv_ax)), ey = _mm512_mul_ps(hy, V1(k->inv_ay));
        const __m512 hz2 = _mm512_max_ps(_mm512_mul_ps(hz, hz), V1(FLT_MIN));
        const __m512 t2 = _mm512_fmadd_ps(ex, ex, _mm512_mul_ps(ey, ey));
        const __m512 e = v_exp_neg(_mm512_sub_ps(_mm512_setzero_ps(), _mm512_mul_ps(t2, v_rcp(hz2))));
        const __m512 ci = _mm512_max_ps(iz, V1(COS_MIN_F)), co = _mm512_max_ps(oz, V1(COS_MIN_F));
        const __m512 hzc = _mm512_add_ps(ci, co);
        const __m512 hh = _mm512_fmadd_ps(hx, hx, _mm512_fmadd_ps(hy, hy, _mm512_mul_ps(hz, hz)));
        const __m512 inv_hzc = v_rcp(hzc);
        const __m512 inv_hzc2 = _mm512_mul_ps(inv_hzc, inv_hzc);
        __m512 nn = _mm512_setzero_ps();
        if (!want_f)
            ; /* the pdf does not depend on the normalisation */
        else if (norm == PGLOSS_NORM_WARD_DUR)
            nn = v_rcp(_mm512_mul_ps(ci, co));
        else if (norm == PGLOSS_NORM_BOUNDED)
            nn = _mm512_mul_ps(hh, _mm512_mul_ps(inv_hzc2, inv_hzc2));
        else
            nn = v_rsqrt(_mm512_mul_ps(ci, co));
        if (want_f) {
            const __m512 fs = _mm512_min_ps(_mm512_mul_ps(_mm512_mul_ps(V1(k->spec_scale), e), nn),
                                            V1(FLT_MAX));
            fr = _mm512_add_ps(fr, fs);
            fg = _mm512_add_ps(fg, fs);
            fb = _mm512_add_ps(fb, fs);
        }
        if (want_p) {
            const __m512 ps = _mm512_mul_ps(V1(k->ps * k->pdf2), _mm512_mul_ps(e, hh));
            p = _mm512_fmadd_ps(ps, _mm512_mul_ps(inv_hzc2, inv_hzc), p);
        }
    }
    if (want_f) {
        _mm512_storeu_ps(fr_, _mm512_maskz_mov_ps(upper, _mm512_min_ps(fr, V1(FLT_MAX))));
        _mm512_storeu_ps(fg_, _mm512_maskz_mov_ps(upper, _mm512_min_ps(fg, V1(FLT_MAX))));
        _mm512_storeu_ps(fb_, _mm512_maskz_mov_ps(upper, _mm512_min_ps(fb, V1(FLT_MAX))));
    }
    if (want_p)
        _mm512_storeu_ps(pdf_, _mm512_maskz_mov_ps(upper, _mm512_min_ps(p, V1(FLT_MAX))));
    return 1;
}

#undef V1
#endif
