// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* shim.h — see shim.c. v = {rho_d r, g, b, rho_s, alpha_x, alpha_y}; q = {L, a, b, c, d}. */
#ifndef PGLOSS_PY_SHIM_H
#define PGLOSS_PY_SHIM_H

#include <stddef.h>

#include "pgloss/pgloss.h"

#ifdef __cplusplus
extern "C" {
#endif

int pgloss_py_material_init(pgloss_material *m, const double v[6], int normalization);
int pgloss_py_check_physical(const double v[6], int normalization);
int pgloss_py_check_perceptual(const double q[5], int space);
int pgloss_py_physical_from_perceptual(const double q[5], int normalization, int space, double out[6],
                                       int *normalization_out);
int pgloss_py_perceptual_from_physical(const double v[6], int normalization, int space, double q[5]);
/* The colour functions with the working space as an int (pgloss_color_space). */
int pgloss_py_rgb_from_lab(const double lab[3], int space, double rgb[3]);
int pgloss_py_lab_from_rgb(const double rgb[3], int space, double lab[3]);
int pgloss_py_luminance(const double rgb[3], int space, double *Y);

/* Batched forms (pgloss/perceptual_batch.h, pgloss/batch_materials.h) with the enums as ints;
 * cols = {rho_d r, g, b, rho_s, alpha_x, alpha_y}, q = {L, a, b, c, d}; st: a status per element. */
int pgloss_py_check_physical_batch(size_t n, const double *const cols[6], int normalization, signed char *st);
int pgloss_py_check_perceptual_batch(size_t n, const double *const q[5], int space, signed char *st);
int pgloss_py_physical_from_perceptual_batch(size_t n, const double *const q[5], int normalization, int space,
                                             double *const out[6], signed char *st);
int pgloss_py_perceptual_from_physical_batch(size_t n, const double *const cols[6], int normalization, int space,
                                             double *const q[5], signed char *st);
int pgloss_py_rgb_from_lab_batch(size_t n, const double *const lab[3], int space, double *const rgb[3],
                                 signed char *st);
int pgloss_py_lab_from_rgb_batch(size_t n, const double *const rgb[3], int space, double *const lab[3],
                                 signed char *st);
int pgloss_py_eval_pdf_batch_materials(const float *const cols[6], int normalization, unsigned lobes, size_t n,
                                       pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f, float *pdf,
                                       signed char *st);
int pgloss_py_sample_batch_materials(const float *const cols[6], int normalization, unsigned lobes, size_t n,
                                     pgloss_vec3_array wo, const float *const u[3], pgloss_vec3_out wi, float *pdf,
                                     pgloss_rgb_out weight, unsigned char *lobe, signed char *st);
int pgloss_py_eval_pdf_batch_materials_d(const double *const cols[6], int normalization, unsigned lobes, size_t n,
                                         pgloss_vec3_array_d wo, pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                         double *pdf, signed char *st);
int pgloss_py_sample_batch_materials_d(const double *const cols[6], int normalization, unsigned lobes, size_t n,
                                       pgloss_vec3_array_d wo, const double *const u[3], pgloss_vec3_out_d wi,
                                       double *pdf, pgloss_rgb_out_d weight, unsigned char *lobe, signed char *st);

#ifdef __cplusplus
}
#endif

#endif
