// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Per-element materials, the double batch path and the batched perceptual functions
// (pgloss/batch.h, pgloss/perceptual_batch.h) against their one-at-a-time definitions: a
// per-element call equals, element by element, the batch called with that element's
// pgloss_material (bit for bit in the FLOAT tier, on every ISA the CPU has); the double path
// agrees with the scalar double reference; statuses per element; n = 0, tails; and every
// layout of the strided arrays (rows, columns, broadcast, negative and odd strides, unaligned)
// gives the bits of plain columns. The shared vectors run through the same entry points in
// test_vectors.cpp. An ISA this CPU or build lacks is GTEST_SKIPped with the reason
// (a hardware property, as in test_isa.cpp; PGLOSS_REQUIRE_ISA makes it a failure).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "batch_util.h"

namespace {

const pgloss_isa kIsas[] = {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512};

bool isa_required(pgloss_isa isa) {
    const char *r = std::getenv("PGLOSS_REQUIRE_ISA");
    if (!r) return false;
    const std::string s(r);
    return s == "all" || s.find(pgloss_isa_name(isa)) != std::string::npos;
}

// A texture of materials with some invalid ones, and directions (a few invalid), with one
// element of padding in front of every array (unaligned).
struct Tex {
    size_t n;
    std::vector<float> m[6];  // rho_d r, g, b, rho_s, alpha_x, alpha_y
    std::vector<float> o[3], i[3], u[3];
    Tex(size_t n_, bool invalid, unsigned seed = 7) : n(n_) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> uni(0.0f, 1.0f);
        for (auto *v : {&m[0], &m[1], &m[2], &m[3], &m[4], &m[5], &o[0], &o[1], &o[2], &i[0], &i[1], &i[2], &u[0],
                        &u[1], &u[2]})
            v->assign(n + 1, 0.0f);
        for (size_t j = 1; j <= n; ++j) {
            for (int k = 0; k < 3; ++k) m[k][j] = 0.8f * uni(rng);
            m[3][j] = 0.2f * uni(rng);
            m[4][j] = 0.001f + 0.3f * uni(rng) * uni(rng);
            m[5][j] = (j % 3) ? m[4][j] : 0.001f + 0.3f * uni(rng);
            if (j % 11 == 0) m[0][j] = m[1][j] = m[2][j] = 0.0f;  // specular only
            if (j % 13 == 0) m[3][j] = 0.0f;                      // diffuse only
            if (j % 17 == 0) m[4][j] = 1e-7f;                     // below PGLOSS_ALPHA_MIN
            if (j % 29 == 0) m[0][j] = m[1][j] = m[2][j] = m[3][j] = 0.0f;  // black
            auto dir = [&](std::vector<float> *v) {
                const float c = 0.05f + 0.95f * uni(rng), p = 6.2831853f * uni(rng);
                const float s = std::sqrt(1.0f - c * c);
                v[0][j] = s * std::cos(p);
                v[1][j] = s * std::sin(p);
                v[2][j] = c;
            };
            dir(o);
            dir(i);
            if (j % 7 == 0) i[2][j] = -i[2][j];  // below the horizon
            for (auto &k : u) k[j] = uni(rng);
            if (invalid) {
                if (j % 19 == 0) m[3][j] = -0.1f;            // NEGATIVE
                if (j % 23 == 0) m[4][j] = 0.0f;             // ALPHA
                if (j % 31 == 0) m[1][j] = INFINITY;         // NONFINITE
                if (j % 37 == 0) o[0][j] = o[1][j] = o[2][j] = 0.0f;  // DIRECTION
                if (j % 41 == 0) i[1][j] = NAN;              // DIRECTION
                if (j % 43 == 0) u[1][j] = NAN;              // RANDOM
            }
        }
    }
    pgloss_physical_array mats(pgloss_normalization nm) const {
        return physical_cols(m[0].data() + 1, m[1].data() + 1, m[2].data() + 1, m[3].data() + 1, m[4].data() + 1,
                             m[5].data() + 1, nm);
    }
    pgloss_strided3 wo(size_t j = 0) const { return soa(o[0].data() + 1 + j, o[1].data() + 1 + j, o[2].data() + 1 + j); }
    pgloss_strided3 wi(size_t j = 0) const { return soa(i[0].data() + 1 + j, i[1].data() + 1 + j, i[2].data() + 1 + j); }
    pgloss_strided3 us(size_t j = 0) const { return soa(u[0].data() + 1 + j, u[1].data() + 1 + j, u[2].data() + 1 + j); }
    pgloss_physical phys(size_t j, pgloss_normalization nm) const {
        pgloss_physical p;
        p.rho_d[0] = m[0][j + 1], p.rho_d[1] = m[1][j + 1], p.rho_d[2] = m[2][j + 1];
        p.rho_s = m[3][j + 1], p.alpha_x = m[4][j + 1], p.alpha_y = m[5][j + 1];
        p.normalization = nm;
        return p;
    }
};

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

class PerIsa : public ::testing::TestWithParam<pgloss_isa> {
protected:
    void SetUp() override {
        if (!pgloss_isa_supported(GetParam())) {
            if (isa_required(GetParam())) FAIL() << pgloss_isa_name(GetParam()) << " required but not supported";
            GTEST_SKIP() << pgloss_isa_name(GetParam()) << ": not supported by this CPU or build";
        }
    }
};

