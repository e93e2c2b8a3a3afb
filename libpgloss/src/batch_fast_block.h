// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The FAST tier's eval/pdf block in SIMD intrinsics, written once over the primitives of
 * batch_avx512_fast.h (16 lanes) or batch_avx2_fast.h (8 lanes), which batch_isa.c includes
 * first: hardware reciprocal and rsqrt estimates refined by one Newton step, FMA, and exp2
 * from its integer and fractional parts — no division and no square root, which bound the
 * FLOAT tier on these ISAs.
 *
 * Blocks of PGLOSS_VW whose directions are all near-unit (pgloss_inl_near_unit)
 * take this path; any other block, and the tail, take the generic loop, which normalises
 * other directions and handles every edge as the FLOAT tier does. */
#ifndef PGLOSS_BATCH_FAST_BLOCK_H
#define PGLOSS_BATCH_FAST_BLOCK_H

/* 2/sqrt(x), x normal: estimate y + one Newton step without its factor 1/2, y (3 - x y²);
 * the caller absorbs the 2 (it is exact). */
PGLOSS_INLINE_FN pgloss__v v_rsqrt2(pgloss__v x)
{
    const pgloss__v y = VRSQRT_EST(x);
    return VMUL(y, VFNMADD(VMUL(x, y), y, V1(3.0f)));
}

/* 1/x, x normal: estimate + one Newton step r (2 - x r). */
PGLOSS_INLINE_FN pgloss__v v_rcp(pgloss__v x)
{
    const pgloss__v r = VRCP_EST(x);
    return VMUL(r, VFNMADD(x, r, V1(2.0f)));
}

/* The reciprocal that seeds a corrected quotient: the estimate itself where it has 14 bits
 * (one correction squares its error to 2^-28), refined once where it has fewer. */
#if VRCP_EST_BITS >= 14
#define RCP_FOR_QUOTIENT(x) VRCP_EST(x)
#else
#define RCP_FOR_QUOTIENT(x) v_rcp(x)
#endif

/* 2^g for g <= 0, exactly 0 below -126 and for NaN on both ISAs (no subnormal result: it
 * costs a microcode assist on some cores): g is clamped to -127 (maxps takes its second
 * operand for NaN), and VSCALE_FLOOR gives 0 where floor(g) = -127. g = floor(g) + f, 2^f on
 * [0, 1) by a degree-5 polynomial with p(0) = 1, minimax in relative error (8.2e-8). */
PGLOSS_INLINE_FN pgloss__v v_exp2_neg(pgloss__v g)
{
    const pgloss__v gc = VMAX(g, V1(-127.0f));
    const pgloss__v f = VFRAC(gc);
    pgloss__v p = V1(1.867124462e-03f);
    p = VFMADD(p, f, V1(9.017041884e-03f));
    p = VFMADD(p, f, V1(5.579990521e-02f));
    p = VFMADD(p, f, V1(2.401644588e-01f));
    p = VFMADD(p, f, V1(6.931512952e-01f));
    p = VFMADD(p, f, V1(1.0f));
    return VSCALE_FLOOR(p, gc, f);
}

/* PGLOSS_VW evaluations of pgloss_inl_eval_pdf_unit (pgloss/inline.h), step by step (the
 * step numbers are that function's); returns 0 (nothing written) if a direction is not
 * near-unit, for the generic loop to normalise. want_f / want_p are constants of the
 * caller's instance. */
