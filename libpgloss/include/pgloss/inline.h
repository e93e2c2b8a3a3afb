// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/inline.h — the lobe at one shading point, header-only, in float.
 *
 *   pgloss_eval_inline, pgloss_pdf_inline, pgloss_eval_pdf_inline, pgloss_sample_inline
 *
 * are pgloss_eval, pgloss_pdf, pgloss_eval_pdf and pgloss_sample of pgloss/brdf.h with the
 * suffix _inline: the same arguments in the same order, the same contracts (brdf.h), at the
 * accuracy of the batched FLOAT tier (pgloss/batch.h). They are static inline: no library
 * call, no allocation, no global state; C99 and C++. Names pgloss_inl_* / PGLOSS_INL_* are
 * internal.
 *
 * The lobe is pgloss/detail/lobe.h, the library's one float definition of eq. 2, its two later
 * normalisations and Walter 2005's pdf and sampling, here over the one-lane helper
 * pgloss/detail/simd_scalar.h; the batched FLOAT and FAST loops run the same code over SIMD
 * helpers. Derivations and measured errors: docs/kernels.md.
 *
 * PGLOSS_INLINE_QUALIFIER: define it before including this header to add qualifiers to every
 * function, e.g. `#define PGLOSS_INLINE_QUALIFIER __host__ __device__` for CUDA or HIP.
 */
#ifndef PGLOSS_INLINE_H
#define PGLOSS_INLINE_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "pgloss/brdf.h"
#include "pgloss/color.h"

#ifndef PGLOSS_INLINE_QUALIFIER
#define PGLOSS_INLINE_QUALIFIER
#endif
#if defined(__GNUC__) || defined(__clang__)
#define PGLOSS_INLINE_ATTR __attribute__((always_inline))
#define PGLOSS_INLINE_FN static inline __attribute__((always_inline)) PGLOSS_INLINE_QUALIFIER
#elif defined(_MSC_VER)
#define PGLOSS_INLINE_ATTR
#define PGLOSS_INLINE_FN static __forceinline PGLOSS_INLINE_QUALIFIER
#else
#define PGLOSS_INLINE_ATTR
#define PGLOSS_INLINE_FN static inline PGLOSS_INLINE_QUALIFIER
#endif