// Element j of a per-element call = the uniform batch on element j's material, in every tier
// (bit for bit in FLOAT and REFERENCE, within FAST's rounding in FAST). Sizes cover n < chunk,
// tails and several chunks.
TEST_P(PerIsa, EvalPdfMaterialsEqualsOneMaterialPerCall) {
    for (size_t n : {size_t(1), size_t(7), size_t(300), size_t(1031)}) {
        const Tex t(n, true);
        for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED})
            for (unsigned lobes : {1u, 2u, 3u})
                for (pgloss_precision prec : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST, PGLOSS_PRECISION_REFERENCE}) {
                    const pgloss_batch_options opt = batch_options(prec, GetParam());
                    const pgloss_physical_array ma = t.mats(nm);
                    std::vector<float> r(n), g(n), b(n), p(n);
                    std::vector<signed char> st(n);
                    const pgloss_status all =
                        pgloss_eval_pdf_batch(&opt, nullptr, &ma, lobes, n, t.wo(), t.wi(),
                                              soa_out(r.data(), g.data(), b.data()), col_out(p.data()), st.data());
                    pgloss_status first = PGLOSS_OK;
                    for (size_t j = 0; j < n; ++j) {
                        const pgloss_physical ph = t.phys(j, nm);
                        pgloss_material mj;
                        const pgloss_status ms = pgloss_material_init(&mj, &ph);
                        float r1, g1, b1, p1;
                        const pgloss_batch_options opt1 = batch_options(prec, GetParam());
                        const pgloss_status ds = pgloss_eval_pdf_batch(&opt1, &mj, nullptr, lobes, 1, t.wo(j), t.wi(j),
                                                                       soa_out(&r1, &g1, &b1), col_out(&p1), nullptr);
                        const pgloss_status want = ms != PGLOSS_OK ? ms : ds;
                        if (first == PGLOSS_OK) first = want;
                        ASSERT_EQ(st[j], static_cast<signed char>(want)) << "element " << j << " n " << n;
                        if (ms != PGLOSS_OK) {
                            EXPECT_TRUE(r[j] == 0 && g[j] == 0 && b[j] == 0 && p[j] == 0) << "invalid material " << j;
                            continue;
                        }
                        if (prec == PGLOSS_PRECISION_FAST) {
                            // FAST fuses multiply-adds, the per-element set-up's too: its
                            // constants may be an ulp from material_init's
                            for (const auto &q : {std::make_pair(r[j], r1), std::make_pair(b[j], b1),
                                                  std::make_pair(p[j], p1)})
                                ASSERT_NEAR(q.first, q.second, 1e-6 * q.second) << "element " << j << " n " << n;
                            continue;
                        }
                        ASSERT_TRUE(same_bits(r[j], r1) && same_bits(g[j], g1) && same_bits(b[j], b1) && same_bits(p[j], p1))
                            << "element " << j << " n " << n << " norm " << nm << " lobes " << lobes << " prec " << prec
                            << ": " << r[j] << " " << p[j] << " vs " << r1 << " " << p1;
                    }
                    EXPECT_EQ(all, first);
                }
    }
}

TEST_P(PerIsa, SampleMaterialsEqualsOneMaterialPerCall) {
    for (size_t n : {size_t(5), size_t(300), size_t(777)}) {
        const Tex t(n, true, 11);
        for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_BOUNDED})
            for (unsigned lobes : {1u, 2u, 3u})
                for (pgloss_precision prec : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_REFERENCE}) {
                    const pgloss_batch_options opt = batch_options(prec, GetParam());
                    const pgloss_physical_array ma = t.mats(nm);
                    std::vector<float> x(n), y(n), z(n), p(n), r(n), g(n), b(n);
                    std::vector<unsigned char> lb(n);
                    std::vector<signed char> st(n);
                    const pgloss_status all = pgloss_sample_batch(
                        &opt, nullptr, &ma, lobes, n, t.wo(), t.us(), soa_out(x.data(), y.data(), z.data()),
                        col_out(p.data()), soa_out(r.data(), g.data(), b.data()), lb.data(), st.data());
                    pgloss_status first = PGLOSS_OK;
                    for (size_t j = 0; j < n; ++j) {
                        const pgloss_physical ph = t.phys(j, nm);
                        pgloss_material mj;
                        const pgloss_status ms = pgloss_material_init(&mj, &ph);
                        float x1, y1, z1, p1, r1, g1, b1;
                        unsigned char l1;
                        const pgloss_status ds =
                            pgloss_sample_batch(&opt, &mj, nullptr, lobes, 1, t.wo(j), t.us(j), soa_out(&x1, &y1, &z1),
                                                col_out(&p1), soa_out(&r1, &g1, &b1), &l1, nullptr);
                        const pgloss_status want = ms != PGLOSS_OK ? ms : ds;
                        if (first == PGLOSS_OK) first = want;
                        ASSERT_EQ(st[j], static_cast<signed char>(want)) << "element " << j;
                        ASSERT_TRUE(same_bits(x[j], x1) && same_bits(y[j], y1) && same_bits(z[j], z1) &&
                                    same_bits(p[j], p1) && same_bits(r[j], r1) && same_bits(g[j], g1) &&
                                    same_bits(b[j], b1) && lb[j] == l1)
                            << "element " << j << " n " << n << " lobes " << lobes << " prec " << prec;
                    }
                    EXPECT_EQ(all, first);
                }
    }
}

