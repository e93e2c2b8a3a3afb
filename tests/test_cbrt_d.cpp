// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The inline cube root (libpgloss/src/cbrt_d.h) against long double cbrtl, an independent
// reference (x87 80-bit: its own error is below 2^-11 of a double ulp); and the vectorised
// perceptual loops of every ISA (perceptual_batch_isa.c) against the scalar functions, bit for
// bit, on random and adversarial inputs that reach every status.

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <random>
#include <vector>

#include "batch_util.h"
#include "cbrt_d.h"
#include "perceptual_batch_isa.h"
#include "test_ulp.h"

// The per-ISA loops: internal symbols of the static library, weak so that a build without
// the AVX2/AVX-512 objects (PGLOSS_ISA_DISPATCH=OFF, another architecture) still links.
extern "C" {
#define DECLARE_LOOP(name, isa)                                                                    \
    __attribute__((weak)) void pgloss__##name##_loop_##isa(size_t, const double *const *,          \
                                                           double *const *, const pgloss__pargs *, \
                                                           signed char *);
#define DECLARE_BASELINE(name) DECLARE_LOOP(name, baseline)
#define DECLARE_AVX2(name) DECLARE_LOOP(name, avx2)
#define DECLARE_AVX512(name) DECLARE_LOOP(name, avx512)
PGLOSS__PERCEPTUAL_LOOPS(DECLARE_BASELINE)
PGLOSS__PERCEPTUAL_LOOPS(DECLARE_AVX2)
PGLOSS__PERCEPTUAL_LOOPS(DECLARE_AVX512)
const double *pgloss__from_xyz_matrix(pgloss_color_space space);
const double *pgloss__to_xyz_matrix(pgloss_color_space space);
}

