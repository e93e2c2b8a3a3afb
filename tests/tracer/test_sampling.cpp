// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The tracer's sampling routines against independent references: the spherical rectangle
// (sphrect.hpp) against Van Oosterom & Strackee's solid angle of a triangle and a quadrature
// of the rectangle's solid angle, its samples against a chi-square test per cell; the Sobol'
// sampler (sampler.hpp) against Sobol's published first points and the (0, m, 2)-net property.
#include "sampler.hpp"
#include "sphrect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Solid angle of the triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983,
// IEEE Trans. Biomed. Eng. 30(2)): tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a).
double triangle_solid_angle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    double w = 2 * std::atan2(num, den);
    return w < 0 ? w + 2 * kPi : w;
}

// The solid angle of the part [s0, s1] × [t0, t1] (fractions of the edges) of a rectangle.
double cell_solid_angle(const pgt::RectFrame &r, glm::dvec3 o, double s0, double s1, double t0, double t1) {
    auto P = [&](double s, double t) { return r.corner + s * r.lx * r.ex + t * r.ly * r.ey - o; };
    return triangle_solid_angle(P(s0, t0), P(s1, t0), P(s1, t1)) + triangle_solid_angle(P(s0, t0), P(s1, t1), P(s0, t1));
}

struct Config {
    const char *name;
    glm::vec3 corner, edge1, edge2, o;
};

// The stimulus scene's light from a floor point, a point on the wall just below it (grazing),
// one right under a corner, one near the light's plane beside it, a rotated non-axis-aligned
// rectangle, a long thin one seen from its end, and a far point.
const Config kConfigs[] = {
    {"floor", {-0.5f, 2.999f, -1.0f}, {1, 0, 0}, {0, 0, 1}, {0.3f, 0.0f, -0.2f}},
    {"wall, grazing", {-0.5f, 2.999f, -1.0f}, {1, 0, 0}, {0, 0, 1}, {-2.0f, 2.9f, -0.5f}},
    {"under a corner, close", {-0.5f, 2.999f, -1.0f}, {1, 0, 0}, {0, 0, 1}, {-0.5f, 2.9f, -1.0f}},
    {"near the plane", {-0.5f, 2.999f, -1.0f}, {1, 0, 0}, {0, 0, 1}, {0.7f, 2.99f, 0.3f}},
    {"rotated", {0.2f, 1.0f, -0.4f}, {0.6f, 0.0f, 0.8f}, {-0.8f * 0.3f, 0.0f, 0.6f * 0.3f}, {0.1f, 0.2f, 0.3f}},
    {"long and thin", {0.0f, 0.0f, 0.0f}, {5.0f, 0.0f, 0.0f}, {0.0f, 0.05f, 0.0f}, {-0.2f, 0.01f, 0.3f}},
    {"far", {-0.5f, 2.999f, -1.0f}, {1, 0, 0}, {0, 0, 1}, {30.0f, -200.0f, 40.0f}},
};

pgt::RectFrame frame_of(const Config &c, glm::vec3 *normal = nullptr) {
    // Emitting towards o, as the scene's one-sided lights face what they light.
    glm::vec3 n = glm::normalize(glm::cross(c.edge1, c.edge2));
    if (glm::dot(c.o - c.corner, n) < 0) n = -n;
    if (normal) *normal = n;
    return pgt::rect_frame(c.corner, c.edge1, c.edge2, n);
}

TEST(SphericalRectangle, SolidAngleMatchesVanOosteromStrackeeAndQuadrature) {
    for (const Config &c : kConfigs) {
        const pgt::RectFrame r = frame_of(c);
        ASSERT_TRUE(r.valid) << c.name;
        // The frame's rectangle is the light's (its far corner within 1e-6 of the size).
        const glm::dvec3 far = glm::dvec3(c.corner) + glm::dvec3(c.edge1) + glm::dvec3(c.edge2);
        EXPECT_LT(glm::length(r.corner + r.lx * r.ex + r.ly * r.ey - far), 1e-6 * (r.lx + r.ly)) << c.name;
        const pgt::SphRect q = pgt::sphrect_setup(r, c.o);
        ASSERT_EQ(q.state, pgt::SphRect::OK) << c.name;
        const glm::dvec3 o(c.o);
        const double vos = cell_solid_angle(r, o, 0, 1, 0, 1);
        // ∫ cos θ_l / d² dA by the midpoint rule (the pdf 1/S integrates to 1 over it).
        const int M = 1000;
        double quad = 0;
        const glm::dvec3 n = glm::normalize(glm::cross(r.ex, r.ey));
        for (int i = 0; i < M; ++i)
            for (int j = 0; j < M; ++j) {
                const glm::dvec3 v = r.corner + (i + 0.5) / M * r.lx * r.ex + (j + 0.5) / M * r.ly * r.ey - o;
                const double d2 = glm::dot(v, v);
                quad += std::abs(glm::dot(n, v)) / (d2 * std::sqrt(d2));
            }
        quad *= r.lx * r.ly / (double(M) * M);
        std::printf("%-22s S %.9g, Van Oosterom-Strackee %.9g (rel %.1e), quadrature %.9g (rel %.1e)\n", c.name, q.S,
                    vos, q.S / vos - 1, quad, q.S / quad - 1);
        EXPECT_NEAR(q.S / vos, 1.0, 1e-9) << c.name;
        EXPECT_NEAR(q.S / quad, 1.0, 2e-3) << c.name;  // the midpoint rule's own error near the light
    }
}

