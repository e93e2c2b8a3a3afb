// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The loops of the batched entry points, built from the per-point functions of
 * pgloss/inline.h (the one float definition of the lobe) over SoA arrays. This file is
 * compiled once per (ISA, tier) — see libpgloss/CMakeLists.txt — with PGLOSS_ISA set to
 * baseline / avx2 / avx512 and PGLOSS_TIER_FAST set to 0 (float tier) or 1 (fast tier);
 * batch.c picks one at run time.
 *
 * Every loop is specialised for (active lobes, normalisation, outputs wanted) by constant
 * arguments of always-inlined functions, so absent lobes and unused normalisations cost
 * nothing, and each loop body is branch-free float code that the compiler vectorises.
 *
 * Tiers. float: the inline functions as they are. fast: on AVX-512 and AVX2 the eval/pdf
 * loop runs batch_fast_block.h (the same steps with hardware reciprocal estimates and a
 * degree-5 exp2, no division) over the primitives of batch_avx512_fast.h /
 * batch_avx2_fast.h; its tails, blocks with other than near-unit directions, the sampler's
 * directions and the baseline ISA run the float code. */
#include "batch_internal.h"

#ifndef PGLOSS_ISA
#error "PGLOSS_ISA must name the instruction set this file is compiled for"
#endif
#ifndef PGLOSS_TIER_FAST
#error "PGLOSS_TIER_FAST must be 0 or 1"
#endif

#define PGLOSS__CAT3(a, b, c) a##_##b##_##c
#define PGLOSS__NAME(fn, isa, tier) PGLOSS__CAT3(fn, isa, tier)
#if PGLOSS_TIER_FAST
#define TIER fast
#else
#define TIER float
#endif
#define EVAL_PDF_FN PGLOSS__NAME(pgloss__eval_pdf, PGLOSS_ISA, TIER)
#define SAMPLE_FN PGLOSS__NAME(pgloss__sample, PGLOSS_ISA, TIER)

/* LOOP(lobes, normalisation) with both as compile-time constants, chosen from the run-time
 * `active` and `norm` in scope: absent lobes and unused normalisations compile away. */
#define PGLOSS__BY_NORM(LOOP, A)                                                                   \
    (norm == PGLOSS_NORM_WARD_DUR                                                                  \
         ? LOOP(A, PGLOSS_NORM_WARD_DUR)                                                           \
         : (norm == PGLOSS_NORM_BOUNDED ? LOOP(A, PGLOSS_NORM_BOUNDED) : LOOP(A, PGLOSS_NORM_WARD)))
#define PGLOSS__BY_LOBES(LOOP)                                                                     \
    (active == PGLOSS_LOBE_DIFFUSE    ? LOOP(PGLOSS_LOBE_DIFFUSE, PGLOSS_NORM_WARD)                \
     : active == PGLOSS_LOBE_SPECULAR ? PGLOSS__BY_NORM(LOOP, PGLOSS_LOBE_SPECULAR)               \
     : active == PGLOSS_LOBE_ALL      ? PGLOSS__BY_NORM(LOOP, PGLOSS_LOBE_ALL)                    \
                                      : LOOP(PGLOSS_LOBE_NONE, PGLOSS_NORM_WARD))

/* The loops work chunk by chunk, with the outputs of a pass kept on the stack: simple loops
 * vectorise where one fused loop defeats GCC's if-conversion. */
#define CHUNK 256

/* Per-element constants of a chunk (per-element materials): what pgloss_inl_consts_of gives
 * for element j's material, the lobes active for it, and its α for the sampler. */
typedef struct chunk_consts {
    float fd0[CHUNK], fd1[CHUNK], fd2[CHUNK], spec[CHUNK], iax[CHUNK], iay[CHUNK];
    float ps[CHUNK], pdf_d[CHUNK], pdf_s[CHUNK], ax[CHUNK], ay[CHUNK];
    int act[CHUNK];
} chunk_consts;

/* The lobe constants of element j: the call's (c NULL, a constant of the instance) or the
 * element's own. */
PGLOSS_INLINE_FN pgloss_inl_consts consts_at(const pgloss__batch_consts *restrict k,
                                             const chunk_consts *restrict c, size_t j)
{
    if (!c)
        return k->lobe;
    pgloss_inl_consts r;
    r.fd[0] = c->fd0[j];
    r.fd[1] = c->fd1[j];
    r.fd[2] = c->fd2[j];
    r.spec_scale = c->spec[j];
    r.inv_ax = c->iax[j];
    r.inv_ay = c->iay[j];
    r.ps = c->ps[j];
    r.pdf_d = c->pdf_d[j];
    r.pdf_s = c->pdf_s[j];
    return r;
}

