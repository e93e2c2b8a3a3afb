// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// A C++17 program that uses an installed or embedded pgloss (scripts/test-package.sh builds it
// through find_package, pkg-config and add_subdirectory). Expected values are the paper's
// formulas written out here: eq. 4 and its inverse eq. 7, eq. 5's distance of a paint to itself,
// and CIE L* = 116 cbrt(Y) - 16.
#include <pgloss/pgloss.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

int failures = 0;

void check(bool ok, const char *what)
{
    if (!ok) {
        std::fprintf(stderr, "consumer.cpp: FAILED %s\n", what);
        ++failures;
    }
}

}  // namespace

int main()
{
    check(std::string(pgloss_version()) == PGLOSS_VERSION_STRING,
          "pgloss_version() is the version of the headers");
    static_assert(PGLOSS_VERSION_MAJOR >= 0 && PGLOSS_VERSION_MINOR >= 0 && PGLOSS_VERSION_PATCH >= 0,
                  "version macros are integers");

    // Experiment 2's contrast-gloss paints: ρd of black, grey and white at ρs = 0.066.
    const std::array<double, 3> rho_d{0.03, 0.193, 0.767};
    const double rho_s = 0.066;
    for (const double rd : rho_d) {
        double c = -1, rs_back = -1, D = -1;
        check(pgloss_contrast_gloss(rd, rho_s, &c) == PGLOSS_OK, "contrast_gloss status");
        check(std::abs(c - (std::cbrt(rho_s + rd / 2) - std::cbrt(rd / 2))) < 1e-12, "eq. 4");
        check(pgloss_specular_from_contrast(rd, c, &rs_back) == PGLOSS_OK, "specular_from_contrast status");
        const double B = std::cbrt(rd / 2);
        check(std::abs(rs_back - (std::pow(c + B, 3) - rd / 2)) < 1e-12, "eq. 7");
        check(pgloss_gloss_distance(c, 0.96, c, 0.96, &D) == PGLOSS_OK && D == 0.0, "eq. 5: D(x, x) = 0");
    }
    double L = -1;
    check(pgloss_lightness_from_luminance(0.18, &L) == PGLOSS_OK, "lightness status");
    check(std::abs(L - (116 * std::cbrt(0.18) - 16)) < 1e-9, "CIE L* of Y = 0.18");
    double Lbad = -1;
    check(pgloss_lightness_from_luminance(-1.0, &Lbad) == PGLOSS_ERR_NEGATIVE, "negative Y is an error");

    if (failures) return 1;
    std::printf("consumer.cpp: pgloss %s, L*(0.18) = %.3f: OK\n", pgloss_version(), L);
    return 0;
}
