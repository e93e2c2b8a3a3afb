// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The float batch loops: the lobe of pgloss/detail/lobe.h over the SIMD helper of the ISA this
 * file is compiled for, a block of PV_LANES elements at a time. The last block of a call is
 * padded with valid inputs, so that every element runs the same code wherever it lies; with
 * one material, FLOAT runs it on the one-lane helper instead, which gives the same bits.
 * libpgloss/CMakeLists.txt compiles it per ISA and tier: PGLOSS_FAST=0 for FLOAT (IEEE
 * operations, never fused: the same bits on every ISA), PGLOSS_FAST=1 for FAST (the lobe's
 * fast option, and -ffp-contract=fast: multiply-adds fused where the ISA has FMA);
 * dispatch.c picks one at run time.
 *
 * Each loop is specialised on (active lobes, normalisation, one material or one per element,
 * outputs wanted) by constant arguments of always-inlined functions: absent lobes, unused
 * normalisations and unwanted outputs cost nothing. */
#include "batch_internal.h"
#include "rows3.h"

#if !defined(PGLOSS_ISA) || !defined(PGLOSS_FAST)
#error "PGLOSS_ISA must name the instruction set this file is compiled for, PGLOSS_FAST the tier"
#endif

/* The helper (twice: the lobe undefines its names at its end, and the loops use them too). */
#if defined(__AVX512F__)
#include "simd_avx512.h"
#include "pgloss/detail/lobe.h"
#include "simd_avx512.h"
#elif defined(__AVX2__) && defined(__FMA__)
#include "simd_avx2.h"
#include "pgloss/detail/lobe.h"
#include "simd_avx2.h"
#elif defined(__SSE2__)
#include "simd_sse2.h"
#include "pgloss/detail/lobe.h"
#include "simd_sse2.h"
#else
#include "pgloss/detail/simd_scalar.h" /* one lane: the lobe of pgloss/inline.h */
#endif

#define V PGLOSS_K
#define W PV_LANES
#define CAT_(a, b, c) a##_##b##_##c
#define CAT(a, b, c) CAT_(a, b, c)
#if PGLOSS_FAST
#define NAME(fn) CAT(fn, PGLOSS_ISA, fast)
#else
#define NAME(fn) CAT(fn, PGLOSS_ISA, float)
#endif

/* m <= W values of a column (the missing lanes: fill), and back. */
PGLOSS_INLINE_FN pv_f load_part(const float *p, size_t m, float fill)
{
    if (m == W)
        return pv_load(p);
#if defined(pv_load_part)
    return pv_load_part(p, m, fill);
#else
    float t[W];
    for (size_t j = 0; j < W; ++j)
        t[j] = j < m ? p[j] : fill;
    return pv_load(t);
#endif
}

PGLOSS_INLINE_FN void store_part(float *p, size_t m, pv_f v)
{
    if (m == W) {
        pv_store(p, v);
        return;
    }
    float t[W];
    pv_store(t, v);
    for (size_t j = 0; j < m; ++j)
        p[j] = t[j];
}

/* The material of the per-element loops' unused one-material constants. */
static const pgloss_material no_material;

/* One material's constants in every lane, for its active lobes. */
PGLOSS_INLINE_FN V(consts) broadcast(const pgloss_material *m, unsigned active)
{
    const pv_f rd[3] = {pv_f1(m->rho_d[0]), pv_f1(m->rho_d[1]), pv_f1(m->rho_d[2])};
    return V(consts_of_parts)(rd, pv_f1(m->spec_scale), pv_f1(m->inv_alpha_x),
                              pv_f1(m->inv_alpha_y), pv_f1(m->pdf_scale),
                              pv_f1(m->specular_probability), pv_f1(m->pdf_diffuse),
                              pv_f1(m->pdf_specular), pv_m1(active & PGLOSS_LOBE_DIFFUSE),
                              pv_m1(active & PGLOSS_LOBE_SPECULAR));
}

