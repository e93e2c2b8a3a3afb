// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// One rule at the model's boundaries, the same in every function: what one function
// returns with OK, every other function accepts. Each case here broke that before.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "batch_util.h"
#include "pgloss/inline.h"

namespace {

// The audit's example: L* 50, a* 0 and this b* put blue at −4.2e-13, within the boundary
// tolerance, so rgb_from_lab said OK while material_init refused the negative channel.
TEST(Boundaries, RgbFromLabWithinTheToleranceIsSnappedToTheGamutBoundary) {
    const double lab[3] = {50.0, 0.0, 55.96100838829443};
    double rgb[3];
    ASSERT_EQ(pgloss_rgb_from_lab(lab, rgb), PGLOSS_OK);
    for (double v : rgb) EXPECT_GE(v, 0.0);
    EXPECT_EQ(rgb[2], 0.0);  // the exact value is −4.2e-13

    const pgloss_perceptual q{50.0, 0.0, 55.96100838829443, 0.05, 0.95};
    pgloss_physical p;
    ASSERT_EQ(pgloss_check_perceptual(&q), PGLOSS_OK);
    ASSERT_EQ(pgloss_physical_from_perceptual(&q, PGLOSS_NORM_WARD, &p), PGLOSS_OK);
    EXPECT_EQ(pgloss_check_physical(&p), PGLOSS_OK);
    pgloss_material m;
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
}

TEST(Boundaries, EveryOkColourNearTheGamutBoundaryMakesAMaterial) {
    // Walk b* across the blue channel's zero for random L*, a*: whatever rgb_from_lab accepts
    // has no negative channel, and physical_from_perceptual's result makes a material.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    int ok = 0, gamut = 0;
    for (int i = 0; i < 20000; ++i) {
        const double L = 5 + 90 * U(rng), a = -20 + 40 * U(rng);
        // Bisect b* for blue = 0 (blue falls as b* grows), then step by a few ulps around it.
        double lo = 0, hi = 300;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi), lab[3] = {L, a, mid};
            double rgb[3];
            pgloss_rgb_from_lab(lab, rgb);
            (rgb[2] >= 0 ? lo : hi) = mid;
        }
        const double b = std::nextafter(lo, (i & 1) ? 1e9 : -1e9) + (i % 7 - 3) * 1e-14 * lo;
        const double lab[3] = {L, a, b};
        double rgb[3];
        const pgloss_status s = pgloss_rgb_from_lab(lab, rgb);
        if (s == PGLOSS_ERR_GAMUT) {
            ++gamut;
            continue;
        }
        ASSERT_EQ(s, PGLOSS_OK) << L << " " << a << " " << b;
        ++ok;
        for (double v : rgb) ASSERT_GE(v, 0.0) << L << " " << a << " " << b;
        const pgloss_perceptual q{L, a, b, 0.0, 0.95};
        pgloss_physical p;
        if (pgloss_physical_from_perceptual(&q, PGLOSS_NORM_WARD, &p) < 0) continue;  // other reasons
        pgloss_material m;
        ASSERT_GE(pgloss_material_init(&m, &p), 0) << L << " " << a << " " << b;
        ASSERT_NE(pgloss_check_physical(&p), PGLOSS_ERR_NEGATIVE) << L << " " << a << " " << b;  // ENERGY may be
    }
    std::printf("near the blue gamut boundary: %d OK, %d out of gamut\n", ok, gamut);
    EXPECT_GT(ok, 1000);
}

// d = 1 − α rounds to 1 for α ≤ 2^-54, and eq. 8 rejects d = 1: gloss_from_physical must not
// return a d that its own inverse refuses.
TEST(Boundaries, TinyAlphaGivesADoiThatEq8Accepts) {
    for (double alpha : {1e-300, 1e-20, 0x1p-54, 0x1p-53, 1e-16, 1e-8}) {
        double L, c, d;
        ASSERT_EQ(pgloss_gloss_from_physical(0.2, 0.05, alpha, &L, &c, &d), PGLOSS_OK) << alpha;
        EXPECT_LT(d, 1.0) << alpha;
        EXPECT_LE(std::fabs(d - (1.0 - alpha)), 0x1p-53) << alpha;  // within an ulp of 1 − α
        double rd, rs, a2;
        ASSERT_EQ(pgloss_physical_from_gloss(L, c, d, &rd, &rs, &a2), PGLOSS_OK) << alpha;
        EXPECT_GT(a2, 0.0) << alpha;
        const pgloss_physical p{{0.2, 0.2, 0.2}, 0.05, alpha, alpha, PGLOSS_NORM_WARD};
        pgloss_perceptual q;
        ASSERT_EQ(pgloss_perceptual_from_physical(&p, &q), PGLOSS_OK) << alpha;
        EXPECT_LT(q.d, 1.0) << alpha;
        pgloss_physical back;
        EXPECT_GE(pgloss_physical_from_perceptual(&q, PGLOSS_NORM_WARD, &back), 0) << alpha;
    }
}

