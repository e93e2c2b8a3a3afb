// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The double batch loops (pgloss/batch_materials.h, the _d functions): the double lobe of
 * lobe_d.h — the code of the scalar reference functions — over SoA double arrays, with one
 * material for the call or one per element (its constants formed inside the loop by
 * pgloss__consts_d_of). Compiled once per ISA (libpgloss/CMakeLists.txt, PGLOSS_ISA);
 * batch_materials.c picks one at run time. The eval/pdf loop is branch-free and vectorises
 * (the exponential's table becomes a gather on AVX2 and AVX-512); so does the sampler, chunk
 * by chunk (its maps in lobe_d.h are branch-free, log1p included). */
#include "batch_internal.h"
#if defined(__FMA__)
#define PGLOSS__D_FUSED 1 /* lobe_d.h: PGLOSS__D_MADD is one fma */
#endif
#include "lobe_d.h"

#ifndef PGLOSS_ISA
#error "PGLOSS_ISA must name the instruction set this file is compiled for"
#endif

#define PGLOSS__CAT2(a, b) a##_##b
#define PGLOSS__NAME2(fn, isa) PGLOSS__CAT2(fn, isa)
#define EVAL_PDF_D_FN PGLOSS__NAME2(pgloss__eval_pdf_batch_d, PGLOSS_ISA)
#define SAMPLE_D_FN PGLOSS__NAME2(pgloss__sample_batch_d, PGLOSS_ISA)

/* 1/sqrt(1 + e) for |e| <= 2^-20 (unit_d, unit_chunk_d) */
PGLOSS__D_FN double near_unit_inv(double e)
{
    return PGLOSS__D_MADD(e, PGLOSS__D_MADD(e, PGLOSS__D_MADD(-0.3125, e, 0.375), -0.5), 1.0);
}

/* Normalises (x, y, z) after an exact power-of-two scaling chosen by the largest component
 * (so no square overflows or underflows; for float-valued inputs the result is bit for bit
 * that of pgloss__normalize where PGLOSS__D_MADD is not fused, within an ulp where it is);
 * zeros for a zero or non-finite vector. Returns a double that is
 * > 0 exactly for a valid vector: validity as a single comparison of a double is what GCC 12
 * vectorises next to double arithmetic (ints combined from several double comparisons stop
 * it). */
PGLOSS__D_FN double unit_d(double *x, double *y, double *z)
{
    const double ax = fabs(*x), ay = fabs(*y), az = fabs(*z);
    const double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    /* ±0 if every component is finite, NaN otherwise */
    const double t = (*x * 0.0 + *y * 0.0) + *z * 0.0;
    /* exact powers of two: the squares of m s stay within [2^-1000, 2^1000] */
    const double s = m > 0x1p500 ? 0x1p-600 : (m < 0x1p-500 ? 0x1p600 : 1.0);
    const double a = *x * s, b = *y * s, c = *z * s;
    const double l2 = PGLOSS__D_MADD(c, c, PGLOSS__D_MADD(b, b, a * a)) + t; /* NaN if not finite, 0 for zero */
    /* near-unit (s = 1 there): unit_chunk_d's polynomial, bit for bit */
    const double e = l2 - 1.0;
    const double inv = fabs(e) <= 0x1p-20 ? near_unit_inv(e) : 1.0 / sqrt(l2 > 0.0 ? l2 : 1.0);
    *x = l2 > 0.0 ? a * inv : 0.0;
    *y = l2 > 0.0 ? b * inv : 0.0;
    *z = l2 > 0.0 ? c * inv : 0.0;
    return l2 > 0.0 ? l2 : 0.0;
}

/* The directions of a chunk, made unit, into stack arrays. A chunk whose squared lengths all
 * lie within 2^-20 of 1 (any unit vector rounded to double or to float does) takes
 * 1/|v| = 1 − ε/2 + 3ε²/8 − 5ε³/16, ε = |v|² − 1 (exact; truncation below 0.28 ε⁴ < 2^-81,
 * so within a few ulp like unit_d): no root and no division, which bound the loop otherwise;
 * then every direction is valid (valid[j] = 1) and the function returns 1, so that the
 * caller may skip `valid`. Elsewhere the chunk goes through unit_d (valid[j] > 0 exactly for
 * a valid direction) and it returns 0. The test is the largest |ε| as int64 bits (a double
 * >= 0 orders as its bits; NaN and Inf are above every finite value), one vpmaxsq per vector
 * on AVX-512. */
PGLOSS__D_FN int unit_chunk_d(size_t m, const double *restrict xs, const double *restrict ys,
                              const double *restrict zs, double *restrict nx,
                              double *restrict ny, double *restrict nz, double *restrict valid)
{
    int64_t far = 0;
    for (size_t j = 0; j < m; ++j) {
        const double x = xs[j], y = ys[j], z = zs[j];
        const double e = PGLOSS__D_MADD(z, z, PGLOSS__D_MADD(y, y, x * x)) - 1.0;
        const double inv = near_unit_inv(e);
        nx[j] = x * inv;
        ny[j] = y * inv;
        nz[j] = z * inv;
        valid[j] = 1.0;
        const double ae = fabs(e);
        int64_t b;
        memcpy(&b, &ae, sizeof b);
        far = b > far ? b : far;
    }
    const double lim = 0x1p-20;
    int64_t lim_bits;
    memcpy(&lim_bits, &lim, sizeof lim_bits);
    if (far <= lim_bits)
        return 1;
    /* some direction is not near-unit: the chunk again through unit_d, which gives the near-unit
     * ones the same bits as above (so an element's result does not depend on its chunk) */
    for (size_t j = 0; j < m; ++j) {
        double x = xs[j], y = ys[j], z = zs[j];
        valid[j] = unit_d(&x, &y, &z);
        nx[j] = x;
        ny[j] = y;
        nz[j] = z;
    }
    return 0;
}

PGLOSS__D_FN double clamp_max(double v)
{
    return PGLOSS__D_MIN(v, (double)FLT_MAX);
}

/* pgloss_material_init's checks on a double parameter set (|v| > FLT_MAX counts as
 * non-finite, NaN fails every comparison): 1 if valid, else 0, as a double (unit_d). */
PGLOSS__D_FN double material_valid_d(double r, double g, double b, double s, double ax, double ay)
{
    const double L = (double)FLT_MAX;
    double v = 1.0;
    v = fabs(r) <= L ? v : 0.0;
    v = fabs(g) <= L ? v : 0.0;
    v = fabs(b) <= L ? v : 0.0;
    v = fabs(s) <= L ? v : 0.0;
    v = fabs(ax) <= L ? v : 0.0;
    v = fabs(ay) <= L ? v : 0.0;
    v = r >= 0.0 ? v : 0.0;
    v = g >= 0.0 ? v : 0.0;
    v = b >= 0.0 ? v : 0.0;
    v = s >= 0.0 ? v : 0.0;
    v = ax > 0.0 ? v : 0.0;
    return ay > 0.0 ? v : 0.0;
}

/* A chunk of element constants, and the material arrays as restrict pointers (outputs never
 * alias them), so that the loops below hold no load the compiler must repeat. */
typedef struct mat_ptrs {
    const double *restrict r, *restrict g, *restrict b, *restrict s, *restrict ax, *restrict ay;
} mat_ptrs;

/* The constants of element j: the call's (per_element a constant 0 of the instance) or those
 * of element j's material (black if invalid; *valid says which). */
PGLOSS__D_FN pgloss__consts_d consts_at_d(const pgloss__consts_d *kc, const mat_ptrs *mp,
                                          const int per_element, unsigned active, int norm,
                                          size_t j, double *valid)
{
    if (!per_element) {
        *valid = 1.0;
        return *kc;
    }
    const double r = mp->r[j], g = mp->g[j], b = mp->b[j], s = mp->s[j];
    const double ax = mp->ax[j], ay = mp->ay[j];
    const double good = material_valid_d(r, g, b, s, ax, ay);
    *valid = good;
    return pgloss__consts_d_of(good > 0.0 ? r : 0.0, good > 0.0 ? g : 0.0, good > 0.0 ? b : 0.0,
                               good > 0.0 ? s : 0.0, good > 0.0 ? ax : 1.0,
                               good > 0.0 ? ay : 1.0, norm, active);
}

PGLOSS__D_FN mat_ptrs mat_ptrs_of(const pgloss__materials_d *pa)
{
    mat_ptrs m = {NULL, NULL, NULL, NULL, NULL, NULL};
    if (pa) {
        m.r = pa->rho_d_r;
        m.g = pa->rho_d_g;
        m.b = pa->rho_d_b;
        m.s = pa->rho_s;
        m.ax = pa->alpha_x;
        m.ay = pa->alpha_y;
    }
    return m;
}

/* A chunk runs in passes over stack arrays: the unit directions (unit_chunk_d), the lobe.
 * With one material for the call the lobe's loop writes the outputs (clamped, 0 where invalid)
 * straight to the caller's arrays: it reads only the stack arrays, so the compiler needs no
 * alias check, and an output that is also an input was read in the unit pass before. With
 * one material per element the loop also reads the material arrays, which an output may
 * share; there it writes stack arrays and a third pass writes them out. No pass is a plain
 * copy, which GCC would make a `rep movsq` (slow on AMD cores: 40 % of the loop's time, perf). */
#define CHUNK_D 256

PGLOSS__D_FN size_t eval_d_chunk(const pgloss__consts_d *kc, const mat_ptrs *mp,
                                 const int per_element, const int all_valid,
                                 const unsigned active, const int norm,
                                 const int want_f, const int want_p, size_t m, size_t base,
                                 const double *restrict oxs, const double *restrict oys,
                                 const double *restrict ozs, const double *restrict ixs,
                                 const double *restrict iys, const double *restrict izs,
                                 const double *restrict vos, const double *restrict vis,
                                 double *restrict fr, double *restrict fg, double *restrict fb,
                                 double *restrict pdf, double *restrict oks)
{
    size_t bad = 0;
    for (size_t j = 0; j < m; ++j) {
        double mat_ok;
        const pgloss__consts_d kj =
            consts_at_d(kc, mp, per_element, active, norm, base + j, &mat_ok);
        /* all_valid (a constant of the instance): every direction of the chunk near-unit */
        const double vo = all_valid ? 1.0 : vos[j], vi = all_valid ? 1.0 : vis[j];
        const double v = vo < vi ? vo : vi;
        double f[3], p;
        pgloss__lobe_d(&kj, active, norm, oxs[j], oys[j], ozs[j], ixs[j], iys[j], izs[j], want_f,
                       want_p, f, &p);
        if (per_element) {
            oks[j] = v < mat_ok ? v : mat_ok; /* > 0 for a valid element */
            if (want_f) {
                fr[j] = f[0];
                fg[j] = f[1];
                fb[j] = f[2];
            }
            if (want_p)
                pdf[j] = p;
        } else {
            /* the outputs, at most FLT_MAX as in every precision (brdf.h), 0 if invalid */
            const int ok = v > 0.0;
            if (want_f) {
                fr[j] = ok ? clamp_max(f[0]) : 0.0;
                fg[j] = ok ? clamp_max(f[1]) : 0.0;
                fb[j] = ok ? clamp_max(f[2]) : 0.0;
            }
            if (want_p)
                pdf[j] = ok ? clamp_max(p) : 0.0;
            bad += !ok;
        }
    }
    return bad;
}

/* The per-element outputs written out in one pass, as eval_d_chunk writes them for one
 * material; returns the number of invalid elements. */
PGLOSS__D_FN size_t write_out_d(size_t m, const int want_f, const int want_p,
                                const double *restrict oks, const double *restrict v0,
                                const double *restrict v1, const double *restrict v2,
                                const double *restrict v3,
                                double *restrict fr, double *restrict fg, double *restrict fb,
                                double *restrict pdf)
{
    size_t bad = 0;
    for (size_t j = 0; j < m; ++j) {
        const int ok = oks[j] > 0.0;
        if (want_f) {
            fr[j] = ok ? clamp_max(v0[j]) : 0.0;
            fg[j] = ok ? clamp_max(v1[j]) : 0.0;
            fb[j] = ok ? clamp_max(v2[j]) : 0.0;
        }
        if (want_p)
            pdf[j] = ok ? clamp_max(v3[j]) : 0.0;
        bad += !ok;
    }
    return bad;
}

PGLOSS__D_FN size_t eval_d_loop(const pgloss__consts_d *k, const pgloss__materials_d *pa,
                                const int per_element, const unsigned active, const int norm,
                                const int want_f, const int want_p, size_t n,
                                const double *oxs, const double *oys, const double *ozs,
                                const double *ixs, const double *iys, const double *izs,
                                double *fr, double *fg, double *fb, double *pdf)
{
    const pgloss__consts_d kc = per_element ? pgloss__consts_d_of(0, 0, 0, 0, 1, 1, 0, 0) : *k;
    const mat_ptrs mp = mat_ptrs_of(pa);
    double in[8][CHUNK_D], out[5][CHUNK_D];
    size_t bad = 0;
    for (size_t base = 0; base < n; base += CHUNK_D) {
        const size_t m = n - base < CHUNK_D ? n - base : CHUNK_D;
        const int near_o = unit_chunk_d(m, oxs + base, oys + base, ozs + base, in[0],
                                             in[1], in[2], in[6]);
        const int near_i = unit_chunk_d(m, ixs + base, iys + base, izs + base, in[3],
                                             in[4], in[5], in[7]);
        if (near_o & near_i) {
            /* every direction near-unit, hence valid: `in[6]`, `in[7]` not read */
            if (!per_element) {
                bad += eval_d_chunk(&kc, &mp, 0, 1, active, norm, want_f, want_p, m, base,
                                    in[0], in[1], in[2], in[3], in[4], in[5], NULL, NULL,
                                    want_f ? fr + base : NULL, want_f ? fg + base : NULL,
                                    want_f ? fb + base : NULL, want_p ? pdf + base : NULL, NULL);
                continue;
            }
            eval_d_chunk(&kc, &mp, 1, 1, active, norm, want_f, want_p, m, base, in[0], in[1],
                         in[2], in[3], in[4], in[5], NULL, NULL, out[0], out[1], out[2], out[3],
                         out[4]);
        } else {
            if (!per_element) {
                bad += eval_d_chunk(&kc, &mp, 0, 0, active, norm, want_f, want_p, m, base,
                                    in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7],
                                    want_f ? fr + base : NULL, want_f ? fg + base : NULL,
                                    want_f ? fb + base : NULL, want_p ? pdf + base : NULL, NULL);
                continue;
            }
            eval_d_chunk(&kc, &mp, 1, 0, active, norm, want_f, want_p, m, base, in[0], in[1],
                         in[2], in[3], in[4], in[5], in[6], in[7], out[0], out[1], out[2], out[3],
                         out[4]);
        }
        bad += write_out_d(m, want_f, want_p, out[4], out[0], out[1], out[2], out[3],
                           want_f ? fr + base : NULL, want_f ? fg + base : NULL,
                           want_f ? fb + base : NULL, want_p ? pdf + base : NULL);
    }
    return bad;
}