// The double path: per element = one material per call (the same double loops), and both
// within the header's 1e-12 of the scalar reference where the material's constants are the
// same (the scalar reference rounds them to float, 1/α included, whose error the exponent
// multiplies: compared at the vectors' float tolerance, 1e-5, there), on every ISA.
TEST_P(PerIsa, DoublePathAgreesWithScalarReference) {
    const size_t n = 1000;
    const Tex t(n, true, 5);
    std::vector<double> d[9];
    for (int k = 0; k < 3; ++k) {
        d[k].assign(t.o[k].begin() + 1, t.o[k].end());
        d[3 + k].assign(t.i[k].begin() + 1, t.i[k].end());
    }
    std::vector<double> mm[6];
    for (int k = 0; k < 6; ++k) mm[k].assign(t.m[k].begin() + 1, t.m[k].end());
    const pgloss_batch_options opt = batch_options(PGLOSS_PRECISION_FLOAT, GetParam(), PGLOSS_FLOAT64);
    for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED}) {
        const pgloss_physical_array pa =
            physical_cols(mm[0].data(), mm[1].data(), mm[2].data(), mm[3].data(), mm[4].data(), mm[5].data(), nm);
        std::vector<double> r(n), g(n), b(n), p(n);
        std::vector<signed char> st(n);
        pgloss_eval_pdf_batch(&opt, nullptr, &pa, PGLOSS_LOBE_ALL, n, soa(d[0].data(), d[1].data(), d[2].data()),
                              soa(d[3].data(), d[4].data(), d[5].data()), soa_out(r.data(), g.data(), b.data()),
                              col_out(p.data()), st.data());
        for (size_t j = 0; j < n; ++j) {
            const pgloss_physical ph = t.phys(j, nm);
            pgloss_material mj;
            const pgloss_status ms = pgloss_material_init(&mj, &ph);
            double r1, g1, b1, p1;
            signed char s1;
            const pgloss_status ds = pgloss_eval_pdf_batch(
                &opt, &mj, nullptr, PGLOSS_LOBE_ALL, 1, soa(&d[0][j], &d[1][j], &d[2][j]), soa(&d[3][j], &d[4][j], &d[5][j]),
                soa_out(&r1, &g1, &b1), col_out(&p1), &s1);
            ASSERT_EQ(st[j], static_cast<signed char>(ms != PGLOSS_OK ? ms : ds)) << j;
            if (ms != PGLOSS_OK) {
                EXPECT_TRUE(r[j] == 0 && p[j] == 0);
                continue;
            }
            // the float material holds the same (float) values, so the double constants agree
            EXPECT_EQ(r[j], r1) << j;
            EXPECT_EQ(g[j], g1) << j;
            EXPECT_EQ(p[j], p1) << j;
            pgloss_rgb fs;
            float ps;
            const pgloss_vec3 o{t.o[0][j + 1], t.o[1][j + 1], t.o[2][j + 1]}, i{t.i[0][j + 1], t.i[1][j + 1], t.i[2][j + 1]};
            ASSERT_EQ(pgloss_eval_pdf(&mj, o, i, PGLOSS_LOBE_ALL, &fs, &ps), ds);
            EXPECT_NEAR(r[j], fs.r, 1e-5 * std::fabs(fs.r) + 1e-30) << j;
            EXPECT_NEAR(p[j], ps, 1e-5 * std::fabs(ps) + 1e-30) << j;
        }
    }
}

