// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// A bridge target's shading model (pgloss/bridge_model.h): roughplastic against Mitsuba 3's own
// BRDF values and internal reflectance, the layered models' white furnace (their base is weighted
// by one minus the compensated specular albedo, so a white base reflects everything), the
// conventions (α, F0, η) and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pgloss/pgloss.h"

namespace {

constexpr double PI = 3.14159265358979323846;
constexpr double MITSUBA_AIR = 1.000277;

double f_of(const pgloss_bridge_shading &s, const double wo[3], const double wi[3], int ch = 0)
{
    double spec, diffuse;
    EXPECT_EQ(pgloss_bridge_shading_eval(&s, wo, wi, &spec, &diffuse), PGLOSS_OK);
    return spec + diffuse * s.base_color[ch];
}

void unit(double x, double y, double v[3])
{
    v[0] = x;
    v[1] = y;
    v[2] = std::sqrt(1 - x * x - y * y);
}

}  // namespace

// Mitsuba 3.9.1 (scalar_rgb) roughplastic, nonlinear false, diffuse_reflectance 0.5, int_ior
// 1.5 × 1.000277 (ext_ior "air"): BSDF::eval(si.wi = ωo, ωi) / cos θi, printed by Mitsuba in
// float32 at these directions (x, y of ωo; x, y of ωi).
TEST(BridgeShading, RoughplasticMeetsMitsubaPerDirection)
{
    const double dirs[5][4] = {{0.3, 0.1, -0.28, -0.12}, {0.6, 0.0, -0.55, 0.05}, {0.2, 0.5, 0.4, -0.3},
                               {0.0, 0.0, 0.1, 0.0},     {0.8, 0.1, -0.7, 0.0}};
    const double alpha[2] = {0.05, 0.2};
    const double mitsuba[2][2][5] = {
        {{1.3484207507226098, 0.8271647866492751, 0.15378010251732135, 0.47368037700653076, 0.2802927247750373},
         {0.21315164079009744, 0.24065944938869105, 0.13191738678236337, 0.19730891287326813, 0.27549643419724984}},
        {{1.4532645692943664, 1.1327612976318404, 0.15680680960728338, 0.6281944513320923, 0.19098592670319534},
         {0.2364726429221931, 0.2703571838087263, 0.15235401276942842, 0.22410036623477936, 0.342491311551468}}};
    double worst = 0;
    for (int m = 0; m < 2; ++m)
        for (int a = 0; a < 2; ++a) {
            const pgloss_bridge_target t = m ? PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN : PGLOSS_BRIDGE_ROUGHPLASTIC_GGX;
            const pgloss_bridge_params p = {{0.5, 0.5, 0.5}, alpha[a], 1.5 * MITSUBA_AIR, 1.0};
            pgloss_bridge_shading s;
            ASSERT_EQ(pgloss_bridge_shading_init(t, &p, &s), PGLOSS_OK);
            EXPECT_NEAR(s.eta, 1.5, 1e-12);
            for (int k = 0; k < 5; ++k) {
                double wo[3], wi[3];
                unit(dirs[k][0], dirs[k][1], wo);
                unit(dirs[k][2], dirs[k][3], wi);
                const double got = f_of(s, wo, wi), want = mitsuba[m][a][k];
                worst = std::max(worst, std::fabs(got / want - 1));
                // Mitsuba's t(μ) and R_int are its own quadratures (R_int agrees to 1e-3,
                // test_bridge); the diffuse is a fifth to all of f here: 0.5% covers both.
                EXPECT_NEAR(got / want, 1, 5e-3) << pgloss_bridge_target_name(t) << " alpha " << alpha[a] << " dir " << k;
            }
        }
    std::printf("roughplastic vs Mitsuba 3 (20 directions): worst relative difference %.2e\n", worst);
}

// R_int from diffuse_scale = 1/(π η² (1 − R_int)) against Mitsuba 3.9.1's own at η 1.5 (the
// values of Bridge.RoughplasticInternalReflectanceMeetsMitsuba, read from its roughplastic).
TEST(BridgeShading, RoughplasticInternalReflectanceMeetsMitsuba)
{
    const double alpha[4] = {0.04, 0.07, 0.1, 0.2};
    const double mitsuba[2][4] = {{0.5800, 0.5672, 0.5519, 0.4863}, {0.5866, 0.5843, 0.5810, 0.5614}};
    for (int m = 0; m < 2; ++m)
        for (int k = 0; k < 4; ++k) {
            const pgloss_bridge_params p = {{0.5, 0.5, 0.5}, alpha[k], 1.5 * MITSUBA_AIR, 1.0};
            pgloss_bridge_shading s;
            ASSERT_EQ(pgloss_bridge_shading_init(m ? PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN : PGLOSS_BRIDGE_ROUGHPLASTIC_GGX,
                                                 &p, &s),
                      PGLOSS_OK);
            EXPECT_EQ(s.diffuse_both, 1);
            EXPECT_EQ(s.distribution, m ? PGLOSS_BRIDGE_DIST_BECKMANN : PGLOSS_BRIDGE_DIST_GGX);
            EXPECT_NEAR(1 - 1 / (PI * s.eta * s.eta * s.diffuse_scale), mitsuba[m][k], 1e-3);
        }
}

