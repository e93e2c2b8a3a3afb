// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* test_inline_c99.h — the functions of pgloss/inline.h as compiled in test_inline_c99.c (C99). */
#ifndef PGLOSS_TEST_INLINE_C99_H
#define PGLOSS_TEST_INLINE_C99_H

#include "pgloss/brdf.h"

#ifdef __cplusplus
extern "C" {
#endif

pgloss_status pgloss_test_eval_inline_c99(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                                          unsigned lobes, pgloss_rgb *f);
pgloss_status pgloss_test_pdf_inline_c99(const pgloss_material *m, pgloss_vec3 wo, pgloss_vec3 wi,
                                         unsigned lobes, float *pdf);
pgloss_status pgloss_test_eval_pdf_inline_c99(const pgloss_material *m, pgloss_vec3 wo,
                                              pgloss_vec3 wi, unsigned lobes, pgloss_rgb *f,
                                              float *pdf);
pgloss_status pgloss_test_sample_inline_c99(const pgloss_material *m, pgloss_vec3 wo,
                                            const float u[3], unsigned lobes,
                                            pgloss_sample_record *s);

#ifdef __cplusplus
}
#endif

#endif