// The double sampler (chunked and vectorised, batch_d_isa.c): per element = one material per
// call (bit for bit), every ISA = the baseline ISA (AVX2 and AVX-512 fuse the multiply-adds
// that lobe_d.h writes as PGLOSS__D_MADD: the same statuses and lobes, wi within the header's
// 1e-12, and pdf and weight within 1e-12 relative of the baseline's eval_pdf at the wi drawn,
// where a sharp lobe's conditioning does not multiply wi's last bits; bit for bit between
// AVX2 and AVX-512, which fuse the same ones),
// pdf and weight = the double eval_pdf at the wi drawn, and the scalar pgloss_sample (double
// inside, float constants and outputs): the same lobe, wi to float rounding,
// on inputs that reach every rule: NaN and out-of-range random numbers (clamped to
// [0, 1 - 2^-24]), wo zero, NaN, huge, tiny or below the horizon, invalid and black materials,
// sizes below, at and across the chunk.
TEST_P(PerIsa, DoubleSamplerEqualsOneMaterialPerCallScalarAndBaseline) {
    for (size_t n : {size_t(1), size_t(129), size_t(1031)}) {
        const Tex t(n, true, 13);
        std::vector<double> o[3], u[3], mm[6];
        for (int k = 0; k < 3; ++k) {
            o[k].assign(t.o[k].begin() + 1, t.o[k].end());
            u[k].assign(t.u[k].begin() + 1, t.u[k].end());
        }
        for (int k = 0; k < 6; ++k) mm[k].assign(t.m[k].begin() + 1, t.m[k].end());
        for (size_t j = 0; j < n; ++j) {
            if (j % 5 == 1) u[0][j] = 0.0;
            if (j % 6 == 2) u[1][j] = 1.0;  // clamped to 1 - 2^-24: the longest tail of the lobe
            if (j % 8 == 3) u[2][j] = 1.0;
            if (j % 9 == 4) u[1][j] = -0.5;
            if (j % 10 == 5) u[0][j] = 2.0;
            if (j % 12 == 6) u[1][j] = u[2][j] = 0.5;  // the concentric map's centre
            if (j % 47 == 7) o[0][j] *= 1e200, o[1][j] *= 1e200, o[2][j] *= 1e200;
            if (j % 53 == 8) o[0][j] *= 1e-200, o[1][j] *= 1e-200, o[2][j] *= 1e-200;
            if (j % 59 == 9) o[2][j] = -o[2][j];
            if (j % 61 == 10) o[2][j] = NAN;
        }
        const pgloss_strided3 wo = soa(o[0].data(), o[1].data(), o[2].data());
        for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED})
            for (unsigned lobes : {1u, 2u, 3u}) {
                const pgloss_physical_array pa =
                    physical_cols(mm[0].data(), mm[1].data(), mm[2].data(), mm[3].data(), mm[4].data(), mm[5].data(), nm);
                struct Out {
                    std::vector<double> v[7];
                    std::vector<unsigned char> lb;
                    std::vector<signed char> st;
                    pgloss_status all;
                };
                auto run = [&](pgloss_isa isa) {
                    Out r;
                    for (auto &v : r.v) v.assign(n, -7.0);
                    r.lb.assign(n, 77);
                    r.st.assign(n, 99);
                    const pgloss_batch_options opt = batch_options(PGLOSS_PRECISION_FLOAT, isa, PGLOSS_FLOAT64);
                    r.all = pgloss_sample_batch(&opt, nullptr, &pa, lobes, n, wo, soa(u[0].data(), u[1].data(), u[2].data()),
                                                soa_out(r.v[0].data(), r.v[1].data(), r.v[2].data()), col_out(r.v[3].data()),
                                                soa_out(r.v[4].data(), r.v[5].data(), r.v[6].data()), r.lb.data(),
                                                r.st.data());
                    return r;
                };
                const Out a = run(GetParam()), base = run(PGLOSS_ISA_BASELINE);
                EXPECT_EQ(a.all, base.all);
                // the baseline's f and pdf at the wi that GetParam()'s sampler drew
                std::vector<double> bf[3], bp(n);
                for (auto &v : bf) v.assign(n, 0.0);
                const pgloss_batch_options base_opt =
                    batch_options(PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_BASELINE, PGLOSS_FLOAT64);
                pgloss_eval_pdf_batch(&base_opt, nullptr, &pa, lobes, n, wo,
                                      soa(a.v[0].data(), a.v[1].data(), a.v[2].data()),
                                      soa_out(bf[0].data(), bf[1].data(), bf[2].data()), col_out(bp.data()), nullptr);
                for (size_t j = 0; j < n; ++j) {
                    ASSERT_EQ(a.st[j], base.st[j]) << j;
                    ASSERT_EQ(a.lb[j], base.lb[j]) << j;
                    for (int k = 0; k < 3; ++k) ASSERT_NEAR(a.v[k][j], base.v[k][j], 1e-12) << "wi " << k << " element " << j;
                    if (!(a.v[3][j] > 0.0)) {
                        ASSERT_EQ(a.v[3][j], base.v[3][j]) << j;
                        continue;
                    }
                    ASSERT_NEAR(a.v[3][j], bp[j], 1e-12 * bp[j]) << "pdf, element " << j;
                    const double c = a.v[2][j] / std::sqrt(a.v[0][j] * a.v[0][j] + a.v[1][j] * a.v[1][j] + a.v[2][j] * a.v[2][j]);
                    for (int k = 0; k < 3; ++k)
                        ASSERT_NEAR(a.v[4 + k][j], bf[k][j] * c / bp[j], 1e-12 * a.v[4 + k][j] + 1e-300)
                            << "weight " << k << " element " << j;
                }
                if (GetParam() == PGLOSS_ISA_AVX512 && pgloss_isa_supported(PGLOSS_ISA_AVX2)) {
                    const Out b = run(PGLOSS_ISA_AVX2);
                    for (size_t j = 0; j < n; ++j)
                        for (int k = 0; k < 7; ++k) ASSERT_EQ(a.v[k][j], b.v[k][j]) << "output " << k << " element " << j;
                }
                const pgloss_batch_options opt = batch_options(PGLOSS_PRECISION_FLOAT, GetParam(), PGLOSS_FLOAT64);
                size_t compared = 0;
                for (size_t j = 0; j < n; ++j) {
                    const pgloss_physical ph = t.phys(j, nm);
                    pgloss_material mj;
                    const pgloss_status ms = pgloss_material_init(&mj, &ph);
                    if (ms != PGLOSS_OK) {
                        ASSERT_EQ(a.st[j], static_cast<signed char>(ms)) << j;
                        EXPECT_TRUE(a.v[0][j] == 0 && a.v[1][j] == 0 && a.v[2][j] == 1 && a.v[3][j] == 0 &&
                                    a.v[4][j] == 0 && a.lb[j] == PGLOSS_LOBE_NONE)
                            << j;
                        continue;
                    }
                    double v1[7];
                    unsigned char l1 = 77;
                    signed char s1 = 99;
                    const pgloss_strided3 o1 = soa(&o[0][j], &o[1][j], &o[2][j]);
                    const pgloss_status ds = pgloss_sample_batch(
                        &opt, &mj, nullptr, lobes, 1, o1, soa(&u[0][j], &u[1][j], &u[2][j]), soa_out(&v1[0], &v1[1], &v1[2]),
                        col_out(&v1[3]), soa_out(&v1[4], &v1[5], &v1[6]), &l1, &s1);
                    ASSERT_EQ(ds, static_cast<pgloss_status>(s1));
                    ASSERT_EQ(a.st[j], s1) << j;
                    ASSERT_EQ(a.lb[j], l1) << j;
                    for (int k = 0; k < 7; ++k) ASSERT_EQ(a.v[k][j], v1[k]) << "output " << k << " element " << j;
                    for (int k = 0; k < 7; ++k) ASSERT_TRUE(std::isfinite(a.v[k][j])) << j;
                    // the scalar function: float inputs only (wo scaled by 1e±200 is not a float)
                    if (j % 47 == 7 || j % 53 == 8) continue;
                    const float uf[3] = {static_cast<float>(u[0][j]), static_cast<float>(u[1][j]), static_cast<float>(u[2][j])};
                    pgloss_sample_record sr;
                    const pgloss_status ss =
                        pgloss_sample(&mj, pgloss_vec3{static_cast<float>(o[0][j]), static_cast<float>(o[1][j]), static_cast<float>(o[2][j])}, uf, lobes, &sr);
                    ASSERT_EQ(static_cast<signed char>(ss), a.st[j]) << j;
                    ASSERT_EQ(static_cast<unsigned>(a.lb[j]), sr.lobe) << j;
                    if (ss != PGLOSS_OK) continue;
                    EXPECT_NEAR(a.v[0][j], sr.wi.x, 2e-6) << j;
                    EXPECT_NEAR(a.v[1][j], sr.wi.y, 2e-6) << j;
                    EXPECT_NEAR(a.v[2][j], sr.wi.z, 2e-6) << j;
                    // pdf and weight: the double eval_pdf at the wi drawn gives the pdf and
                    // weight = f cosθi / pdf; the scalar function (float constants, evaluated at
                    // the float wi: a sharp lobe amplifies that rounding) agrees to 1e-2, away
                    // from the horizon and the rejection borders, where a rounding of wi decides
                    if (a.v[3][j] > 0.0) {
                        double f[3], pe;
                        ASSERT_EQ(pgloss_eval_pdf_batch(&opt, &mj, nullptr, lobes, 1, o1,
                                                        soa(&a.v[0][j], &a.v[1][j], &a.v[2][j]),
                                                        soa_out(&f[0], &f[1], &f[2]), col_out(&pe), nullptr),
                                  PGLOSS_OK);
                        const double c = a.v[2][j] / std::sqrt(a.v[0][j] * a.v[0][j] + a.v[1][j] * a.v[1][j] + a.v[2][j] * a.v[2][j]);
                        EXPECT_NEAR(a.v[3][j], pe, 1e-12 * pe) << j;
                        EXPECT_NEAR(a.v[4][j], f[0] * c / pe, 1e-12 * a.v[4][j] + 1e-300) << j;
                        EXPECT_NEAR(a.v[6][j], f[2] * c / pe, 1e-12 * a.v[6][j] + 1e-300) << j;
                    }
                    if (sr.pdf > 0.0f && a.v[3][j] > 0.0 && sr.wi.z > 1e-3f) {
                        EXPECT_NEAR(a.v[3][j], sr.pdf, 1e-2 * sr.pdf) << j;
                        EXPECT_NEAR(a.v[4][j], sr.weight.r, 1e-2 * sr.weight.r + 1e-30) << j;
                        EXPECT_NEAR(a.v[6][j], sr.weight.b, 1e-2 * sr.weight.b + 1e-30) << j;
                        ++compared;
                    }
                }
                EXPECT_GE(compared, n / 4) << "n " << n << " lobes " << lobes;
            }
    }
}

