// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* test_vectors_shim.c — C helper for test_vectors.cpp: passes an arbitrary int as a
 * pgloss_normalization argument (unknown values are part of the vectors). Converting an
 * out-of-range int to an enum is well defined in C but not in C++ (UBSan flags it). */
#include "pgloss/pgloss.h"

pgloss_status pgloss_test_physical_from_perceptual(const pgloss_perceptual *q, int normalization,
                                                   pgloss_physical *p);

pgloss_status pgloss_test_physical_from_perceptual(const pgloss_perceptual *q, int normalization,
                                                   pgloss_physical *p)
{
    return pgloss_physical_from_perceptual(q, (pgloss_normalization)normalization, p);
}

/* The _ex functions with the working colour space as an int (unknown spaces are in the vectors). */
pgloss_status pgloss_test_rgb_from_lab_ex(const double lab[3], int space, double rgb[3]);
pgloss_status pgloss_test_lab_from_rgb_ex(const double rgb[3], int space, double lab[3]);
pgloss_status pgloss_test_luminance_ex(const double rgb[3], int space, double *Y);
pgloss_status pgloss_test_check_perceptual_ex(const pgloss_perceptual *q, int space);
pgloss_status pgloss_test_physical_from_perceptual_ex(const pgloss_perceptual *q, int normalization, int space,
                                                      pgloss_physical *p);
pgloss_status pgloss_test_perceptual_from_physical_ex(const pgloss_physical *p, int space, pgloss_perceptual *q);

pgloss_status pgloss_test_rgb_from_lab_ex(const double lab[3], int space, double rgb[3])
{
    return pgloss_rgb_from_lab_ex(lab, (pgloss_color_space)space, rgb);
}

pgloss_status pgloss_test_lab_from_rgb_ex(const double rgb[3], int space, double lab[3])
{
    return pgloss_lab_from_rgb_ex(rgb, (pgloss_color_space)space, lab);
}

pgloss_status pgloss_test_luminance_ex(const double rgb[3], int space, double *Y)
{
    return pgloss_luminance_ex(rgb, (pgloss_color_space)space, Y);
}

pgloss_status pgloss_test_check_perceptual_ex(const pgloss_perceptual *q, int space)
{
    return pgloss_check_perceptual_ex(q, (pgloss_color_space)space);
}

pgloss_status pgloss_test_physical_from_perceptual_ex(const pgloss_perceptual *q, int normalization, int space,
                                                      pgloss_physical *p)
{
    return pgloss_physical_from_perceptual_ex(q, (pgloss_normalization)normalization, (pgloss_color_space)space, p);
}

pgloss_status pgloss_test_perceptual_from_physical_ex(const pgloss_physical *p, int space, pgloss_perceptual *q)
{
    return pgloss_perceptual_from_physical_ex(p, (pgloss_color_space)space, q);
}
