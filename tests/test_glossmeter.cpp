// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The virtual glossmeter (pgloss/glossmeter.h) against independent truth: the shared vectors
// (tests/vectors/glossmeter.json, mpmath and an independent quadrature), the primary standard,
// Fresnel mirrors, the closed form of a perfect diffuser, the sharp-lobe limit of eq. 2, the
// physics' monotonicity, the inverse's round trips, the finishes, and the error contract.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

extern "C" {
#include "pgloss/pgloss.h"
}

#ifndef PGLOSS_VECTORS_DIR
#error "PGLOSS_VECTORS_DIR must be defined (tests/CMakeLists.txt does it)"
#endif

namespace {

using json = nlohmann::json;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Unpolarised Fresnel reflectance, written here from the s and p amplitudes (not the library's form).
double fresnel(double n, double c)
{
    const double ct = std::sqrt(1.0 - (1.0 - c * c) / (n * n));
    const double rs = (c - n * ct) / (c + n * ct), rp = (n * c - ct) / (n * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

double mirror_of(double c, void *user) { return fresnel(*static_cast<double *>(user), c); }
double lambert(const double *, const double *, void *user) { return *static_cast<double *>(user) / kPi; }

double number(const json &v)
{
    if (v.is_string()) {
        const std::string s = v.get<std::string>();
        if (s == "nan") return std::nan("");
        return s == "inf" ? HUGE_VAL : -HUGE_VAL;
    }
    return v.get<double>();
}

pgloss_glossmeter_kind kind_of(const std::string &s)
{
    static const char *names[] = {"PGLOSS_GLOSS_20", "PGLOSS_GLOSS_60", "PGLOSS_GLOSS_85", "PGLOSS_HAZE_20",
                                  "PGLOSS_HAZE_INDEX", "PGLOSS_DOI_30", "PGLOSS_CONTRAST_60"};
    for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k)
        if (s == names[k]) return static_cast<pgloss_glossmeter_kind>(k);
    ADD_FAILURE() << "unknown kind " << s;
    return PGLOSS_GLOSS_60;
}

pgloss_physical paint(double rd, double rs, double a, pgloss_normalization n = PGLOSS_NORM_WARD)
{
    return pgloss_physical{{rd, rd, rd}, rs, a, a, n};
}

double read(pgloss_glossmeter_kind k, const pgloss_physical &p, double tol = 1e-8, double az = 0.0)
{
    pgloss_gloss_reading r;
    EXPECT_GE(pgloss_glossmeter_read_physical(k, &p, az, tol, &r), 0);
    return r.value;
}

TEST(GlossmeterVectors, EveryCase)
{
    const std::string path = std::string(PGLOSS_VECTORS_DIR) + "/glossmeter.json";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    const json doc = json::parse(in);
    int n = 0;
    for (const json &c : doc.at("cases")) {
        SCOPED_TRACE(c.at("id").get<std::string>());
        const std::string fn = c.at("function");
        const json &i = c.at("input");
        const std::string want_status = c.at("status");
        const double want = c.at("expected").contains("value") ? c.at("expected").at("value").get<double>() : 0.0;
        const double werr = c.at("error").get<double>();
        pgloss_status st;
        pgloss_gloss_reading got{0.0, 0.0};
        if (fn == "fresnel_dielectric") {
            st = pgloss_fresnel_dielectric(number(i.at("n")), number(i.at("c")), &got.value);
            if (st == PGLOSS_OK) {
                EXPECT_NEAR(got.value, want, 1e-14 * std::fabs(want) + 1e-300);
            }
        } else if (fn == "glossmeter_standard_flux") {
            pgloss_glossmeter_geometry g;
            ASSERT_EQ(pgloss_glossmeter_geometry_of(kind_of(i.at("kind")), &g), PGLOSS_OK);
            st = pgloss_glossmeter_standard_flux(&g, &got.value);
            EXPECT_NEAR(got.value, want, 1e-13 * want);
        } else {
            const pgloss_glossmeter_kind k = kind_of(i.at("kind"));
            const double tol = 1e-9;
            if (fn == "glossmeter_read_fresnel") {
                double idx = i.at("n");
                const pgloss_glossmeter_brdf b = {nullptr, mirror_of, &idx, 0.0};
                st = pgloss_glossmeter_read(k, &b, 0.0, tol, &got);
            } else if (fn == "glossmeter_read_lambert") {
                double rho = i.at("rho");
                const pgloss_glossmeter_brdf b = {lambert, nullptr, &rho, 1.0};
                st = pgloss_glossmeter_read(k, &b, 0.0, tol, &got);
            } else {
                ASSERT_EQ(fn, "glossmeter_read_physical");
                const json &p = i.at("physical");
                const pgloss_physical ph = {{p["rho_d"][0], p["rho_d"][1], p["rho_d"][2]}, p["rho_s"],
                                            p["alpha_x"], p["alpha_y"],
                                            static_cast<pgloss_normalization>(p["normalization"].get<int>())};
                st = pgloss_glossmeter_read_physical(k, &ph, i.at("azimuth_deg"), tol, &got);
            }
            if (st >= 0) {
                EXPECT_LE(std::fabs(got.value - want), got.error + werr + 1e-12 * std::fabs(want))
                    << "got " << got.value << " +- " << got.error << ", want " << want << " +- " << werr;
                EXPECT_LE(got.error, 1e-6 * std::max(1.0, std::fabs(want))) << "the error estimate is its own bound";
            }
        }
        EXPECT_STREQ(pgloss_status_name(st), want_status.c_str());
        ++n;
    }
    EXPECT_GE(n, 40);
}

// The primary standard reads 100 GU at each geometry; a Fresnel mirror of another index reads its
// Fresnel ratio × 100 (to second order in the source's half-width).
TEST(Glossmeter, BlackGlassAndFresnelMirrors)
{
    const double angles[3] = {20.0, 60.0, 85.0};
    for (int k = 0; k < 3; ++k) {
        for (double n : {1.567, 1.5, 1.45, 2.0}) {
            const pgloss_glossmeter_brdf b = {nullptr, mirror_of, &n, 0.0};
            pgloss_gloss_reading r;
            ASSERT_EQ(pgloss_glossmeter_read(static_cast<pgloss_glossmeter_kind>(k), &b, 0.0, 0.0, &r), PGLOSS_OK);
            const double c = std::cos(angles[k] * kDeg);
            EXPECT_NEAR(r.value, 100.0 * fresnel(n, c) / fresnel(1.567, c), n == 1.567 ? 1e-12 : 2e-4 * r.value)
                << "n " << n << " at " << angles[k];
        }
    }
}

// A perfect diffuser reads 100 (ρ/π) cos θ Q(receptor) Ω(source) / Φ(standard), with the closed
// forms of the projected solid angle of a centred gnomonic rectangle Q and of the solid angle Ω;
// Φ(standard) by a 400 × 400 midpoint rule here.
TEST(Glossmeter, PerfectDiffuserClosedForm)
{
    auto Q = [](double a, double b) {
        const double A = std::sqrt(1 + a * a), B = std::sqrt(1 + b * b);
        return 2.0 * (a / A * std::atan(b / A) + b / B * std::atan(a / B));
    };
    const double th[3] = {20, 60, 85}, rw[3] = {1.8, 4.4, 4.0}, rh[3] = {3.6, 11.7, 6.0};
    const double sa = std::tan(0.375 * kDeg), sb = std::tan(1.25 * kDeg);
    const double omega = 4.0 * std::atan(sa * sb / std::sqrt(1 + sa * sa + sb * sb));
    for (int k = 0; k < 3; ++k) {
        const double st = std::sin(th[k] * kDeg), ct = std::cos(th[k] * kDeg);
        double std_flux = 0.0;
        const int N = 400;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) {
                const double s = -sa + 2 * sa * (i + 0.5) / N, t = -sb + 2 * sb * (j + 0.5) / N, q = 1 + s * s + t * t;
                std_flux += fresnel(1.567, (ct - s * st) / std::sqrt(q)) / (q * std::sqrt(q));
            }
        std_flux *= 4 * sa * sb / (N * N);
        const double a = std::tan(0.5 * rw[k] * kDeg), b = std::tan(0.5 * rh[k] * kDeg);
        double rho = 0.8;
        const double want = 100.0 * rho / kPi * ct * Q(a, b) * omega / std_flux;
        const pgloss_glossmeter_brdf L = {lambert, nullptr, &rho, 1.0};
        pgloss_gloss_reading r;
        ASSERT_EQ(pgloss_glossmeter_read(static_cast<pgloss_glossmeter_kind>(k), &L, 0.0, 0.0, &r), PGLOSS_OK);
        EXPECT_NEAR(r.value, want, 1e-7 * want) << th[k];
        // and the Ward paint with no specular lobe reads the same (luminance of ρd)
        const pgloss_physical p = {{0.9, 0.8, 0.5}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD};
        const double Y = 0.21263900587151036 * 0.9 + 0.71516867876775593 * 0.8 + 0.072192315360733715 * 0.5;
        EXPECT_NEAR(read(static_cast<pgloss_glossmeter_kind>(k), p), want * Y / rho, 1e-6 * want);
    }
}

// gloss-bridge-facts.md: a sharp Ward lobe reads about 100 ρs cos θ / R_F(θ) GU.
TEST(Glossmeter, SharpWardLobeReadsRhoSCosThetaOverFresnel)
{
    const double th[3] = {20, 60, 85};
    for (int k = 0; k < 3; ++k) {
        const double c = std::cos(th[k] * kDeg);
        const double want = 100.0 * 0.066 * c / fresnel(1.567, c);
        EXPECT_NEAR(read(static_cast<pgloss_glossmeter_kind>(k), paint(0.0, 0.066, 0.002), 1e-6), want, 2e-3 * want);
    }
}

// Readings are linear in ρs, fall with α at every gloss geometry and for DOI, and haze rises with
// α while the lobe is sharper than the haze windows' offset.
TEST(Glossmeter, MonotoneWherePhysicsSaysSo)
{
    const double alphas[] = {0.005, 0.01, 0.02, 0.04, 0.07, 0.1, 0.2};
    for (int k : {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60, PGLOSS_GLOSS_85, PGLOSS_DOI_30}) {
        double prev = HUGE_VAL;
        for (double a : alphas) {
            const double g = read(static_cast<pgloss_glossmeter_kind>(k), paint(0.1, 0.05, a), 1e-6);
            EXPECT_LT(g, prev) << "kind " << k << " alpha " << a;
            prev = g;
        }
    }
    double prev = -1.0;
    for (double a : {0.003, 0.006, 0.01, 0.015}) {
        const double h = read(PGLOSS_HAZE_20, paint(0.1, 0.05, a), 1e-6);
        EXPECT_GT(h, prev) << a;
        prev = h;
    }
    for (int k : {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60, PGLOSS_GLOSS_85}) {
        const auto kk = static_cast<pgloss_glossmeter_kind>(k);
        const double g0 = read(kk, paint(0.2, 0.0, 0.05)), g1 = read(kk, paint(0.2, 0.03, 0.05)),
                     g2 = read(kk, paint(0.2, 0.06, 0.05));
        EXPECT_GT(g1, g0);
        EXPECT_NEAR(g2 - g1, g1 - g0, 1e-7 * g2) << "linear in rho_s";
    }
}

// An anisotropic lobe turned by 90° reads as the lobe with αx and αy swapped; the float material
// reads as its parameters (to float rounding).
TEST(Glossmeter, AnisotropyAzimuthAndMaterialPath)
{
    const pgloss_physical a = {{0.1, 0.1, 0.1}, 0.05, 0.03, 0.08, PGLOSS_NORM_WARD};
    const pgloss_physical b = {{0.1, 0.1, 0.1}, 0.05, 0.08, 0.03, PGLOSS_NORM_WARD};
    for (int k : {PGLOSS_GLOSS_20, PGLOSS_GLOSS_60}) {
        const auto kk = static_cast<pgloss_glossmeter_kind>(k);
        EXPECT_NEAR(read(kk, a, 1e-9, 90.0), read(kk, b, 1e-9, 0.0), 1e-7);
        EXPECT_GT(std::fabs(read(kk, a, 1e-9, 0.0) - read(kk, b, 1e-9, 0.0)), 0.1);
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &a), PGLOSS_OK);
        pgloss_gloss_reading r;
        ASSERT_EQ(pgloss_glossmeter_read_material(kk, &m, 0.0, 1e-9, &r), PGLOSS_OK);
        EXPECT_NEAR(r.value, read(kk, a, 1e-9), 1e-6 * r.value);
    }
}

