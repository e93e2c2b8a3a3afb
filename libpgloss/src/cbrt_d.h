// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The cube root in double (eqs. 4, 6–7 and CIELAB's f), called by the scalar functions and the
 * batched perceptual loops alike, so that they agree bit for bit. libm's cbrt is a call the
 * compiler cannot vectorise (and a division or two inside); this one is straight-line code —
 * no branch, no table, no division — that GCC and Clang vectorise on SSE2, AVX2 and AVX-512.
 * Not installed.
 *
 * Every double is handled: subnormals, ±0 and negatives (∛(−x) = −∛x); NaN and ±Inf give
 * themselves. Error: within 0.5 ulp plus a few 2^-60 relative (a correctly rounded result but
 * for near-halfway cases); measured against long double cbrtl in tests/test_cbrt_d.cpp, the
 * derivation in docs/kernels.md. It needs no FMA: -ffp-contract=off builds give the same bits
 * on every ISA (where FMA is there, it computes step 4's exact residual in one operation, to
 * the same bits). */
#ifndef PGLOSS_CBRT_D_H
#define PGLOSS_CBRT_D_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(__GNUC__) || defined(__clang__)
#define PGLOSS__CBRT_FN static inline __attribute__((always_inline))
#else
#define PGLOSS__CBRT_FN static inline
#endif

PGLOSS__CBRT_FN uint64_t pgloss__bits_d(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

PGLOSS__CBRT_FN double pgloss__from_bits_d(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* Steps 2–5 below for v = 0 or 2^-900 <= v <= 2^900: ∛v for v > 0 (any value for v = 0,
 * which the callers select away). */
PGLOSS__CBRT_FN double pgloss__cbrt_core_d(double v)
{
    /* 2. z ≈ v^(-1/3) to 3.5 % from the high word h of v (the exponent divided by 3, as
     *    Blinn's and fdlibm's first guesses): high word K − h/3, K = 1430187896 fitted for the
     *    smallest error over a period of 3 binades. h < 2^31 is exact as a double (its bits
     *    ORed into 2^52's), and K + 2^52 − h/3 rounds to an integer whose low bits are it. */
    const double h = pgloss__from_bits_d((pgloss__bits_d(v) >> 32) | 0x4330000000000000u) - 0x1p52;
    const double q = (1430187896.0 + 0x1p52) - h * (1.0 / 3.0);
    double z = pgloss__from_bits_d((pgloss__bits_d(q) & 0x000fffffffffffffu) << 32);
    /* 3. Three Newton steps on v z³ = 1, z ← z + z (1/3 − (v/3) z³): error 3.5e-2 → 2.4e-3 →
     *    1.1e-5 → 2.6e-10 (each step squares it, times 2); no division. */
    const double v3 = v * (1.0 / 3.0);
    for (int k = 0; k < 3; ++k)
        z = z + z * ((1.0 / 3.0) - ((v3 * z) * z) * z);
    /* 4. t = v z² ≈ ∛v rounded to 23 bits, so that t² (46 bits) is exact; split t² into
     *    23-bit halves, and the residual R = v − t³ comes out exact up to its last rounding
     *    (v − hi·t is exact: the two are within a factor 2 of each other, Sterbenz). */
    const double y = (v * z) * z;
    const double e = 1.0 - y * z; /* 1 − v z³, |e| < 1e-9 */
    const double t = pgloss__from_bits_d((pgloss__bits_d(y) + 0x20000000u) & 0xffffffffc0000000u);
    const double s = t * t;
#if defined(__FMA__)
    /* the same R: v − s t rounded once, by the fused multiply-add (fewer operations; the
     * scalar functions, built without FMA, take the split and agree bit for bit) */
    const double R = fma(-s, t, v);
#else
    const double s_hi = pgloss__from_bits_d(pgloss__bits_d(s) & 0xffffffffc0000000u);
    const double s_lo = s - s_hi;
    const double R = (v - s_hi * t) - s_lo * t;
#endif
    /* 5. ∛v = t (1 − u)^(-1/3) with u = R/v (|u| < 2^-21), 1/v = z³/(1 − e) = z³ (1 + e) to
     *    e² < 1e-18: t (1 + u/3 + 2u²/9 + O(u³)), the O(u³) term below 2^-66. */
    const double u = (R * ((z * z) * z)) * (1.0 + e);
    return t + t * (u * ((1.0 / 3.0) + u * (2.0 / 9.0)));
}

/* ∛x for every double x. (Selects on double comparisons throughout: that is what the
 * vectoriser turns into blends next to double arithmetic.) */
PGLOSS__CBRT_FN double pgloss__cbrt_d(double x)
{
    const double ax = fabs(x);
    /* 1. Into [2^-900, 2^900] by an exact power of 2^3k (subnormals included), so that no
     *    product in steps 2–5 overflows or underflows; undone exactly at the end. */
    const double in = ax < 0x1p-900 ? 0x1p300 : (ax > 0x1p900 ? 0x1p-300 : 1.0);
    const double out = ax < 0x1p-900 ? 0x1p-100 : (ax > 0x1p900 ? 0x1p100 : 1.0);
    const double r = pgloss__cbrt_core_d(ax * in) * out;
    /* ±0 and NaN, ±Inf: themselves (x + x quiets a NaN). */
    return ax <= DBL_MAX ? (ax > 0.0 ? copysign(r, x) : x) : x + x;
}

/* x is 0 or within [2^-900, 2^900], where pgloss__cbrt_d scales by 1 (one comparison per
 * bound, what vectorises). */
PGLOSS__CBRT_FN int pgloss__cbrt_in_range_d(double x)
{
    return (x == 0.0) | ((x >= 0x1p-900) & (x <= 0x1p900));
}

/* pgloss__cbrt_d(x), bit for bit, for x known to pass pgloss__cbrt_in_range_d: no scaling
 * and no special cases (the batches check a chunk's inputs once and then take this). */
PGLOSS__CBRT_FN double pgloss__cbrt_in_range_only_d(double x)
{
    return x > 0.0 ? pgloss__cbrt_core_d(x) : x;
}

#endif