PGLOSS_INLINE_FN int v_eval_pdf_block(const pgloss__batch_consts *restrict kb, const unsigned active,
                                   const int norm, const float *ox_, const float *oy_,
                                   const float *oz_, const float *ix_, const float *iy_,
                                   const float *iz_, float *fr_, float *fg_, float *fb_,
                                   float *pdf_, const int want_f, const int want_p)
{
    const pgloss_inl_consts *k = &kb->lobe;
    const pgloss__v ox = VLOAD(ox_), oy = VLOAD(oy_), oz = VLOAD(oz_);
    const pgloss__v ix = VLOAD(ix_), iy = VLOAD(iy_), iz = VLOAD(iz_);
    const pgloss__v lo2 = VFMADD(ox, ox, VFMADD(oy, oy, VMUL(oz, oz)));
    const pgloss__v li2 = VFMADD(ix, ix, VFMADD(iy, iy, VMUL(iz, iz)));
    if (!v_all_in(lo2, li2, PGLOSS_INL_UNIT_L2_LO, PGLOSS_INL_UNIT_L2_HI)) /* pgloss_inl_near_unit */
        return 0;
    /* 1. ro, ri = 1.5 − |v|²/2; cosines; one-sided mask */
    const pgloss__v ro = VFNMADD(lo2, V1(0.5f), V1(1.5f)), ri = VFNMADD(li2, V1(0.5f), V1(1.5f));
    const pgloss__v co = VMUL(oz, ro), ci = VMUL(iz, ri);
    const pgloss__m upper = VBOTH_POSITIVE(co, ci);
    pgloss__v fs = VZERO(), p = VZERO();
    if ((active & PGLOSS_LOBE_DIFFUSE) && want_p) /* 2. diffuse pdf (f: at the stores) */
        p = VMUL(V1(k->pdf_d), ci);
    if (active & PGLOSS_LOBE_SPECULAR) {
        /* 3. h = s − (D/4) d, here as 4h = 4s − D d: the factor 4 (two exact doublings, on
         * the add pipes) cancels in the exponent and is taken back in the constants of hh. */
        const pgloss__v sx = VADD(ix, ox), sy = VADD(iy, oy), sz = VADD(iz, oz);
        const pgloss__v dx = VSUB(ix, ox), dy = VSUB(iy, oy), dz = VSUB(iz, oz);
        const pgloss__v dd = VFMADD(dx, sx, VFMADD(dy, sy, VMUL(dz, sz)));
        const pgloss__v s2x = VADD(sx, sx), s2y = VADD(sy, sy), s2z = VADD(sz, sz);
        const pgloss__v hx = VFNMADD(dd, dx, VADD(s2x, s2x)), hy = VFNMADD(dd, dy, VADD(s2y, s2y));
        const pgloss__v hz = VFNMADD(dd, dz, VADD(s2z, s2z));
        /* 4. the exponent in base 2, (hx² log2e/αx² + hy² log2e/αy²)/hz², then 2^−x. The
         * quotient: a reciprocal estimate and
         * one correction of the quotient itself, g = g0 − r (t2 + g0 hz²) (exact residual with
         * FMA): within an ulp or so. */
        const pgloss__v t2 = VFMADD(VMUL(hx, hx), V1(kb->inv_ax2_log2),
                                    VMUL(VMUL(hy, hy), V1(kb->inv_ay2_log2)));
        /* hz floored at 1.1e-19 as the inline function's hzt (here 4h: 16 hz² >= 16·1.1e-19²),
         * so that hz² is never 0 or subnormal (whose estimate is Inf); g0 floored at -1e30, so
         * that the correction below never meets Inf − Inf. Both leave regular lanes alone. */
        const pgloss__v hz2 = VMAX_POS(VMUL(hz, hz), V1(16.0f * 1.1e-19f * 1.1e-19f));
        const pgloss__v r = RCP_FOR_QUOTIENT(hz2);
        const pgloss__v g0 = VMAX(VFNMADD(t2, r, VZERO()), V1(-1e30f));
        const pgloss__v e = v_exp2_neg(VFNMADD(VFMADD(g0, hz2, t2), r, g0));
        /* 5. cosines raised to COS_MIN; 1/hzc; 16 hhs = 16 hh/hzc² */
        const pgloss__v cic = VMAX_POS(ci, V1((float)PGLOSS_COS_MIN)), coc = VMAX_POS(co, V1((float)PGLOSS_COS_MIN));
        pgloss__v hh16 = VZERO(), inv_hzc = VZERO();
        if (want_p || (want_f && norm == PGLOSS_NORM_BOUNDED)) {
            /* 16 hhs = |4h/hzc|² ro ri: h scaled before it is squared (no underflow) */
            inv_hzc = v_rcp(VADD(cic, coc));
            const pgloss__v gx = VMUL(hx, inv_hzc), gy = VMUL(hy, inv_hzc), gz = VMUL(hz, inv_hzc);
            const pgloss__v g2 = VFMADD(gx, gx, VFMADD(gy, gy, VMUL(gz, gz)));
            hh16 = VMUL(g2, VMUL(ro, ri));
        }
        if (want_f) { /* 6. the normalisation, fs = spec_scale e norm */
            pgloss__v nn, scale = V1(k->spec_scale);
            if (norm == PGLOSS_NORM_WARD_DUR) { /* 1/(ci co) */
                nn = v_rcp(VMUL(cic, coc));
            } else if (norm == PGLOSS_NORM_BOUNDED) { /* hhs/hzc² */
                nn = VMUL(hh16, VMUL(inv_hzc, inv_hzc));
                scale = V1(0.0625f * k->spec_scale);
            } else { /* eq. 2: 1/sqrt(ci co) = (2/sqrt(ci co))/2 */
                nn = v_rsqrt2(VMUL(cic, coc));
                scale = V1(0.5f * k->spec_scale);
            }
            /* 8. min(·, FLT_MAX), only for materials whose f can overflow at all */
            fs = VMUL(VMUL(scale, e), nn);
            if (kb->may_overflow)
                fs = VMIN(fs, V1(FLT_MAX));
        }
        if (want_p) /* 7. Walter 2005: pdf += Ps 2 pdf_scale e hhs / hzc */
            p = VFMADD(VMUL(V1(0.0625f * k->pdf_s), VMUL(e, hh16)), inv_hzc, p);
    }
    /* 2., 8. f = ρd/π + fs above the horizon, 0 below; ρd/π + FLT_MAX rounds to FLT_MAX. */
    if (want_f && active == PGLOSS_LOBE_ALL) {
        VSTORE(fr_, VADD_KEEP(upper, V1(k->fd[0]), fs));
        VSTORE(fg_, VADD_KEEP(upper, V1(k->fd[1]), fs));
        VSTORE(fb_, VADD_KEEP(upper, V1(k->fd[2]), fs));
    } else if (want_f && active == PGLOSS_LOBE_DIFFUSE) {
        VSTORE(fr_, VKEEP(upper, V1(k->fd[0])));
        VSTORE(fg_, VKEEP(upper, V1(k->fd[1])));
        VSTORE(fb_, VKEEP(upper, V1(k->fd[2])));
    } else if (want_f) {
        VSTORE(fr_, VKEEP(upper, fs));
        VSTORE(fg_, VKEEP(upper, fs));
        VSTORE(fb_, VKEEP(upper, fs));
    }
    if (want_p)
        VSTORE(pdf_, VKEEP(upper, kb->may_overflow ? VMIN(p, V1(FLT_MAX)) : p));
    return 1;
}

#endif