// The error estimate is honest: a loose reading is within its estimate of a tight one.
TEST(Glossmeter, ErrorEstimateCoversTheError)
{
    for (double a : {0.004, 0.07})
        for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k) {
            if (k == PGLOSS_CONTRAST_60) continue;
            const auto kk = static_cast<pgloss_glossmeter_kind>(k);
            pgloss_gloss_reading loose, tight;
            const pgloss_physical p = paint(0.3, 0.08, a);
            ASSERT_GE(pgloss_glossmeter_read_physical(kk, &p, 0.0, 1e-3, &loose), 0);
            ASSERT_GE(pgloss_glossmeter_read_physical(kk, &p, 0.0, 1e-9, &tight), 0);
            EXPECT_LE(std::fabs(loose.value - tight.value), loose.error + tight.error + 1e-12)
                << "kind " << k << " alpha " << a;
        }
}

// Readings → paint returns the paint that made them (every second reading), with the documented
// assumption for one reading, and NO_FIT where no Ward paint reads so.
TEST(GlossmeterInverse, RoundTrips)
{
    struct C { double rd, rs, a; pgloss_gloss_second second; pgloss_glossmeter_kind k; };
    const C cases[] = {{0.193, 0.066, 0.04, PGLOSS_SECOND_GLOSS_20, PGLOSS_GLOSS_20},
                       {0.767, 0.099, 0.10, PGLOSS_SECOND_GLOSS_20, PGLOSS_GLOSS_20},
                       {0.03, 0.033, 0.07, PGLOSS_SECOND_DOI_30, PGLOSS_DOI_30},
                       {0.2, 0.05, 0.01, PGLOSS_SECOND_HAZE_20, PGLOSS_HAZE_20}};
    for (const C &c : cases) {
        const pgloss_physical p = paint(c.rd, c.rs, c.a);
        double L, cg, d;
        pgloss_gloss_from_physical(c.rd, c.rs, c.a, &L, &cg, &d);
        const double g60 = read(PGLOSS_GLOSS_60, p, 1e-9), x = read(c.k, p, 1e-9);
        pgloss_perceptual q;
        pgloss_physical out;
        EXPECT_EQ(pgloss_paint_from_gloss_units(L, 0, 0, PGLOSS_NORM_WARD, g60, c.second, x, &q, &out), PGLOSS_OK);
        EXPECT_NEAR(q.d, d, 2e-6) << c.rd << " " << c.rs << " " << c.a;
        EXPECT_NEAR(q.c, cg, 2e-6);
        EXPECT_NEAR(out.rho_s, c.rs, 2e-6);
        EXPECT_NEAR(out.rho_d[1], c.rd, 1e-9);
        // one reading: d given, or the assumed d = 0.93
        EXPECT_EQ(pgloss_paint_from_gloss_units(L, 0, 0, PGLOSS_NORM_WARD, g60, PGLOSS_SECOND_NONE, d, &q, &out), PGLOSS_OK);
        EXPECT_NEAR(q.c, cg, 1e-7);
    }
    pgloss_perceptual q;
    pgloss_physical out;
    const double g60 = read(PGLOSS_GLOSS_60, paint(0.2, 0.05, 0.07));
    pgloss_paint_from_gloss_units(50.0, 0, 0, PGLOSS_NORM_WARD, g60, PGLOSS_SECOND_NONE, 2.0, &q, &out);
    EXPECT_DOUBLE_EQ(q.d, PGLOSS_ASSUMED_DOI_GLOSS);
}