// Wilson & Hilferty's approximation of the chi-square quantile with k degrees of freedom.
double chi2_quantile(double k, double z) {
    const double a = 2 / (9 * k);
    return k * std::pow(1 - a + z * std::sqrt(a), 3);
}

TEST(SphericalRectangle, SamplesAreUniformInSolidAngle) {
    std::mt19937_64 gen(12345);
    std::uniform_real_distribution<double> U(0, 1);
    for (const Config &c : kConfigs) {
        const pgt::RectFrame r = frame_of(c);
        const pgt::SphRect q = pgt::sphrect_setup(r, c.o);
        ASSERT_EQ(q.state, pgt::SphRect::OK) << c.name;
        // Cells of equal area on the rectangle; expected counts from their solid angles.
        const int G = 8, N = 400000;
        std::vector<double> count(G * G, 0.0);
        for (int k = 0; k < N; ++k) {
            const glm::dvec2 st = pgt::sphrect_sample(r, q, U(gen), U(gen));
            ASSERT_TRUE(std::isfinite(st.x) && std::isfinite(st.y)) << c.name;
            ASSERT_TRUE(st.x >= 0 && st.x <= r.lx && st.y >= 0 && st.y <= r.ly) << c.name;
            const int i = std::min(G - 1, int(st.x / r.lx * G)), j = std::min(G - 1, int(st.y / r.ly * G));
            count[size_t(i * G + j)] += 1;
        }
        double chi2 = 0, total = 0;
        for (int i = 0; i < G; ++i)
            for (int j = 0; j < G; ++j) {
                const double p = cell_solid_angle(r, glm::dvec3(c.o), double(i) / G, double(i + 1) / G, double(j) / G,
                                                  double(j + 1) / G) / q.S;
                total += p;
                const double e = p * N;
                ASSERT_GT(e, 5.0) << c.name << ": the cells are too small for the chi-square test";
                chi2 += (count[size_t(i * G + j)] - e) * (count[size_t(i * G + j)] - e) / e;
            }
        const double limit = chi2_quantile(G * G - 1, 4.265);  // p = 1e-5
        std::printf("%-22s chi-square %.1f (%d cells; 1e-5 quantile %.1f), cells' solid angles sum to %.9f S\n",
                    c.name, chi2, G * G, limit, total);
        EXPECT_LT(chi2, limit) << c.name;
        EXPECT_NEAR(total, 1.0, 1e-9) << c.name;
    }
}

