// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The batched paths on every instruction set and accuracy tier (batch.h): the FLOAT tier is
// bit-identical on every ISA the CPU has (no FMA contraction, same code); FAST stays within
// its stated error of the scalar double reference; REFERENCE is the scalar functions
// element by element; option errors are PGLOSS_ERR_ARGUMENT. The shared vectors test the
// default (FLOAT, AUTO) path; this test covers the others, including edge inputs.
//
// Each ISA is its own test case (Isa/PerIsa.*/baseline|avx2|avx512). An ISA this CPU or this
// build lacks is GTEST_SKIPped with the reason, so ctest lists it as not run; a CPU feature is
// hardware, not a missing dependency, so PGLOSS_REQUIRE_ALL=1 leaves it a skip, and
// PGLOSS_REQUIRE_ISA=avx2,avx512 (or "all") makes it a failure (CI sets it: .ci/run).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "batch_util.h"
#include "pgloss/inline.h"

namespace {

struct Data {
    std::size_t n;
    std::vector<float> ox, oy, oz, ix, iy, iz, u0, u1, u2;
};

// Regular inputs (both directions above the horizon), plus edges: grazing, below the
// horizon, zero / huge / denormal / non-finite directions, u at 0, 1 and NaN.
Data make_data(std::size_t n, bool edges)
{
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    Data d{n, {}, {}, {}, {}, {}, {}, {}, {}, {}};
    for (std::size_t j = 0; j < n; ++j) {
        auto dir = [&](std::vector<float> &x, std::vector<float> &y, std::vector<float> &z) {
            const float c = 0.02f + 0.98f * uni(rng), p = 6.2831853f * uni(rng);
            const float s = std::sqrt(1.0f - c * c);
            x.push_back(s * std::cos(p));
            y.push_back(s * std::sin(p));
            z.push_back(c);
        };
        dir(d.ox, d.oy, d.oz);
        dir(d.ix, d.iy, d.iz);
        d.u0.push_back(uni(rng));
        d.u1.push_back(uni(rng));
        d.u2.push_back(uni(rng));
    }
    if (edges) {
        const float inf = INFINITY, nan = NAN;
        const float special[][3] = {{0, 0, 0},      {1, 0, 0},         {0, 0, -1},
                                    {1, 0, 1e-7f},  {3e38f, 0, 3e38f}, {1e-45f, 0, 1e-45f},
                                    {inf, 0, 1},    {nan, 0, 1},       {0.3f, -0.2f, 1e-30f}};
        std::size_t j = 0;
        for (const auto &s : special)
            for (const auto &t : special) {
                if (j >= n)
                    break;
                d.ox[j] = s[0]; d.oy[j] = s[1]; d.oz[j] = s[2];
                d.ix[j] = t[0]; d.iy[j] = t[1]; d.iz[j] = t[2];
                ++j;
            }
        const float us[] = {0.0f, 1.0f, 0x1.fffffep-1f, -1.0f, 2.0f, nan, inf, 1e-30f};
        for (std::size_t k = 0; k < n && k < 512; ++k) {
            d.u0[k] = us[k % 8];
            d.u1[k] = us[(k / 8) % 8];
            d.u2[k] = us[(k / 64) % 8];
        }
    }
    return d;
}

struct Out {
    std::vector<float> fr, fg, fb, pdf, wx, wy, wz;
    std::vector<unsigned char> lobe;
    pgloss_status st_eval = PGLOSS_OK, st_sample = PGLOSS_OK;
    explicit Out(std::size_t n)
        : fr(n), fg(n), fb(n), pdf(n), wx(n), wy(n), wz(n), lobe(n) {}
};

Out run(const Data &d, const pgloss_material &m, pgloss_batch_options opt, bool sample)
{
    Out o(d.n);
    const pgloss_strided3 wo = soa(d.ox.data(), d.oy.data(), d.oz.data());
    const pgloss_strided3 wi = soa(d.ix.data(), d.iy.data(), d.iz.data());
    const pgloss_strided3_out f = soa_out(o.fr.data(), o.fg.data(), o.fb.data());
    if (!sample) {
        o.st_eval = pgloss_eval_pdf_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, d.n, wo, wi, f,
                                          col_out(o.pdf.data()), nullptr);
    } else {
        o.st_sample = pgloss_sample_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, d.n, wo,
                                          soa(d.u0.data(), d.u1.data(), d.u2.data()),
                                          soa_out(o.wx.data(), o.wy.data(), o.wz.data()),
                                          col_out(o.pdf.data()), f, o.lobe.data(), nullptr);
    }
    return o;
}