// Grazing directions (cosines 1e-20, 1e-25): the float paths squared the half vector before
// scaling it, so it underflowed; FAST on AVX2 met Inf − Inf and returned FLT_MAX. Every tier and
// ISA must agree with the double reference there. Narrowed: below ~1e-28
// h/hzc squared is subnormal and the pdf's specular part (< 1e-32 there) loses digits.
TEST(Boundaries, GrazingMirrorDirectionsAgreeWithTheReference) {
    for (pgloss_normalization norm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED}) {
        const pgloss_physical p{{0.2, 0.2, 0.2}, 0.3, 0.1, 0.1, norm};
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        for (float c : {1e-20f, 1e-25f}) {
            const float s = 1.0f;  // (±1, 0, c) is a float unit vector: |v|² rounds to 1
            pgloss_rgb f;
            float pdf;
            ASSERT_EQ(pgloss_eval_pdf(&m, {s, 0, c}, {-s, 0, c}, PGLOSS_LOBE_ALL, &f, &pdf), PGLOSS_OK);
            const size_t n = 40;  // whole SIMD blocks and a tail
            std::vector<float> ox(n, s), oy(n, 0), oz(n, c), ix(n, -s), iy(n, 0), iz(n, c);
            for (pgloss_precision tier : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST})
                for (pgloss_isa isa : {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512}) {
                    if (!pgloss_isa_supported(isa)) continue;  // test_isa reports which ISAs ran
                    const pgloss_batch_options opt = batch_options(tier, isa);
                    std::vector<float> fr(n), fg(n), fb(n), pd(n);
                    ASSERT_EQ(pgloss_eval_pdf_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, n, soa(ox.data(), oy.data(), oz.data()),
                                                    soa(ix.data(), iy.data(), iz.data()),
                                                    soa_out(fr.data(), fg.data(), fb.data()), col_out(pd.data()), nullptr),
                              PGLOSS_OK);
                    for (size_t k = 0; k < n; ++k) {
                        ASSERT_NEAR(fr[k], f.r, 1e-5 * f.r) << norm << " " << c << " " << tier << " " << isa;
                        ASSERT_NEAR(pd[k], pdf, 1e-5 * pdf) << norm << " " << c << " " << tier << " " << isa;
                    }
                }
        }
    }
}