TEST(GlossmeterInverse, NoFitIsAStatusNotAGuess)
{
    pgloss_perceptual q;
    pgloss_physical p;
    // G20/G60 of a Ward paint never exceeds the sharp lobe's (cos 20°/R(20°))/(cos 60°/R(60°)) = 3.83
    EXPECT_EQ(pgloss_paint_from_gloss_units(50, 0, 0, PGLOSS_NORM_WARD, 20.0, PGLOSS_SECOND_GLOSS_20, 90.0, &q, &p),
              PGLOSS_ERR_NO_FIT);
    EXPECT_TRUE(std::isfinite(q.c) && std::isfinite(q.d));
    // a 60° gloss below what the diffuse alone reads
    EXPECT_EQ(pgloss_paint_from_gloss_units(95, 0, 0, PGLOSS_NORM_WARD, 0.5, PGLOSS_SECOND_NONE, 0.9, &q, &p),
              PGLOSS_ERR_NO_FIT);
    EXPECT_EQ(p.rho_s, 0.0);
    EXPECT_EQ(pgloss_paint_from_gloss_units(50, 0, 0, PGLOSS_NORM_WARD, -1.0, PGLOSS_SECOND_NONE, 0.9, &q, &p),
              PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_paint_from_gloss_units(120, 0, 0, PGLOSS_NORM_WARD, 10.0, PGLOSS_SECOND_NONE, 0.9, &q, &p),
              PGLOSS_ERR_LIGHTNESS);
    EXPECT_EQ(pgloss_paint_from_gloss_units(NAN, 0, 0, PGLOSS_NORM_WARD, 10.0, PGLOSS_SECOND_NONE, 0.9, &q, &p),
              PGLOSS_ERR_NONFINITE);
    EXPECT_EQ(pgloss_paint_from_gloss_units(50, 0, 0, PGLOSS_NORM_WARD, 10.0, PGLOSS_SECOND_NONE, 0.9, nullptr, &p),
              PGLOSS_ERR_NULL);
}