std::vector<pgloss_material> materials()
{
    const pgloss_physical ps[] = {
        {{0.193, 0.193, 0.193}, 0.066, 0.07, 0.07, PGLOSS_NORM_WARD},
        {{0.8, 0.2, 0.05}, 0.1, 0.3, 0.05, PGLOSS_NORM_WARD_DUR},
        {{0.0, 0.0, 0.0}, 0.5, 0.01, 0.01, PGLOSS_NORM_BOUNDED},
        {{0.5, 0.5, 0.5}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD},
        {{0.1, 0.1, 0.1}, 0.2, 3e38, 1e-4, PGLOSS_NORM_WARD},
    };
    std::vector<pgloss_material> out;
    for (const auto &p : ps) {
        pgloss_material m;
        EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        out.push_back(m);
    }
    return out;
}

bool bits_equal(const std::vector<float> &a, const std::vector<float> &b)
{
    return std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

const pgloss_isa kIsas[] = {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512};

// Whether the CPU has the ISA's features, asked independently of libpgloss, so that a skip
// can say whether the CPU or the build is why (the same feature sets as batch.c).
bool cpu_has(pgloss_isa isa)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    switch (isa) {
    case PGLOSS_ISA_BASELINE: return true;
    case PGLOSS_ISA_AVX2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case PGLOSS_ISA_AVX512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
               __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
    default: return false;
    }
#else
    return isa == PGLOSS_ISA_BASELINE;
#endif
}

// PGLOSS_REQUIRE_ISA: a comma-separated list of ISA names (pgloss_isa_name) or "all".
bool isa_required(pgloss_isa isa)
{
    const char *env = std::getenv("PGLOSS_REQUIRE_ISA");
    std::stringstream list(env ? env : "");
    for (std::string item; std::getline(list, item, ',');)
        if (item == "all" || item == pgloss_isa_name(isa))
            return true;
    return false;
}

std::string why_unsupported(pgloss_isa isa)
{
    const char *name = pgloss_isa_name(isa);
    if (!cpu_has(isa))
        return std::string("this CPU lacks ") + name +
               (isa == PGLOSS_ISA_AVX512 ? " (avx512f/vl/dq/bw)" : " (avx2 + fma)");
    return std::string("this libpgloss was built without its ") + name +
           " kernels (PGLOSS_ISA_DISPATCH=OFF, or not x86-64 GCC/Clang)";
}

// One test case per ISA: skipped, with the reason, where the ISA is not available, and a
// failure instead where PGLOSS_REQUIRE_ISA names it.
class PerIsa : public ::testing::TestWithParam<pgloss_isa> {
protected:
    void SetUp() override
    {
        const pgloss_isa isa = GetParam();
        if (pgloss_isa_supported(isa))
            return;
        if (isa_required(isa))
            FAIL() << pgloss_isa_name(isa) << " is not tested: " << why_unsupported(isa)
                   << ", and PGLOSS_REQUIRE_ISA=" << std::getenv("PGLOSS_REQUIRE_ISA")
                   << " requires it";
        GTEST_SKIP() << pgloss_isa_name(isa) << " kernels NOT tested: " << why_unsupported(isa)
                     << " (PGLOSS_REQUIRE_ISA=" << pgloss_isa_name(isa)
                     << " makes this a failure)";
    }
};