/* pgloss_material_init of elements [0, m) of the arrays (offset to the chunk), inside the
 * loop: validity (ok &= valid), pgloss_inl_material_derive, pgloss_inl_consts_of for the
 * lobes that the mask and the element's material share. An invalid element gets a black
 * material (and ok = 0, so 0 outputs). Returns the number of invalid elements. */
PGLOSS_INLINE_FN size_t derive_chunk(unsigned lobes, int norm, size_t m,
                                     const pgloss__materials_f *ma, size_t base,
                                     chunk_consts *restrict c, int *restrict ok)
{
    const float *restrict rr = ma->rho_d_r + base, *restrict rg = ma->rho_d_g + base;
    const float *restrict rb = ma->rho_d_b + base, *restrict rs = ma->rho_s + base;
    const float *restrict axs = ma->alpha_x + base, *restrict ays = ma->alpha_y + base;
    size_t bad = 0;
    for (size_t j = 0; j < m; ++j) {
        const float r = rr[j], g = rg[j], b = rb[j], s = rs[j], ax = axs[j], ay = ays[j];
        const int good = pgloss__material_valid_f(r, g, b, s, ax, ay);
        pgloss_material mm;
        /* An invalid element's reflectances become +0 by masking their bits: a select
         * (good ? r : 0) lets GCC 12 thread the later r > 0 into a select of booleans,
         * which it cannot vectorise. */
        const int32_t keep = -(int32_t)good;
        mm.rho_d[0] = pgloss_inl_from_bits(pgloss_inl_bits(r) & keep);
        mm.rho_d[1] = pgloss_inl_from_bits(pgloss_inl_bits(g) & keep);
        mm.rho_d[2] = pgloss_inl_from_bits(pgloss_inl_bits(b) & keep);
        mm.rho_s = pgloss_inl_from_bits(pgloss_inl_bits(s) & keep);
        mm.alpha_x = good ? ax : 1.0f;
        mm.alpha_y = good ? ay : 1.0f;
        mm.normalization = (pgloss_normalization)norm;
        pgloss_inl_material_derive(&mm);
        const unsigned act = lobes & mm.lobes;
        const pgloss_inl_consts k = pgloss_inl_consts_of(&mm, act);
        c->fd0[j] = k.fd[0];
        c->fd1[j] = k.fd[1];
        c->fd2[j] = k.fd[2];
        c->spec[j] = k.spec_scale;
        c->iax[j] = k.inv_ax;
        c->iay[j] = k.inv_ay;
        c->ps[j] = k.ps;
        c->pdf_d[j] = k.pdf_d;
        c->pdf_s[j] = k.pdf_s;
        c->ax[j] = mm.alpha_x;
        c->ay[j] = mm.alpha_y;
        c->act[j] = (int)act;
        ok[j] &= good;
        bad += !good;
    }
    return bad;
}

/* Whether every direction of a chunk is near-unit (which also rules out NaN and Inf). */
PGLOSS_INLINE_FN int chunk_near_unit(size_t n, const float *restrict xs, const float *restrict ys,
                                  const float *restrict zs)
{
    size_t out = 0;
    for (size_t j = 0; j < n; ++j) {
        out += !pgloss_inl_near_unit(xs[j], ys[j], zs[j]);
    }
    return out == 0;
}

/* Copies a chunk's directions for the kernel: near-unit ones as they are, others normalised
 * (after an exact power-of-two scaling, so that no square overflows or underflows); a zero
 * or non-finite direction becomes (0, 0, 1) with ok = 0. Returns the number of those. */
PGLOSS_INLINE_FN size_t unit_chunk(size_t n, const float *restrict xs, const float *restrict ys,
                                const float *restrict zs, float *restrict nx, float *restrict ny,
                                float *restrict nz, int *restrict ok)
{
    size_t bad = 0;
    for (size_t j = 0; j < n; ++j) {
        float x = xs[j], y = ys[j], z = zs[j];
        if (!pgloss_inl_near_unit(x, y, z)) {
            const int v = pgloss_inl_normalize(&x, &y, &z);
            z = v ? z : 1.0f;
            ok[j] &= v;
            bad += !v;
        }
        nx[j] = x;
        ny[j] = y;
        nz[j] = z;
    }
    return bad;
}

