// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The Monte Carlo virtual glossmeter (examples/tracer/src/glossmeter_mc.hpp) agrees with
// pgloss/glossmeter.h's quadrature within its own standard error, reading by reading (|z| < 4.5)
// and over all of them (chi-square below its 0.1 % quantile), for the representative paints of
// the MPI gloss levels G1–G7, a sharp black paint and an anisotropic rotated one.
#include "glossmeter_mc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

TEST(GlossmeterMonteCarlo, AgreesWithQuadratureWithinStandardError)
{
    const std::uint64_t n = 1u << 18;
    double chi2 = 0.0;
    int dof = 0;
    unsigned stream = 0;  // one PCG32 stream per case, so that the z-scores are independent
    for (const auto &c : pgt::glossmeter_mc_cases())
        for (pgloss_glossmeter_kind kind : c.kinds) {
            const pgt::GlossmeterMc mc = pgt::glossmeter_mc(kind, c.paint, c.azimuth_deg, n, 7000 + stream++);
            pgloss_gloss_reading q;
            ASSERT_GE(pgloss_glossmeter_read_physical(kind, &c.paint, c.azimuth_deg, 1e-6, &q), 0);
            ASSERT_GT(mc.std_error, 0.0) << c.name;
            const double z = (mc.value - q.value) / std::sqrt(mc.std_error * mc.std_error + q.error * q.error);
            std::printf("glossmeter mc: %-11s kind %d  MC %10.5f +- %.5f  quadrature %10.5f  z %+.2f\n", c.name.c_str(),
                        int(kind), mc.value, mc.std_error, q.value, z);
            EXPECT_LT(std::fabs(z), 4.5) << c.name << " kind " << int(kind);
            chi2 += z * z;
            ++dof;
        }
    EXPECT_GE(dof, 25);
    // chi-square 0.1 % upper quantile for ~30 degrees of freedom is ~59.7; dof + 5 sqrt(2 dof) bounds it
    EXPECT_LT(chi2, dof + 5.0 * std::sqrt(2.0 * dof)) << "chi-square " << chi2 << " on " << dof;
    std::printf("glossmeter mc: chi-square %.1f on %d readings\n", chi2, dof);
}

// A paint with no specular lobe in the 20° receptor: the MC's standard error is honest where only
// a small fraction of the samples land in the window.
TEST(GlossmeterMonteCarlo, RejectsWhatItCannotRead)
{
    const pgloss_physical p = {{0.5, 0.5, 0.5}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD};
    EXPECT_THROW(pgt::glossmeter_mc(PGLOSS_CONTRAST_60, p, 0.0, 100, 1), std::invalid_argument);
    EXPECT_THROW(pgt::glossmeter_mc(PGLOSS_GLOSS_60, p, 0.0, 0, 1), std::invalid_argument);
}