TEST(Isa, NamesAndSupport)
{
    EXPECT_STREQ(pgloss_isa_name(PGLOSS_ISA_AUTO), "auto");
    EXPECT_STREQ(pgloss_isa_name(PGLOSS_ISA_AVX512), "avx512");
    EXPECT_STREQ(pgloss_isa_name(static_cast<pgloss_isa>(77)), "unknown");
    EXPECT_TRUE(pgloss_isa_supported(PGLOSS_ISA_AUTO));
    EXPECT_TRUE(pgloss_isa_supported(PGLOSS_ISA_BASELINE));
    EXPECT_FALSE(pgloss_isa_supported(static_cast<pgloss_isa>(77)));
    EXPECT_TRUE(pgloss_isa_supported(pgloss_isa_best()));
    std::printf("best ISA on this CPU: %s\n", pgloss_isa_name(pgloss_isa_best()));
    std::string tested, untested;
    for (pgloss_isa isa : kIsas) {
        if (pgloss_isa_supported(isa))
            tested += std::string(tested.empty() ? "" : ", ") + pgloss_isa_name(isa);
        else
            untested += std::string(untested.empty() ? "" : "; ") + why_unsupported(isa);
    }
    std::printf("ISAs tested: %s; not tested: %s\n", tested.c_str(),
                untested.empty() ? "none" : untested.c_str());
}

// FLOAT on this ISA is bit-identical to FLOAT on the baseline, and AUTO is the best ISA.
TEST_P(PerIsa, FloatTierIsBitIdenticalToBaseline)
{
    const pgloss_isa isa = GetParam();
    const Data d = make_data(3000, true);
    int compared = 0;
    for (const auto &m : materials())
        for (bool sample : {false, true}) {
            const Out ref = run(d, m, batch_options(PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_BASELINE), sample);
            const Out o = run(d, m, batch_options(PGLOSS_PRECISION_FLOAT, isa), sample);
            EXPECT_TRUE(bits_equal(o.fr, ref.fr) && bits_equal(o.fg, ref.fg) &&
                        bits_equal(o.fb, ref.fb) && bits_equal(o.pdf, ref.pdf))
                << pgloss_isa_name(isa) << (sample ? " sample" : " eval_pdf");
            if (sample) {
                EXPECT_TRUE(bits_equal(o.wx, ref.wx) && bits_equal(o.wy, ref.wy) &&
                            bits_equal(o.wz, ref.wz) && o.lobe == ref.lobe);
            }
            EXPECT_EQ(o.st_eval, ref.st_eval);
            EXPECT_EQ(o.st_sample, ref.st_sample);
            ++compared;
            if (isa == pgloss_isa_best()) {
                const Out a = run(d, m, batch_options(PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO), sample);
                EXPECT_TRUE(bits_equal(a.fr, o.fr) && bits_equal(a.pdf, o.pdf)) << "AUTO";
            }
        }
    std::printf("%s: %d bit-identical comparisons with the baseline\n", pgloss_isa_name(isa), compared);
}

// Every output finite, on every tier, including the edge inputs.
TEST_P(PerIsa, EveryPathIsFiniteOnEdges)
{
    const pgloss_isa isa = GetParam();
    const Data d = make_data(3000, true);
    for (const auto &m : materials())
        for (int prec = 0; prec < 3; ++prec)
            for (bool sample : {false, true}) {
                const Out o = run(d, m, batch_options(static_cast<pgloss_precision>(prec), isa), sample);
                for (std::size_t j = 0; j < d.n; ++j) {
                    ASSERT_TRUE(std::isfinite(o.fr[j]) && std::isfinite(o.fg[j]) &&
                                std::isfinite(o.fb[j]) && std::isfinite(o.pdf[j]))
                        << "prec " << prec << " " << pgloss_isa_name(isa) << " j " << j;
                    ASSERT_GE(o.pdf[j], 0.0f);
                    if (sample) {
                        ASSERT_TRUE(std::isfinite(o.wx[j]) && std::isfinite(o.wy[j]) &&
                                    std::isfinite(o.wz[j]));
                    }
                }
            }
}