TEST(GlossmeterFinishes, TableAndRepresentativePaint)
{
    ASSERT_NE(pgloss_finish_find("satin"), nullptr);
    EXPECT_EQ(pgloss_finish_find("Satin"), pgloss_finish_find("G4"));
    EXPECT_EQ(pgloss_finish_find("mpi-g4"), pgloss_finish_find("satin"));
    EXPECT_EQ(pgloss_finish_find("semi gloss"), pgloss_finish_at(4));
    EXPECT_EQ(pgloss_finish_find("lacquer"), nullptr);
    EXPECT_EQ(pgloss_finish_at(7), nullptr);
    const pgloss_finish *f = pgloss_finish_find("satin");
    EXPECT_EQ(f->gloss_60_min, 20.0);
    EXPECT_EQ(f->gloss_60_max, 35.0);
    EXPECT_EQ(f->sheen_85_min, 35.0);
    pgloss_perceptual q;
    pgloss_physical p;
    double cr[2], dr[2];
    int sheen = 1;
    ASSERT_EQ(pgloss_finish_paint(f, 90.0, 0.0, 0.0, PGLOSS_NORM_WARD, &q, &p, cr, dr, &sheen), PGLOSS_OK);
    EXPECT_NEAR(read(PGLOSS_GLOSS_60, p, 1e-8), 27.5, 1e-4);
    EXPECT_DOUBLE_EQ(q.d, PGLOSS_ASSUMED_DOI_GLOSS);
    EXPECT_LE(cr[0], q.c);
    EXPECT_GE(cr[1], q.c);
    EXPECT_EQ(dr[0], 0.90);
    EXPECT_EQ(dr[1], 0.96);
    EXPECT_EQ(sheen, 0) << "no Ward paint reaches the 85° sheen of a satin";
}