// Grazing, not mirrored: both cosines down to the subnormals (1e-20 … 1e-40), the half vector
// tilted by tanδ = 0.05 · k from the normal (k = 1, 4, 8: e = exp(−0.25 k²) with α = 0.1). The
// float paths floored the exponent's h.z at 1.1e-19, so below it tan²δ came out too small and
// f too large (3.98e10 against the reference's 0.55). Every path, tier and ISA must
// agree with the double reference: within 1e-5 of f and of the pdf, the float inputs being the
// same, but for the pdf's specular part (hhs/hzc, below 1e-30 here), which float computes from
// subnormals (docs/kernels.md): 1e-33 absolute.
TEST(Boundaries, GrazingTiltedDirectionsAgreeWithTheReference) {
    for (pgloss_normalization norm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED}) {
        const pgloss_physical p{{0.2, 0.2, 0.2}, 0.3, 0.1, 0.1, norm};
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        for (float c : {1e-20f, 1e-25f, 1e-30f, 1e-36f, 1e-40f})
            for (float k : {1.0f, 4.0f, 8.0f}) {
                // h = o + i = (0, 0.1 k c, 2c): hy / hz = 0.05 k
                const pgloss_vec3 o{1.0f, 0.05f * k * c, c}, i{-1.0f, 0.05f * k * c, c};
                pgloss_rgb f;
                float pdf;
                ASSERT_EQ(pgloss_eval_pdf(&m, o, i, PGLOSS_LOBE_ALL, &f, &pdf), PGLOSS_OK);
                ASSERT_GT(f.r, 0.2f / 3.1416f) << "the specular lobe is there";
                pgloss_rgb fi;
                float pi;
                ASSERT_EQ(pgloss_eval_pdf_inline(&m, o, i, PGLOSS_LOBE_ALL, &fi, &pi), PGLOSS_OK);
                EXPECT_NEAR(fi.r, f.r, 1e-5 * f.r) << "inline " << norm << " c " << c << " k " << k;
                EXPECT_NEAR(pi, pdf, 1e-5 * pdf + 1e-33) << "inline " << norm << " c " << c << " k " << k;
                const size_t n = 40;  // whole SIMD blocks and a tail
                std::vector<float> ox(n, o.x), oy(n, o.y), oz(n, o.z), ix(n, i.x), iy(n, i.y), iz(n, i.z);
                for (pgloss_precision tier : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST})
                    for (pgloss_isa isa : {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512}) {
                        if (!pgloss_isa_supported(isa)) continue;  // test_isa reports which ISAs ran
                        const pgloss_batch_options opt = batch_options(tier, isa);
                        std::vector<float> fr(n), fg(n), fb(n), pd(n);
                        ASSERT_EQ(pgloss_eval_pdf_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, n,
                                                        soa(ox.data(), oy.data(), oz.data()),
                                                        soa(ix.data(), iy.data(), iz.data()),
                                                        soa_out(fr.data(), fg.data(), fb.data()), col_out(pd.data()),
                                                        nullptr),
                                  PGLOSS_OK);
                        for (size_t j = 0; j < n; ++j) {
                            ASSERT_NEAR(fr[j], f.r, 1e-5 * f.r)
                                << norm << " c " << c << " k " << k << " tier " << tier << " " << pgloss_isa_name(isa);
                            ASSERT_NEAR(pd[j], pdf, 1e-5 * pdf + 1e-33)
                                << norm << " c " << c << " k " << k << " tier " << tier << " " << pgloss_isa_name(isa);
                        }
                    }
            }
    }
}

// brdf.h states f(wo, wi) = f(wi, wo) without condition. The audit found it off by 6e-6 for an
// anisotropic lobe at cos 1e-8; every path must be exactly reciprocal, grazing and non-unit
// directions included.
TEST(Boundaries, ReciprocityIsExactForAnisotropicLobesAtGrazingAngles) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> U(0.0f, 1.0f);
    int checked = 0;
    for (float ax : {0.05f, 0.3f})
        for (float ay : {0.01f, 0.2f}) {
            const pgloss_physical p{{0.2, 0.2, 0.2}, 0.3, ax, ay, PGLOSS_NORM_WARD};
            pgloss_material m;
            ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
            for (int k = 0; k < 3000; ++k) {
                const float c1 = k % 3 == 0 ? 1e-8f : k % 3 == 1 ? 1e-4f : U(rng), c2 = U(rng);
                const float s1 = std::sqrt(1 - c1 * c1), s2 = std::sqrt(1 - c2 * c2);
                const float p1 = 6.2831853f * U(rng), p2 = 6.2831853f * U(rng), sc = k % 2 ? 3.0f : 1.0f;
                const pgloss_vec3 a{sc * s1 * std::cos(p1), sc * s1 * std::sin(p1), sc * c1};
                const pgloss_vec3 b{s2 * std::cos(p2) / sc, s2 * std::sin(p2) / sc, c2 / sc};
                pgloss_rgb f1, f2;
                ASSERT_EQ(pgloss_eval(&m, a, b, PGLOSS_LOBE_ALL, &f1), PGLOSS_OK);
                ASSERT_EQ(pgloss_eval(&m, b, a, PGLOSS_LOBE_ALL, &f2), PGLOSS_OK);
                ASSERT_EQ(f1.r, f2.r) << ax << " " << ay << " " << k;
                const float X[2] = {a.x, b.x}, Y[2] = {a.y, b.y}, Z[2] = {a.z, b.z};
                const float X2[2] = {b.x, a.x}, Y2[2] = {b.y, a.y}, Z2[2] = {b.z, a.z};
                float R[2], G[2], B[2];
                ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, 2, soa(X, Y, Z), soa(X2, Y2, Z2),
                                                soa_out(R, G, B), no_out(), nullptr),
                          PGLOSS_OK);
                ASSERT_EQ(R[0], R[1]) << ax << " " << ay << " " << k;
                ++checked;
            }
        }
    std::printf("reciprocity exact (scalar and batch) on %d anisotropic pairs, cosines down to 1e-8\n", checked);
}

}  // namespace
