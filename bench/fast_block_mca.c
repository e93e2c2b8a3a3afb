// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The float lobe's FAST tier over the AVX-512 helper, one block of 16 between llvm-mca
 * markers, for a static throughput analysis (bench/mca.sh): both lobes, eq. 2's
 * normalisation, near-unit directions. Compiled with the flags of the library's AVX-512
 * objects. */
#include <float.h>

#include "batch_internal.h"
#include "simd_avx512.h"
#include "pgloss/detail/lobe.h"
#include "simd_avx512.h"

void pgloss_mca_eval(const pgloss_material *m, size_t n, const float *ox, const float *oy,
                     const float *oz, const float *ix, const float *iy, const float *iz,
                     float *fr, float *fg, float *fb, float *pdf);

void pgloss_mca_eval(const pgloss_material *m, size_t n, const float *ox, const float *oy,
                     const float *oz, const float *ix, const float *iy, const float *iz,
                     float *fr, float *fg, float *fb, float *pdf)
{
    const pv_f rd[3] = {pv_f1(m->rho_d[0]), pv_f1(m->rho_d[1]), pv_f1(m->rho_d[2])};
    const pgloss__v_consts k = pgloss__v_consts_of_parts(
        rd, pv_f1(m->spec_scale), pv_f1(m->inv_alpha_x), pv_f1(m->inv_alpha_y),
        pv_f1(m->pdf_scale), pv_f1(m->specular_probability), pv_f1(m->pdf_diffuse),
        pv_f1(m->pdf_specular), pv_m1(1), pv_m1(1));
    for (size_t j = 0; j + PV_LANES <= n; j += PV_LANES) {
        __asm__ volatile("# LLVM-MCA-BEGIN eval_block");
        pv_f f[3], p;
        pgloss__v_eval_pdf_unit(&k, PGLOSS_LOBE_ALL, PGLOSS_NORM_WARD, 1, 0, pv_load(ox + j),
                                pv_load(oy + j), pv_load(oz + j), pv_load(ix + j), pv_load(iy + j),
                                pv_load(iz + j), pv_m1(1), f, &p);
        pv_store(fr + j, f[0]);
        pv_store(fg + j, f[1]);
        pv_store(fb + j, f[2]);
        pv_store(pdf + j, p);
        __asm__ volatile("# LLVM-MCA-END eval_block");
    }
}
