// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The loops of perceptual_batch_isa.c, one set per ISA built (libpgloss/CMakeLists.txt), for
 * perceptual_batch.c. Each takes one chunk of m <= PGLOSS__PCHUNK elements as contiguous
 * columns: in[k] (read), out[k] (written, never aliasing an input), and writes every
 * element's status to st. Not installed. */
#ifndef PGLOSS_PERCEPTUAL_BATCH_ISA_H
#define PGLOSS_PERCEPTUAL_BATCH_ISA_H

#include <stddef.h>

#define PGLOSS__PCHUNK 256

/* What a loop takes besides its columns: the working space's XYZ → RGB matrix (row-major;
 * RGB → XYZ for perceptual_from_physical and lab_from_rgb), and for check_physical and
 * physical_from_perceptual 1 for a known normalisation, else 0. */
typedef struct pgloss__pargs {
    const double *M;
    double norm_ok;
} pgloss__pargs;

typedef void (*pgloss__perceptual_loop)(size_t m, const double *const *in, double *const *out,
                                        const pgloss__pargs *a, signed char *st);

/* The columns, in order: gloss_from_physical ρd ρs α → L c d; physical_from_gloss L c d →
 * ρd ρs α; envelope_contrast L → c_max; match_gloss ρd ρs L → ρd ρs; check_physical
 * r g b ρs αx αy; check_perceptual L a b c d; physical_from_perceptual L a b c d →
 * r g b ρs αx αy; perceptual_from_physical r g b ρs αx αy → L a b c d; rgb_from_lab
 * L a b → r g b; lab_from_rgb r g b → L a b. */
#define PGLOSS__PERCEPTUAL_LOOPS(X)                                                                \
    X(gloss_from_physical) X(physical_from_gloss) X(envelope_contrast) X(match_gloss)              \
    X(check_physical) X(check_perceptual) X(physical_from_perceptual)                              \
    X(perceptual_from_physical) X(rgb_from_lab) X(lab_from_rgb)

#endif