/* (lobes, normalisation) as constants (PGLOSS__BY_LOBES), then the outputs wanted. */
PGLOSS__D_FN size_t eval_d_outputs(const pgloss__consts_d *k, const pgloss__materials_d *pa,
                                   const int per_element, unsigned active, int norm, size_t n,
                                   pgloss__vec3_d wo, pgloss__vec3_d wi,
                                   pgloss__rgb_out_d f, double *pdf)
{
#define LOOP_FP(A, N)                                                                              \
    eval_d_loop(k, pa, per_element, A, N, 1, 1, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g,   \
                f.b, pdf)
#define LOOP_F(A, N)                                                                               \
    eval_d_loop(k, pa, per_element, A, N, 1, 0, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g,   \
                f.b, pdf)
#define LOOP_P(A, N)                                                                               \
    eval_d_loop(k, pa, per_element, A, N, 0, 1, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g,   \
                f.b, pdf)
    if (f.r && pdf)
        return PGLOSS__BY_LOBES(LOOP_FP, active, norm);
    if (f.r)
        return PGLOSS__BY_LOBES(LOOP_F, active, norm);
    return PGLOSS__BY_LOBES(LOOP_P, active, norm);
#undef LOOP_FP
#undef LOOP_F
#undef LOOP_P
}

size_t EVAL_PDF_D_FN(const pgloss__consts_d *k, const pgloss__materials_d *pa, unsigned active,
                     int norm, size_t n, pgloss__vec3_d wo, pgloss__vec3_d wi,
                     pgloss__rgb_out_d f, double *pdf)
{
    if (pa)
        return eval_d_outputs(NULL, pa, 1, active, norm, n, wo, wi, f, pdf);
    return eval_d_outputs(k, NULL, 0, active, norm, n, wo, wi, f, pdf);
}