/* The materials of lanes [j, j + m): pgloss_material_init's checks (*good; an invalid one is
 * black, ρ = 0 and α = 1), the lobe's constants for the lobes of `active` each has, and α. */
typedef struct lane_material {
    V(consts) k;
    pv_f ax, ay;
    pv_m has_d, has_s, good;
} lane_material;

PGLOSS_INLINE_FN lane_material lane_materials(const pgloss__materials_f *ms, unsigned active,
                                              const int norm, size_t j, size_t m)
{
    const pv_f r = load_part(ms->rho_d_r + j, m, 0.0f), g = load_part(ms->rho_d_g + j, m, 0.0f);
    const pv_f b = load_part(ms->rho_d_b + j, m, 0.0f), s = load_part(ms->rho_s + j, m, 0.0f);
    const pv_f ax = load_part(ms->alpha_x + j, m, 1.0f), ay = load_part(ms->alpha_y + j, m, 1.0f);
    const pv_f zero = pv_f1(0.0f), one = pv_f1(1.0f);
    lane_material l;
    l.good = pv_and(pv_and(pv_and(V(finite)(r), V(finite)(g)), pv_and(V(finite)(b), V(finite)(s))),
                    pv_and(V(finite)(ax), V(finite)(ay)));
    l.good = pv_and(l.good, pv_and(pv_and(pv_ge(r, zero), pv_ge(g, zero)),
                                   pv_and(pv_ge(b, zero), pv_ge(s, zero))));
    l.good = pv_and(l.good, pv_and(pv_gt(ax, zero), pv_gt(ay, zero)));
    const V(derived) d = V(derive)(pv_sel(l.good, r, zero), pv_sel(l.good, g, zero),
                                   pv_sel(l.good, b, zero), pv_sel(l.good, s, zero),
                                   pv_sel(l.good, ax, one), pv_sel(l.good, ay, one), norm);
    l.has_d = pv_and(d.has_d, pv_m1(active & PGLOSS_LOBE_DIFFUSE));
    l.has_s = pv_and(d.has_s, pv_m1(active & PGLOSS_LOBE_SPECULAR));
    l.k = V(consts_of_parts)(d.rho_d, d.spec_scale, d.iax, d.iay, d.pdf_scale, d.ps, d.pdf_d,
                             d.pdf_s, l.has_d, l.has_s);
    l.ax = d.ax;
    l.ay = d.ay;
    return l;
}

/* A direction of lanes [j, j + m) as the lobe takes it (pgloss_inl_unit); padding (0, 0, 1). */
PGLOSS_INLINE_FN pv_m load_dir(const float *xs, const float *ys, const float *zs, size_t j,
                               size_t m, pv_f *x, pv_f *y, pv_f *z)
{
    *x = load_part(xs + j, m, 0.0f);
    *y = load_part(ys + j, m, 0.0f);
    *z = load_part(zs + j, m, 1.0f);
    return V(unit)(x, y, z);
}

/* ---- eval / pdf --------------------------------------------------------------------------- */

/* One block: elements [j, j + m), m <= W; returns how many are invalid (the padding is valid). */
PGLOSS_INLINE_FN size_t eval_block(const pgloss__call_f *c, const V(consts) *k1, const unsigned active,
                                   const int norm, const int per_element, const int clamp,
                                   const int want_f, const int want_p, size_t j, size_t m,
                                   pgloss__vec3_f wo, pgloss__vec3_f wi, pgloss__rgb_out_f f,
                                   float *pdf)
{
    pv_f ox = load_part(wo.x + j, m, 0.0f), oy = load_part(wo.y + j, m, 0.0f);
    pv_f oz = load_part(wo.z + j, m, 1.0f), ix = load_part(wi.x + j, m, 0.0f);
    pv_f iy = load_part(wi.y + j, m, 0.0f), iz = load_part(wi.z + j, m, 1.0f);
    pv_m ok = V(units)(&ox, &oy, &oz, &ix, &iy, &iz);
    V(consts) k = *k1;
    if (per_element) {
        const lane_material l = lane_materials(c->ms, active, norm, j, m);
        k = l.k;
        ok = pv_and(ok, l.good);
    }
    pv_f fv[3], p;
    V(eval_pdf_unit)(&k, active, norm, PGLOSS_FAST, clamp, ox, oy, oz, ix, iy, iz, ok, fv, &p);
    if (want_f) {
        store_part(f.r + j, m, fv[0]);
        store_part(f.g + j, m, fv[1]);
        store_part(f.b + j, m, fv[2]);
    }
    if (want_p)
        store_part(pdf + j, m, p);
    return (size_t)pv_count(pv_not(ok));
}