// ---- strided arrays: every layout gives the bits of plain columns -----------------------------

// k values per element (k = 1 or 3) of type T in a byte buffer, in one of these layouts:
// columns, (n, k) rows, rows in reverse order (a negative stride), rows at an odd stride from an
// odd address (unaligned), packed rows from an odd address (the library's wide de-interleave
// of float rows, unaligned), or one value for every element (stride 0, inputs only).
enum Layout { kColumns, kRows, kReversed, kOdd, kRowsOdd, kBroadcast };

template <class T>
struct Laid {
    std::vector<unsigned char> buf;
    ptrdiff_t stride = 0;
    size_t off[3] = {0, 0, 0};
    size_t k;
    Laid(size_t n, size_t k_, Layout l, unsigned char fill = 0xab) : k(k_) {
        const size_t sz = sizeof(T), rows = l == kBroadcast ? 1 : n;
        size_t total = 0;
        if (l == kColumns) {
            stride = static_cast<ptrdiff_t>(sz);
            for (size_t c = 0; c < k; ++c) off[c] = c * (rows * sz + 8);
            total = k * (rows * sz + 8);
        } else {
            const size_t row = l == kOdd ? k * sz + 1 : k * sz;
            const size_t first = l == kOdd || l == kRowsOdd ? 1 : 0;
            for (size_t c = 0; c < k; ++c) off[c] = first + c * sz;
            total = first + rows * row;
            stride = l == kBroadcast ? 0 : static_cast<ptrdiff_t>(row);
            if (l == kReversed) {  // element 0 is the last row
                for (size_t c = 0; c < k; ++c) off[c] += (rows - 1) * row;
                stride = -stride;
            }
        }
        buf.assign(total + 16, fill);
    }
    unsigned char *at(size_t c, size_t j) { return buf.data() + off[c] + static_cast<ptrdiff_t>(j) * stride; }
    void set(size_t c, size_t j, T v) { std::memcpy(at(c, j), &v, sizeof v); }
    T get(size_t c, size_t j) {
        T v;
        std::memcpy(&v, at(c, j), sizeof v);
        return v;
    }
    pgloss_strided3 in3() { return pgloss_strided3{{at(0, 0), at(1, 0), at(2, 0)}, stride}; }
    pgloss_strided3_out out3() { return pgloss_strided3_out{{at(0, 0), at(1, 0), at(2, 0)}, stride}; }
    pgloss_strided in1() { return pgloss_strided{at(0, 0), stride}; }
    pgloss_strided_out out1() { return pgloss_strided_out{at(0, 0), stride}; }
};