TEST(Glossmeter, BadInputGetsAReason)
{
    pgloss_gloss_reading r{1.0, 1.0};
    const pgloss_physical ok = paint(0.2, 0.05, 0.05);
    EXPECT_EQ(pgloss_glossmeter_read_physical(static_cast<pgloss_glossmeter_kind>(99), &ok, 0, 0, &r), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(r.value, 0.0);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_GLOSS_60, nullptr, 0, 0, &r), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_GLOSS_60, &ok, NAN, 0, &r), PGLOSS_ERR_NONFINITE);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_GLOSS_60, &ok, 0, NAN, &r), PGLOSS_ERR_NONFINITE);
    const pgloss_physical neg = paint(0.2, -0.05, 0.05), zero_alpha = paint(0.2, 0.05, 0.0);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_GLOSS_60, &neg, 0, 0, &r), PGLOSS_ERR_NEGATIVE);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_GLOSS_60, &zero_alpha, 0, 0, &r), PGLOSS_ERR_ALPHA);
    pgloss_glossmeter_geometry g;
    ASSERT_EQ(pgloss_glossmeter_geometry_of(PGLOSS_GLOSS_85, &g), PGLOSS_OK);
    g.specular.width_deg = 20.0; // reaches the horizon at 85°
    double rho = 0.5;
    const pgloss_glossmeter_brdf L = {lambert, nullptr, &rho, 1.0};
    EXPECT_EQ(pgloss_glossmeter_read_geometry(PGLOSS_GLOSS_85, &g, &L, 0, 0, &r), PGLOSS_ERR_ARGUMENT);
    g.specular.width_deg = -1.0;
    EXPECT_EQ(pgloss_glossmeter_read_geometry(PGLOSS_GLOSS_85, &g, &L, 0, 0, &r), PGLOSS_ERR_ARGUMENT);
    EXPECT_EQ(pgloss_glossmeter_geometry_of(static_cast<pgloss_glossmeter_kind>(-1), &g), PGLOSS_ERR_ARGUMENT);
    double f;
    EXPECT_EQ(pgloss_fresnel_dielectric(1.0, 0.5, &f), PGLOSS_ERR_ARGUMENT);
    // contrast gloss needs diffuse reflection at 45°:0°
    const pgloss_physical black = paint(0.0, 0.05, 0.01);
    EXPECT_EQ(pgloss_glossmeter_read_physical(PGLOSS_CONTRAST_60, &black, 0, 0, &r), PGLOSS_ERR_ARGUMENT);
}

