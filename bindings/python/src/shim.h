// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* shim.h — see shim.c. v = {rho_d r, g, b, rho_s, alpha_x, alpha_y}; q = {L, a, b, c, d}. */
#ifndef PGLOSS_PY_SHIM_H
#define PGLOSS_PY_SHIM_H

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

#ifdef __cplusplus
}
#endif

#endif
