// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Per-element materials, the double batch path and the batched perceptual functions
// (pgloss/batch_materials.h, pgloss/perceptual_batch.h) against their one-at-a-time
// definitions: a per-element call equals, element by element, the uniform batch called with
// that element's pgloss_material (bit for bit in the FLOAT tier, on every ISA the CPU has);
// the double path agrees with the scalar double reference; statuses per element; n = 0,
// tails and unaligned arrays. The shared vectors run through the same entry points in
// test_vectors.cpp. An ISA this CPU or build lacks is GTEST_SKIPped with the reason
// (a hardware property, as in test_isa.cpp; PGLOSS_REQUIRE_ISA makes it a failure).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

extern "C" {
#include "pgloss/pgloss.h"
}

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
    pgloss_material_array mats(pgloss_normalization nm) const {
        return {m[0].data() + 1, m[1].data() + 1, m[2].data() + 1, m[3].data() + 1, m[4].data() + 1, m[5].data() + 1, nm};
    }
    pgloss_vec3_array wo() const { return {o[0].data() + 1, o[1].data() + 1, o[2].data() + 1}; }
    pgloss_vec3_array wi() const { return {i[0].data() + 1, i[1].data() + 1, i[2].data() + 1}; }
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
// (bit for bit in FLOAT; FAST runs the FLOAT code for per-element materials, REFERENCE the
// scalar functions either way). Sizes cover n < chunk, tails and several chunks.
TEST_P(PerIsa, EvalPdfMaterialsEqualsOneMaterialPerCall) {
    for (size_t n : {size_t(1), size_t(7), size_t(300), size_t(1031)}) {
        const Tex t(n, true);
        for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED})
            for (unsigned lobes : {1u, 2u, 3u})
                for (pgloss_precision prec : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST, PGLOSS_PRECISION_REFERENCE}) {
                    const pgloss_batch_options opt{prec, GetParam()};
                    const pgloss_material_array ma = t.mats(nm);
                    std::vector<float> r(n), g(n), b(n), p(n);
                    std::vector<signed char> st(n);
                    const pgloss_status all =
                        pgloss_eval_pdf_batch_materials_ex(&opt, &ma, lobes, n, t.wo(), t.wi(),
                                                           pgloss_rgb_out{r.data(), g.data(), b.data()}, p.data(), st.data());
                    pgloss_status first = PGLOSS_OK;
                    for (size_t j = 0; j < n; ++j) {
                        const pgloss_physical ph = t.phys(j, nm);
                        pgloss_material mj;
                        const pgloss_status ms = pgloss_material_init(&mj, &ph);
                        float r1, g1, b1, p1;
                        const pgloss_batch_options opt1{prec == PGLOSS_PRECISION_FAST ? PGLOSS_PRECISION_FLOAT : prec,
                                                        GetParam()};
                        const pgloss_vec3_array o1{t.o[0].data() + 1 + j, t.o[1].data() + 1 + j, t.o[2].data() + 1 + j};
                        const pgloss_vec3_array i1{t.i[0].data() + 1 + j, t.i[1].data() + 1 + j, t.i[2].data() + 1 + j};
                        const pgloss_status ds = pgloss_eval_pdf_batch_ex(&opt1, &mj, lobes, 1, o1, i1,
                                                                          pgloss_rgb_out{&r1, &g1, &b1}, &p1);
                        const pgloss_status want = ms != PGLOSS_OK ? ms : ds;
                        if (first == PGLOSS_OK) first = want;
                        ASSERT_EQ(st[j], static_cast<signed char>(want)) << "element " << j << " n " << n;
                        if (ms != PGLOSS_OK) {
                            EXPECT_TRUE(r[j] == 0 && g[j] == 0 && b[j] == 0 && p[j] == 0) << "invalid material " << j;
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
                    const pgloss_batch_options opt{prec, GetParam()};
                    const pgloss_material_array ma = t.mats(nm);
                    std::vector<float> x(n), y(n), z(n), p(n), r(n), g(n), b(n);
                    std::vector<unsigned char> lb(n);
                    std::vector<signed char> st(n);
                    const pgloss_status all = pgloss_sample_batch_materials_ex(
                        &opt, &ma, lobes, n, t.wo(), t.u[0].data() + 1, t.u[1].data() + 1, t.u[2].data() + 1,
                        pgloss_vec3_out{x.data(), y.data(), z.data()}, p.data(), pgloss_rgb_out{r.data(), g.data(), b.data()},
                        lb.data(), st.data());
                    pgloss_status first = PGLOSS_OK;
                    for (size_t j = 0; j < n; ++j) {
                        const pgloss_physical ph = t.phys(j, nm);
                        pgloss_material mj;
                        const pgloss_status ms = pgloss_material_init(&mj, &ph);
                        float x1, y1, z1, p1, r1, g1, b1;
                        unsigned char l1;
                        const pgloss_vec3_array o1{t.o[0].data() + 1 + j, t.o[1].data() + 1 + j, t.o[2].data() + 1 + j};
                        const pgloss_status ds = pgloss_sample_batch_ex(
                            &opt, &mj, lobes, 1, o1, t.u[0].data() + 1 + j, t.u[1].data() + 1 + j, t.u[2].data() + 1 + j,
                            pgloss_vec3_out{&x1, &y1, &z1}, &p1, pgloss_rgb_out{&r1, &g1, &b1}, &l1);
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
    const pgloss_vec3_array_d wo{d[0].data(), d[1].data(), d[2].data()}, wi{d[3].data(), d[4].data(), d[5].data()};
    const pgloss_batch_options opt{PGLOSS_PRECISION_FLOAT, GetParam()};
    for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED}) {
        const pgloss_physical_array pa{mm[0].data(), mm[1].data(), mm[2].data(), mm[3].data(), mm[4].data(), mm[5].data(), nm};
        std::vector<double> r(n), g(n), b(n), p(n);
        std::vector<signed char> st(n);
        pgloss_eval_pdf_batch_materials_d_ex(&opt, &pa, PGLOSS_LOBE_ALL, n, wo, wi, pgloss_rgb_out_d{r.data(), g.data(), b.data()},
                                             p.data(), st.data());
        for (size_t j = 0; j < n; ++j) {
            const pgloss_physical ph = t.phys(j, nm);
            pgloss_material mj;
            const pgloss_status ms = pgloss_material_init(&mj, &ph);
            double r1, g1, b1, p1;
            signed char s1;
            const pgloss_vec3_array_d o1{wo.x + j, wo.y + j, wo.z + j}, i1{wi.x + j, wi.y + j, wi.z + j};
            const pgloss_status ds = pgloss_eval_pdf_batch_d_ex(&opt, &mj, PGLOSS_LOBE_ALL, 1, o1, i1,
                                                                pgloss_rgb_out_d{&r1, &g1, &b1}, &p1, &s1);
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
        const pgloss_vec3_array_d wo{o[0].data(), o[1].data(), o[2].data()};
        for (pgloss_normalization nm : {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED})
            for (unsigned lobes : {1u, 2u, 3u}) {
                const pgloss_physical_array pa{mm[0].data(), mm[1].data(), mm[2].data(), mm[3].data(),
                                               mm[4].data(), mm[5].data(), nm};
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
                    const pgloss_batch_options opt{PGLOSS_PRECISION_FLOAT, isa};
                    r.all = pgloss_sample_batch_materials_d_ex(
                        &opt, &pa, lobes, n, wo, u[0].data(), u[1].data(), u[2].data(),
                        pgloss_vec3_out_d{r.v[0].data(), r.v[1].data(), r.v[2].data()}, r.v[3].data(),
                        pgloss_rgb_out_d{r.v[4].data(), r.v[5].data(), r.v[6].data()}, r.lb.data(), r.st.data());
                    return r;
                };
                const Out a = run(GetParam()), base = run(PGLOSS_ISA_BASELINE);
                EXPECT_EQ(a.all, base.all);
                // the baseline's f and pdf at the wi that GetParam()'s sampler drew
                std::vector<double> bf[3], bp(n);
                for (auto &v : bf) v.assign(n, 0.0);
                const pgloss_batch_options base_opt{PGLOSS_PRECISION_FLOAT, PGLOSS_ISA_BASELINE};
                pgloss_eval_pdf_batch_materials_d_ex(
                    &base_opt, &pa, lobes, n, wo, pgloss_vec3_array_d{a.v[0].data(), a.v[1].data(), a.v[2].data()},
                    pgloss_rgb_out_d{bf[0].data(), bf[1].data(), bf[2].data()}, bp.data(), nullptr);
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
                const pgloss_batch_options opt{PGLOSS_PRECISION_FLOAT, GetParam()};
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
                    const pgloss_vec3_array_d o1{wo.x + j, wo.y + j, wo.z + j};
                    const pgloss_status ds = pgloss_sample_batch_d_ex(
                        &opt, &mj, lobes, 1, o1, &u[0][j], &u[1][j], &u[2][j], pgloss_vec3_out_d{&v1[0], &v1[1], &v1[2]},
                        &v1[3], pgloss_rgb_out_d{&v1[4], &v1[5], &v1[6]}, &l1, &s1);
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
                        const pgloss_vec3_array_d i1{&a.v[0][j], &a.v[1][j], &a.v[2][j]};
                        ASSERT_EQ(pgloss_eval_pdf_batch_d_ex(&opt, &mj, lobes, 1, o1, i1, pgloss_rgb_out_d{&f[0], &f[1], &f[2]},
                                                             &pe, nullptr),
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

INSTANTIATE_TEST_SUITE_P(Isa, PerIsa, ::testing::ValuesIn(kIsas),
                         [](const ::testing::TestParamInfo<pgloss_isa> &i) { return std::string(pgloss_isa_name(i.param)); });

TEST(BatchMaterials, EmptyNullAndOptions) {
    const pgloss_vec3_array none{nullptr, nullptr, nullptr};
    const pgloss_rgb_out fnone{nullptr, nullptr, nullptr};
    EXPECT_EQ(pgloss_eval_batch_materials(nullptr, 3, 0, none, none, fnone), PGLOSS_OK);
    EXPECT_EQ(pgloss_eval_batch_materials(nullptr, 3, 1, none, none, fnone), PGLOSS_ERR_NULL);
    const Tex t(4, false);
    pgloss_material_array ma = t.mats(PGLOSS_NORM_WARD);
    float r[4] = {-1, -1, -1, -1}, g[4], b[4];
    ma.normalization = static_cast<pgloss_normalization>(7);
    EXPECT_EQ(pgloss_eval_batch_materials(&ma, 3, 4, t.wo(), t.wi(), pgloss_rgb_out{r, g, b}), PGLOSS_ERR_NORMALIZATION);
    EXPECT_EQ(r[0], -1.0f) << "nothing written";
    ma.normalization = PGLOSS_NORM_WARD;
    const pgloss_batch_options bad{static_cast<pgloss_precision>(9), PGLOSS_ISA_AUTO};
    EXPECT_EQ(pgloss_eval_pdf_batch_materials_ex(&bad, &ma, 3, 4, t.wo(), t.wi(), pgloss_rgb_out{r, g, b}, nullptr, nullptr),
              PGLOSS_ERR_ARGUMENT);
    // alpha_y NULL: isotropic, αy = αx
    std::vector<float> ax(t.m[4].begin() + 1, t.m[4].end());
    pgloss_material_array iso = ma, both = ma;
    iso.alpha_y = nullptr;
    both.alpha_y = ax.data();
    float r2[4], g2[4], b2[4];
    EXPECT_EQ(pgloss_eval_batch_materials(&iso, 3, 4, t.wo(), t.wi(), pgloss_rgb_out{r, g, b}), PGLOSS_OK);
    EXPECT_EQ(pgloss_eval_batch_materials(&both, 3, 4, t.wo(), t.wi(), pgloss_rgb_out{r2, g2, b2}), PGLOSS_OK);
    for (int j = 0; j < 4; ++j) EXPECT_EQ(r[j], r2[j]);
    // the double forms
    const pgloss_vec3_array_d dn{nullptr, nullptr, nullptr};
    EXPECT_EQ(pgloss_eval_batch_d(nullptr, 3, 0, dn, dn, pgloss_rgb_out_d{nullptr, nullptr, nullptr}), PGLOSS_OK);
    EXPECT_EQ(pgloss_eval_batch_materials_d(nullptr, 3, 2, dn, dn, pgloss_rgb_out_d{nullptr, nullptr, nullptr}),
              PGLOSS_ERR_NULL);
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
    pgloss_status r = pgloss_gloss_from_physical_batch(n, a.data() + 1, b.data() + 1, c.data() + 1, o1.data(), o2.data(),
                                                       o3.data(), st.data());
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
        r = pgloss_physical_from_perceptual_batch_ex(
            n, pgloss_perceptual_array{L.data() + 1, A.data() + 1, B.data() + 1, C.data() + 1, D.data() + 1},
            PGLOSS_NORM_BOUNDED, sp, pgloss_physical_out{o1.data(), o2.data(), o3.data(), o4.data(), o5.data(), o6.data()},
            st.data());
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
    r = pgloss_check_perceptual_batch(n, pgloss_perceptual_array{L.data() + 1, A.data() + 1, B.data() + 1, C.data() + 1, D.data() + 1},
                                      st.data());
    for (size_t j = 0; j < n; ++j) {
        const pgloss_perceptual q{L[j + 1], A[j + 1], B[j + 1], C[j + 1], D[j + 1]};
        const pgloss_status s = pgloss_check_perceptual(&q);
        note(s);
        ASSERT_EQ(st[j], s) << j;
    }
    EXPECT_EQ(r, first != PGLOSS_OK ? first : warn);
    EXPECT_EQ(pgloss_check_perceptual_batch(n, pgloss_perceptual_array{L.data() + 1, A.data() + 1, B.data() + 1, C.data() + 1,
                                                                       D.data() + 1},
                                            nullptr),
              r);
    // in place: an output may be the very input array
    std::vector<double> y(L.begin() + 1, L.end()), c2(n);
    std::vector<double> ref(n);
    for (size_t j = 0; j < n; ++j) pgloss_envelope_contrast(y[j], &ref[j]);
    pgloss_envelope_contrast_batch(n, y.data(), y.data(), nullptr);
    for (size_t j = 0; j < n; ++j) ASSERT_TRUE(eq(y[j], ref[j])) << j;
}

TEST(PerceptualBatch, EmptyAndWholeCallErrors) {
    EXPECT_EQ(pgloss_envelope_contrast_batch(0, nullptr, nullptr, nullptr), PGLOSS_OK);
    EXPECT_EQ(pgloss_envelope_contrast_batch(1, nullptr, nullptr, nullptr), PGLOSS_ERR_NULL);
    double L = 50, a = 0, c = 0.05, d = 0.95, o = -7;
    const pgloss_perceptual_array q{&L, &a, &a, &c, &d};
    const pgloss_physical_out p{&o, &o, &o, &o, &o, nullptr};
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, q, static_cast<pgloss_normalization>(5), p, nullptr),
              PGLOSS_ERR_NORMALIZATION);
    EXPECT_EQ(o, -7) << "nothing written";
    EXPECT_EQ(pgloss_physical_from_perceptual_batch_ex(1, q, PGLOSS_NORM_WARD, static_cast<pgloss_color_space>(4), p, nullptr),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_physical_from_perceptual_batch(1, q, PGLOSS_NORM_WARD, p, nullptr), PGLOSS_OK);
}

}  // namespace