template <class T>
bool same(T a, T b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// One call's inputs laid out one way, and its outputs: directions (wo; wi or u), materials
// (ρd as three values per element, ρs, αx, αy as one each) and the outputs (f or wi; pdf;
// weight). With kBroadcast the inputs hold element `one`'s values, the outputs are rows.
template <class T>
struct Call {
    Laid<T> wo, x, rd, rs, ax, ay, y0, y1, y2;
    std::vector<unsigned char> lobe;
    std::vector<signed char> st;
    pgloss_status all = PGLOSS_OK;
    Call(const Tex &t, size_t n, Layout l, bool sample, size_t one = 0)
        : wo(n, 3, l), x(n, 3, l), rd(n, 3, l), rs(n, 1, l), ax(n, 1, l), ay(n, 1, l),
          y0(n, 3, l == kBroadcast ? kRows : l), y1(n, 1, l == kBroadcast ? kRows : l),
          y2(n, 3, l == kBroadcast ? kRows : l), lobe(n, 77), st(n, 99) {
        const size_t rows = l == kBroadcast ? 1 : n;
        for (size_t j = 0; j < rows; ++j) {
            const size_t e = l == kBroadcast ? one : j;
            for (size_t c = 0; c < 3; ++c) {
                wo.set(c, j, static_cast<T>(t.o[c][e + 1]));
                x.set(c, j, static_cast<T>(sample ? t.u[c][e + 1] : t.i[c][e + 1]));
                rd.set(c, j, static_cast<T>(t.m[c][e + 1]));
            }
            rs.set(0, j, static_cast<T>(t.m[3][e + 1]));
            ax.set(0, j, static_cast<T>(t.m[4][e + 1]));
            ay.set(0, j, static_cast<T>(t.m[5][e + 1]));
        }
    }
    pgloss_physical_array mats(pgloss_normalization nm) {
        return pgloss_physical_array{rd.in3(), rs.in1(), ax.in1(), ay.in1(), nm};
    }
    void run(const pgloss_batch_options *opt, const pgloss_material *m, bool per_element, bool sample, size_t n) {
        const pgloss_physical_array ma = mats(PGLOSS_NORM_WARD_DUR);
        const pgloss_physical_array *pm = per_element ? &ma : nullptr;
        const pgloss_material *one = per_element ? nullptr : m;
        all = sample ? pgloss_sample_batch(opt, one, pm, 3, n, wo.in3(), x.in3(), y0.out3(), y1.out1(), y2.out3(),
                                           lobe.data(), st.data())
                     : pgloss_eval_pdf_batch(opt, one, pm, 3, n, wo.in3(), x.in3(), y0.out3(), y1.out1(), st.data());
    }
};

template <class T>
void strided_layouts_match_columns(pgloss_isa isa) {
    const size_t n = 301;  // more than one chunk, and an odd last one (the rows copies' tails)
    const Tex t(n, true, 17);
    pgloss_material m;
    const pgloss_physical ph = t.phys(3, PGLOSS_NORM_WARD_DUR);
    ASSERT_EQ(pgloss_material_init(&m, &ph), PGLOSS_OK);
    const pgloss_scalar_type type = sizeof(T) == 8 ? PGLOSS_FLOAT64 : PGLOSS_FLOAT32;
    for (pgloss_precision prec : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST, PGLOSS_PRECISION_REFERENCE}) {
        const pgloss_batch_options opt = batch_options(prec, isa, type);
        for (int sample = 0; sample < 2; ++sample)
            for (int per_element = 0; per_element < 2; ++per_element) {
                Call<T> ref(t, n, kColumns, sample);
                ref.run(&opt, &m, per_element, sample, n);
                for (Layout l : {kRows, kReversed, kOdd, kRowsOdd}) {
                    Call<T> c(t, n, l, sample);
                    c.run(&opt, &m, per_element, sample, n);
                    ASSERT_EQ(c.all, ref.all) << "layout " << l;
                    for (size_t j = 0; j < n; ++j) {
                        ASSERT_EQ(c.st[j], ref.st[j]) << j;
                        ASSERT_EQ(c.lobe[j], ref.lobe[j]) << j;
                        for (size_t k = 0; k < 3; ++k) {
                            ASSERT_TRUE(same(c.y0.get(k, j), ref.y0.get(k, j)))
                                << "layout " << l << " element " << j << " prec " << prec << " sample " << sample;
                            if (sample) {
                                ASSERT_TRUE(same(c.y2.get(k, j), ref.y2.get(k, j))) << "weight " << j;
                            }
                        }
                        ASSERT_TRUE(same(c.y1.get(0, j), ref.y1.get(0, j))) << "layout " << l << " element " << j;
                    }
                }
                // one value for every element (stride 0) = that value repeated in columns
                const size_t one = 5;
                Call<T> b(t, n, kBroadcast, sample, one);
                b.run(&opt, &m, per_element, sample, n);
                Call<T> rep(t, n, kColumns, sample);
                for (size_t j = 0; j < n; ++j)
                    for (size_t c = 0; c < 3; ++c) {
                        rep.wo.set(c, j, rep.wo.get(c, one));
                        rep.x.set(c, j, rep.x.get(c, one));
                        rep.rd.set(c, j, rep.rd.get(c, one));
                        if (c == 0) {
                            rep.rs.set(0, j, rep.rs.get(0, one));
                            rep.ax.set(0, j, rep.ax.get(0, one));
                            rep.ay.set(0, j, rep.ay.get(0, one));
                        }
                    }
                rep.run(&opt, &m, per_element, sample, n);
                ASSERT_EQ(b.all, rep.all);
                for (size_t j = 0; j < n; ++j) {
                    ASSERT_EQ(b.st[j], rep.st[j]) << j;
                    for (size_t k = 0; k < 3; ++k)
                        ASSERT_TRUE(same(b.y0.get(k, j), rep.y0.get(k, j))) << "broadcast, element " << j;
                    ASSERT_TRUE(same(b.y1.get(0, j), rep.y1.get(0, j))) << "broadcast, element " << j;
                }
            }
    }
}