/* ---- sampling: pgloss_sample in double, chunk by chunk ------------------------------------ */

#define ONE_MINUS_EPS_D 0x1.fffffep-1 /* 1 - 2^-24, as the float paths (brdf.h) */

PGLOSS__D_FN double clamp_u_d(double u)
{
    return u > 0.0 ? (u < ONE_MINUS_EPS_D ? u : ONE_MINUS_EPS_D) : 0.0;
}

/* The sampler's chunk: half the eval chunk, as it keeps about thirty arrays on the stack. */
#define CHUNK_S 128

/* Per-element constants of a chunk (what pgloss__consts_d_of gives for element j's material)
 * and whether the element has an active lobe (1.0 or 0.0). */
typedef struct chunk_consts_d {
    double fd0[CHUNK_S], fd1[CHUNK_S], fd2[CHUNK_S], spec[CHUNK_S], iax[CHUNK_S], iay[CHUNK_S];
    double ps[CHUNK_S], pd[CHUNK_S], pdf_scale[CHUNK_S], ax[CHUNK_S], ay[CHUNK_S], has[CHUNK_S];
    double valid[CHUNK_S]; /* the material passes pgloss_material_init's checks */
} chunk_consts_d;

/* Element j's constants from the chunk's arrays (per_element) or the call's. */
PGLOSS__D_FN pgloss__consts_d consts_of_chunk_d(const pgloss__consts_d *kc,
                                                const chunk_consts_d *restrict cc,
                                                const int per_element, const unsigned active,
                                                size_t j)
{
    if (!per_element)
        return *kc;
    pgloss__consts_d r;
    r.fd[0] = cc->fd0[j];
    r.fd[1] = cc->fd1[j];
    r.fd[2] = cc->fd2[j];
    r.spec_scale = cc->spec[j];
    r.inv_ax = cc->iax[j];
    r.inv_ay = cc->iay[j];
    r.ps = cc->ps[j];
    r.pd = cc->pd[j];
    r.pdf_scale = cc->pdf_scale[j];
    r.alpha_x = cc->ax[j];
    r.alpha_y = cc->ay[j];
    r.active = active;
    return r;
}