namespace {

using pgt::ulp_error;

double from_bits(uint64_t u) {
    double x;
    std::memcpy(&x, &u, sizeof x);
    return x;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The documented bound (cbrt_d.h): 0.5 ulp plus a few 2^-60 relative, i.e. correctly rounded
// but for near-halfway cases.
constexpr double kMaxUlp = 0.5 + 1e-4;

TEST(CbrtD, RandomBitPatterns) {
    std::mt19937_64 rng(2026);
    double worst = 0.0, worst_x = 0.0;
    for (int k = 0; k < 4000000; ++k) {
        const double x = from_bits(rng());
        if (!std::isfinite(x)) continue;
        const double e = ulp_error(pgloss__cbrt_d(x), cbrtl(static_cast<long double>(x)));
        if (e > worst) worst = e, worst_x = x;
    }
    EXPECT_LE(worst, kMaxUlp) << "at x = " << std::hexfloat << worst_x;
    std::printf("cbrt_d: max error %.9f ulp over random bit patterns\n", worst);
}

TEST(CbrtD, UnitIntervalAndReflectances) {
    std::mt19937_64 rng(7);
    double worst = 0.0;
    for (int k = 0; k < 4000000; ++k) {
        const double x = static_cast<double>(rng() >> 11) * 0x1p-53;  // [0, 1): the model's domain
        worst = std::max(worst, ulp_error(pgloss__cbrt_d(x), cbrtl(static_cast<long double>(x))));
    }
    EXPECT_LE(worst, kMaxUlp);
    std::printf("cbrt_d: max error %.9f ulp on [0, 1)\n", worst);
}

TEST(CbrtD, SubnormalsZerosAndExtremes) {
    std::mt19937_64 rng(11);
    for (int k = 0; k < 200000; ++k) {
        const double x = from_bits(rng() & 0x800fffffffffffffu);  // subnormals of both signs
        EXPECT_LE(ulp_error(pgloss__cbrt_d(x), cbrtl(static_cast<long double>(x))), kMaxUlp) << x;
    }
    // every binade, both ends, both signs; the scaling thresholds 2^±900
    for (int e = -1074; e <= 1023; ++e) {
        for (double m : {1.0, 1.5, 2.0 - 0x1p-52}) {
            const double x = std::ldexp(m, e);
            if (!std::isfinite(x) || x == 0.0) continue;
            for (double s : {x, -x})
                EXPECT_LE(ulp_error(pgloss__cbrt_d(s), cbrtl(static_cast<long double>(s))), kMaxUlp)
                    << std::hexfloat << s;
        }
    }
    EXPECT_TRUE(same_bits(pgloss__cbrt_d(0.0), 0.0));
    EXPECT_TRUE(same_bits(pgloss__cbrt_d(-0.0), -0.0));
    EXPECT_EQ(pgloss__cbrt_d(INFINITY), INFINITY);
    EXPECT_EQ(pgloss__cbrt_d(-INFINITY), -INFINITY);
    EXPECT_TRUE(std::isnan(pgloss__cbrt_d(NAN)));
    EXPECT_EQ(pgloss__cbrt_d(DBL_MAX), static_cast<double>(cbrtl(static_cast<long double>(DBL_MAX))));
}

// The batches' in-range cube root (no scaling, no special cases) against the general one, bit
// for bit, over the whole range it is used on and its bounds.
TEST(CbrtD, InRangeOnlyEqualsGeneral) {
    std::mt19937_64 rng(900);
    for (int k = 0; k < 2000000; ++k) {
        const double x = std::ldexp(1.0 + static_cast<double>(rng() >> 12) * 0x1p-52, int(rng() % 1800) - 900);
        if (!pgloss__cbrt_in_range_d(x)) continue;  // 2^900 (1 + f), f > 0
        ASSERT_TRUE(same_bits(pgloss__cbrt_in_range_only_d(x), pgloss__cbrt_d(x))) << x;
    }
    for (double x : std::initializer_list<double>{0.0, -0.0, 0x1p-900, 0x1p900, 1.0, 0.5, 8.0})
        EXPECT_TRUE(pgloss__cbrt_in_range_d(x) && same_bits(pgloss__cbrt_in_range_only_d(x), pgloss__cbrt_d(x))) << x;
    for (double x : std::initializer_list<double>{-1.0, 0x1p-901, 0x1.0000000000001p900, 1e-310, INFINITY, NAN})
        EXPECT_FALSE(pgloss__cbrt_in_range_d(x)) << x;
}

TEST(CbrtD, ExactCubesAreExact) {
    for (int64_t k = -200000; k <= 200000; ++k) {
        const double c = static_cast<double>(k);
        ASSERT_EQ(pgloss__cbrt_d(c * c * c), c) << k;  // k³ < 2^53: exact input
    }
    for (int e = -340; e <= 340; ++e) {  // powers of 8 (and 1/8)
        const double r = std::ldexp(1.0, e);
        ASSERT_EQ(pgloss__cbrt_d(r * r * r), r) << e;
    }
}

// L* = 116 ∛Y − 16 takes ∛Y as 2^(1/3) ∛(Y/2) (perceptual_d.h): its error against long double.
TEST(CbrtD, LightnessAgainstLongDouble) {
    std::mt19937_64 rng(5);
    double worst = 0.0;
    for (int k = 0; k < 4000000; ++k) {
        const double Y = static_cast<double>(rng() >> 11) * 0x1p-53;
        if (Y <= PGLOSS_CIE_EPSILON) continue;
        double L = 0.0;
        ASSERT_EQ(pgloss_lightness_from_luminance(Y, &L), PGLOSS_OK);
        const long double ref = 116.0L * cbrtl(static_cast<long double>(Y)) - 16.0L;
        worst = std::max(worst, static_cast<double>(std::fabs((static_cast<long double>(L) - ref) / ref)));
    }
    EXPECT_LE(worst, 8e-16);  // glibc's cbrt in the same formula: 1.2e-15
    std::printf("lightness_from_luminance: max relative error %.3e\n", worst);
}

// ---- the vectorised loops of every ISA against the scalar functions, bit for bit ----------

struct Isa {
    const char *name;
    pgloss_isa isa;
    pgloss__perceptual_loop gloss, physical, from_gloss, envelope, match, check_physical, check_perceptual,
        to_perceptual, rgb_from_lab, lab_from_rgb;
};

// A loop over n elements, chunk by chunk as perceptual_batch.c runs it (columns in, out).
void run(pgloss__perceptual_loop f, size_t n, const std::vector<const double *> &in, const std::vector<double *> &out,
         const double *M, double norm_ok, signed char *st) {
    const pgloss__pargs a{M, norm_ok};
    for (size_t base = 0; base < n; base += PGLOSS__PCHUNK) {
        const double *ic[6];
        double *oc[6];
        size_t k = 0;
        for (const double *p : in) ic[k++] = p + base;
        k = 0;
        for (double *p : out) oc[k++] = p + base;
        f(std::min<size_t>(PGLOSS__PCHUNK, n - base), ic, oc, &a, st + base);
    }
}

std::vector<Isa> isas() {
    // A call through the public batch links perceptual_batch.c, and with it the loops it
    // dispatches to (a weak reference alone pulls no member out of a static library).
    double x = 0.5, L, c, d;
    signed char st;
    EXPECT_EQ(pgloss_gloss_from_physical_batch(1, col(&x), col(&x), col(&x), col_out(&L), col_out(&c), col_out(&d), &st),
              PGLOSS_WARN_ALPHA_UNTRUSTED);
#define ISA_LOOPS(isa)                                                                                    \
    pgloss__gloss_from_physical_loop_##isa, pgloss__physical_from_perceptual_loop_##isa,                    \
        pgloss__physical_from_gloss_loop_##isa, pgloss__envelope_contrast_loop_##isa,                       \
        pgloss__match_gloss_loop_##isa, pgloss__check_physical_loop_##isa,                                  \
        pgloss__check_perceptual_loop_##isa, pgloss__perceptual_from_physical_loop_##isa,                   \
        pgloss__rgb_from_lab_loop_##isa, pgloss__lab_from_rgb_loop_##isa
    return {{"baseline", PGLOSS_ISA_BASELINE, ISA_LOOPS(baseline)},
            {"avx2", PGLOSS_ISA_AVX2, ISA_LOOPS(avx2)},
            {"avx512", PGLOSS_ISA_AVX512, ISA_LOOPS(avx512)}};
#undef ISA_LOOPS
}

// Values that reach every check: negatives, zeros, subnormals, NaN, ±Inf, huge, the ε and
// trusted-α boundaries, out-of-range L*, out-of-gamut a*, b*.
double pick(std::mt19937_64 &rng, double lo, double hi) {
    static const double special[] = {0.0, -0.0, 1e-310, -1e-310, NAN, INFINITY, -INFINITY, 1e308,
                                     -1e308, 216.0 / 24389.0, 8.0, 0.2, 0.8, 1.0, 100.0, -1.0,
                                     100.0 + 1e-13, 1e200, 5e102, 0.19999999999999998};
    const uint64_t r = rng();
    if (r % 16 == 0) return special[(r >> 8) % (sizeof special / sizeof *special)];
    return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1p-53);
}

// Loops run at several lengths and offsets (vector bodies, epilogues, chunk edges).
constexpr size_t kSizes[] = {1, 3, 7, 17, 255, 256, 257, 1000, 4099};

TEST(PerceptualLoops, GlossFromPhysicalEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(18);
    int tested = 0;
    for (const Isa &I : isas()) {
        if (!I.gloss || !pgloss_isa_supported(I.isa)) {
            std::printf("%s loops NOT tested: %s\n", I.name, I.gloss ? "the CPU lacks it" : "not built");
            continue;
        }
        ++tested;
        for (size_t n : kSizes) {
            std::vector<double> rd(n), rs(n), al(n), L(n), c(n), d(n);
            std::vector<signed char> st(n);
            for (size_t j = 0; j < n; ++j)
                rd[j] = pick(rng, 0.0, 1.0), rs[j] = pick(rng, 0.0, 0.2), al[j] = pick(rng, 0.0, 0.3);
            run(I.gloss, n, {rd.data(), rs.data(), al.data()}, {L.data(), c.data(), d.data()}, nullptr, 0, st.data());
            for (size_t j = 0; j < n; ++j) {
                double l, cc, dd;
                const pgloss_status want = pgloss_gloss_from_physical(rd[j], rs[j], al[j], &l, &cc, &dd);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " n=" << n << " j=" << j;
                ASSERT_TRUE(same_bits(L[j], l) && same_bits(c[j], cc) && same_bits(d[j], dd))
                    << I.name << " j=" << j << " rho_d=" << rd[j] << " rho_s=" << rs[j] << " alpha=" << al[j];
            }
        }
    }
    EXPECT_GE(tested, 1);
    std::printf("gloss_from_physical loops tested on %d ISA(s)\n", tested);
}

// The loops take a faster kernel for a chunk whose every paint passes the checks and needs no
// scaling in the cube roots (ρd, ρs in {0} ∪ [2^-899, 2^899], α finite > 0): such chunks, and
// chunks where one element at a time breaks the rule, against the scalar function bit for bit.
double pick_plain(std::mt19937_64 &rng) {
    const uint64_t r = rng();
    switch (r % 8) {
    case 0: return 0.0;
    case 1: return (r >> 8) % 2 ? 0x1p-899 : 0x1p899;
    case 2: return std::ldexp(1.0 + static_cast<double>(rng() >> 12) * 0x1p-52, int((r >> 8) % 1798) - 899);
    default: return static_cast<double>(rng() >> 11) * 0x1p-53;
    }
}

TEST(PerceptualLoops, GlossFromPhysicalPlainChunksEqualScalarOnEveryIsa) {
    std::mt19937_64 rng(2000);
    const double breakers[] = {-0.0 - 1e-300, 0x1p-900, 0x1p900, NAN, INFINITY, 1e-310};
    int tested = 0;
    for (const Isa &I : isas()) {
        if (!I.gloss || !pgloss_isa_supported(I.isa)) continue;  // reported above
        ++tested;
        const size_t n = 1024;
        for (int round = 0; round < 40; ++round) {
            std::vector<double> rd(n), rs(n), al(n), L(n), c(n), d(n);
            std::vector<signed char> st(n);
            for (size_t j = 0; j < n; ++j) {
                rd[j] = pick_plain(rng), rs[j] = pick_plain(rng);
                al[j] = round % 2 ? 0.3 * static_cast<double>(rng() >> 11) * 0x1p-53 + 1e-300 : pick_plain(rng) + 1e-300;
            }
            if (round >= 20) {  // one element out of the plain range, at some position
                const size_t j = rng() % n;
                double *col[] = {rd.data(), rs.data(), al.data()};
                col[rng() % 3][j] = breakers[rng() % (sizeof breakers / sizeof *breakers)];
            }
            run(I.gloss, n, {rd.data(), rs.data(), al.data()}, {L.data(), c.data(), d.data()}, nullptr, 0, st.data());
            for (size_t j = 0; j < n; ++j) {
                double l, cc, dd;
                const pgloss_status want = pgloss_gloss_from_physical(rd[j], rs[j], al[j], &l, &cc, &dd);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " round=" << round << " j=" << j;
                ASSERT_TRUE(same_bits(L[j], l) && same_bits(c[j], cc) && same_bits(d[j], dd))
                    << I.name << " j=" << j << " rho_d=" << rd[j] << " rho_s=" << rs[j] << " alpha=" << al[j];
            }
        }
    }
    EXPECT_GE(tested, 1);
}

TEST(PerceptualLoops, PhysicalFromPerceptualEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(19);
    int tested = 0;
    for (const Isa &I : isas()) {
        if (!I.physical || !pgloss_isa_supported(I.isa)) continue;  // reported by the test above
        ++tested;
        for (int space = 0; space <= 3; ++space) {
            const auto sp = static_cast<pgloss_color_space>(space);
            for (size_t n : kSizes) {
                std::vector<double> L(n), a(n), b(n), c(n), d(n), r(n), g(n), bl(n), s(n), ax(n), ay(n);
                std::vector<signed char> st(n);
                for (size_t j = 0; j < n; ++j) {
                    L[j] = pick(rng, -5.0, 105.0), a[j] = pick(rng, -150.0, 150.0), b[j] = pick(rng, -150.0, 150.0);
                    c[j] = pick(rng, -0.01, 0.2), d[j] = pick(rng, 0.7, 1.01);
                }
                run(I.physical, n, {L.data(), a.data(), b.data(), c.data(), d.data()},
                    {r.data(), g.data(), bl.data(), s.data(), ax.data(), ay.data()}, pgloss__from_xyz_matrix(sp), 1,
                    st.data());
                for (size_t j = 0; j < n; ++j) {
                    const pgloss_perceptual v{L[j], a[j], b[j], c[j], d[j]};
                    pgloss_physical o;
                    const pgloss_status want = pgloss_physical_from_perceptual_ex(&v, PGLOSS_NORM_WARD, sp, &o);
                    ASSERT_EQ(int(st[j]), int(want)) << I.name << " space " << space << " j=" << j;
                    ASSERT_TRUE(same_bits(r[j], o.rho_d[0]) && same_bits(g[j], o.rho_d[1]) &&
                                same_bits(bl[j], o.rho_d[2]) && same_bits(s[j], o.rho_s) &&
                                same_bits(ax[j], o.alpha_x) && same_bits(ay[j], o.alpha_y))
                        << I.name << " space " << space << " j=" << j << " L=" << L[j] << " a=" << a[j]
                        << " b=" << b[j] << " c=" << c[j] << " d=" << d[j];
                }
            }
        }
    }
    EXPECT_GE(tested, 1);
    std::printf("physical_from_perceptual loops tested on %d ISA(s)\n", tested);
}

// The other loops, each against its scalar function in the same way: every ISA built and run
// by the CPU, every length of kSizes, the adversarial pick() values (every status reached:
// counted), every colour space where the function takes one.

// Runs body(isa, n) for each ISA the CPU has (loop non-NULL) and each length; returns the ISAs.
template <class Get, class Body>
int each_isa(Get get, Body body) {
    int tested = 0;
    for (const Isa &I : isas()) {
        if (!get(I) || !pgloss_isa_supported(I.isa)) continue;  // reported above
        ++tested;
        for (size_t n : kSizes) body(I, n);
    }
    EXPECT_GE(tested, 1);
    return tested;
}

// The statuses seen, so that a test can show it reached the ones it means to.
struct Seen {
    std::vector<int> v;
    void add(int s) {
        if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
    }
    bool has(pgloss_status s) const { return std::find(v.begin(), v.end(), int(s)) != v.end(); }
};

TEST(PerceptualLoops, PhysicalFromGlossEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(20);
    Seen seen;
    each_isa([](const Isa &I) { return I.from_gloss; }, [&](const Isa &I, size_t n) {
        std::vector<double> L(n), c(n), d(n), rd(n), rs(n), al(n);
        std::vector<signed char> st(n);
        for (size_t j = 0; j < n; ++j)
            L[j] = pick(rng, -5.0, 105.0), c[j] = pick(rng, -0.01, 0.2), d[j] = pick(rng, 0.7, 1.01);
        run(I.from_gloss, n, {L.data(), c.data(), d.data()}, {rd.data(), rs.data(), al.data()}, nullptr, 0, st.data());
        for (size_t j = 0; j < n; ++j) {
            double x, y, z;
            const pgloss_status want = pgloss_physical_from_gloss(L[j], c[j], d[j], &x, &y, &z);
            seen.add(want);
            ASSERT_EQ(int(st[j]), int(want)) << I.name << " n=" << n << " j=" << j;
            ASSERT_TRUE(same_bits(rd[j], x) && same_bits(rs[j], y) && same_bits(al[j], z))
                << I.name << " j=" << j << " L=" << L[j] << " c=" << c[j] << " d=" << d[j];
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_WARN_ALPHA_UNTRUSTED, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_LIGHTNESS,
                            PGLOSS_ERR_NEGATIVE, PGLOSS_ERR_ALPHA})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

TEST(PerceptualLoops, EnvelopeEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(21);
    Seen seen;
    each_isa([](const Isa &I) { return I.envelope; }, [&](const Isa &I, size_t n) {
        std::vector<double> L(n), cm(n);
        std::vector<signed char> st(n);
        for (size_t j = 0; j < n; ++j) L[j] = pick(rng, -5.0, 105.0);
        run(I.envelope, n, {L.data()}, {cm.data()}, nullptr, 0, st.data());
        for (size_t j = 0; j < n; ++j) {
            double x;
            const pgloss_status want = pgloss_envelope_contrast(L[j], &x);
            seen.add(want);
            ASSERT_EQ(int(st[j]), int(want)) << I.name << " n=" << n << " j=" << j;
            ASSERT_TRUE(same_bits(cm[j], x)) << I.name << " j=" << j << " L=" << L[j];
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_LIGHTNESS})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

TEST(PerceptualLoops, MatchGlossEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(22);
    Seen seen;
    each_isa([](const Isa &I) { return I.match; }, [&](const Isa &I, size_t n) {
        std::vector<double> rd(n), rs(n), L(n), od(n), os(n);
        std::vector<signed char> st(n);
        for (size_t j = 0; j < n; ++j)
            rd[j] = pick(rng, -0.01, 1.0), rs[j] = pick(rng, -0.01, 0.4), L[j] = pick(rng, -5.0, 105.0);
        run(I.match, n, {rd.data(), rs.data(), L.data()}, {od.data(), os.data()}, nullptr, 0, st.data());
        for (size_t j = 0; j < n; ++j) {
            double x, y;
            const pgloss_status want = pgloss_match_gloss(rd[j], rs[j], L[j], &x, &y);
            seen.add(want);
            ASSERT_EQ(int(st[j]), int(want)) << I.name << " n=" << n << " j=" << j;
            ASSERT_TRUE(same_bits(od[j], x) && same_bits(os[j], y))
                << I.name << " j=" << j << " rho_d=" << rd[j] << " rho_s=" << rs[j] << " L=" << L[j];
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_ERR_ENVELOPE, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_LIGHTNESS,
                            PGLOSS_ERR_NEGATIVE})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

// n physical parameter sets from pick(): ρd, ρs, αx, αy (the specials reach FLT_MAX, NaN, ±Inf,
// negatives, α = 0 and the trusted-α bound).
struct Sets {
    std::vector<double> r, g, b, s, ax, ay;
    Sets(std::mt19937_64 &rng, size_t n) : r(n), g(n), b(n), s(n), ax(n), ay(n) {
        for (size_t j = 0; j < n; ++j) {
            r[j] = pick(rng, -0.01, 1.0), g[j] = pick(rng, 0.0, 1.0), b[j] = pick(rng, 0.0, 1.0);
            s[j] = pick(rng, -0.01, 0.4), ax[j] = pick(rng, -0.01, 0.3), ay[j] = pick(rng, -0.01, 0.3);
        }
    }
    pgloss_physical at(size_t j, bool iso, pgloss_normalization nm) const {
        return pgloss_physical{{r[j], g[j], b[j]}, s[j], ax[j], iso ? ax[j] : ay[j], nm};
    }
    // the six columns (isotropic: αx twice, as perceptual_batch.c passes it)
    std::vector<const double *> cols(bool iso) const {
        return {r.data(), g.data(), b.data(), s.data(), ax.data(), iso ? ax.data() : ay.data()};
    }
};

TEST(PerceptualLoops, CheckPhysicalEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(23);
    Seen seen;
    each_isa([](const Isa &I) { return I.check_physical; }, [&](const Isa &I, size_t n) {
        for (int variant = 0; variant < 3; ++variant) {  // anisotropic, isotropic, unknown normalisation
            const Sets P(rng, n);
            const bool iso = variant == 1;
            const auto nm = variant == 2 ? static_cast<pgloss_normalization>(7) : PGLOSS_NORM_WARD_DUR;
            std::vector<signed char> st(n);
            run(I.check_physical, n, P.cols(iso), {}, nullptr, variant == 2 ? 0.0 : 1.0, st.data());
            for (size_t j = 0; j < n; ++j) {
                const pgloss_physical v = P.at(j, iso, nm);
                const pgloss_status want = pgloss_check_physical(&v);
                seen.add(want);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " variant " << variant << " n=" << n << " j=" << j
                                                 << " " << v.rho_d[0] << " " << v.rho_d[1] << " " << v.rho_d[2]
                                                 << " " << v.rho_s << " " << v.alpha_x << " " << v.alpha_y;
            }
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_WARN_ALPHA_UNTRUSTED, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_NEGATIVE,
                            PGLOSS_ERR_ALPHA, PGLOSS_ERR_NORMALIZATION, PGLOSS_ERR_ENERGY})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

TEST(PerceptualLoops, PerceptualFromPhysicalEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(24);
    Seen seen;
    each_isa([](const Isa &I) { return I.to_perceptual; }, [&](const Isa &I, size_t n) {
        for (int space = 0; space <= 3; ++space) {
            const auto sp = static_cast<pgloss_color_space>(space);
            const bool iso = space % 2 == 1;
            const Sets P(rng, n);
            std::vector<double> L(n), a(n), b(n), c(n), d(n);
            std::vector<signed char> st(n);
            run(I.to_perceptual, n, P.cols(iso), {L.data(), a.data(), b.data(), c.data(), d.data()},
                pgloss__to_xyz_matrix(sp), 0, st.data());
            for (size_t j = 0; j < n; ++j) {
                const pgloss_physical v = P.at(j, iso, PGLOSS_NORM_WARD);
                pgloss_perceptual o;
                const pgloss_status want = pgloss_perceptual_from_physical_ex(&v, sp, &o);
                seen.add(want);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " space " << space << " n=" << n << " j=" << j;
                ASSERT_TRUE(same_bits(L[j], o.L) && same_bits(a[j], o.a) && same_bits(b[j], o.b) &&
                            same_bits(c[j], o.c) && same_bits(d[j], o.d))
                    << I.name << " space " << space << " j=" << j;
            }
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_WARN_ALPHA_UNTRUSTED, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_NEGATIVE,
                            PGLOSS_ERR_ALPHA})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

TEST(PerceptualLoops, CheckPerceptualEqualsScalarOnEveryIsa) {
    std::mt19937_64 rng(25);
    Seen seen;
    each_isa([](const Isa &I) { return I.check_perceptual; }, [&](const Isa &I, size_t n) {
        for (int space = 0; space <= 3; ++space) {
            const auto sp = static_cast<pgloss_color_space>(space);
            std::vector<double> L(n), a(n), b(n), c(n), d(n);
            std::vector<signed char> st(n);
            for (size_t j = 0; j < n; ++j) {
                L[j] = pick(rng, -5.0, 105.0), a[j] = pick(rng, -60.0, 60.0), b[j] = pick(rng, -60.0, 60.0);
                c[j] = pick(rng, -0.01, 0.25), d[j] = pick(rng, 0.7, 1.01);
            }
            run(I.check_perceptual, n, {L.data(), a.data(), b.data(), c.data(), d.data()}, {},
                pgloss__from_xyz_matrix(sp), 0, st.data());
            for (size_t j = 0; j < n; ++j) {
                const pgloss_perceptual v{L[j], a[j], b[j], c[j], d[j]};
                const pgloss_status want = pgloss_check_perceptual_ex(&v, sp);
                seen.add(want);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " space " << space << " n=" << n << " j=" << j
                                                 << " L=" << L[j] << " a=" << a[j] << " b=" << b[j]
                                                 << " c=" << c[j] << " d=" << d[j];
            }
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_WARN_ALPHA_UNTRUSTED, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_LIGHTNESS,
                            PGLOSS_ERR_NEGATIVE, PGLOSS_ERR_ALPHA, PGLOSS_ERR_GAMUT, PGLOSS_ERR_ENVELOPE,
                            PGLOSS_ERR_ENERGY})
        EXPECT_TRUE(seen.has(s)) << pgloss_status_name(s);
}

TEST(PerceptualLoops, RgbFromLabAndLabFromRgbEqualScalarOnEveryIsa) {
    std::mt19937_64 rng(26);
    Seen to_rgb, to_lab;
    each_isa([](const Isa &I) { return I.rgb_from_lab && I.lab_from_rgb; }, [&](const Isa &I, size_t n) {
        for (int space = 0; space <= 3; ++space) {
            const auto sp = static_cast<pgloss_color_space>(space);
            std::vector<double> L(n), a(n), b(n), R(n), G(n), B(n), L2(n), a2(n), b2(n);
            std::vector<signed char> st(n), st2(n);
            for (size_t j = 0; j < n; ++j)
                L[j] = pick(rng, -5.0, 105.0), a[j] = pick(rng, -150.0, 150.0), b[j] = pick(rng, -150.0, 150.0);
            run(I.rgb_from_lab, n, {L.data(), a.data(), b.data()}, {R.data(), G.data(), B.data()},
                pgloss__from_xyz_matrix(sp), 0, st.data());
            // back again, the GAMUT elements' negative channels included
            run(I.lab_from_rgb, n, {R.data(), G.data(), B.data()}, {L2.data(), a2.data(), b2.data()},
                pgloss__to_xyz_matrix(sp), 0, st2.data());
            for (size_t j = 0; j < n; ++j) {
                const double lab[3] = {L[j], a[j], b[j]}, rgb[3] = {R[j], G[j], B[j]};
                double o[3], o2[3];
                const pgloss_status want = pgloss_rgb_from_lab_ex(lab, sp, o);
                const pgloss_status want2 = pgloss_lab_from_rgb_ex(rgb, sp, o2);
                to_rgb.add(want), to_lab.add(want2);
                ASSERT_EQ(int(st[j]), int(want)) << I.name << " space " << space << " n=" << n << " j=" << j;
                ASSERT_TRUE(same_bits(R[j], o[0]) && same_bits(G[j], o[1]) && same_bits(B[j], o[2]))
                    << I.name << " rgb_from_lab space " << space << " j=" << j;
                ASSERT_EQ(int(st2[j]), int(want2)) << I.name << " space " << space << " n=" << n << " j=" << j;
                ASSERT_TRUE(same_bits(L2[j], o2[0]) && same_bits(a2[j], o2[1]) && same_bits(b2[j], o2[2]))
                    << I.name << " lab_from_rgb space " << space << " j=" << j;
            }
        }
        // lab_from_rgb on its own domain's specials too (NaN, ±Inf, 1e308: NONFINITE results)
        std::vector<double> r(n), g(n), bb(n), L(n), a(n), b(n);
        std::vector<signed char> st(n);
        for (size_t j = 0; j < n; ++j) r[j] = pick(rng, 0.0, 1.0), g[j] = pick(rng, 0.0, 1.0), bb[j] = pick(rng, 0.0, 1.0);
        run(I.lab_from_rgb, n, {r.data(), g.data(), bb.data()}, {L.data(), a.data(), b.data()},
            pgloss__to_xyz_matrix(PGLOSS_COLOR_SPACE_ACESCG), 0, st.data());
        for (size_t j = 0; j < n; ++j) {
            const double rgb[3] = {r[j], g[j], bb[j]};
            double o[3];
            const pgloss_status want = pgloss_lab_from_rgb_ex(rgb, PGLOSS_COLOR_SPACE_ACESCG, o);
            to_lab.add(want);
            ASSERT_EQ(int(st[j]), int(want)) << I.name << " n=" << n << " j=" << j;
            ASSERT_TRUE(same_bits(L[j], o[0]) && same_bits(a[j], o[1]) && same_bits(b[j], o[2])) << I.name << " j=" << j;
        }
    });
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_LIGHTNESS, PGLOSS_ERR_GAMUT})
        EXPECT_TRUE(to_rgb.has(s)) << "rgb_from_lab " << pgloss_status_name(s);
    for (pgloss_status s : {PGLOSS_OK, PGLOSS_ERR_NONFINITE, PGLOSS_ERR_NEGATIVE})
        EXPECT_TRUE(to_lab.has(s)) << "lab_from_rgb " << pgloss_status_name(s);
}

}  // namespace
