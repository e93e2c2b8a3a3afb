// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The loops of perceptual_batch_isa.c, one set per ISA built (libpgloss/CMakeLists.txt), for
 * perceptual_batch.c's run-time dispatch. They write every element's status to st (never
 * NULL here) and every output; the arguments are checked by the caller. Not installed. */
#ifndef PGLOSS_PERCEPTUAL_BATCH_ISA_H
#define PGLOSS_PERCEPTUAL_BATCH_ISA_H

#include <stddef.h>
#include "pgloss/perceptual_batch.h"

/* M: the working space's XYZ → RGB matrix, row-major (pgloss__from_xyz_matrix); for
 * perceptual_from_physical and lab_from_rgb, its RGB → XYZ matrix (pgloss__to_xyz_matrix).
 * check_physical: norm_ok 1 for a known normalisation, else 0; alpha_y NULL is isotropic. */
#define PGLOSS__DECLARE_PERCEPTUAL_LOOPS(isa)                                                     \
    void pgloss__gloss_from_physical_loop_##isa(size_t, const double *, const double *,          \
                                                const double *, double *, double *, double *,     \
                                                signed char *);                                   \
    void pgloss__physical_from_perceptual_loop_##isa(size_t, pgloss_perceptual_array,            \
                                                     const double *, pgloss_physical_out,         \
                                                     signed char *);                      \
    void pgloss__physical_from_gloss_loop_##isa(size_t, const double *, const double *,          \
                                                const double *, double *, double *, double *,     \
                                                signed char *);                                   \
    void pgloss__envelope_contrast_loop_##isa(size_t, const double *, double *, signed char *);   \
    void pgloss__match_gloss_loop_##isa(size_t, const double *, const double *, const double *,  \
                                        double *, double *, signed char *);                       \
    void pgloss__check_physical_loop_##isa(size_t, pgloss_physical_array, double,                \
                                           signed char *);                                        \
    void pgloss__check_perceptual_loop_##isa(size_t, pgloss_perceptual_array, const double *,    \
                                             signed char *);                                      \
    void pgloss__perceptual_from_physical_loop_##isa(size_t, pgloss_physical_array,              \
                                                     const double *, pgloss_perceptual_out,       \
                                                     signed char *);                              \
    void pgloss__rgb_from_lab_loop_##isa(size_t, pgloss_lab_array, const double *,               \
                                         pgloss_rgb_out_d, signed char *);                        \
    void pgloss__lab_from_rgb_loop_##isa(size_t, pgloss_rgb_array_d, const double *,             \
                                         pgloss_lab_out, signed char *);

PGLOSS__DECLARE_PERCEPTUAL_LOOPS(baseline)
#if defined(PGLOSS_HAVE_AVX2)
PGLOSS__DECLARE_PERCEPTUAL_LOOPS(avx2)
#endif
#if defined(PGLOSS_HAVE_AVX512)
PGLOSS__DECLARE_PERCEPTUAL_LOOPS(avx512)
#endif

#endif