/* Unit directions (for the sampler); returns the number of invalid ones. */
PGLOSS_INLINE_FN size_t normalize_chunk(size_t n, const float *restrict xs, const float *restrict ys,
                                     const float *restrict zs, float *restrict nx,
                                     float *restrict ny, float *restrict nz, int *restrict ok)
{
    /* The common case first: when every squared length of the chunk lies in [2^-100, 2^100]
     * (so no square overflowed or underflowed, and no component is NaN or Inf), x/|x| needs
     * no scaling: a third of the operations of the careful path below. */
    size_t unsafe = 0;
    for (size_t j = 0; j < n; ++j) {
        const float x = xs[j], y = ys[j], z = zs[j];
        const float l2 = x * x + y * y + z * z;
        nz[j] = l2; /* scratch until written below */
        unsafe += !((l2 >= 0x1p-100f) & (l2 <= 0x1p100f));
    }
    if (unsafe == 0) {
        for (size_t j = 0; j < n; ++j) {
            const float inv = 1.0f / sqrtf(nz[j]);
            nx[j] = xs[j] * inv;
            ny[j] = ys[j] * inv;
            nz[j] = zs[j] * inv;
        }
        return 0;
    }
    size_t bad = 0;
    for (size_t j = 0; j < n; ++j) {
        float x = xs[j], y = ys[j], z = zs[j];
        const int v = pgloss_inl_normalize(&x, &y, &z);
        nx[j] = x;
        ny[j] = y;
        nz[j] = z;
        ok[j] &= v;
        bad += !v;
    }
    return bad;
}

/* f and pdf of a chunk (ok: validity in and out); returns the number of invalid directions.
 * Unwanted outputs go to scratch chunks instead of being a specialisation of their own: the
 * loops stay branch-free, and the file compiles in a third of the time. */
PGLOSS_INLINE_FN size_t eval_chunk(const pgloss__batch_consts *restrict k,
                                const chunk_consts *restrict pc, const unsigned active,
                                const int norm, size_t m, const float *oxs, const float *oys,
                                const float *ozs, const float *ixs, const float *iys,
                                const float *izs, int *restrict ok, float *restrict r,
                                float *restrict g, float *restrict b, float *restrict p)
{
    float ox[CHUNK], oy[CHUNK], oz[CHUNK], ix[CHUNK], iy[CHUNK], iz[CHUNK];
    size_t bad = 0;
    if (!chunk_near_unit(m, oxs, oys, ozs)) {
        bad += unit_chunk(m, oxs, oys, ozs, ox, oy, oz, ok);
        oxs = ox;
        oys = oy;
        ozs = oz;
    }
    if (!chunk_near_unit(m, ixs, iys, izs)) {
        bad += unit_chunk(m, ixs, iys, izs, ix, iy, iz, ok);
        ixs = ix;
        iys = iy;
        izs = iz;
    }
    for (size_t j = 0; j < m; ++j) {
        float f[3], pj;
        const pgloss_inl_consts kj = consts_at(k, pc, j);
        pgloss_inl_eval_pdf_unit(&kj, active, norm, oxs[j], oys[j], ozs[j], ixs[j], iys[j],
                                 izs[j], ok[j], f, &pj);
        r[j] = f[0];
        g[j] = f[1];
        b[j] = f[2];
        p[j] = pj;
    }
    return bad;
}

PGLOSS_INLINE_FN size_t eval_pdf_loop(const pgloss__batch_consts *restrict k, const unsigned active,
                                   const int norm, size_t n, const float *restrict oxs,
                                   const float *restrict oys, const float *restrict ozs,
                                   const float *restrict ixs, const float *restrict iys,
                                   const float *restrict izs, float *fr, float *fg, float *fb,
                                   float *pdf)
{
    size_t bad = 0;
    float sr[CHUNK], sg[CHUNK], sb[CHUNK], sp[CHUNK];
    int ok[CHUNK];
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        for (size_t j = 0; j < m; ++j)
            ok[j] = 1;
        bad += eval_chunk(k, NULL, active, norm, m, oxs + base, oys + base, ozs + base, ixs + base,
                          iys + base, izs + base, ok, fr ? fr + base : sr, fr ? fg + base : sg,
                          fr ? fb + base : sb, pdf ? pdf + base : sp);
    }
    return bad;
}