// FAST within its stated error of the double reference (the scalar functions) on regular
// inputs where the specular exponent is moderate (the error of any float exp grows with it).
// Unit directions (every renderer's) take the intrinsics blocks and the cancellation-free
// half vector: ~2.5e-7 per unit of exponent, below 4e-6 here (BENCHMARKS.md). Directions of
// other lengths are normalised first, and their rounding is amplified near the mirror
// direction by ~1/α (batch_isa.c): 1e-4 for them.
TEST_P(PerIsa, FastTierWithinStatedError)
{
    const pgloss_isa isa = GetParam();
    const Data unit = make_data(20000, false);
    Data scaled = unit;
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> len(0.25f, 4.0f);
    for (std::size_t j = 0; j < scaled.n; ++j) {
        const float a = len(rng), b = len(rng);
        scaled.ox[j] *= a, scaled.oy[j] *= a, scaled.oz[j] *= a;
        scaled.ix[j] *= b, scaled.iy[j] *= b, scaled.iz[j] *= b;
    }
    for (const auto &m : materials()) {
        if (m.alpha_x > 1.0f)
            continue; // the degenerate α = 3e38 material has no regular range
        for (const Data *d : std::initializer_list<const Data *>{&unit, &scaled}) {
            const double bound = d == &unit ? 4e-6 : 1e-4;
            const Out ref = run(*d, m, batch_options(PGLOSS_PRECISION_REFERENCE, PGLOSS_ISA_AUTO), false);
            const Out o = run(*d, m, batch_options(PGLOSS_PRECISION_FAST, isa), false);
            double worst = 0;
            for (std::size_t j = 0; j < d->n; ++j) {
                const double want = ref.fr[j];
                if (!(want > 1e-3 * (m.rho_d[0] + m.spec_scale)))
                    continue; // the far tail of the lobe: conditioning, not the tier
                worst = std::fmax(worst, std::fabs(o.fr[j] - want) / want);
                worst = std::fmax(worst, std::fabs(o.pdf[j] - ref.pdf[j]) / ref.pdf[j]);
            }
            EXPECT_LT(worst, bound) << pgloss_isa_name(isa);
            std::printf("fast tier, %s directions, %s, alpha %.3g/%.3g: max rel err %.2e\n",
                        d == &unit ? "unit" : "non-unit", pgloss_isa_name(isa), m.alpha_x,
                        m.alpha_y, worst);
        }
    }
}

