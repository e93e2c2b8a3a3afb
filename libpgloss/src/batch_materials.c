// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Batched BRDF entry points with per-element materials and the double path
 * (pgloss/batch_materials.h). Stubs until the loops land: PGLOSS_ERR_ARGUMENT. */
#include "batch_internal.h"
#include "internal.h"
#include "pgloss/batch_materials.h"

#define STUB return PGLOSS_ERR_ARGUMENT

pgloss_status pgloss_eval_pdf_batch_materials_ex(const pgloss_batch_options *options,
                                                 const pgloss_material_array *m, unsigned lobes,
                                                 size_t n, pgloss_vec3_array wo,
                                                 pgloss_vec3_array wi, pgloss_rgb_out f,
                                                 float *pdf, signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)wi; (void)f; (void)pdf;
    (void)status;
    STUB;
}

pgloss_status pgloss_sample_batch_materials_ex(const pgloss_batch_options *options,
                                               const pgloss_material_array *m, unsigned lobes,
                                               size_t n, pgloss_vec3_array wo, const float *u0,
                                               const float *u1, const float *u2,
                                               pgloss_vec3_out wi, float *pdf,
                                               pgloss_rgb_out weight, unsigned char *lobe,
                                               signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)u0; (void)u1; (void)u2;
    (void)wi; (void)pdf; (void)weight; (void)lobe; (void)status;
    STUB;
}

pgloss_status pgloss_eval_pdf_batch_d_ex(const pgloss_batch_options *options,
                                         const pgloss_material *m, unsigned lobes, size_t n,
                                         pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                         pgloss_rgb_out_d f, double *pdf, signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)wi; (void)f; (void)pdf;
    (void)status;
    STUB;
}

pgloss_status pgloss_sample_batch_d_ex(const pgloss_batch_options *options,
                                       const pgloss_material *m, unsigned lobes, size_t n,
                                       pgloss_vec3_array_d wo, const double *u0,
                                       const double *u1, const double *u2, pgloss_vec3_out_d wi,
                                       double *pdf, pgloss_rgb_out_d weight, unsigned char *lobe,
                                       signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)u0; (void)u1; (void)u2;
    (void)wi; (void)pdf; (void)weight; (void)lobe; (void)status;
    STUB;
}

pgloss_status pgloss_eval_pdf_batch_materials_d_ex(const pgloss_batch_options *options,
                                                   const pgloss_physical_array *m, unsigned lobes,
                                                   size_t n, pgloss_vec3_array_d wo,
                                                   pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                   double *pdf, signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)wi; (void)f; (void)pdf;
    (void)status;
    STUB;
}

pgloss_status pgloss_sample_batch_materials_d_ex(const pgloss_batch_options *options,
                                                 const pgloss_physical_array *m, unsigned lobes,
                                                 size_t n, pgloss_vec3_array_d wo,
                                                 const double *u0, const double *u1,
                                                 const double *u2, pgloss_vec3_out_d wi,
                                                 double *pdf, pgloss_rgb_out_d weight,
                                                 unsigned char *lobe, signed char *status)
{
    (void)options; (void)m; (void)lobes; (void)n; (void)wo; (void)u0; (void)u1; (void)u2;
    (void)wi; (void)pdf; (void)weight; (void)lobe; (void)status;
    STUB;
}

/* ---- the convenience forms: default options, no status array ------------------------- */

pgloss_status pgloss_eval_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                          size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi,
                                          pgloss_rgb_out f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                         size_t n, pgloss_vec3_array wo, pgloss_vec3_array wi,
                                         float *pdf)
{
    const pgloss_rgb_out none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                              size_t n, pgloss_vec3_array wo,
                                              pgloss_vec3_array wi, pgloss_rgb_out f, float *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_materials(const pgloss_material_array *m, unsigned lobes,
                                            size_t n, pgloss_vec3_array wo, const float *u0,
                                            const float *u1, const float *u2,
                                            pgloss_vec3_out wi, float *pdf,
                                            pgloss_rgb_out weight, unsigned char *lobe)
{
    return pgloss_sample_batch_materials_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight,
                                            lobe, NULL);
}

pgloss_status pgloss_eval_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                  pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                  pgloss_rgb_out_d f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                 pgloss_vec3_array_d wo, pgloss_vec3_array_d wi, double *pdf)
{
    const pgloss_rgb_out_d none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                      pgloss_vec3_array_d wo, pgloss_vec3_array_d wi,
                                      pgloss_rgb_out_d f, double *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_d_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_d(const pgloss_material *m, unsigned lobes, size_t n,
                                    pgloss_vec3_array_d wo, const double *u0, const double *u1,
                                    const double *u2, pgloss_vec3_out_d wi, double *pdf,
                                    pgloss_rgb_out_d weight, unsigned char *lobe)
{
    return pgloss_sample_batch_d_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight, lobe,
                                    NULL);
}

pgloss_status pgloss_eval_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                            size_t n, pgloss_vec3_array_d wo,
                                            pgloss_vec3_array_d wi, pgloss_rgb_out_d f)
{
    if (n && !f.r)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, f, NULL, NULL);
}

pgloss_status pgloss_pdf_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                           size_t n, pgloss_vec3_array_d wo,
                                           pgloss_vec3_array_d wi, double *pdf)
{
    const pgloss_rgb_out_d none = {NULL, NULL, NULL};
    if (n && !pdf)
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, none, pdf, NULL);
}

pgloss_status pgloss_eval_pdf_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                                size_t n, pgloss_vec3_array_d wo,
                                                pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                                double *pdf)
{
    if (n && (!f.r || !pdf))
        return PGLOSS_ERR_NULL;
    return pgloss_eval_pdf_batch_materials_d_ex(NULL, m, lobes, n, wo, wi, f, pdf, NULL);
}

pgloss_status pgloss_sample_batch_materials_d(const pgloss_physical_array *m, unsigned lobes,
                                              size_t n, pgloss_vec3_array_d wo, const double *u0,
                                              const double *u1, const double *u2,
                                              pgloss_vec3_out_d wi, double *pdf,
                                              pgloss_rgb_out_d weight, unsigned char *lobe)
{
    return pgloss_sample_batch_materials_d_ex(NULL, m, lobes, n, wo, u0, u1, u2, wi, pdf, weight,
                                              lobe, NULL);
}