TEST(SphericalRectangle, DegenerateCasesFallBackWithoutNaN) {
    const pgt::RectFrame r = pgt::rect_frame({-0.5f, 3, -1}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
    ASSERT_TRUE(r.valid);
    // Behind the light and in its plane: nothing to sample.
    EXPECT_EQ(pgt::sphrect_setup(r, {0, 3.5f, 0}).state, pgt::SphRect::BEHIND);
    EXPECT_EQ(pgt::sphrect_setup(r, {2, 3, 0}).state, pgt::SphRect::BEHIND);
    // A hair in front of the plane beside the light: the spherical rectangle is a sliver, sampled by area.
    EXPECT_EQ(pgt::sphrect_setup(r, {2, 2.999999f, 0}).state, pgt::SphRect::DEGENERATE);
    // Very far: area sampling.
    EXPECT_EQ(pgt::sphrect_setup(r, {0, -3e4f, 0}).state, pgt::SphRect::DEGENERATE);
    // A parallelogram that is not a rectangle, and a zero edge.
    EXPECT_FALSE(pgt::rect_frame({0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0, 0, 1}).valid);
    EXPECT_FALSE(pgt::rect_frame({0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}).valid);
    // Close and grazing points, with u, v at their ends: finite samples on the rectangle.
    const double us[] = {0.0, 1e-12, 0.5, 1 - 1e-12, 1.0 - 0x1p-24};
    for (glm::vec3 o : {glm::vec3(0, 2.9999f, -0.5f), glm::vec3(-0.5f, 2.99f, -1.0f), glm::vec3(3, 2.9f, 0.5f),
                        glm::vec3(0.5f, 2.0f, 0.0f), glm::vec3(1e-3f, 3 - 1e-5f, 1e-3f)}) {
        const pgt::SphRect q = pgt::sphrect_setup(r, o);
        if (q.state != pgt::SphRect::OK) continue;
        EXPECT_TRUE(q.S > 0 && q.S < 2 * kPi);
        for (double u : us)
            for (double v : us) {
                const glm::dvec2 st = pgt::sphrect_sample(r, q, u, v);
                EXPECT_TRUE(std::isfinite(st.x) && std::isfinite(st.y) && st.x >= 0 && st.x <= 1 && st.y >= 0 && st.y <= 1)
                    << "o " << o.x << "," << o.y << "," << o.z << " u " << u << " v " << v;
            }
    }
}

// ---------------------------------------------------------------- Sobol'

TEST(Sobol, FirstDimensionsAreSobolsSequence) {
    // The first points of Sobol's sequence, dimensions 1 and 2, as Joe & Kuo's generator
    // (sobol.cc, new-joe-kuo-6.21201) prints them: in Gray-code order, point n being the
    // sequence's point of index n ⊕ (n >> 1).
    const double d0[8] = {0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125};
    const double d1[8] = {0, 0.5, 0.25, 0.75, 0.375, 0.875, 0.125, 0.625};
    for (std::uint32_t n = 0; n < 8; ++n) {
        const std::uint32_t i = n ^ (n >> 1);
        EXPECT_EQ(pgt::sobol::dim0(i) * 0x1p-32, d0[n]) << n;
        EXPECT_EQ(pgt::sobol::dim1(i) * 0x1p-32, d1[n]) << n;
    }
}

TEST(Sobol, EachDimensionOfAPixelIsANet) {
    // The first 2^m samples of a pixel, in each 2D dimension of the path, put exactly one point
    // in each elementary interval of area 2^-m (a (0, m, 2)-net: what the scrambling keeps).
    const int m = 8, n = 1 << m;
    for (std::uint64_t pixel : {0ull, 1ull, 12345ull})
        for (int dim = 0; dim < 4; ++dim)
            for (int a = 0; a <= m; ++a) {  // intervals 2^-a × 2^-(m-a)
                std::set<std::pair<int, int>> seen;
                for (int s = 0; s < n; ++s) {
                    pgt::PathSampler ps(pgt::Sampler::SOBOL, 7, pixel, std::uint64_t(s));
                    glm::vec2 u{};
                    for (int d = 0; d <= dim; ++d) u = ps.get2();
                    ASSERT_TRUE(u.x >= 0 && u.x < 1 && u.y >= 0 && u.y < 1);
                    seen.insert({int(u.x * float(1 << a)), int(u.y * float(1 << (m - a)))});
                }
                EXPECT_EQ(int(seen.size()), n) << "pixel " << pixel << " dim " << dim << " interval 2^-" << a;
            }
}

TEST(Sobol, DimensionsAndPixelsAreDecorrelated) {
    // Different pixels and dimensions get different scrambles: the mean of the product of
    // two dimensions over many samples is 1/4 within noise, as for independent uniforms.
    double sum = 0, sum_px = 0;
    const int n = 1 << 14;
    for (int s = 0; s < n; ++s) {
        pgt::PathSampler a(pgt::Sampler::SOBOL, 1, 42, std::uint64_t(s)), b(pgt::Sampler::SOBOL, 1, 43, std::uint64_t(s));
        const float x = a.get1(), y = a.get1();
        sum += double(x) * y;
        sum_px += double(x) * b.get1();
    }
    // sd of the mean of a product of independent uniforms: sqrt(7/144) / sqrt(n) ≈ 0.0017
    EXPECT_NEAR(sum / n, 0.25, 0.01);
    EXPECT_NEAR(sum_px / n, 0.25, 0.01);
}

}  // namespace