// The FAST tier's SIMD block follows pgloss/inline.h's lobe step by step: on the same unit
// inputs it agrees with pgloss_eval_pdf_inline within the FAST tier's stated error (what
// differs is its degree-5 exp2 and the refined reciprocal estimates), on every ISA.
TEST_P(PerIsa, FastTierMatchesInlineFunction)
{
    const pgloss_isa isa = GetParam();
    const Data d = make_data(20000, false);
    for (const auto &m : materials()) {
        if (m.alpha_x > 1.0f)
            continue; // the degenerate α = 3e38 material has no regular range
        {
            const Out o = run(d, m, batch_options(PGLOSS_PRECISION_FAST, isa), false);
            double worst = 0;
            for (std::size_t j = 0; j < d.n; ++j) {
                pgloss_rgb f;
                float p;
                ASSERT_EQ(pgloss_eval_pdf_inline(&m, {d.ox[j], d.oy[j], d.oz[j]},
                                                 {d.ix[j], d.iy[j], d.iz[j]}, PGLOSS_LOBE_ALL, &f, &p),
                          PGLOSS_OK);
                if (!(f.r > 1e-3 * (m.rho_d[0] + m.spec_scale)))
                    continue; // the far tail of the lobe: conditioning, not the tier
                worst = std::fmax(worst, std::fabs(o.fr[j] - f.r) / f.r);
                worst = std::fmax(worst, std::fabs(o.fb[j] - f.b) / f.b);
                worst = std::fmax(worst, std::fabs(o.pdf[j] - p) / p);
            }
            EXPECT_LT(worst, 4e-6) << pgloss_isa_name(isa);
            std::printf("fast tier vs inline, %s, alpha %.3g/%.3g: max rel diff %.2e\n",
                        pgloss_isa_name(isa), m.alpha_x, m.alpha_y, worst);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Isa, PerIsa, ::testing::ValuesIn(kIsas),
                         [](const ::testing::TestParamInfo<pgloss_isa> &info) {
                             return std::string(pgloss_isa_name(info.param));
                         });

TEST(Isa, ReferenceTierIsTheScalarFunctions)
{
    const Data d = make_data(500, true);
    for (const auto &m : materials()) {
        const Out o = run(d, m, batch_options(PGLOSS_PRECISION_REFERENCE, PGLOSS_ISA_AUTO), false);
        for (std::size_t j = 0; j < d.n; ++j) {
            pgloss_rgb f;
            float p;
            pgloss_eval_pdf(&m, {d.ox[j], d.oy[j], d.oz[j]}, {d.ix[j], d.iy[j], d.iz[j]},
                            PGLOSS_LOBE_ALL, &f, &p);
            ASSERT_EQ(f.r, o.fr[j]);
            ASSERT_EQ(f.b, o.fb[j]);
            ASSERT_EQ(p, o.pdf[j]);
        }
        const Out s = run(d, m, batch_options(PGLOSS_PRECISION_REFERENCE, PGLOSS_ISA_AUTO), true);
        for (std::size_t j = 0; j < d.n; ++j) {
            const float u[3] = {d.u0[j], d.u1[j], d.u2[j]};
            pgloss_sample_record r;
            pgloss_sample(&m, {d.ox[j], d.oy[j], d.oz[j]}, u, PGLOSS_LOBE_ALL, &r);
            ASSERT_EQ(r.wi.x, s.wx[j]);
            ASSERT_EQ(r.pdf, s.pdf[j]);
            ASSERT_EQ(r.weight.g, s.fg[j]);
            ASSERT_EQ(r.lobe, s.lobe[j]);
        }
    }
}

TEST(Isa, BadOptionsAreArgumentErrors)
{
    const Data d = make_data(8, false);
    const pgloss_material m = materials()[0];
    Out o(d.n);
    const pgloss_strided3 wo = soa(d.ox.data(), d.oy.data(), d.oz.data());
    const pgloss_strided3_out f = soa_out(o.fr.data(), o.fg.data(), o.fb.data());
    const pgloss_strided_out pdf = col_out(o.pdf.data());
    const pgloss_batch_options bad_prec = batch_options(static_cast<pgloss_precision>(9));
    const pgloss_batch_options bad_isa = batch_options(PGLOSS_PRECISION_FLOAT, static_cast<pgloss_isa>(9));
    EXPECT_EQ(pgloss_eval_pdf_batch(&bad_prec, &m, nullptr, 3, d.n, wo, wo, f, pdf, nullptr), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_eval_pdf_batch(&bad_isa, &m, nullptr, 3, d.n, wo, wo, f, pdf, nullptr), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, d.n, wo, wo, no_out3(), no_out(), nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, d.n, wo, wo, no_out3(), pdf, nullptr), PGLOSS_OK);
    // An ISA the CPU lacks is an argument error, not a crash; where the CPU has every ISA
    // that path cannot be reached, and the test says so.
    int unsupported = 0;
    for (pgloss_isa isa : kIsas)
        if (!pgloss_isa_supported(isa)) {
            const pgloss_batch_options o2 = batch_options(PGLOSS_PRECISION_FLOAT, isa);
            EXPECT_EQ(pgloss_eval_pdf_batch(&o2, &m, nullptr, 3, d.n, wo, wo, f, pdf, nullptr),
                      PGLOSS_ERR_ARGUMENT);
            ++unsupported;
        }
    std::printf("unsupported-ISA argument error: %s\n",
                unsupported ? "checked" : "not reachable here (every ISA is supported)");
}

} // namespace