#if !PGLOSS_FAST && PV_LANES > 1
/* FLOAT's last, partial block with one material: the one-lane lobe of pgloss/inline.h, whose
 * bits are a lane's (Isa.FloatTierEqualsInline), at a fraction of a padded block's latency. */
PGLOSS_INLINE_FN size_t eval_tail(const pgloss_material *mat, const unsigned active, const int norm,
                                  const int clamp, const int want_f, const int want_p, size_t j,
                                  size_t n, pgloss__vec3_f wo, pgloss__vec3_f wi,
                                  pgloss__rgb_out_f f, float *pdf)
{
    const pgloss_inl_consts k = pgloss_inl_consts_of(mat, active);
    size_t bad = 0;
    for (; j < n; ++j) {
        float ox = wo.x[j], oy = wo.y[j], oz = wo.z[j], ix = wi.x[j], iy = wi.y[j], iz = wi.z[j];
        const int ok = pgloss_inl_units(&ox, &oy, &oz, &ix, &iy, &iz);
        float fv[3], p;
        pgloss_inl_eval_pdf_unit(&k, active, norm, 0, clamp, ox, oy, oz, ix, iy, iz, ok, fv, &p);
        if (want_f) {
            f.r[j] = fv[0];
            f.g[j] = fv[1];
            f.b[j] = fv[2];
        }
        if (want_p)
            pdf[j] = p;
        bad += !ok;
    }
    return bad;
}
#endif

/* Full blocks (m = W, a constant: plain loads and stores), then the last, partial one. */
PGLOSS_INLINE_FN size_t eval_loop(const pgloss__call_f *c, const unsigned active, const int norm,
                                  const int per_element, const int clamp, const int want_f,
                                  const int want_p, size_t n, pgloss__vec3_f wo,
                                  pgloss__vec3_f wi, pgloss__rgb_out_f f, float *pdf)
{
    const V(consts) k1 = broadcast(per_element ? &no_material : c->m, active);
    size_t bad = 0, j = 0;
    for (; j + W <= n; j += W)
        bad += eval_block(c, &k1, active, norm, per_element, clamp, want_f, want_p, j, W, wo, wi,
                          f, pdf);
    if (j == n)
        return bad;
#if !PGLOSS_FAST && PV_LANES > 1
    if (!per_element)
        return bad + eval_tail(c->m, active, norm, clamp, want_f, want_p, j, n, wo, wi, f, pdf);
#endif
    return bad + eval_block(c, &k1, active, norm, per_element, clamp, want_f, want_p, j, n - j, wo,
                            wi, f, pdf);
}

/* One out-of-line function per (lobes, normalisation) (PGLOSS__EACH_LOBES), choosing among
 * its nine loops (per element, or one material whose outputs can or cannot exceed FLT_MAX;
 * outputs wanted); the entry point picks the function. */
#define EVAL_FN(A, N) CAT(eval, A, N)
#define OUT(A, N, E, C)                                                                            \
    (wf && wp ? eval_loop(c, A, N, E, C, 1, 1, n, wo, wi, f, pdf)                                  \
              : (wf ? eval_loop(c, A, N, E, C, 1, 0, n, wo, wi, f, pdf)                            \
                    : eval_loop(c, A, N, E, C, 0, 1, n, wo, wi, f, pdf)))