/* The outputs of a chunk: wi as drawn, and where the sample stands (ok > 0: drawn, wo above
 * the horizon, wo·h > 0 for a specular draw, wi not zero) pdf and weight = f cosθi / pdf
 * at the unit wi, at most FLT_MAX; a zero pdf is a rejected sample (weight 0). Out of line:
 * inlined into the sampler, GCC 12 finds no vector type for its loads and leaves it scalar. */
static PGLOSS__NOINLINE void write_sample_d(size_t m, const double *restrict oks,
                                 const double *restrict vis, const double *restrict wx,
                                 const double *restrict wy, const double *restrict wz,
                                 const double *restrict iz, const double *restrict fr,
                                 const double *restrict fg, const double *restrict fb,
                                 const double *restrict pr, double *restrict ox_,
                                 double *restrict oy_, double *restrict oz_,
                                 double *restrict pdf, double *restrict gr,
                                 double *restrict gg, double *restrict gb)
{
    for (size_t j = 0; j < m; ++j) {
        /* every load unconditional, the selects flat: GCC 12 if-converts nothing else here */
        const double okj = oks[j], vij = vis[j], pj = pr[j], izj = iz[j];
        double p = okj > 0.0 ? pj : 0.0;
        p = vij > 0.0 ? p : 0.0;
        const int pos = p > 0.0;
        const double r = izj / (pos ? p : 1.0);
        ox_[j] = wx[j];
        oy_[j] = wy[j];
        oz_[j] = wz[j];
        pdf[j] = pos ? clamp_max(p) : 0.0;
        gr[j] = pos ? clamp_max(fr[j] * r) : 0.0;
        gg[j] = pos ? clamp_max(fg[j] * r) : 0.0;
        gb[j] = pos ? clamp_max(fb[j] * r) : 0.0;
    }
}

