// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* One call of pgloss/inline.h's eval_pdf and of its sample between llvm-mca markers
 * (bench/mca.sh --inline): repeated, the static throughput of independent calls; once, the
 * critical path of a call from its inputs to its last output (the latency along one path).
 * llvm-mca follows no branch, so the regions hold the path that a renderer's predicted
 * branches take: near-unit directions, both lobes, eq. 2's normalisation (the internal
 * functions that pgloss_eval_pdf_inline and pgloss_sample_inline run on it). */
#include "pgloss/inline.h"

void mca_eval_pdf(const pgloss_material *m, const pgloss_vec3 *wo, const pgloss_vec3 *wi,
                  pgloss_rgb *f, float *p);
void mca_sample(const pgloss_material *m, const pgloss_vec3 *wo, const float *u,
                pgloss_sample_record *s);

void mca_eval_pdf(const pgloss_material *m, const pgloss_vec3 *wo, const pgloss_vec3 *wi,
                  pgloss_rgb *f, float *p)
{
    __asm__ volatile("# LLVM-MCA-BEGIN eval_pdf");
    const pgloss_inl_consts k = pgloss_inl_consts_of(m, PGLOSS_LOBE_ALL);
    float fv[3];
    pgloss_inl_eval_pdf_unit(&k, PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD, 0, 1, wo->x, wo->y, wo->z, wi->x,
                             wi->y, wi->z, 1, fv, p);
    f->r = fv[0], f->g = fv[1], f->b = fv[2];
    __asm__ volatile("# LLVM-MCA-END eval_pdf");
}

void mca_sample(const pgloss_material *m, const pgloss_vec3 *wo, const float *u,
                pgloss_sample_record *s)
{
    __asm__ volatile("# LLVM-MCA-BEGIN sample");
    /* the specular lobe's path (the longer one) */
    const pgloss_inl_consts k = pgloss_inl_consts_of(m, PGLOSS_LOBE_ALL);
    pgloss_vec3 w;
    const float oh = pgloss_inl_sample_specular(m->alpha_x, m->alpha_y, wo->x, wo->y, wo->z,
                                                pgloss_inl_clamp_u(u[1]), pgloss_inl_clamp_u(u[2]),
                                                &w.x, &w.y, &w.z);
    float fv[3], p;
    pgloss_inl_eval_pdf_unit(&k, PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD, 0, 1, wo->x, wo->y, wo->z, w.x,
                             w.y, w.z, 1, fv, &p);
    pgloss_inl_weight(oh > 0.0f, w.x, w.y, w.z, &p, &fv[0], &fv[1], &fv[2]);
    s->wi = w, s->pdf = p, s->weight.r = fv[0], s->weight.g = fv[1], s->weight.b = fv[2];
    __asm__ volatile("# LLVM-MCA-END sample");
}