// ---- the gloss bridge's microfacet targets (pgloss_glossmeter_readings_bridge) ----------------

pgloss_bridge_params bridge_params(double base, double roughness, double ior, double specular)
{
    pgloss_bridge_params p{};
    p.base_color[0] = p.base_color[1] = p.base_color[2] = base;
    p.roughness = roughness;
    p.ior = ior;
    p.specular = specular;
    return p;
}

// The targets' conventions for a black dielectric of relative index n (docs/bridge.md): roughness
// is sqrt(α) except Mitsuba's alpha; Principled's Specular IOR Level 0.5 leaves F0 at the IOR's;
// Mitsuba's int_ior is relative to its ext_ior "air" = 1.000277.
struct BridgeCase { pgloss_bridge_target t; bool ggx_roughness; double ior_scale, specular; };
const BridgeCase kBridgeCases[] = {
    {PGLOSS_BRIDGE_OPENPBR, true, 1.0, 1.0},          {PGLOSS_BRIDGE_STANDARD_SURFACE, true, 1.0, 1.0},
    {PGLOSS_BRIDGE_GLTF, true, 1.0, 1.0},             {PGLOSS_BRIDGE_PRINCIPLED, true, 1.0, 0.5},
    {PGLOSS_BRIDGE_ROUGHPLASTIC_GGX, false, 1.000277, 1.0},
    {PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN, false, 1.000277, 1.0}};

