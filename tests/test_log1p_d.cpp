// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The double sampler's inline functions (libpgloss/src/lobe_d.h) against independent
// references: pgloss__log1p_d against long double log1pl (x87 80-bit, its own error far below
// a double ulp), and the branch-free direction maps (pgloss__cos_sin_turn,
// pgloss__sample_cosine_d) against cosl/sinl of their defining angles.

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

#include "lobe_d.h"
#include "test_ulp.h"

namespace {

using pgt::ulp_error;

double err_at(double x) { return ulp_error(pgloss__log1p_d(x), log1pl(static_cast<long double>(x))); }

// The bound stated in lobe_d.h: below 1 ulp (0.89 measured).
constexpr double kMaxUlp = 0.9;

// Uniform doubles in [0, 1) with all 53 bits.
double unit(std::mt19937_64 &rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

TEST(Log1pD, SamplerDomain) {
    // −ln(1 − u) for u in [0, 1 − 2^-24] (the sampler's clamped random numbers): uniform u,
    // u spread over 80 binades towards 0, and 1 − u spread over the binades down to 2^-24.
    std::mt19937_64 rng(2026);
    double worst = 0.0, worst_x = 0.0;
    for (int k = 0; k < 3000000; ++k) {
        double u = unit(rng);
        if (k % 3 == 1) u = std::ldexp(u, -static_cast<int>(rng() % 80));
        if (k % 3 == 2) u = 1.0 - std::ldexp(std::max(u, 0.5), -static_cast<int>(rng() % 24));
        u = std::min(u, 1.0 - 0x1p-24);
        const double e = err_at(-u);
        if (e > worst) worst = e, worst_x = -u;
    }
    EXPECT_LE(worst, kMaxUlp) << "at x = " << std::hexfloat << worst_x;
    std::printf("log1p_d: max error %.4f ulp on [-(1 - 2^-24), 0]\n", worst);
}

TEST(Log1pD, WholeDomain) {
    // x > −1 over every binade from 2^-1074 to 2^1023, both signs where −1 < x.
    std::mt19937_64 rng(7);
    double worst = 0.0, worst_x = 0.0;
    for (int k = 0; k < 3000000; ++k) {
        const double m = 1.0 + unit(rng);
        double x = std::ldexp(m, static_cast<int>(rng() % 2098) - 1074);
        if (k & 1) x = -x;
        if (!(x > -1.0) || !std::isfinite(x)) continue;
        const double e = err_at(x);
        if (e > worst) worst = e, worst_x = x;
    }
    EXPECT_LE(worst, kMaxUlp) << "at x = " << std::hexfloat << worst_x;
    std::printf("log1p_d: max error %.4f ulp over (-1, DBL_MAX]\n", worst);
}

TEST(Log1pD, EdgesAndBinadeBorders) {
    // the sampler's extremes; the reduction's thresholds (1 + x near √2/2, √2, 2√2 and the
    // powers of 2 where k changes); where the correction c/u is dropped (k = 54).
    EXPECT_EQ(pgloss__log1p_d(0.0), 0.0);
    EXPECT_EQ(pgloss__log1p_d(-0.0), 0.0);
    EXPECT_EQ(pgloss__log1p_d(0x1p-1074), 0x1p-1074);
    EXPECT_EQ(pgloss__log1p_d(-0x1p-60), -0x1p-60);
    EXPECT_LE(err_at(-(1.0 - 0x1p-24)), kMaxUlp);
    EXPECT_LE(err_at(-0x1p-53), kMaxUlp);
    EXPECT_LE(err_at(DBL_MAX), kMaxUlp);
    for (int e = -60; e <= 70; ++e) {
        for (double b : {std::sqrt(0.5), 1.0, std::sqrt(2.0)}) {
            const double c = std::ldexp(b, e);
            for (int d = -64; d <= 64; ++d) {
                const double x = std::nextafter(c, d < 0 ? 0.0 : INFINITY) + d * std::ldexp(c, -52) - 1.0;
                if (!(x > -1.0)) continue;
                ASSERT_LE(err_at(x), kMaxUlp) << std::hexfloat << x;
            }
        }
    }
}

// ---- the direction maps ----------------------------------------------------------------

TEST(SamplingMapsD, CosSinTurn) {
    // (cos 2πu, sin 2πu): every quadrant, the quadrant borders u = k/8 (where the rounding of 4u
    // changes k) and their neighbours, random u. The reduction is exact, so the error is the
    // polynomials' (a few ulp of 1).
    std::mt19937_64 rng(3);
    double worst = 0.0;
    auto check = [&](double u) {
        double c, s;
        pgloss__cos_sin_turn(u, &c, &s);
        const long double t = 2.0L * 3.14159265358979323846264338327950288L * static_cast<long double>(u);
        worst = std::max(worst, static_cast<double>(std::max(std::fabs(c - cosl(t)), std::fabs(s - sinl(t)))));
    };
    for (int k = 0; k <= 8; ++k) {
        double u = k / 8.0;
        for (int d = 0; d < 4; ++d) u = std::nextafter(u, 0.0);
        for (int d = 0; d < 9; ++d, u = std::nextafter(u, 1.0))
            if (u >= 0.0 && u <= 1.0 - 0x1p-24) check(u);
    }
    for (int k = 0; k < 1000000; ++k) check(std::min(unit(rng), 1.0 - 0x1p-24));
    EXPECT_LE(worst, 4 * DBL_EPSILON);
    std::printf("cos_sin_turn: max error %.3g (units of 1)\n", worst);
}

TEST(SamplingMapsD, ConcentricDiskCosineHemisphere) {
    // Shirley & Chiu's map against its definition in long double: r = a, φ = (π/4)(b/a) where
    // |a| > |b|, else r = b, φ = π/2 − (π/4)(a/b); the centre (u1 = u2 = 1/2) is (0, 0, 1); the
    // results are unit vectors in the upper hemisphere.
    std::mt19937_64 rng(5);
    const long double pi = 3.14159265358979323846264338327950288L;
    double worst = 0.0;
    auto check = [&](double u1, double u2) {
        double w[3];
        pgloss__sample_cosine_d(u1, u2, w);
        const long double a = 2.0L * u1 - 1.0L, b = 2.0L * u2 - 1.0L;
        long double x = 0.0L, y = 0.0L;
        if (a != 0.0L || b != 0.0L) {
            const bool am = std::fabs(a) > std::fabs(b);
            const long double r = am ? a : b, phi = am ? (pi / 4) * (b / a) : pi / 2 - (pi / 4) * (a / b);
            x = r * cosl(phi);
            y = r * sinl(phi);
        }
        const long double z = sqrtl(std::max(0.0L, 1.0L - x * x - y * y));
        worst = std::max(worst, static_cast<double>(std::max({std::fabs(w[0] - x), std::fabs(w[1] - y)})));
        // z: its error grows as 1/z at the rim; compared through z² (the lifted radius)
        worst = std::max(worst, static_cast<double>(std::fabs(static_cast<long double>(w[2]) * w[2] - z * z)));
        EXPECT_GE(w[2], 0.0);
    };
    double w[3];
    pgloss__sample_cosine_d(0.5, 0.5, w);
    EXPECT_TRUE(w[0] == 0.0 && w[1] == 0.0 && w[2] == 1.0);
    for (double u1 : {0.0, 0.25, 0.5, 0.75, 1.0 - 0x1p-24})
        for (double u2 : {0.0, 0.25, 0.5, 0.75, 1.0 - 0x1p-24}) check(u1, u2);
    for (int k = 0; k < 1000000; ++k) {
        const double u1 = std::min(unit(rng), 1.0 - 0x1p-24);
        const double u2 = (k % 4 == 0) ? u1 : std::min(unit(rng), 1.0 - 0x1p-24);  // the diagonal |a| = |b|
        check(u1, u2);
    }
    EXPECT_LE(worst, 8 * DBL_EPSILON);
    std::printf("sample_cosine_d: max error %.3g (units of 1)\n", worst);
}

}  // namespace
