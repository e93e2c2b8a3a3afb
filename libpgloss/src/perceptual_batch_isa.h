// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The loops of perceptual_batch_isa.c, one set per ISA built (libpgloss/CMakeLists.txt), for
 * perceptual_batch.c's run-time dispatch. They write every element's status to st (never
 * NULL here) and every output; the arguments are checked by the caller. Not installed. */
#ifndef PGLOSS_PERCEPTUAL_BATCH_ISA_H
#define PGLOSS_PERCEPTUAL_BATCH_ISA_H

#include <stddef.h>
#include "pgloss/perceptual_batch.h"

/* M: the working space's XYZ → RGB matrix, row-major (pgloss__from_xyz_matrix). */
#define PGLOSS__DECLARE_PERCEPTUAL_LOOPS(isa)                                                     \
    void pgloss__gloss_from_physical_loop_##isa(size_t, const double *, const double *,          \
                                                const double *, double *, double *, double *,     \
                                                signed char *);                                   \
    void pgloss__physical_from_perceptual_loop_##isa(size_t, pgloss_perceptual_array,            \
                                                     const double *, pgloss_physical_out,         \
                                                     signed char *);

PGLOSS__DECLARE_PERCEPTUAL_LOOPS(baseline)
#if defined(PGLOSS_HAVE_AVX2)
PGLOSS__DECLARE_PERCEPTUAL_LOOPS(avx2)
#endif
#if defined(PGLOSS_HAVE_AVX512)
PGLOSS__DECLARE_PERCEPTUAL_LOOPS(avx512)
#endif

#endif