/* The constants of elements [base, base + m) into the chunk (per-element materials). */
PGLOSS__D_FN void derive_chunk_d(const mat_ptrs *mp, const unsigned active, const int norm,
                                 size_t m, size_t base, chunk_consts_d *restrict cc)
{
    /* the chunk's pointers in a local copy: through *mp, GCC 12 finds no vector type for the
     * loads */
    const mat_ptrs lm = {mp->r + base, mp->g + base, mp->b + base,
                         mp->s + base, mp->ax + base, mp->ay + base};
    for (size_t j = 0; j < m; ++j) {
        double mat_ok;
        const pgloss__consts_d kj = consts_at_d(NULL, &lm, 1, active, norm, j, &mat_ok);
        cc->fd0[j] = kj.fd[0];
        cc->fd1[j] = kj.fd[1];
        cc->fd2[j] = kj.fd[2];
        cc->spec[j] = kj.spec_scale;
        cc->iax[j] = kj.inv_ax;
        cc->iay[j] = kj.inv_ay;
        cc->ps[j] = kj.ps;
        cc->pd[j] = kj.pd;
        cc->pdf_scale[j] = kj.pdf_scale;
        cc->ax[j] = kj.alpha_x;
        cc->ay[j] = kj.alpha_y;
        /* an active lobe exactly where Ps > 0 or 1 − Ps > 0 (pgloss__lobe_probs_d;
         * none for an invalid material, which is black) */
        const double h = kj.pd > 0.0 ? mat_ok : 0.0;
        cc->has[j] = kj.ps > 0.0 ? mat_ok : h;
        cc->valid[j] = mat_ok;
    }
}