TEST_P(PerIsa, StridedLayoutsMatchColumnsFloat32) { strided_layouts_match_columns<float>(GetParam()); }
TEST_P(PerIsa, StridedLayoutsMatchColumnsFloat64) { strided_layouts_match_columns<double>(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Isa, PerIsa, ::testing::ValuesIn(kIsas),
                         [](const ::testing::TestParamInfo<pgloss_isa> &i) { return std::string(pgloss_isa_name(i.param)); });

TEST(Batch, EmptyNullAndWholeCallErrors) {
    const pgloss_strided3 none{{nullptr, nullptr, nullptr}, 0};
    // n == 0: OK whatever else is missing; options are checked first
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, nullptr, 3, 0, none, none, no_out3(), no_out(), nullptr), PGLOSS_OK);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, nullptr, 3, 1, none, none, no_out3(), no_out(), nullptr),
              PGLOSS_ERR_NULL);
    const Tex t(4, false);
    pgloss_physical_array ma = t.mats(PGLOSS_NORM_WARD);
    float r[4] = {-1, -1, -1, -1}, g[4], b[4], p[4];
    const pgloss_strided3_out f = soa_out(r, g, b);
    ma.normalization = static_cast<pgloss_normalization>(7);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, &ma, 3, 4, t.wo(), t.wi(), f, no_out(), nullptr),
              PGLOSS_ERR_NORMALIZATION);
    EXPECT_EQ(r[0], -1.0f) << "nothing written";
    ma.normalization = PGLOSS_NORM_WARD;
    const pgloss_batch_options bad{static_cast<pgloss_precision>(9), PGLOSS_ISA_AUTO, PGLOSS_FLOAT32};
    const pgloss_batch_options bad_type{PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_AUTO, static_cast<pgloss_scalar_type>(2)};
    EXPECT_EQ(pgloss_eval_pdf_batch(&bad, nullptr, &ma, 3, 4, t.wo(), t.wi(), f, no_out(), nullptr), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_eval_pdf_batch(&bad_type, nullptr, &ma, 3, 0, t.wo(), t.wi(), f, no_out(), nullptr),
              PGLOSS_ERR_ARGUMENT);
    pgloss_material m;
    const pgloss_physical ph = t.phys(0, PGLOSS_NORM_WARD);
    ASSERT_EQ(pgloss_material_init(&m, &ph), PGLOSS_OK);
    // one material and per-element materials at once; an output with stride 0 for n > 1
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, &ma, 3, 4, t.wo(), t.wi(), f, no_out(), nullptr), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, 4, t.wo(), t.wi(), f, pgloss_strided_out{p, 0}, nullptr),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, 1, t.wo(), t.wi(), f, pgloss_strided_out{p, 0}, nullptr),
              PGLOSS_OK);
    // neither output, or an incomplete one
    r[0] = -1;
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, 4, t.wo(), t.wi(), no_out3(), no_out(), nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, 3, 4, t.wo(), t.wi(), soa_out(r, g, static_cast<float *>(nullptr)),
                                    no_out(), nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(r[0], -1.0f) << "nothing written";
    // sampling: every output but the lobe is required
    float x[4], y[4], z[4];
    EXPECT_EQ(pgloss_sample_batch(nullptr, &m, nullptr, 3, 4, t.wo(), t.us(), soa_out(x, y, z), no_out(), f, nullptr,
                                  nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_sample_batch(nullptr, &m, nullptr, 3, 4, t.wo(), t.us(), soa_out(x, y, z), col_out(p),
                                  pgloss_strided3_out{{r, g, b}, 0}, nullptr, nullptr),
              PGLOSS_ERR_ARGUMENT);
    // alpha_y NULL: isotropic, αy = αx
    std::vector<float> ax(t.m[4].begin() + 1, t.m[4].end());
    pgloss_physical_array iso = ma, both = ma;
    iso.alpha_y = pgloss_strided{nullptr, 0};
    both.alpha_y = col(ax.data());
    float r2[4], g2[4], b2[4];
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, &iso, 3, 4, t.wo(), t.wi(), f, no_out(), nullptr), PGLOSS_OK);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, &both, 3, 4, t.wo(), t.wi(), soa_out(r2, g2, b2), no_out(), nullptr),
              PGLOSS_OK);
    for (int j = 0; j < 4; ++j) EXPECT_EQ(r[j], r2[j]);
}

// ---- batched perceptual functions: element by element the scalar function, statuses --------