#if PGLOSS_TIER_FAST && defined(__AVX512F__)
#include "batch_avx512_fast.h"
#elif PGLOSS_TIER_FAST && defined(__AVX2__) && defined(__FMA__)
#include "batch_avx2_fast.h"
#endif
#if defined(PGLOSS_VW)
#include "batch_fast_block.h"
/* The generic loop, out of line, for the blocks the intrinsics refuse and the tail: the
 * block loop below keeps its registers to itself. */
static __attribute__((noinline)) size_t
eval_pdf_generic(const pgloss__batch_consts *k, unsigned active, int norm, size_t n,
                 const float *ox, const float *oy, const float *oz, const float *ix,
                 const float *iy, const float *iz, float *r, float *g, float *b, float *p)
{
#define LOOP(A, N) eval_pdf_loop(k, A, N, n, ox, oy, oz, ix, iy, iz, r, g, b, p)
    return PGLOSS__BY_LOBES(LOOP);
#undef LOOP
}

/* Blocks of PGLOSS_VW in intrinsics where they qualify, the generic loop elsewhere. */
PGLOSS_INLINE_FN size_t eval_pdf_loop_v(const pgloss__batch_consts *restrict k, const unsigned active,
                                     const int norm, size_t n, const float *oxs, const float *oys,
                                     const float *ozs, const float *ixs, const float *iys,
                                     const float *izs, float *fr, float *fg, float *fb,
                                     float *pdf, const int want_f, const int want_p)
{
    size_t bad = 0, j = 0;
    for (; j + PGLOSS_VW <= n; j += PGLOSS_VW) {
        float *r = want_f ? fr + j : NULL, *g = want_f ? fg + j : NULL;
        float *b = want_f ? fb + j : NULL, *p = want_p ? pdf + j : NULL;
        if (!v_eval_pdf_block(k, active, norm, oxs + j, oys + j, ozs + j, ixs + j, iys + j,
                              izs + j, r, g, b, p, want_f, want_p))
            bad += eval_pdf_generic(k, active, norm, PGLOSS_VW, oxs + j, oys + j, ozs + j,
                                    ixs + j, iys + j, izs + j, r, g, b, p);
    }
    if (j < n)
        bad += eval_pdf_generic(k, active, norm, n - j, oxs + j, oys + j, ozs + j, ixs + j,
                                iys + j, izs + j, want_f ? fr + j : NULL, want_f ? fg + j : NULL,
                                want_f ? fb + j : NULL, want_p ? pdf + j : NULL);
    return bad;
}
/* Specialised on the outputs wanted too: the block skips the pdf for eval and f for pdf. */
#define EVAL_PDF_LOOP(k, A, N, n, ox, oy, oz, ix, iy, iz, r, g, b, p)                              \
    ((r) && (p) ? eval_pdf_loop_v(k, A, N, n, ox, oy, oz, ix, iy, iz, r, g, b, p, 1, 1)            \
                : ((r) ? eval_pdf_loop_v(k, A, N, n, ox, oy, oz, ix, iy, iz, r, g, b, p, 1, 0)     \
                       : eval_pdf_loop_v(k, A, N, n, ox, oy, oz, ix, iy, iz, r, g, b, p, 0, 1)))
#else
#define EVAL_PDF_LOOP eval_pdf_loop
#endif

size_t EVAL_PDF_FN(const pgloss__batch_consts *k, unsigned active, int norm, size_t n,
                   pgloss__vec3_f wo, pgloss__vec3_f wi, pgloss__rgb_out_f f, float *pdf)
{
#define LOOP(A, N) EVAL_PDF_LOOP(k, A, N, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g, f.b, pdf)
    return PGLOSS__BY_LOBES(LOOP);
#undef LOOP
}

/* ---- sampling ---------------------------------------------------------------------- */

/* Three passes per chunk (wo, then the drawn direction, then f and pdf at it), for the
 * same reason as eval_pdf_loop. */