/* pgloss_sample over the arrays, in chunks of passes over stack arrays (as eval_d_loop and
 * the float sample_loop): the random numbers clamped and checked, wo made unit, the
 * elements' constants (per_element), both lobes' directions drawn and one selected, the drawn
 * direction made unit, the lobe at it, the outputs. Every pass is branch-free and vectorises
 * (GCC 12 leaves the per-element constants scalar for some lobe sets: docs/kernels.md);
 * every input of a chunk is read before any of its outputs is written (so an output may be
 * its element's input). The rules are pgloss_sample's: an invalid element (random number
 * NaN, wo zero or not finite, material invalid) is drawn as (0, 0, 1) with lobe NONE and
 * zeros, as is one without an active lobe; a valid one below the horizon or with wo·h <= 0
 * keeps its direction and lobe, with pdf and weight 0. */
PGLOSS__D_FN size_t sample_d_loop(const pgloss__consts_d *k, const pgloss__materials_d *pa,
                                const int per_element, const unsigned active, const int norm,
                                size_t n, pgloss__vec3_d wo, const double *u0s,
                                const double *u1s, const double *u2s, pgloss__vec3_out_d wi,
                                double *pdf, pgloss__rgb_out_d weight, unsigned char *lobe)
{
    const pgloss__consts_d kc = per_element ? pgloss__consts_d_of(0, 0, 0, 0, 1, 1, 0, 0) : *k;
    const mat_ptrs mp = mat_ptrs_of(pa);
    const double has_u = kc.active ? 1.0 : 0.0;
    chunk_consts_d cc;
    double c0[CHUNK_S], c1[CHUNK_S], c2[CHUNK_S], ok[CHUNK_S];
    double ox[CHUNK_S], oy[CHUNK_S], oz[CHUNK_S], vo[CHUNK_S];
    double wx[CHUNK_S], wy[CHUNK_S], wz[CHUNK_S], lb[CHUNK_S];
    double nx[CHUNK_S], ny[CHUNK_S], nz[CHUNK_S], vi[CHUNK_S];
    double fr[CHUNK_S], fg[CHUNK_S], fb[CHUNK_S], pr[CHUNK_S];
    size_t bad = 0;
    for (size_t base = 0; base < n; base += CHUNK_S) {
        const size_t m = n - base < CHUNK_S ? n - base : CHUNK_S;
        /* random numbers: 1.0 where none is NaN (as nested selects: GCC 12 vectorises those
         * next to double arithmetic), clamped to [0, 1 - 2^-24] */
        for (size_t j = 0; j < m; ++j) {
            const double r0 = u0s[base + j], r1 = u1s[base + j], r2 = u2s[base + j];
            double v = r0 == r0 ? 1.0 : 0.0;
            v = r1 == r1 ? v : 0.0;
            ok[j] = r2 == r2 ? v : 0.0;
            c0[j] = clamp_u_d(r0);
            c1[j] = clamp_u_d(r1);
            c2[j] = clamp_u_d(r2);
        }
        unit_chunk_d(m, wo.x + base, wo.y + base, wo.z + base, ox, oy, oz, vo);
        if (per_element)
            derive_chunk_d(&mp, active, norm, m, base, &cc);
        for (size_t j = 0; j < m; ++j) /* the invalid elements, counted for the front end */
            bad += !(ok[j] > 0.0 && vo[j] > 0.0 && (!per_element || cc.valid[j] > 0.0));
        /* both lobes' directions, one selected by u0 < Ps (Ps is 1 for the specular lobe
         * alone, 0 for the diffuse one alone) */
        for (size_t j = 0; j < m; ++j) {
            /* every load unconditional and the selects flat, as GCC 12 if-converts them */
            const double ax = per_element ? cc.ax[j] : kc.alpha_x;
            const double ay = per_element ? cc.ay[j] : kc.alpha_y;
            const double ps = per_element ? cc.ps[j] : kc.ps;
            const double has = per_element ? cc.has[j] : has_u;
            const double okj = ok[j], voj = vo[j], oxj = ox[j], oyj = oy[j], ozj = oz[j];
            const double u0 = c0[j], u1 = c1[j], u2 = c2[j];
            double drawn = okj > 0.0 ? has : 0.0;
            drawn = voj > 0.0 ? drawn : 0.0;
            double sw[3] = {0.0, 0.0, 1.0}, dw[3] = {0.0, 0.0, 1.0}, og = 1.0;
            if (active & PGLOSS_LOBE_SPECULAR)
                og = pgloss__sample_specular_d(ax, ay, oxj, oyj, ozj, 1.0, u1, u2, sw);
            if (active & PGLOSS_LOBE_DIFFUSE)
                pgloss__sample_cosine_d(u1, u2, dw);
            const double sx = u0 < ps ? sw[0] : dw[0], sy = u0 < ps ? sw[1] : dw[1];
            const double sz = u0 < ps ? sw[2] : dw[2];
            const double l = u0 < ps ? (double)PGLOSS_LOBE_SPECULAR : (double)PGLOSS_LOBE_DIFFUSE;
            /* kept (pdf and weight) where wo is above the horizon and, drawn specular, wo·h > 0 */
            const double keep_s = og > 0.0 ? drawn : 0.0;
            const double keep = u0 < ps ? keep_s : drawn;
            wx[j] = drawn > 0.0 ? sx : 0.0;
            wy[j] = drawn > 0.0 ? sy : 0.0;
            wz[j] = drawn > 0.0 ? sz : 1.0;
            ok[j] = ozj > 0.0 ? keep : 0.0;
            lb[j] = drawn > 0.0 ? l : (double)PGLOSS_LOBE_NONE;
        }
        unit_chunk_d(m, wx, wy, wz, nx, ny, nz, vi);
        for (size_t j = 0; j < m; ++j) {
            const pgloss__consts_d kj = consts_of_chunk_d(&kc, &cc, per_element, active, j);
            double f[3], p;
            pgloss__lobe_d(&kj, active, norm, ox[j], oy[j], oz[j], nx[j], ny[j], nz[j], 1, 1, f,
                           &p);
            fr[j] = f[0];
            fg[j] = f[1];
            fb[j] = f[2];
            pr[j] = p;
        }
        write_sample_d(m, ok, vi, wx, wy, wz, nz, fr, fg, fb, pr, wi.x + base, wi.y + base,
                       wi.z + base, pdf + base, weight.r + base, weight.g + base,
                       weight.b + base);
        if (lobe)
            for (size_t j = 0; j < m; ++j)
                lobe[base + j] = (unsigned char)lb[j];
    }
    return bad;
}

size_t SAMPLE_D_FN(const pgloss__consts_d *k, const pgloss__materials_d *pa, unsigned active,
                 int norm, size_t n, pgloss__vec3_d wo, const double *u0s, const double *u1s,
                 const double *u2s, pgloss__vec3_out_d wi, double *pdf, pgloss__rgb_out_d weight,
                 unsigned char *lobe)
{
#define LOOP_PE(A, N) sample_d_loop(NULL, pa, 1, A, N, n, wo, u0s, u1s, u2s, wi, pdf, weight, lobe)
#define LOOP_U(A, N) sample_d_loop(k, NULL, 0, A, N, n, wo, u0s, u1s, u2s, wi, pdf, weight, lobe)
    return pa ? PGLOSS__BY_LOBES(LOOP_PE, active, norm) : PGLOSS__BY_LOBES(LOOP_U, active, norm);
#undef LOOP_PE
#undef LOOP_U
}