#define DEFINE_EVAL(A, N)                                                                          \
    static PGLOSS__NOINLINE size_t EVAL_FN(A, N)(const pgloss__call_f *c, size_t n,                \
                                                 pgloss__vec3_f wo, pgloss__vec3_f wi,             \
                                                 pgloss__rgb_out_f f, float *pdf)                  \
    {                                                                                              \
        const int wf = f.r != NULL, wp = pdf != NULL;                                              \
        return c->ms ? OUT(A, N, 1, 1) : (c->clamp ? OUT(A, N, 0, 1) : OUT(A, N, 0, 0));           \
    }
PGLOSS__EACH_LOBES(DEFINE_EVAL)
#undef DEFINE_EVAL
#undef OUT

size_t NAME(pgloss__eval_pdf)(const pgloss__call_f *c, size_t n, pgloss__vec3_f wo,
                              pgloss__vec3_f wi, pgloss__rgb_out_f f, float *pdf)
{
#define LOOP(A, N) EVAL_FN(A, N)(c, n, wo, wi, f, pdf)
    return PGLOSS__BY_LOBES(LOOP, c->active, c->norm);
#undef LOOP
}

/* ---- sampling ----------------------------------------------------------------------------- */

/* pgloss_sample_inline lane by lane: both lobes' directions drawn, one selected by u0 < Ps,
 * f and pdf at it, weight = f cosθi / pdf. An invalid element (a NaN random number, wo zero
 * or not finite, an invalid material), or one without an active lobe, is drawn as (0, 0, 1)
 * with lobe NONE and zeros; the returned count is of invalid elements. */
PGLOSS_INLINE_FN size_t sample_loop(const pgloss__call_f *c, const unsigned active, const int norm,
                                    const int per_element, size_t n,
                                    pgloss__vec3_f wo, const float *u0s, const float *u1s,
                                    const float *u2s, pgloss__vec3_out_f wi, float *pdfs,
                                    pgloss__rgb_out_f weight, unsigned char *lobe)
{
    const pgloss_material *m1 = per_element ? &no_material : c->m;
    const V(consts) k1 = broadcast(m1, active);
    const pv_f zero = pv_f1(0.0f), one = pv_f1(1.0f);
    size_t bad = 0;
    for (size_t j = 0; j < n; j += W) {
        const size_t m = n - j < W ? n - j : W;
        const pv_f u0 = load_part(u0s + j, m, 0.0f), u1 = load_part(u1s + j, m, 0.0f);
        const pv_f u2 = load_part(u2s + j, m, 0.0f);
        pv_m ok = pv_and(pv_and(pv_ge(u0, u0), pv_ge(u1, u1)), pv_ge(u2, u2)); /* no NaN */
        const pv_f c0 = V(clamp_u)(u0), c1 = V(clamp_u)(u1), c2 = V(clamp_u)(u2);
        pv_f ox, oy, oz;
        ok = pv_and(ok, load_dir(wo.x, wo.y, wo.z, j, m, &ox, &oy, &oz));
        V(consts) k = k1;
        pv_f ax = pv_f1(m1->alpha_x), ay = pv_f1(m1->alpha_y);
        pv_m has_d = pv_m1(active & PGLOSS_LOBE_DIFFUSE), has_s = pv_m1(active & PGLOSS_LOBE_SPECULAR);
        if (per_element) {
            const lane_material l = lane_materials(c->ms, active, norm, j, m);
            k = l.k;
            ax = l.ax;
            ay = l.ay;
            has_d = l.has_d;
            has_s = l.has_s;
            ok = pv_and(ok, l.good);
        }
        bad += (size_t)pv_count(pv_not(ok));
        const pv_m drawn = pv_and(ok, pv_or(has_d, has_s));
        const pv_m spec = pv_and(has_s, pv_or(pv_not(has_d), pv_lt(c0, k.ps)));
        pv_f sx = zero, sy = zero, sz = one, dx = zero, dy = zero, dz = one, oh = one;
        if (active & PGLOSS_LOBE_SPECULAR)
            oh = V(sample_specular)(ax, ay, ox, oy, oz, c1, c2, &sx, &sy, &sz);
        if (active & PGLOSS_LOBE_DIFFUSE)
            V(sample_cosine)(c1, c2, &dx, &dy, &dz);
        const pv_f wx = pv_sel(drawn, pv_sel(spec, sx, dx), zero);
        const pv_f wy = pv_sel(drawn, pv_sel(spec, sy, dy), zero);
        const pv_f wz = pv_sel(drawn, pv_sel(spec, sz, dz), one);
        const pv_m good = pv_and(drawn, pv_or(pv_not(spec), pv_gt(oh, zero)));
        pv_f f[3], p;
        V(eval_pdf_unit)(&k, active, norm, PGLOSS_FAST, 1, ox, oy, oz, wx, wy, wz, good, f, &p);
        V(weight)(good, wx, wy, wz, &p, &f[0], &f[1], &f[2]);
        store_part(wi.x + j, m, wx);
        store_part(wi.y + j, m, wy);
        store_part(wi.z + j, m, wz);
        store_part(pdfs + j, m, p);
        store_part(weight.r + j, m, f[0]);
        store_part(weight.g + j, m, f[1]);
        store_part(weight.b + j, m, f[2]);
        if (lobe) {
            const pv_i lb = pv_seli(drawn, pv_seli(spec, pv_i1(PGLOSS_LOBE_SPECULAR), pv_i1(PGLOSS_LOBE_DIFFUSE)),
                                    pv_i1(PGLOSS_LOBE_NONE));
            int32_t t[W];
            pv_store_i(t, lb);
            for (size_t q = 0; q < m; ++q)
                lobe[j + q] = (unsigned char)t[q];
        }
    }
    return bad;
}