PGLOSS_INLINE_FN void sample_loop(const pgloss__batch_consts *restrict k,
                               const pgloss__materials_f *ma, const int per_element,
                               const unsigned active, const int norm, size_t n,
                               const float *restrict oxs,
                               const float *restrict oys, const float *restrict ozs,
                               const float *restrict u0s, const float *restrict u1s,
                               const float *restrict u2s, float *restrict wx,
                               float *restrict wy, float *restrict wz, float *restrict pdfs,
                               float *restrict wr, float *restrict wg, float *restrict wb,
                               unsigned char *restrict lobe_out)
{
    float ox[CHUNK], oy[CHUNK], oz[CHUNK], ix[CHUNK], iy[CHUNK], iz[CHUNK];
    float c0[CHUNK], c1[CHUNK], c2[CHUNK];
    int ok[CHUNK], spec_c[CHUNK];
    chunk_consts cc;
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        /* Clamped random numbers in a pass of their own: GCC 12 does not if-convert the
         * clamps together with the sampling code below. */
        for (size_t j = 0; j < m; ++j) {
            const float r0 = u0s[base + j], r1 = u1s[base + j], r2 = u2s[base + j];
            ok[j] = !((r0 != r0) | (r1 != r1) | (r2 != r2));
            c0[j] = pgloss_inl_clamp_u(r0);
            c1[j] = pgloss_inl_clamp_u(r1);
            c2[j] = pgloss_inl_clamp_u(r2);
        }
        if (per_element)
            derive_chunk(active, norm, m, ma, base, &cc, ok);
        normalize_chunk(m, oxs + base, oys + base, ozs + base, ox, oy, oz, ok);
        /* The diffuse candidates (into ix, iy, iz, free until the eval pass). */
        if (active & PGLOSS_LOBE_DIFFUSE) {
            for (size_t j = 0; j < m; ++j)
                pgloss_inl_sample_cosine(c1[j], c2[j], &ix[j], &iy[j], &iz[j]);
        }
        for (size_t j = 0; j < m; ++j) {
            const float u0 = c0[j];
            /* the lobes of this element: the call's, or those its own material has */
            const unsigned act = per_element ? (unsigned)cc.act[j] : active;
            const float ps = per_element ? cc.ps[j] : k->lobe.ps;
            const int spec = (act == PGLOSS_LOBE_SPECULAR) |
                             ((act == PGLOSS_LOBE_ALL) & (u0 < ps));
            const int drawn = ok[j] & (act != PGLOSS_LOBE_NONE);
            float sx = 0.0f, sy = 0.0f, sz = 1.0f, oh = 1.0f;
            if (active & PGLOSS_LOBE_SPECULAR)
                oh = pgloss_inl_sample_specular(per_element ? cc.ax[j] : k->alpha_x,
                                                per_element ? cc.ay[j] : k->alpha_y, ox[j], oy[j],
                                                oz[j], c1[j], c2[j], &sx, &sy, &sz);
            const float dx = (active & PGLOSS_LOBE_DIFFUSE) ? ix[j] : 0.0f;
            const float dy = (active & PGLOSS_LOBE_DIFFUSE) ? iy[j] : 0.0f;
            const float dz = (active & PGLOSS_LOBE_DIFFUSE) ? iz[j] : 1.0f;
            wx[base + j] = drawn ? (spec ? sx : dx) : 0.0f;
            wy[base + j] = drawn ? (spec ? sy : dy) : 0.0f;
            wz[base + j] = drawn ? (spec ? sz : dz) : 1.0f;
            ok[j] = drawn & ((!spec) | (oh > 0.0f));
            spec_c[j] = drawn ? (spec ? PGLOSS_LOBE_SPECULAR : PGLOSS_LOBE_DIFFUSE)
                              : PGLOSS_LOBE_NONE;
        }
        /* f and pdf at the float direction handed back, as the scalar function does (in the
         * FAST tier's blocks where it has them; rejected samples are zeroed below by ok). */
#if defined(PGLOSS_VW)
        eval_pdf_loop_v(k, active, norm, m, oxs + base, oys + base, ozs + base, wx + base,
                        wy + base, wz + base, wr + base, wg + base, wb + base, pdfs + base, 1, 1);
#else
        eval_chunk(k, per_element ? &cc : NULL, active, norm, m, oxs + base, oys + base, ozs + base,
                   wx + base, wy + base, wz + base, ok, wr + base, wg + base, wb + base,
                   pdfs + base);
#endif
        /* weight = f cosθi / pdf, 0 where the sample is rejected (pdf 0). */
        for (size_t j = 0; j < m; ++j)
            pgloss_inl_weight(ok[j], wx[base + j], wy[base + j], wz[base + j], &pdfs[base + j],
                              &wr[base + j], &wg[base + j], &wb[base + j]);
        if (lobe_out)
            for (size_t j = 0; j < m; ++j)
                lobe_out[base + j] = (unsigned char)spec_c[j];
    }
}

