// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The FAST tier's AVX-512 eval block alone, between llvm-mca markers, for a static throughput
 * analysis (bench/mca.sh): both lobes, eq. 2's normalisation, f only — the configuration of
 * BENCHMARKS.md's operation count. Compiled with the flags of the library's AVX-512 objects. */
#include <float.h>

#include "batch_internal.h"
#include "pgloss/inline.h"

#include "batch_avx512_fast.h"
#include "batch_fast_block.h"

void pgloss_mca_eval(const pgloss__batch_consts *k, size_t n, const float *ox, const float *oy,
                     const float *oz, const float *ix, const float *iy, const float *iz,
                     float *fr, float *fg, float *fb);

void pgloss_mca_eval(const pgloss__batch_consts *k, size_t n, const float *ox, const float *oy,
                     const float *oz, const float *ix, const float *iy, const float *iz,
                     float *fr, float *fg, float *fb)
{
    for (size_t j = 0; j + PGLOSS_VW <= n; j += PGLOSS_VW) {
        __asm__ volatile("# LLVM-MCA-BEGIN eval_block");
        v_eval_pdf_block(k, PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD, ox + j, oy + j, oz + j, ix + j,
                         iy + j, iz + j, fr + j, fg + j, fb + j, NULL, 1, 0);
        __asm__ volatile("# LLVM-MCA-END eval_block");
    }
}
