// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The double lobe's inline exponential (pgloss__exp_neg_d in libpgloss/src/lobe_d.h, e^-t for
// t >= 0) against long double expl, an independent reference (x87 80-bit: its own error is
// far below a double ulp), over the whole range the lobe uses: the normal range (t <= 700,
// within the stated 2.5 ulp), the subnormal tail (700 < t <= 1416: relative 2e-13 plus the
// subnormal's rounding) and 0 beyond. The AVX-512 batches evaluate the same code with their
// bounds taken as int64 (lobe_d.h), the same values: the shared vectors check the batches.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>

#include "lobe_d.h"
#include "test_ulp.h"

namespace {

using pgt::ulp_error;

// The documented bound on the normal range (lobe_d.h).
constexpr double kMaxUlp = 2.5;

TEST(ExpD, NormalRangeUniformAndLogUniform) {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> uni(0.0, 700.0), lg(-40.0, std::log(700.0));
    double worst = 0.0, worst_t = 0.0;
    for (int k = 0; k < 2000000; ++k) {
        const double t = (k & 1) ? uni(rng) : std::exp(lg(rng));
        const double e = ulp_error(pgloss__exp_neg_d(t), expl(-static_cast<long double>(t)));
        if (e > worst) worst = e, worst_t = t;
    }
    RecordProperty("max_ulp", std::to_string(worst));
    EXPECT_LE(worst, kMaxUlp) << "t = " << worst_t;
    std::printf("exp_neg_d on [0, 700]: max %.3f ulp (t = %.17g)\n", worst, worst_t);
}

// Around every reduction boundary (t = (m + 1/2) ln2, where the polynomial's argument is
// largest) and every multiple of ln2 (where it is 0).
TEST(ExpD, ReductionBoundaries) {
    double worst = 0.0;
    for (int m = 0; m <= 1009; ++m) {
        for (const double c : {m * 0.6931471805599453, (m + 0.5) * 0.6931471805599453}) {
            double t = c;
            for (int k = 0; k < 8; ++k) {
                if (t >= 0.0 && t <= 700.0)
                    worst = std::fmax(worst, ulp_error(pgloss__exp_neg_d(t), expl(-static_cast<long double>(t))));
                t = std::nextafter(t, (k & 1) ? 0.0 : 1e9);
            }
        }
    }
    EXPECT_LE(worst, kMaxUlp);
}

TEST(ExpD, ExactPointsAndLimits) {
    EXPECT_EQ(pgloss__exp_neg_d(0.0), 1.0);
    EXPECT_EQ(pgloss__exp_neg_d(1417.0), 0.0);
    EXPECT_EQ(pgloss__exp_neg_d(1e300), 0.0);
    EXPECT_EQ(pgloss__exp_neg_d(INFINITY), 0.0);
    EXPECT_TRUE(std::isfinite(pgloss__exp_neg_d(NAN))) << "a NaN argument gives a finite value";
    // tiny t: e^-t = 1 − t rounded
    EXPECT_EQ(pgloss__exp_neg_d(1e-300), 1.0);
    EXPECT_EQ(pgloss__exp_neg_d(0x1p-60), 1.0 - 0x1p-60);
}

// The subnormal tail: e^-(t − 1021 ln2) · 2^-1021, the shift rounded (relative ~1e-13), then
// the subnormal's own rounding (half a 2^-1074).
TEST(ExpD, SubnormalTail) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uni(700.0, 1416.0);
    double worst_rel = 0.0;
    for (int k = 0; k < 400000; ++k) {
        const double t = k < 1000 ? 700.0 + k * 0.716 : uni(rng);
        const long double ref = expl(-static_cast<long double>(t));
        const double got = pgloss__exp_neg_d(t);
        ASSERT_TRUE(got >= 0.0 && std::isfinite(got)) << t;
        const long double err = std::fabs(static_cast<long double>(got) - ref);
        ASSERT_LE(err, 2e-13L * ref + std::ldexp(1.0L, -1075)) << "t = " << t;
        if (ref > static_cast<long double>(DBL_MIN))
            worst_rel = std::fmax(worst_rel, static_cast<double>(err / ref));
    }
    // monotone across the switch at t = 700
    EXPECT_GE(pgloss__exp_neg_d(700.0), pgloss__exp_neg_d(std::nextafter(700.0, 800.0)));
    std::printf("exp_neg_d on (700, 1416], normal results: max relative %.3g\n", worst_rel);
}

}  // namespace
