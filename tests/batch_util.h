// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Strided views of the tests' arrays for the batched calls (pgloss/batch.h).
#ifndef PGLOSS_TESTS_BATCH_UTIL_H
#define PGLOSS_TESTS_BATCH_UTIL_H

extern "C" {
#include "pgloss/pgloss.h"
}

// Three columns (SoA), one column, and "not wanted" outputs.
template <class T>
pgloss_strided3 soa(const T *x, const T *y, const T *z) {
    return pgloss_strided3_soa(x, y, z, sizeof(T));
}
template <class T>
pgloss_strided3_out soa_out(T *x, T *y, T *z) {
    return pgloss_strided3_out_soa(x, y, z, sizeof(T));
}
template <class T>
pgloss_strided col(const T *p) {
    return pgloss_strided_of(p, static_cast<ptrdiff_t>(sizeof(T)));
}
template <class T>
pgloss_strided_out col_out(T *p) {
    return pgloss_strided_out_of(p, static_cast<ptrdiff_t>(sizeof(T)));
}
inline pgloss_strided3_out no_out3() { return pgloss_strided3_out{{nullptr, nullptr, nullptr}, 0}; }
inline pgloss_strided_out no_out() { return pgloss_strided_out{nullptr, 0}; }

// Per-element materials from six columns (ay NULL: isotropic).
template <class T>
pgloss_physical_array physical_cols(const T *r, const T *g, const T *b, const T *s, const T *ax, const T *ay,
                                    pgloss_normalization norm) {
    pgloss_physical_array p;
    p.rho_d = soa(r, g, b);
    p.rho_s = col(s);
    p.alpha_x = col(ax);
    p.alpha_y = ay ? col(ay) : pgloss_strided{nullptr, 0};
    p.normalization = norm;
    return p;
}

// The perceptual batches' parameter sets (pgloss/perceptual_batch.h), as columns.
inline pgloss_perceptual_array perceptual_cols(const double *L, const double *a, const double *b, const double *c,
                                               const double *d) {
    return pgloss_perceptual_array{col(L), col(a), col(b), col(c), col(d)};
}
inline pgloss_perceptual_array_out perceptual_cols_out(double *L, double *a, double *b, double *c, double *d) {
    return pgloss_perceptual_array_out{col_out(L), col_out(a), col_out(b), col_out(c), col_out(d)};
}
inline pgloss_physical_array_out physical_cols_out(double *r, double *g, double *b, double *s, double *ax, double *ay) {
    return pgloss_physical_array_out{soa_out(r, g, b), col_out(s), col_out(ax),
                                     ay ? col_out(ay) : pgloss_strided_out{nullptr, 0}};
}

inline pgloss_batch_options batch_options(pgloss_precision p, pgloss_isa isa = PGLOSS_ISA_AUTO,
                                          pgloss_scalar_type t = PGLOSS_FLOAT32) {
    return pgloss_batch_options{p, isa, t};
}
inline const pgloss_batch_options *f64_options() {
    static const pgloss_batch_options o{PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO, PGLOSS_FLOAT64};
    return &o;
}

#endif