#ifdef __cplusplus
extern "C" {
#endif

#include "pgloss/detail/simd_scalar.h"
#include "pgloss/detail/lobe.h"

/* ---- the material ---------------------------------------------------------------------------- */

/* What pgloss_material_init derives from validated parameters: m's rho_d, rho_s, alpha_x,
 * alpha_y and normalization are set; this raises α to PGLOSS_ALPHA_MIN and fills the rest
 * (brdf.h), by the lobe's pgloss_inl_derive. */
PGLOSS_INLINE_FN void pgloss_inl_material_derive(pgloss_material *m)
{
    const pgloss_inl_derived d = pgloss_inl_derive(m->rho_d[0], m->rho_d[1], m->rho_d[2], m->rho_s,
                                                   m->alpha_x, m->alpha_y, (int)m->normalization);
    m->rho_d[0] = d.rho_d[0];
    m->rho_d[1] = d.rho_d[1];
    m->rho_d[2] = d.rho_d[2];
    m->rho_s = d.rho_s;
    m->alpha_x = d.ax;
    m->alpha_y = d.ay;
    m->inv_alpha_x = d.iax;
    m->inv_alpha_y = d.iay;
    m->spec_scale = d.spec_scale;
    m->pdf_scale = d.pdf_scale;
    m->lobes = (d.has_d ? (unsigned)PGLOSS_LOBE_DIFFUSE : 0u) |
               (d.has_s ? (unsigned)PGLOSS_LOBE_SPECULAR : 0u);
    m->weight_diffuse = d.wd;
    m->weight_specular = d.ws;
    m->specular_probability = d.ps;
    m->pdf_diffuse = d.pdf_d;
    m->pdf_specular = d.pdf_s;
}

/* The lobe's constants of m for the active lobes (no division: the material stores them). */
PGLOSS_INLINE_FN pgloss_inl_consts pgloss_inl_consts_of(const pgloss_material *m, unsigned active)
{
    return pgloss_inl_consts_of_parts(m->rho_d, m->spec_scale, m->inv_alpha_x, m->inv_alpha_y,
                                      m->pdf_scale, m->specular_probability, m->pdf_diffuse,
                                      m->pdf_specular, (active & PGLOSS_LOBE_DIFFUSE) != 0,
                                      (active & PGLOSS_LOBE_SPECULAR) != 0);
}

/* ---- the per-shading-point API (contracts: pgloss/brdf.h) --------------------------------- */

PGLOSS_INLINE_FN pgloss_status pgloss_eval_pdf_inline(const pgloss_material *m, pgloss_vec3 wo,
                                                      pgloss_vec3 wi, unsigned lobes,
                                                      pgloss_rgb *f, float *pdf)
{
    if (f) f->r = f->g = f->b = 0.0f;
    if (pdf) *pdf = 0.0f;
    if (!m || (!f && !pdf))
        return PGLOSS_ERR_NULL;
    if (!pgloss_inl_units(&wo.x, &wo.y, &wo.z, &wi.x, &wi.y, &wi.z))
        return PGLOSS_ERR_DIRECTION;
    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    const pgloss_inl_consts k = pgloss_inl_consts_of(m, active);
    float fv[3], p;
    pgloss_inl_eval_pdf_unit(&k, active, (int)m->normalization, 0, 1, wo.x, wo.y, wo.z, wi.x, wi.y,
                             wi.z, 1, fv, &p);
    if (f) {
        f->r = fv[0];
        f->g = fv[1];
        f->b = fv[2];
    }
    if (pdf)
        *pdf = p;
    return PGLOSS_OK;
}

PGLOSS_INLINE_FN pgloss_status pgloss_eval_inline(const pgloss_material *m, pgloss_vec3 wo,
                                                  pgloss_vec3 wi, unsigned lobes, pgloss_rgb *f)
{
    if (!f)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_inline(m, wo, wi, lobes, f, NULL);
}

PGLOSS_INLINE_FN pgloss_status pgloss_pdf_inline(const pgloss_material *m, pgloss_vec3 wo,
                                                 pgloss_vec3 wi, unsigned lobes, float *pdf)
{
    if (!pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_inline(m, wo, wi, lobes, NULL, pdf);
}

PGLOSS_INLINE_FN pgloss_status pgloss_sample_inline(const pgloss_material *m, pgloss_vec3 wo,
                                                    const float u[3], unsigned lobes,
                                                    pgloss_sample_record *s)
{
    if (!s)
        return PGLOSS_ERR_NULL;
    s->wi.x = s->wi.y = 0.0f;
    s->wi.z = 1.0f;
    s->lobe = PGLOSS_LOBE_NONE;
    s->pdf = 0.0f;
    s->weight.r = s->weight.g = s->weight.b = 0.0f;
    if (!m || !u)
        return PGLOSS_ERR_NULL;
    if ((u[0] != u[0]) | (u[1] != u[1]) | (u[2] != u[2]))
        return PGLOSS_ERR_RANDOM;
    if (!pgloss_inl_unit(&wo.x, &wo.y, &wo.z))
        return PGLOSS_ERR_DIRECTION;
    const unsigned active = lobes & m->lobes & PGLOSS_LOBE_ALL;
    if (!active)
        return PGLOSS_OK;
    const pgloss_inl_consts k = pgloss_inl_consts_of(m, active);
    const float u1 = pgloss_inl_clamp_u(u[1]), u2 = pgloss_inl_clamp_u(u[2]);
    pgloss_vec3 w;
    int good = wo.z > 0.0f;
    if (pgloss_inl_clamp_u(u[0]) < k.ps) {
        s->lobe = PGLOSS_LOBE_SPECULAR;
        const float oh = pgloss_inl_sample_specular(m->alpha_x, m->alpha_y, wo.x, wo.y, wo.z, u1,
                                                    u2, &w.x, &w.y, &w.z);
        good &= oh > 0.0f;
    } else {
        s->lobe = PGLOSS_LOBE_DIFFUSE;
        pgloss_inl_sample_cosine(u1, u2, &w.x, &w.y, &w.z);
    }
    s->wi = w;
    if (!good)
        return PGLOSS_OK;
    float fv[3], p;
    pgloss_inl_eval_pdf_unit(&k, active, (int)m->normalization, 0, 1, wo.x, wo.y, wo.z, w.x, w.y,
                             w.z, 1, fv, &p);
    pgloss_inl_weight(1, w.x, w.y, w.z, &p, &fv[0], &fv[1], &fv[2]);
    s->pdf = p;
    s->weight.r = fv[0];
    s->weight.g = fv[1];
    s->weight.b = fv[2];
    return PGLOSS_OK;
}

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_INLINE_H */