// In the smooth limit a black dielectric reads the Fresnel ratio of ISO 2813's definition,
// 100 R_F(n, θ)/R_F(1.567, θ), at 20°, 60° and 85°: both through the quadrature of a sharp lobe
// (α = 2e-4) and as the ideal mirror below α = 1e-4. 2e-3 relative covers the lobe's Fresnel
// and shadowing at that α (~1e-4) and the aperture's averaging of the two Fresnel curves.
TEST(GlossmeterBridge, SmoothLimitIsTheFresnelRatio)
{
    const double th[3] = {20, 60, 85};
    for (const BridgeCase &bc : kBridgeCases)
        for (double n : {1.33, 2.0})
            for (double alpha : {2e-4, 5e-5}) {
                if (alpha > 1e-4 && n > 1.5)
                    continue; // the sharp lobe's quadrature takes ~0.5 s: one index per target
                const double rough = bc.ggx_roughness ? std::sqrt(alpha) : alpha;
                const pgloss_bridge_params p = bridge_params(0.0, rough, n * bc.ior_scale, bc.specular);
                pgloss_glossmeter_readings r;
                ASSERT_GE(pgloss_glossmeter_readings_bridge(bc.t, &p, 0, 1e-4, &r), PGLOSS_OK)
                    << pgloss_bridge_target_name(bc.t);
                for (int k = 0; k < 3; ++k) {
                    const double c = std::cos(th[k] * kDeg), want = 100.0 * fresnel(n, c) / fresnel(1.567, c);
                    EXPECT_NEAR(r.r[k].value, want, 2e-3 * want)
                        << pgloss_bridge_target_name(bc.t) << " n " << n << " alpha " << alpha << " at " << th[k];
                }
            }
}

// Beckmann's D is Ward's Gaussian in tan θh (Ward 1992; Walter et al. 2007 eq. 25), so a black
// roughplastic at α reads as the Ward paint of the same α whose ρs carries the Fresnel factor
// and the cosine Ward's lobe lacks: G_beck/R_F(n, θ) = G_ward/(ρs cos θ). The two lobes differ
// at second order in the window's offsets from the mirror direction (Ward's 1/sqrt(μi μo)
// against Beckmann's 1/(μi μo cos⁴θh)), O(α² (1 + tan²θ)): at most 1 % at α = 0.05 and 60°.
// Shadowing is 1 there (Mitsuba's G1 fit is 1 for 1/(α tan θ) >= 1.6). Tolerance 1 %.
TEST(GlossmeterBridge, BeckmannReadsAsWardOfTheSameAlpha)
{
    const double th[2] = {20, 60}, n = 1.5, rho_s = 0.1;
    for (double alpha : {0.01, 0.02, 0.05}) {
        const pgloss_bridge_params p = bridge_params(0.0, alpha, n * 1.000277, 1.0);
        pgloss_glossmeter_readings rb;
        ASSERT_GE(pgloss_glossmeter_readings_bridge(PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN, &p, 0, 1e-5, &rb), PGLOSS_OK);
        for (int k = 0; k < 2; ++k) {
            const double c = std::cos(th[k] * kDeg);
            const double ward = read(static_cast<pgloss_glossmeter_kind>(k), paint(0.0, rho_s, alpha), 1e-6);
            const double want = ward / (rho_s * c) * fresnel(n, c);
            EXPECT_NEAR(rb.r[k].value, want, 0.01 * want) << "alpha " << alpha << " at " << th[k];
        }
    }
}