void SAMPLE_FN(const pgloss__batch_consts *k, unsigned active, int norm, size_t n,
               pgloss__vec3_f wo, const float *u0, const float *u1, const float *u2,
               pgloss__vec3_out_f wi, float *pdf, pgloss__rgb_out_f weight, unsigned char *lobe)
{
#define LOOP(A, N)                                                                                 \
    sample_loop(k, NULL, 0, A, N, n, wo.x, wo.y, wo.z, u0, u1, u2, wi.x, wi.y, wi.z, pdf,       \
                weight.r, weight.g, weight.b, lobe)
    PGLOSS__BY_LOBES(LOOP);
#undef LOOP
}

/* ---- per-element materials (FLOAT tier only: FAST runs these loops too) ------------------ */

#if !PGLOSS_TIER_FAST
#define PGLOSS__CAT2(a, b) a##_##b
#define PGLOSS__NAME2(fn, isa) PGLOSS__CAT2(fn, isa)
#define EVAL_PDF_MATERIALS_FN PGLOSS__NAME2(pgloss__eval_pdf_materials, PGLOSS_ISA)
#define SAMPLE_MATERIALS_FN PGLOSS__NAME2(pgloss__sample_materials, PGLOSS_ISA)

/* As eval_pdf_loop, with each chunk's constants derived from its materials first. */
PGLOSS_INLINE_FN size_t eval_pdf_materials_loop(const pgloss__materials_f *ma,
                                                const unsigned active, const int norm, size_t n,
                                                const float *restrict oxs,
                                                const float *restrict oys,
                                                const float *restrict ozs,
                                                const float *restrict ixs,
                                                const float *restrict iys,
                                                const float *restrict izs, float *fr, float *fg,
                                                float *fb, float *pdf)
{
    size_t bad = 0;
    float sr[CHUNK], sg[CHUNK], sb[CHUNK], sp[CHUNK];
    int ok[CHUNK];
    chunk_consts cc;
    for (size_t base = 0; base < n; base += CHUNK) {
        const size_t m = n - base < CHUNK ? n - base : CHUNK;
        for (size_t j = 0; j < m; ++j)
            ok[j] = 1;
        bad += derive_chunk(active, norm, m, ma, base, &cc, ok);
        bad += eval_chunk(NULL, &cc, active, norm, m, oxs + base, oys + base, ozs + base,
                          ixs + base, iys + base, izs + base, ok, fr ? fr + base : sr,
                          fr ? fg + base : sg, fr ? fb + base : sb, pdf ? pdf + base : sp);
    }
    return bad;
}

/* Here `active` is the call's mask (lobes & PGLOSS_LOBE_ALL): each element narrows it to the
 * lobes its material has through its constants. */
size_t EVAL_PDF_MATERIALS_FN(const pgloss__materials_f *m, unsigned active, size_t n,
                             pgloss__vec3_f wo, pgloss__vec3_f wi, pgloss__rgb_out_f f,
                             float *pdf)
{
    const int norm = (int)m->normalization;
#define LOOP(A, N)                                                                                 \
    eval_pdf_materials_loop(m, A, N, n, wo.x, wo.y, wo.z, wi.x, wi.y, wi.z, f.r, f.g, f.b, pdf)
    return PGLOSS__BY_LOBES(LOOP);
#undef LOOP
}

void SAMPLE_MATERIALS_FN(const pgloss__materials_f *m, unsigned active, size_t n,
                         pgloss__vec3_f wo, const float *u0, const float *u1, const float *u2,
                         pgloss__vec3_out_f wi, float *pdf, pgloss__rgb_out_f weight,
                         unsigned char *lobe)
{
    const int norm = (int)m->normalization;
#define LOOP(A, N)                                                                                 \
    sample_loop(NULL, m, 1, A, N, n, wo.x, wo.y, wo.z, u0, u1, u2, wi.x, wi.y, wi.z, pdf,          \
                weight.r, weight.g, weight.b, lobe)
    PGLOSS__BY_LOBES(LOOP);
#undef LOOP
}
#endif