#define SAMPLE_FN(A, N) CAT(sample, A, N)
#define DEFINE_SAMPLE(A, N)                                                                        \
    static PGLOSS__NOINLINE size_t SAMPLE_FN(A, N)(                                                \
        const pgloss__call_f *c, size_t n, pgloss__vec3_f wo, const float *u0, const float *u1,    \
        const float *u2, pgloss__vec3_out_f wi, float *pdf, pgloss__rgb_out_f weight,              \
        unsigned char *lobe)                                                                       \
    {                                                                                              \
        return c->ms ? sample_loop(c, A, N, 1, n, wo, u0, u1, u2, wi, pdf, weight, lobe)           \
                     : sample_loop(c, A, N, 0, n, wo, u0, u1, u2, wi, pdf, weight, lobe);          \
    }
PGLOSS__EACH_LOBES(DEFINE_SAMPLE)
#undef DEFINE_SAMPLE

size_t NAME(pgloss__sample)(const pgloss__call_f *c, size_t n, pgloss__vec3_f wo, const float *u0,
                            const float *u1, const float *u2, pgloss__vec3_out_f wi, float *pdf,
                            pgloss__rgb_out_f weight, unsigned char *lobe)
{
#define LOOP(A, N) SAMPLE_FN(A, N)(c, n, wo, u0, u1, u2, wi, pdf, weight, lobe)
    return PGLOSS__BY_LOBES(LOOP, c->active, c->norm);
#undef LOOP
}

/* ---- (n, 3) float rows ------------------------------------------------------------------- */

#if !PGLOSS_FAST /* one copy per ISA: the tiers share it */
void CAT(pgloss__rows_in, PGLOSS_ISA, f)(const void *rows, size_t n, float *x, float *y, float *z)
{
    pgloss__rows3_to_columns(rows, n, x, y, z);
}

void CAT(pgloss__rows_out, PGLOSS_ISA, f)(const float *x, const float *y, const float *z,
                                          size_t n, void *rows)
{
    pgloss__columns_to_rows3(x, y, z, n, rows);
}
#endif
