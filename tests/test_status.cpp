// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Status codes and the API's NULL / fallback contract: every failing call returns a named
// reason and leaves finite, documented outputs (brdf.h, perceptual.h, status.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "batch_util.h"

namespace {

const pgloss_status kAll[] = {
    PGLOSS_OK, PGLOSS_WARN_ALPHA_UNTRUSTED, PGLOSS_ERR_NULL, PGLOSS_ERR_NONFINITE,
    PGLOSS_ERR_NEGATIVE, PGLOSS_ERR_ALPHA, PGLOSS_ERR_ENERGY, PGLOSS_ERR_ENVELOPE,
    PGLOSS_ERR_LIGHTNESS, PGLOSS_ERR_GAMUT, PGLOSS_ERR_DIRECTION, PGLOSS_ERR_NORMALIZATION,
    PGLOSS_ERR_ARGUMENT, PGLOSS_ERR_RANDOM, PGLOSS_WARN_QUADRATURE, PGLOSS_ERR_NO_FIT};

TEST(Status, NamesAndSentencesAreDistinctAndNonEmpty)
{
    std::set<std::string> names, sentences;
    for (pgloss_status s : kAll) {
        const std::string n = pgloss_status_name(s), t = pgloss_status_string(s);
        EXPECT_EQ(n.rfind("PGLOSS_", 0), 0u) << n;
        EXPECT_GT(t.size(), 2u);
        names.insert(n);
        sentences.insert(t);
    }
    EXPECT_EQ(names.size(), std::size(kAll));
    EXPECT_EQ(sentences.size(), std::size(kAll));
    EXPECT_STREQ(pgloss_status_name(static_cast<pgloss_status>(12345)), "PGLOSS_UNKNOWN");
    EXPECT_NE(pgloss_status_string(static_cast<pgloss_status>(-999)), nullptr);
}

TEST(Status, WarningsArePositiveErrorsNegative)
{
    EXPECT_EQ(PGLOSS_OK, 0);
    EXPECT_GT(PGLOSS_WARN_ALPHA_UNTRUSTED, 0);
    for (pgloss_status s : kAll)
        if (std::string(pgloss_status_name(s)).find("_ERR_") != std::string::npos) {
            EXPECT_LT(s, 0) << pgloss_status_name(s);
        }
}

TEST(NullPointers, EveryEntryPointRejectsNull)
{
    pgloss_physical p = {{0.2, 0.2, 0.2}, 0.05, 0.1, 0.1, PGLOSS_NORM_WARD};
    pgloss_material m;
    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    EXPECT_EQ(pgloss_material_init(nullptr, &p), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_material_init(&m, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(m.lobes, 0u) << "a failed init leaves a black material";

    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    const pgloss_vec3 w = {0.f, 0.f, 1.f};
    pgloss_rgb f;
    float pdf;
    pgloss_sample_record s;
    const float u[3] = {0.5f, 0.5f, 0.5f};
    EXPECT_EQ(pgloss_eval(nullptr, w, w, PGLOSS_LOBE_ALL, &f), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval(&m, w, w, PGLOSS_LOBE_ALL, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_pdf(&m, w, w, PGLOSS_LOBE_ALL, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval_pdf(&m, w, w, PGLOSS_LOBE_ALL, nullptr, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_sample(&m, w, nullptr, PGLOSS_LOBE_ALL, &s), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_sample(&m, w, u, PGLOSS_LOBE_ALL, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_pdf(nullptr, w, w, PGLOSS_LOBE_ALL, &pdf), PGLOSS_ERR_NULL);
    EXPECT_EQ(pdf, 0.0f);

    double x;
    EXPECT_EQ(pgloss_lightness_from_luminance(0.5, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_luminance_from_lightness(50, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_contrast_gloss(0.1, 0.1, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_specular_from_contrast(0.1, 0.1, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_gloss_from_physical(0.1, 0.1, 0.1, &x, nullptr, &x), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_physical_from_gloss(50, 0.1, 0.9, nullptr, &x, &x), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_gloss_distance(0, 0, 0, 0, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_envelope_contrast(50, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_match_gloss(0.1, 0.1, 50, &x, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_isogloss_contour(0.1, 0.9, 0.04, 4, nullptr, &x), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_check_physical(nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_check_perceptual(nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_physical_from_perceptual(nullptr, PGLOSS_NORM_WARD, &p), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_perceptual_from_physical(&p, nullptr), PGLOSS_ERR_NULL);
    double v3[3];
    EXPECT_EQ(pgloss_rgb_from_lab(nullptr, v3), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_lab_from_rgb(v3, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_luminance(nullptr, &x), PGLOSS_ERR_NULL);
}

TEST(Batch, NullArraysAndEmptyBatches)
{
    pgloss_physical p = {{0.2, 0.2, 0.2}, 0.05, 0.1, 0.1, PGLOSS_NORM_WARD};
    pgloss_material m;
    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    float a[1] = {1.f};
    const float *none = nullptr;
    const pgloss_strided3 v = soa(a, a, a), bad = soa(a, none, a);
    float r[1], g[1], b[1];
    const pgloss_strided3_out f = soa_out(r, g, b);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, 0, bad, bad, f, no_out(), nullptr), PGLOSS_OK)
        << "n = 0 reads nothing";
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, 1, bad, v, f, no_out(), nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, 1, v, v, no_out3(), no_out(), nullptr),
              PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_eval_pdf_batch(nullptr, nullptr, nullptr, PGLOSS_LOBE_ALL, 1, v, v, f, no_out(), nullptr),
              PGLOSS_ERR_NULL);
}

// The material init contract of brdf.h: rejects what cannot be evaluated, in the documented order.
TEST(Material, InitValidationOrder)
{
    pgloss_material m;
    const double nan = std::nan("");
    pgloss_physical p = {{0.2, 0.2, 0.2}, 0.05, 0.1, 0.1, PGLOSS_NORM_WARD};
    p.rho_s = nan;
    p.alpha_x = -1;
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_NONFINITE);
    p.rho_s = -0.1;
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_NEGATIVE);
    p.rho_s = 0.1;
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_ALPHA);
    p.alpha_x = 0.1;
    p.normalization = static_cast<pgloss_normalization>(7);
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_NORMALIZATION);
    p.normalization = PGLOSS_NORM_BOUNDED;
    p.rho_d[0] = 1e300;  // finite double, not a finite float
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_NONFINITE);
    p.rho_d[0] = 0.95;  // energy above 1 is allowed for rendering; check_physical says why not
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    EXPECT_EQ(pgloss_check_physical(&p), PGLOSS_ERR_ENERGY);
    p.alpha_x = p.alpha_y = 1e-9;
    EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    EXPECT_EQ(m.alpha_x, PGLOSS_ALPHA_MIN);
    EXPECT_EQ(m.lobes, unsigned(PGLOSS_LOBE_ALL));
}

}  // namespace