TEST(PerceptualBatch, EqualsScalarFunctionsElementByElement) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(-0.2, 1.2);
    const size_t n = 2000;
    std::vector<double> a(n + 1), b(n + 1), c(n + 1), L(n + 1), A(n + 1), B(n + 1), C(n + 1), D(n + 1);
    for (size_t j = 1; j <= n; ++j) {
        a[j] = uni(rng), b[j] = 0.3 * uni(rng), c[j] = 0.3 * uni(rng);
        L[j] = 110 * uni(rng), A[j] = 80 * (uni(rng) - 0.5), B[j] = 80 * (uni(rng) - 0.5);
        C[j] = 0.25 * uni(rng), D[j] = uni(rng);
        if (j % 97 == 0) a[j] = NAN;
        if (j % 89 == 0) L[j] = INFINITY;
    }
    auto eq = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    std::vector<double> o1(n), o2(n), o3(n), o4(n), o5(n), o6(n);
    std::vector<signed char> st(n);
    // gloss_from_physical
    pgloss_status first = PGLOSS_OK, warn = PGLOSS_OK;
    auto note = [&](pgloss_status s) {
        if (s < 0 && first == PGLOSS_OK) first = s;
        if (s > 0 && warn == PGLOSS_OK) warn = s;
    };
    pgloss_status r = pgloss_gloss_from_physical_batch(n, col(a.data() + 1), col(b.data() + 1), col(c.data() + 1),
                                                       col_out(o1.data()), col_out(o2.data()), col_out(o3.data()),
                                                       st.data());
    for (size_t j = 0; j < n; ++j) {
        double x, y, z;
        const pgloss_status s = pgloss_gloss_from_physical(a[j + 1], b[j + 1], c[j + 1], &x, &y, &z);
        note(s);
        ASSERT_EQ(st[j], s) << j;
        ASSERT_TRUE(eq(x, o1[j]) && eq(y, o2[j]) && eq(z, o3[j])) << j;
    }
    EXPECT_EQ(r, first != PGLOSS_OK ? first : warn);
    // physical_from_perceptual (Rec. 709 and ACEScg)
    for (pgloss_color_space sp : {PGLOSS_COLOR_SPACE_LINEAR_REC709, PGLOSS_COLOR_SPACE_ACESCG}) {
        first = warn = PGLOSS_OK;
        const pgloss_perceptual_array q = perceptual_cols(L.data() + 1, A.data() + 1, B.data() + 1, C.data() + 1, D.data() + 1);
        const pgloss_physical_array_out po =
            physical_cols_out(o1.data(), o2.data(), o3.data(), o4.data(), o5.data(), o6.data());
        r = pgloss_physical_from_perceptual_batch(n, &q, PGLOSS_NORM_BOUNDED, sp, &po, st.data());
        for (size_t j = 0; j < n; ++j) {
            const pgloss_perceptual q{L[j + 1], A[j + 1], B[j + 1], C[j + 1], D[j + 1]};
            pgloss_physical p;
            const pgloss_status s = pgloss_physical_from_perceptual_ex(&q, PGLOSS_NORM_BOUNDED, sp, &p);
            note(s);
            ASSERT_EQ(st[j], s) << j;
            ASSERT_TRUE(eq(p.rho_d[0], o1[j]) && eq(p.rho_d[1], o2[j]) && eq(p.rho_d[2], o3[j]) && eq(p.rho_s, o4[j]) &&
                        eq(p.alpha_x, o5[j]) && eq(p.alpha_y, o6[j]))
                << j;
        }
        EXPECT_EQ(r, first != PGLOSS_OK ? first : warn);
    }
    // check_perceptual: statuses only, status array optional
    first = warn = PGLOSS_OK;
    const pgloss_perceptual_array q = perceptual_cols(L.data() + 1, A.data() + 1, B.data() + 1, C.data() + 1, D.data() + 1);
    r = pgloss_check_perceptual_batch(n, &q, PGLOSS_COLOR_SPACE_LINEAR_REC709, st.data());
    for (size_t j = 0; j < n; ++j) {
        const pgloss_perceptual q{L[j + 1], A[j + 1], B[j + 1], C[j + 1], D[j + 1]};
        const pgloss_status s = pgloss_check_perceptual(&q);
        note(s);
        ASSERT_EQ(st[j], s) << j;
    }
    EXPECT_EQ(r, first != PGLOSS_OK ? first : warn);
    EXPECT_EQ(pgloss_check_perceptual_batch(n, &q, PGLOSS_COLOR_SPACE_LINEAR_REC709, nullptr), r);
    // in place: an output may be the very input array
    std::vector<double> y(L.begin() + 1, L.end()), c2(n);
    std::vector<double> ref(n);
    for (size_t j = 0; j < n; ++j) pgloss_envelope_contrast(y[j], &ref[j]);
    pgloss_envelope_contrast_batch(n, col(y.data()), col_out(y.data()), nullptr);
    for (size_t j = 0; j < n; ++j) ASSERT_TRUE(eq(y[j], ref[j])) << j;
}

TEST(PerceptualBatch, EmptyAndWholeCallErrors) {
    const pgloss_strided none{nullptr, 0};
    EXPECT_EQ(pgloss_envelope_contrast_batch(0, none, no_out(), nullptr), PGLOSS_OK);
    EXPECT_EQ(pgloss_envelope_contrast_batch(1, none, no_out(), nullptr), PGLOSS_ERR_NULL);
    double L = 50, a = 0, c = 0.05, d = 0.95, o = -7, o2[2] = {-7, -7};
    const pgloss_perceptual_array q = perceptual_cols(&L, &a, &a, &c, &d);
    const pgloss_physical_array_out p = physical_cols_out(&o, &o, &o, &o, &o, nullptr);
    const auto rec709 = PGLOSS_COLOR_SPACE_LINEAR_REC709;
    // an unknown normalisation is each element's status after its input checks, as in the
    // scalar function: NORMALIZATION and 0 outputs here, LIGHTNESS for L* = 150
    signed char st = 99;
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, &q, static_cast<pgloss_normalization>(5), rec709, &p, &st),
              PGLOSS_ERR_NORMALIZATION);
    EXPECT_EQ(st, PGLOSS_ERR_NORMALIZATION);
    EXPECT_EQ(o, 0.0);
    double L2 = 150;
    const pgloss_perceptual_array q2 = perceptual_cols(&L2, &a, &a, &c, &d);
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, &q2, static_cast<pgloss_normalization>(5), rec709, &p, &st),
              PGLOSS_ERR_LIGHTNESS);
    o = -7;
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, &q, PGLOSS_NORM_WARD, static_cast<pgloss_color_space>(4), &p, nullptr),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(o, -7) << "nothing written";
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, nullptr, PGLOSS_NORM_WARD, rec709, &p, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, &q, PGLOSS_NORM_WARD, rec709, &p, nullptr), PGLOSS_OK);
    // an output with stride 0 for more than one element; one input broadcast to two is fine
    EXPECT_EQ(pgloss_envelope_contrast_batch(2, pgloss_strided{&L, 0}, pgloss_strided_out{o2, 0}, nullptr),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(o2[0], -7) << "nothing written";
    EXPECT_EQ(pgloss_envelope_contrast_batch(2, pgloss_strided{&L, 0}, col_out(o2), nullptr), PGLOSS_OK);
    EXPECT_EQ(o2[0], o2[1]);
}

}  // namespace