// The layered models with a white base, by this test's own quadrature over ωi (2000 rings in
// cos θi × 400 φ cells). Cycles (Principled) weights the base by one minus the compensated
// specular albedo with the same Fresnel factor, so ∫ f cos θi dωi = 1 at every view: the bound
// 4e-3 is the 64-node lerp and this quadrature at α 0.04 (measured 2.9e-3 at μo 0.2, ≤ 6e-4
// elsewhere). MaterialX weights it by the albedo with Schlick's Fresnel (mx_ggx_dir_albedo) while
// the lobe has the exact one, so its furnace is off by up to 2% by design (measured 1.9e-2).
TEST(BridgeShading, LayeredWhiteFurnace)
{
    const pgloss_bridge_target targets[2] = {PGLOSS_BRIDGE_PRINCIPLED, PGLOSS_BRIDGE_OPENPBR};
    const double roughness[3] = {0.2, 0.4, 0.7};
    double worst = 0;
    for (pgloss_bridge_target t : targets)
        for (double r : roughness) {
            // Specular IOR Level 0.5 and specular_weight 1 leave F0 at the IOR's.
            const pgloss_bridge_params p = {{1.0, 1.0, 1.0}, r, 1.5, t == PGLOSS_BRIDGE_PRINCIPLED ? 0.5 : 1.0};
            pgloss_bridge_shading s;
            ASSERT_EQ(pgloss_bridge_shading_init(t, &p, &s), PGLOSS_OK);
            EXPECT_EQ(s.diffuse_both, 0);
            EXPECT_NEAR(s.alpha, r * r, 1e-15);  // α = roughness² (OpenPBR, Cycles)
            EXPECT_NEAR(s.f0, 0.04, 1e-15);      // ((1.5 − 1)/(1.5 + 1))²
            EXPECT_NEAR(s.diffuse_scale, 1 / PI, 1e-15);
            for (double mo : {0.2, 0.5, 0.9}) {
                const double wo[3] = {std::sqrt(1 - mo * mo), 0, mo};
                const int NT = 2000, NP = 400;
                double sum = 0;
                for (int i = 0; i < NT; ++i) {
                    const double c0 = 1 - (double)i / NT, c1 = 1 - (double)(i + 1) / NT, ci = 0.5 * (c0 + c1);
                    const double si = std::sqrt(1 - ci * ci);
                    for (int j = 0; j < NP; ++j) {
                        const double ph = 2 * PI * (j + 0.5) / NP;
                        const double wi[3] = {si * std::cos(ph), si * std::sin(ph), ci};
                        sum += f_of(s, wo, wi) * ci * (c0 - c1) * 2 * PI / NP;
                    }
                }
                worst = std::max(worst, std::fabs(sum - 1));
                std::printf("  %s roughness %.1f mu %.1f: albedo %.5f\n", pgloss_bridge_target_name(t), r, mo, sum);
                EXPECT_NEAR(sum, 1, t == PGLOSS_BRIDGE_PRINCIPLED ? 4e-3 : 2.5e-2) << pgloss_bridge_target_name(t) << " roughness " << r << " mu " << mo;
            }
        }
    std::printf("layered white furnace: worst |albedo - 1| %.2e (principled and openpbr)\n", worst);
}

TEST(BridgeShading, ConventionsAndErrors)
{
    pgloss_bridge_shading s;
    // OpenPBR specular_weight 0.5 halves F0 (bridge.h): F0 0.02, η of it.
    pgloss_bridge_params p = {{0.2, 0.3, 0.4}, 0.3, 1.5, 0.5};
    ASSERT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_OPENPBR, &p, &s), PGLOSS_OK);
    EXPECT_NEAR(s.f0, 0.02, 1e-15);
    EXPECT_NEAR(s.eta, (1 + std::sqrt(0.02)) / (1 - std::sqrt(0.02)), 1e-12);
    EXPECT_EQ(s.model, PGLOSS_BRIDGE_MODEL_MATERIALX);
    EXPECT_EQ(s.base_color[2], 0.4);
    ASSERT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_GLTF, &p, &s), PGLOSS_OK);
    EXPECT_EQ(s.model, PGLOSS_BRIDGE_MODEL_PRINCIPLED);
    // Below the horizon: 0.
    double spec = 1, diffuse = 1;
    const double up[3] = {0, 0, 1}, down[3] = {0, 0, -1};
    EXPECT_EQ(pgloss_bridge_shading_eval(&s, up, down, &spec, &diffuse), PGLOSS_OK);
    EXPECT_EQ(spec + diffuse, 0.0);
    EXPECT_EQ(pgloss_bridge_shading_eval(nullptr, up, up, &spec, &diffuse), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_OPENPBR, nullptr, &s), PGLOSS_ERR_NULL);
    p.base_color[0] = 1.5;
    EXPECT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_OPENPBR, &p, &s), PGLOSS_ERR_BRIDGE_BASE);
    EXPECT_EQ(s.alpha, 0.0);  // zeroed on error
    p.base_color[0] = 0.2;
    p.roughness = NAN;
    EXPECT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_OPENPBR, &p, &s), PGLOSS_ERR_NONFINITE);
    p.roughness = 1.5;  // α 2.25
    EXPECT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_OPENPBR, &p, &s), PGLOSS_ERR_BRIDGE_ROUGHNESS);
    p.roughness = 0.3;
    EXPECT_EQ(pgloss_bridge_shading_init((pgloss_bridge_target)99, &p, &s), PGLOSS_ERR_ARGUMENT);
    // Finite everywhere on the hemisphere, grazing included.
    ASSERT_EQ(pgloss_bridge_shading_init(PGLOSS_BRIDGE_ROUGHPLASTIC_GGX, &p, &s), PGLOSS_OK);
    const double graze[3] = {1, 0, 1e-300}, back[3] = {-1, 0, 1e-300};
    EXPECT_EQ(pgloss_bridge_shading_eval(&s, graze, back, &spec, &diffuse), PGLOSS_OK);
    EXPECT_TRUE(std::isfinite(spec) && std::isfinite(diffuse));
}