// Over each target's parameter ranges every reading is finite and >= 0, and a base gives
// contrast gloss a diffuse reference. DOI alone may dip below 0 by quadrature-size amounts where
// the lobe is far wider than the 0.3° offset (R0.3 ≈ Rs: Fresnel and shadowing tilt the flat top).
// (Lobes of α ~ 1e-3 take about a second each: the range's ends and middle are read here.)
TEST(GlossmeterBridge, FiniteAndNonNegativeOverTheRanges)
{
    for (const BridgeCase &bc : kBridgeCases)
        for (double alpha : {1e-5, 0.02, 0.3, 1.0})
            for (double n : {1.05, 3.0})
                for (double base : {0.0, 1.0}) {
                    const double rough = bc.ggx_roughness ? std::sqrt(alpha) : alpha;
                    const pgloss_bridge_params p = bridge_params(base, rough, n * bc.ior_scale, bc.specular);
                    pgloss_glossmeter_readings r;
                    const pgloss_status st = pgloss_glossmeter_readings_bridge(bc.t, &p, 0, 1e-4, &r);
                    ASSERT_GE(st, PGLOSS_OK) << pgloss_bridge_target_name(bc.t) << " " << alpha << " " << n;
                    for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k) {
                        EXPECT_TRUE(std::isfinite(r.r[k].value));
                        if (k != PGLOSS_HAZE_INDEX) {
                            EXPECT_GE(r.r[k].value, k == PGLOSS_DOI_30 ? -0.01 : 0.0)
                                << pgloss_bridge_target_name(bc.t) << " kind " << k;
                        }
                    }
                    if (base > 0.0) {
                        EXPECT_GT(r.r[PGLOSS_CONTRAST_60].value, 0.0);
                    }
                }
}

TEST(GlossmeterBridge, BadInputGetsAReason)
{
    pgloss_glossmeter_readings r;
    const pgloss_bridge_params ok = bridge_params(0.5, 0.3, 1.5, 1.0);
    EXPECT_EQ(pgloss_glossmeter_readings_bridge(PGLOSS_BRIDGE_OPENPBR, nullptr, 0, 0, &r), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_glossmeter_readings_bridge(PGLOSS_BRIDGE_OPENPBR, &ok, 0, 0, nullptr), PGLOSS_ERR_NULL);
    EXPECT_EQ(pgloss_glossmeter_readings_bridge(static_cast<pgloss_bridge_target>(99), &ok, 0, 0, &r),
              PGLOSS_ERR_ARGUMENT);
    const auto expect = [&](pgloss_bridge_target t, pgloss_bridge_params p, pgloss_status want) {
        r.r[0].value = 1.0;
        EXPECT_EQ(pgloss_glossmeter_readings_bridge(t, &p, 0, 0, &r), want) << pgloss_bridge_target_name(t);
        EXPECT_EQ(r.r[0].value, 0.0);
    };
    expect(PGLOSS_BRIDGE_OPENPBR, bridge_params(0.5, -0.1, 1.5, 1.0), PGLOSS_ERR_NEGATIVE);
    expect(PGLOSS_BRIDGE_OPENPBR, bridge_params(0.5, 0.0, 1.5, 1.0), PGLOSS_ERR_NEGATIVE);
    expect(PGLOSS_BRIDGE_GLTF, bridge_params(0.5, 0.3, NAN, 1.0), PGLOSS_ERR_NONFINITE);
    expect(PGLOSS_BRIDGE_PRINCIPLED, bridge_params(1.5, 0.3, 1.5, 0.5), PGLOSS_ERR_BRIDGE_BASE);
    expect(PGLOSS_BRIDGE_GLTF_CORE, bridge_params(0.5, 0.3, 1.4, 1.0), PGLOSS_ERR_ARGUMENT);
    expect(PGLOSS_BRIDGE_ROUGHPLASTIC_GGX, bridge_params(0.5, 2.0, 1.5, 1.0), PGLOSS_ERR_BRIDGE_ROUGHNESS);
    expect(PGLOSS_BRIDGE_GLTF, bridge_params(0.5, 0.3, 1.5, 100.0), PGLOSS_ERR_BRIDGE_SPECULAR);
    EXPECT_EQ(pgloss_glossmeter_readings_bridge(PGLOSS_BRIDGE_OPENPBR, &ok, 0, 0, &r), PGLOSS_OK);
    EXPECT_GT(r.r[PGLOSS_GLOSS_60].value, 0.0);
}

}  // namespace
