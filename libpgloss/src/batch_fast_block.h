/* The FAST tier's eval/pdf block in SIMD intrinsics, written once over the primitives of
 * batch_avx512_fast.h (16 lanes) or batch_avx2_fast.h (8 lanes), which batch_isa.c includes
 * first: hardware reciprocal and rsqrt estimates refined by one Newton step, FMA, and the
 * power of two of exp built directly — no division and no square root, which bound the FLOAT
 * tier on these ISAs.
 *
 * Blocks of PGLOSS_VW whose directions all have squared lengths in [2^-100, 2^100] (so
 * nothing overflows, underflows or is non-finite) take this path; any other block, and the
 * tail, take the generic loop, which handles every edge as the FLOAT tier does. */
#ifndef PGLOSS_BATCH_FAST_BLOCK_H
#define PGLOSS_BATCH_FAST_BLOCK_H

/* 1/sqrt(x), x normal: estimate + one Newton step y (1.5 - 0.5 x y²). */
PGLOSS_INLINE pgloss__v v_rsqrt(pgloss__v x)
{
    const pgloss__v y = VRSQRT_EST(x);
    return VMUL(y, VFNMADD(VMUL(VMUL(V1(0.5f), x), y), y, V1(1.5f)));
}

/* 1/x, x normal: estimate + one Newton step r (2 - x r). */
PGLOSS_INLINE pgloss__v v_rcp(pgloss__v x)
{
    const pgloss__v r = VRCP_EST(x);
    return VMUL(r, VFNMADD(x, r, V1(2.0f)));
}

/* exp(x) for x <= 0 (0 below ln FLT_MIN): the reduction and degree-5 polynomial of
 * pgloss__exp_neg_fast. */
PGLOSS_INLINE pgloss__v v_exp_neg(pgloss__v x)
{
    const pgloss__v xc = VMAX(x, V1(-87.33654f));
    const pgloss__v n = VROUND(VMUL(xc, V1(1.44269504088896341f)));
    pgloss__v r = VFNMADD(n, V1(0.693145751953125f), xc);
    r = VFNMADD(n, V1(1.428606765330187e-06f), r);
    pgloss__v p = V1(1.0f / 120.0f);
    p = VFMADD(p, r, V1(1.0f / 24.0f));
    p = VFMADD(p, r, V1(1.0f / 6.0f));
    p = VFMADD(p, r, V1(0.5f));
    p = VFMADD(p, r, V1(1.0f));
    p = VFMADD(p, r, V1(1.0f));
    return VKEEP(VCMP(x, V1(-87.33654f), _CMP_GE_OQ), VSCALE2(p, n));
}

PGLOSS_INLINE pgloss__m v_length2_safe(pgloss__v l2)
{
    return MAND(VCMP(l2, V1(0x1p-100f), _CMP_GE_OQ), VCMP(l2, V1(0x1p100f), _CMP_LE_OQ));
}

/* PGLOSS_VW evaluations; returns 0 (nothing written) if the block needs the generic path.
 * f and pdf as kernel_eval_pdf; want_f / want_p are constants of the caller's instance. */
PGLOSS_INLINE int v_eval_pdf_block(const pgloss__batch_consts *restrict k, const unsigned active,
                                   const int norm, const float *ox_, const float *oy_,
                                   const float *oz_, const float *ix_, const float *iy_,
                                   const float *iz_, float *fr_, float *fg_, float *fb_,
                                   float *pdf_, const int want_f, const int want_p)
{
    pgloss__v ox = VLOAD(ox_), oy = VLOAD(oy_), oz = VLOAD(oz_);
    pgloss__v ix = VLOAD(ix_), iy = VLOAD(iy_), iz = VLOAD(iz_);
    const pgloss__v lo2 = VFMADD(ox, ox, VFMADD(oy, oy, VMUL(oz, oz)));
    const pgloss__v li2 = VFMADD(ix, ix, VFMADD(iy, iy, VMUL(iz, iz)));
    if (!MALL(MAND(v_length2_safe(lo2), v_length2_safe(li2))))
        return 0;
    const pgloss__v no = v_rsqrt(lo2), ni = v_rsqrt(li2);
    ox = VMUL(ox, no);
    oy = VMUL(oy, no);
    oz = VMUL(oz, no);
    ix = VMUL(ix, ni);
    iy = VMUL(iy, ni);
    iz = VMUL(iz, ni);
    const pgloss__m upper = MAND(VCMP(oz, VZERO(), _CMP_GT_OQ), VCMP(iz, VZERO(), _CMP_GT_OQ));
    pgloss__v fr = VZERO(), fg = fr, fb = fr, p = fr;
    if (active & PGLOSS_LOBE_DIFFUSE) {
        fr = V1(k->fd[0]);
        fg = V1(k->fd[1]);
        fb = V1(k->fd[2]);
        if (want_p)
            p = VMUL(V1(k->pd * PGLOSS_INV_PI_F), iz);
    }
    if (active & PGLOSS_LOBE_SPECULAR) {
        const pgloss__v hx = VADD(ox, ix), hy = VADD(oy, iy), hz = VADD(oz, iz);
        const pgloss__v ex = VMUL(hx, V1(k->inv_ax)), ey = VMUL(hy, V1(k->inv_ay));
        const pgloss__v hz2 = VMAX(VMUL(hz, hz), V1(FLT_MIN));
        const pgloss__v t2 = VFMADD(ex, ex, VMUL(ey, ey));
        const pgloss__v e = v_exp_neg(VSUB(VZERO(), VMUL(t2, v_rcp(hz2)))); /* eq. 2 */
        const pgloss__v ci = VMAX(iz, V1(COS_MIN_F)), co = VMAX(oz, V1(COS_MIN_F));
        const pgloss__v hh = VFMADD(hx, hx, VFMADD(hy, hy, VMUL(hz, hz)));
        const pgloss__v inv_hzc = v_rcp(VADD(ci, co));
        const pgloss__v inv_hzc2 = VMUL(inv_hzc, inv_hzc);
        if (want_f) {
            pgloss__v nn;
            if (norm == PGLOSS_NORM_WARD_DUR)
                nn = v_rcp(VMUL(ci, co));
            else if (norm == PGLOSS_NORM_BOUNDED)
                nn = VMUL(hh, VMUL(inv_hzc2, inv_hzc2));
            else
                nn = v_rsqrt(VMUL(ci, co));
            const pgloss__v fs = VMUL(VMUL(V1(k->spec_scale), e), nn);
            fr = VADD(fr, fs);
            fg = VADD(fg, fs);
            fb = VADD(fb, fs);
        }
        if (want_p) /* Walter 2005 (the pdf does not depend on the normalisation) */
            p = VFMADD(VMUL(V1(k->ps * k->pdf2), VMUL(e, hh)), VMUL(inv_hzc2, inv_hzc), p);
    }
    /* min(·, FLT_MAX) turns an overflow to Inf into FLT_MAX; finite input gives no NaN here. */
    if (want_f) {
        VSTORE(fr_, VKEEP(upper, VMIN(fr, V1(FLT_MAX))));
        VSTORE(fg_, VKEEP(upper, VMIN(fg, V1(FLT_MAX))));
        VSTORE(fb_, VKEEP(upper, VMIN(fb, V1(FLT_MAX))));
    }
    if (want_p)
        VSTORE(pdf_, VKEEP(upper, VMIN(p, V1(FLT_MAX))));
    return 1;
}

#endif
