// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The error measure of the inline double functions' tests (cube root, exponential, log1p):
// |got − ref| in ulps of the double nearest a long double reference.
#ifndef PGLOSS_TEST_ULP_H
#define PGLOSS_TEST_ULP_H

#include <cfloat>
#include <cmath>

namespace pgt {

// |got − ref| in ulps of the double nearest ref (subnormal ulps below DBL_MIN); 0 or +Inf at
// ref = 0.
inline double ulp_error(double got, long double ref) {
    if (ref == 0.0L) return got == 0.0 ? 0.0 : INFINITY;
    int e = 0;
    std::frexp(static_cast<double>(ref), &e);
    long double ulp = std::ldexp(1.0L, e - 53);
    if (std::fabs(ref) < static_cast<long double>(DBL_MIN)) ulp = std::ldexp(1.0L, -1074);
    return static_cast<double>(std::fabs(static_cast<long double>(got) - ref) / ulp);
}

}  // namespace pgt

#endif
