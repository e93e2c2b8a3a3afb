// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* test_inline_c99.c — pgloss/inline.h compiled as strict C99 (-std=c99 -pedantic, see
 * tests/CMakeLists.txt); test_vectors.cpp runs the shared vectors through these wrappers as
 * well as through the header compiled as C++. */
#include "pgloss/inline.h"

#include "test_inline_c99.h"

pgloss_status pgloss_test_eval_inline_c99(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                                          unsigned lobes, pgloss_rgb *f)
{
    return pgloss_eval_inline(m, wo, wi, lobes, f);
}

pgloss_status pgloss_test_pdf_inline_c99(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                                         unsigned lobes, float *pdf)
{
    return pgloss_pdf_inline(m, wo, wi, lobes, pdf);
}

pgloss_status pgloss_test_eval_pdf_inline_c99(const pgloss_material *m, pgloss_vec3 wo,
                                              pgloss_vec3 wi, unsigned lobes, pgloss_rgb *f,
                                              float *pdf)
{
    return pgloss_eval_pdf_inline(m, wo, wi, lobes, f, pdf);
}

pgloss_status pgloss_test_sample_inline_c99(const pgloss_material *m, pgloss_vec3 wo,
                                            const float u[3], unsigned lobes,
                                            pgloss_sample_record *s)
{
    return pgloss_sample_inline(m, wo, u, lobes, s);
}
