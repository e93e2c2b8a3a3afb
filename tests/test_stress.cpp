// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Stress test: 10^6 random and adversarial inputs per public function (a quarter under the
// sanitizers): grazing and exactly horizontal directions, ±0, denormals, FLT_MAX / DBL_MAX,
// NaN and ±Inf, tiny α (1e-4 and below, raised to PGLOSS_ALPHA_MIN), huge α (up to FLT_MAX),
// random numbers 0, 1 − 2^-24, 1, ±Inf, NaN, extreme lightness, negative values. For every
// call: every output is finite, the status is one the header documents for that function,
// and the header's classification holds (a NaN/Inf input is PGLOSS_ERR_NONFINITE, a NaN
// random number PGLOSS_ERR_RANDOM, ...), error outputs are the documented fallback, and
// BRDF values are non-negative with weight 0 wherever pdf is 0. Under the sanitizer build
// (scripts/test-core.sh) any ASan/UBSan report aborts the test. Counts are printed.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <set>
#include <vector>

#include "batch_util.h"
#include "test_common.h"

using namespace pgt;

namespace {

// Per-function tally of statuses, printed at the end of each test.
struct Tally {
    explicit Tally(std::string name) : fn(std::move(name)) {}
    std::string fn;
    std::size_t calls = 0, nonfinite_out = 0, bad_status = 0, bad_value = 0;
    std::map<int, std::size_t> by_status;
    void add(pgloss_status s) {
        ++calls;
        ++by_status[s];
    }
    void print() const {
        std::printf("[stress] %-26s %8zu calls  nonfinite outputs %zu  undocumented statuses %zu  bad values %zu |", fn.c_str(),
                    calls, nonfinite_out, bad_status, bad_value);
        for (const auto &[s, n] : by_status) std::printf(" %s:%zu", pgloss_status_name(static_cast<pgloss_status>(s)) + 7, n);
        std::printf("\n");
    }
};

bool fin(double v) { return std::isfinite(v); }

// ----- generators ----------------------------------------------------------------------

float special_u(Pcg32 &rng) {
    static const float v[] = {0.0f, -0.0f, 1.0f - 0x1p-24f, 1.0f, 2.0f, -1.0f, FLT_MAX, -FLT_MAX, FLT_TRUE_MIN,
                              0x1p-24f, 0.5f, INFINITY, -INFINITY, NAN};
    return v[rng.below(sizeof v / sizeof v[0])];
}
float rand_u(Pcg32 &rng) {
    const std::uint32_t k = rng.below(10);
    if (k < 6) return rng.uniform_float();
    if (k < 9) return special_u(rng);
    return wild_float(rng);
}

float grazing_z(Pcg32 &rng) {
    static const float v[] = {0.0f, -0.0f, FLT_TRUE_MIN, -FLT_TRUE_MIN, FLT_MIN, 1e-30f, 1e-10f, 1e-9f, 2e-9f,
                              1e-6f, 1e-4f, 1e-3f};
    return v[rng.below(sizeof v / sizeof v[0])];
}

pgloss_vec3 rand_dir(Pcg32 &rng) {
    switch (rng.below(10)) {
    case 0: case 1: case 2: case 3: return random_upper(rng, 1e-6);
    case 4: case 5: {  // grazing / horizontal, unit in xy
        const double ph = 2 * kPi * rng.uniform();
        return {static_cast<float>(std::cos(ph)), static_cast<float>(std::sin(ph)), grazing_z(rng)};
    }
    case 6: return {wild_float(rng), wild_float(rng), wild_float(rng)};
    case 7: {  // scaled: tiny or huge lengths, denormals
        pgloss_vec3 v = random_upper(rng, 1e-3);
        const float s = special_float(rng);
        return {v.x * s, v.y * s, v.z * s};
    }
    case 8: {
        pgloss_vec3 v = random_sphere(rng);
        if (rng.below(4) == 0) v = {0.0f, 0.0f, rng.below(2) ? 0.0f : -0.0f};
        return v;
    }
    default: {
        pgloss_vec3 v = random_upper(rng);
        float *c[3] = {&v.x, &v.y, &v.z};
        *c[rng.below(3)] = nonfinite_float(rng);
        return v;
    }
    }
}

bool dir_valid(pgloss_vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && (v.x != 0 || v.y != 0 || v.z != 0);
}

double material_value(Pcg32 &rng, bool alpha) {
    switch (rng.below(8)) {
    case 0: return wild_double(rng);
    case 1: return rng.below(6) == 0 ? nonfinite_double(rng) : wild_double(rng);
    case 2: {
        static const double a[] = {1e-4, 1e-5, 1e-30, 1e-310, 0.0, -0.0, 1e19, 1e20, 1e30, FLT_MAX, 3.5e38, 1.0};
        static const double r[] = {0.0, -0.0, 1e-45, 1e-38, 1.0, 1e30, FLT_MAX, 3.5e38, DBL_MAX, 1e-310};
        return alpha ? a[rng.below(sizeof a / sizeof a[0])] : r[rng.below(sizeof r / sizeof r[0])];
    }
    default: return alpha ? std::pow(10.0, rng.uniform(-4, 0.3)) : rng.uniform();
    }
}

pgloss_physical rand_physical(Pcg32 &rng) {
    pgloss_physical p{};
    const bool grey = rng.below(2);
    for (int k = 0; k < 3; ++k) p.rho_d[k] = (grey && k > 0) ? p.rho_d[0] : material_value(rng, false);
    if (rng.below(6) == 0) p.rho_d[0] = p.rho_d[1] = p.rho_d[2] = 0.0;
    p.rho_s = rng.below(6) == 0 ? 0.0 : material_value(rng, false);
    p.alpha_x = material_value(rng, true);
    p.alpha_y = rng.below(2) ? p.alpha_x : material_value(rng, true);
    // 3 is outside the enumerators but inside the enum's value range (valid C++): unknown.
    p.normalization = static_cast<pgloss_normalization>(rng.below(20) == 0 ? 3 : rng.below(3));
    return p;
}

// The header's order of material_init checks.
pgloss_status expected_init(const pgloss_physical &p) {
    const double v[6] = {p.rho_d[0], p.rho_d[1], p.rho_d[2], p.rho_s, p.alpha_x, p.alpha_y};
    for (double x : v)
        if (!std::isfinite(x) || std::fabs(x) > FLT_MAX) return PGLOSS_ERR_NONFINITE;
    for (int k = 0; k < 4; ++k)
        if (v[k] < 0) return PGLOSS_ERR_NEGATIVE;
    if (!(p.alpha_x > 0) || !(p.alpha_y > 0)) return PGLOSS_ERR_ALPHA;
    if (p.normalization != PGLOSS_NORM_WARD && p.normalization != PGLOSS_NORM_WARD_DUR &&
        p.normalization != PGLOSS_NORM_BOUNDED)
        return PGLOSS_ERR_NORMALIZATION;
    return PGLOSS_OK;
}

unsigned rand_mask(Pcg32 &rng) {
    static const unsigned v[] = {PGLOSS_LOBE_ALL, PGLOSS_LOBE_ALL, PGLOSS_LOBE_DIFFUSE, PGLOSS_LOBE_SPECULAR,
                                 PGLOSS_LOBE_NONE, 4u, 0xFFFFFFFFu};
    return v[rng.below(sizeof v / sizeof v[0])];
}

bool rgb_ok(const pgloss_rgb &c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0;
}

// ----- BRDF ------------------------------------------------------------------------------

TEST(Stress, MaterialAndScalarBrdf) {
    const std::size_t n = scaled(1000000);
    Pcg32 rng(101);
    Tally ti{"material_init"}, tp{"specular_probability"}, te{"eval"}, tq{"pdf"}, tep{"eval_pdf"}, ts{"sample"};
    pgloss_material m;
    pgloss_physical p{};
    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_ERR_ALPHA);  // black until the first swap
    unsigned fresh = 0;
    for (std::size_t k = 0; k < n; ++k) {
        // material_init on every iteration (into a scratch material); the BRDF calls switch to
        // that material every 4th iteration.
        {
            pgloss_material mm;
            p = rand_physical(rng);
            const pgloss_status st = pgloss_material_init(&mm, &p);
            if (fresh == 0) m = mm;
            ti.add(st);
            if (st != expected_init(p)) ++ti.bad_status;
            const float fl[] = {mm.rho_d[0], mm.rho_d[1], mm.rho_d[2], mm.rho_s, mm.alpha_x, mm.alpha_y,
                                mm.inv_alpha_x, mm.inv_alpha_y, mm.spec_scale, mm.pdf_scale, mm.weight_diffuse,
                                mm.weight_specular};
            for (float v : fl)
                if (!std::isfinite(v)) ++ti.nonfinite_out;
            if (st != PGLOSS_OK && mm.lobes != 0) ++ti.bad_value;  // a failed init leaves black
            if (st == PGLOSS_OK && (mm.alpha_x < PGLOSS_ALPHA_MIN || mm.alpha_y < PGLOSS_ALPHA_MIN)) ++ti.bad_value;
            const float ps = pgloss_specular_probability(&mm, rand_mask(rng));
            tp.add(PGLOSS_OK);
            if (!std::isfinite(ps)) ++tp.nonfinite_out;
            if (!(ps >= 0 && ps <= 1)) ++tp.bad_value;
        }
        fresh = (fresh + 1) % 4;
        const pgloss_vec3 wo = rand_dir(rng), wi = rand_dir(rng);
        const unsigned mask = rand_mask(rng);
        const pgloss_status want = (dir_valid(wo) && dir_valid(wi)) ? PGLOSS_OK : PGLOSS_ERR_DIRECTION;

        pgloss_rgb f;
        pgloss_status st = pgloss_eval(&m, wo, wi, mask, &f);
        te.add(st);
        if (st != want) ++te.bad_status;
        if (!all_finite(f)) ++te.nonfinite_out;
        if (!rgb_ok(f) || (st != PGLOSS_OK && (f.r != 0 || f.g != 0 || f.b != 0))) ++te.bad_value;

        float pdf = -1;
        st = pgloss_pdf(&m, wo, wi, mask, &pdf);
        tq.add(st);
        if (st != want) ++tq.bad_status;
        if (!std::isfinite(pdf)) ++tq.nonfinite_out;
        if (!(pdf >= 0) || (st != PGLOSS_OK && pdf != 0)) ++tq.bad_value;

        pgloss_rgb f2;
        float pdf2 = -1;
        st = pgloss_eval_pdf(&m, wo, wi, mask, &f2, &pdf2);
        tep.add(st);
        if (st != want) ++tep.bad_status;
        if (!all_finite(f2) || !std::isfinite(pdf2)) ++tep.nonfinite_out;
        if (f2.r != f.r || f2.g != f.g || f2.b != f.b || pdf2 != pdf) ++tep.bad_value;

        const float u[3] = {rand_u(rng), rand_u(rng), rand_u(rng)};
        pgloss_sample_record s;
        st = pgloss_sample(&m, wo, u, mask, &s);
        ts.add(st);
        const pgloss_status want_s = (std::isnan(u[0]) || std::isnan(u[1]) || std::isnan(u[2])) ? PGLOSS_ERR_RANDOM
                                     : dir_valid(wo)                                            ? PGLOSS_OK
                                                                                                : PGLOSS_ERR_DIRECTION;
        if (st != want_s) ++ts.bad_status;
        if (!all_finite(s.wi) || !std::isfinite(s.pdf) || !all_finite(s.weight)) ++ts.nonfinite_out;
        bool bad = !rgb_ok(s.weight) || !(s.pdf >= 0);
        if (!(s.pdf > 0) && (s.weight.r != 0 || s.weight.g != 0 || s.weight.b != 0)) bad = true;  // bug (a)
        if (st != PGLOSS_OK && s.pdf != 0) bad = true;
        if (s.lobe != PGLOSS_LOBE_NONE) {
            const double l = std::sqrt(static_cast<double>(s.wi.x) * s.wi.x + static_cast<double>(s.wi.y) * s.wi.y +
                                       static_cast<double>(s.wi.z) * s.wi.z);
            if (std::fabs(l - 1) > 1e-5) bad = true;  // "sampled direction, unit length"
        }
        if (s.pdf > 0 && !(s.wi.z > 0)) bad = true;
        if (bad) ++ts.bad_value;
    }
    for (const Tally *t : {&ti, &tp, &te, &tq, &tep, &ts}) {
        t->print();
        EXPECT_EQ(t->nonfinite_out, 0u) << t->fn;
        EXPECT_EQ(t->bad_status, 0u) << t->fn;
        EXPECT_EQ(t->bad_value, 0u) << t->fn;
    }
}

TEST(Stress, BatchBrdf) {
    const std::size_t n = scaled(1000000), nb = 1024;
    Pcg32 rng(202);
    Tally te{"eval_batch"}, tq{"pdf_batch"}, tep{"eval_pdf_batch"}, ts{"sample_batch"};
    std::vector<float> ox(nb), oy(nb), oz(nb), ix(nb), iy(nb), iz(nb), r(nb), g(nb), b(nb), pdf(nb), r2(nb), g2(nb),
        b2(nb), pdf2(nb), u0(nb), u1(nb), u2(nb), wx(nb), wy(nb), wz(nb);
    std::vector<unsigned char> lobe(nb);
    for (std::size_t base = 0; base < n; base += nb) {
        pgloss_material m;
        const pgloss_physical p = rand_physical(rng);
        pgloss_material_init(&m, &p);
        const unsigned mask = rand_mask(rng);
        const bool clean = rng.below(3) == 0;  // a third of the batches all valid: status OK expected
        pgloss_status want = PGLOSS_OK, want_s = PGLOSS_OK;
        bool rnd_bad = false;
        for (std::size_t j = 0; j < nb; ++j) {
            pgloss_vec3 a = rand_dir(rng), c = rand_dir(rng);
            if (clean) {
                if (!dir_valid(a)) a = {0, 0, 1};
                if (!dir_valid(c)) c = {0, 0, 1};
            }
            ox[j] = a.x, oy[j] = a.y, oz[j] = a.z, ix[j] = c.x, iy[j] = c.y, iz[j] = c.z;
            u0[j] = rand_u(rng), u1[j] = rand_u(rng), u2[j] = rand_u(rng);
            if (clean) {
                if (std::isnan(u0[j])) u0[j] = 0.5f;
                if (std::isnan(u1[j])) u1[j] = 0.5f;
                if (std::isnan(u2[j])) u2[j] = 0.5f;
            }
            if (!dir_valid(a) || !dir_valid(c)) want = PGLOSS_ERR_DIRECTION;
            // sample: the first invalid element's reason, RANDOM checked before DIRECTION.
            if (want_s == PGLOSS_OK && !rnd_bad) {
                if (std::isnan(u0[j]) || std::isnan(u1[j]) || std::isnan(u2[j])) want_s = PGLOSS_ERR_RANDOM, rnd_bad = true;
                else if (!dir_valid(a)) want_s = PGLOSS_ERR_DIRECTION;
            }
        }
        const pgloss_strided3 wo = soa(ox.data(), oy.data(), oz.data()), wi = soa(ix.data(), iy.data(), iz.data());
        pgloss_status st =
            pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi, soa_out(r.data(), g.data(), b.data()), no_out(),
                                  nullptr);
        te.add(st);
        if (st != want) ++te.bad_status;
        st = pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi, no_out3(), col_out(pdf.data()), nullptr);
        tq.add(st);
        if (st != want) ++tq.bad_status;
        st = pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi, soa_out(r2.data(), g2.data(), b2.data()),
                                   col_out(pdf2.data()), nullptr);
        tep.add(st);
        if (st != want) ++tep.bad_status;
        for (std::size_t j = 0; j < nb; ++j) {
            const bool valid = dir_valid({ox[j], oy[j], oz[j]}) && dir_valid({ix[j], iy[j], iz[j]});
            if (!fin(r[j]) || !fin(g[j]) || !fin(b[j])) ++te.nonfinite_out;
            if (!(r[j] >= 0 && g[j] >= 0 && b[j] >= 0) || (!valid && (r[j] != 0 || g[j] != 0 || b[j] != 0))) ++te.bad_value;
            if (!fin(pdf[j])) ++tq.nonfinite_out;
            if (!(pdf[j] >= 0) || (!valid && pdf[j] != 0)) ++tq.bad_value;
            if (!fin(r2[j]) || !fin(pdf2[j])) ++tep.nonfinite_out;
            if (r2[j] != r[j] || g2[j] != g[j] || b2[j] != b[j] || pdf2[j] != pdf[j]) ++tep.bad_value;
        }
        st = pgloss_sample_batch(nullptr, &m, nullptr, mask, nb, wo, soa(u0.data(), u1.data(), u2.data()),
                                 soa_out(wx.data(), wy.data(), wz.data()), col_out(pdf.data()),
                                 soa_out(r.data(), g.data(), b.data()), lobe.data(), nullptr);
        ts.add(st);
        if (st != want_s) ++ts.bad_status;
        for (std::size_t j = 0; j < nb; ++j) {
            if (!fin(wx[j]) || !fin(wy[j]) || !fin(wz[j]) || !fin(pdf[j]) || !fin(r[j]) || !fin(g[j]) || !fin(b[j]))
                ++ts.nonfinite_out;
            bool bad = !(pdf[j] >= 0) || !(r[j] >= 0 && g[j] >= 0 && b[j] >= 0);
            if (!(pdf[j] > 0) && (r[j] != 0 || g[j] != 0 || b[j] != 0)) bad = true;
            if (pdf[j] > 0 && !(wz[j] > 0)) bad = true;
            if (bad) ++ts.bad_value;
        }
    }
    for (const Tally *t : {&te, &tq, &tep, &ts}) {
        std::printf("[stress] %-26s (%zu elements in batches of %zu)\n", t->fn.c_str(), n, nb);
        t->print();
        EXPECT_EQ(t->nonfinite_out, 0u) << t->fn;
        EXPECT_EQ(t->bad_status, 0u) << t->fn;
        EXPECT_EQ(t->bad_value, 0u) << t->fn;
    }
}

// Huge α: the half vector (αx s cos t, αy s sin t, 1) overflows float unless scaled first.
// The batch must give finite unit directions that agree with the scalar reference.
TEST(Stress, HugeAlphaBatchMatchesScalar) {
    Pcg32 rng(303);
    std::size_t worse = 0, total = 0;
    double max_d = 0;
    for (double a : {1e10, 1.8e19, 1e20, 1e25, 1e30, 1e38, static_cast<double>(FLT_MAX)}) {
        pgloss_material m;
        const pgloss_physical p = physical(0, 0, 0, 0.5, a, rng.below(2) ? a : 0.3, PGLOSS_NORM_WARD);
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const std::size_t nb = 512;
        std::vector<float> ox(nb), oy(nb), oz(nb), u0(nb, 0.0f), u1(nb), u2(nb), wx(nb), wy(nb), wz(nb), pdf(nb),
            r(nb), g(nb), b(nb);
        for (std::size_t j = 0; j < nb; ++j) {
            const pgloss_vec3 o = random_upper(rng, 0.05);
            ox[j] = o.x, oy[j] = o.y, oz[j] = o.z;
            u1[j] = rng.uniform_float(), u2[j] = rng.uniform_float();
        }
        u1[0] = 0.0f;  // s = 0: h = +z
        ASSERT_EQ(pgloss_sample_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, nb, soa(ox.data(), oy.data(), oz.data()),
                                      soa(u0.data(), u1.data(), u2.data()), soa_out(wx.data(), wy.data(), wz.data()),
                                      col_out(pdf.data()), soa_out(r.data(), g.data(), b.data()), nullptr, nullptr),
                  PGLOSS_OK);
        for (std::size_t j = 0; j < nb; ++j) {
            const float u[3] = {u0[j], u1[j], u2[j]};
            pgloss_sample_record s;
            ASSERT_EQ(pgloss_sample(&m, {ox[j], oy[j], oz[j]}, u, PGLOSS_LOBE_ALL, &s), PGLOSS_OK);
            ASSERT_TRUE(fin(wx[j]) && fin(wy[j]) && fin(wz[j])) << "alpha " << a;
            const double d = std::max({std::fabs(s.wi.x - wx[j]), std::fabs(s.wi.y - wy[j]), std::fabs(s.wi.z - wz[j])});
            max_d = std::max(max_d, d);
            ++total;
            if (d > 1e-4) ++worse;
        }
    }
    std::printf("[stress] huge alpha (1e10..FLT_MAX): %zu samples, max |wi_batch - wi_scalar| = %.3g, %zu above 1e-4\n",
                total, max_d, worse);
    EXPECT_EQ(worse, 0u);
}

// ----- perceptual, colour, status --------------------------------------------------------

double rand_d(Pcg32 &rng) {
    switch (rng.below(12)) {
    case 0: return nonfinite_double(rng);
    case 1: case 2: case 3: return wild_double(rng);
    case 4: {  // around the special points of the model
        static const double v[] = {0.0, -0.0, 8.0, 100.0, 100.0 + 1e-13, -1e-300, 216.0 / 24389.0, 0.2, 0.8, 1.0,
                                   1e103, 6.6e104, 1e105, 1e300, DBL_MAX, DBL_TRUE_MIN};
        return v[rng.below(sizeof v / sizeof v[0])];
    }
    case 5: case 6: return rng.uniform(0, 100);   // lightness-like
    case 7: return rng.uniform(-130, 130);        // a*, b*-like
    default: return rng.uniform(-0.1, 1.1);        // reflectance / c / d-like
    }
}

using StatusSet = std::set<int>;
#define S(x) PGLOSS_##x

void check(Tally &t, pgloss_status st, const StatusSet &allowed, bool any_nonfinite_in,
           std::initializer_list<double> outs, bool zero_on_error = true) {
    t.add(st);
    if (!allowed.count(st)) ++t.bad_status;
    if (any_nonfinite_in && st != PGLOSS_ERR_NONFINITE) ++t.bad_status;
    for (double v : outs)
        if (!std::isfinite(v)) ++t.nonfinite_out;
    if (st < 0 && zero_on_error)
        for (double v : outs)
            if (v != 0) ++t.bad_value;
}

// Calls first, then reads the outputs (function arguments are evaluated in unspecified order).
#define CHECK_CALL(tally, call, ...)              \
    do {                                          \
        const pgloss_status st_ = (call);         \
        check(tally, st_, __VA_ARGS__);           \
    } while (0)

TEST(Stress, PerceptualAndColour) {
    const std::size_t n = scaled(1000000);
    Pcg32 rng(404);
    std::vector<Tally> t;
    const char *names[] = {"lightness_from_luminance", "luminance_from_lightness", "contrast_gloss",
                           "specular_from_contrast", "gloss_from_physical", "physical_from_gloss", "gloss_distance",
                           "envelope_contrast", "match_gloss", "isogloss_contour", "check_physical",
                           "check_perceptual", "physical_from_perceptual", "perceptual_from_physical",
                           "rgb_from_lab", "lab_from_rgb", "luminance", "status_string/name"};
    for (const char *nm : names) t.push_back(Tally{nm});
    const StatusSet kOkNf{S(OK), S(ERR_NONFINITE)};
    for (std::size_t k = 0; k < n; ++k) {
        const double x = rand_d(rng), y = rand_d(rng), z = rand_d(rng), w = rand_d(rng), v = rand_d(rng);
        const bool nx = !fin(x), nxy = !fin(x) || !fin(y), nxyz = nxy || !fin(z), nall = nxyz || !fin(w);
        double o1 = 0, o2 = 0, o3 = 0;
        CHECK_CALL(t[0], pgloss_lightness_from_luminance(x, &o1), {S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE)}, nx, {o1});
        CHECK_CALL(t[1], pgloss_luminance_from_lightness(x, &o1), {S(OK), S(ERR_NONFINITE), S(ERR_LIGHTNESS)}, nx, {o1});
        CHECK_CALL(t[2], pgloss_contrast_gloss(x, y, &o1), {S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE)}, nxy, {o1});
        CHECK_CALL(t[3], pgloss_specular_from_contrast(x, y, &o1), {S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE)}, nxy, {o1});
        CHECK_CALL(t[4], pgloss_gloss_from_physical(x, y, z, &o1, &o2, &o3),
              {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_ALPHA)}, nxyz, {o1, o2, o3});
        CHECK_CALL(t[5], pgloss_physical_from_gloss(x, y, z, &o1, &o2, &o3),
              {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_LIGHTNESS), S(ERR_NEGATIVE), S(ERR_ALPHA)},
              nxyz, {o1, o2, o3});
        {
            const pgloss_status st = pgloss_gloss_distance(x, y, z, w, &o1);
            // the verdict on the two paints; NEGATIVE and ALPHA still write D (finite points)
            check(t[6], st, {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_ALPHA)},
                  nall, {o1}, st == PGLOSS_ERR_NONFINITE);
        }
        CHECK_CALL(t[7], pgloss_envelope_contrast(x, &o1), {S(OK), S(ERR_NONFINITE), S(ERR_LIGHTNESS)}, nx, {o1});
        {
            const pgloss_status st = pgloss_match_gloss(x, y, z, &o1, &o2);
            // ENVELOPE still writes the (finite) matched values.
            check(t[8], st, {S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_LIGHTNESS), S(ERR_ENVELOPE)}, nxyz,
                  {o1, o2}, st != PGLOSS_ERR_ENVELOPE);
        }
        {
            double c[8], d[8];
            const std::size_t m = rng.below(9);
            const pgloss_status st = pgloss_isogloss_contour(x, y, z, m, c, d);
            t[9].add(st);
            if (!StatusSet{S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_ARGUMENT)}.count(st) ||
                (nxyz && st != PGLOSS_ERR_NONFINITE))
                ++t[9].bad_status;
            for (std::size_t j = 0; j < m; ++j) {
                if (!fin(c[j]) || !fin(d[j])) ++t[9].nonfinite_out;
                if (st < 0 && (c[j] != 0 || d[j] != 0)) ++t[9].bad_value;
            }
        }
        pgloss_physical p{};
        p.rho_d[0] = x;
        p.rho_d[1] = rng.below(2) ? x : y;
        p.rho_d[2] = rng.below(2) ? x : z;
        p.rho_s = w;
        p.alpha_x = rng.below(2) ? std::fabs(v) : v;
        p.alpha_y = rng.below(2) ? p.alpha_x : rand_d(rng);
        p.normalization = static_cast<pgloss_normalization>(rng.below(20) == 0 ? 3 : rng.below(3));
        const bool np = !fin(p.rho_d[0]) || !fin(p.rho_d[1]) || !fin(p.rho_d[2]) || !fin(p.rho_s) ||
                        !fin(p.alpha_x) || !fin(p.alpha_y);
        CHECK_CALL(t[10], pgloss_check_physical(&p),
              {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_ALPHA), S(ERR_NORMALIZATION),
               S(ERR_ENERGY)},
              np, {});
        pgloss_perceptual q{x, y, z, w, v};
        if (rng.below(2)) q = {rng.uniform(0, 100), rng.uniform(-40, 40), rng.uniform(-40, 40), rng.uniform(0, 0.3), rng.uniform(0.6, 1.0)};
        const bool nq = !fin(q.L) || !fin(q.a) || !fin(q.b) || !fin(q.c) || !fin(q.d);
        CHECK_CALL(t[11], pgloss_check_perceptual(&q),
              {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_LIGHTNESS), S(ERR_NEGATIVE), S(ERR_ALPHA),
               S(ERR_GAMUT), S(ERR_ENVELOPE), S(ERR_ENERGY)},
              nq, {});
        {
            pgloss_physical out{};
            const pgloss_status st = pgloss_physical_from_perceptual(&q, p.normalization, &out);
            // GAMUT still writes the exact (negative) RGB.
            check(t[12], st,
                  {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_LIGHTNESS), S(ERR_NEGATIVE), S(ERR_ALPHA),
                   S(ERR_NORMALIZATION), S(ERR_GAMUT)},
                  nq, {out.rho_d[0], out.rho_d[1], out.rho_d[2], out.rho_s, out.alpha_x, out.alpha_y},
                  st != PGLOSS_ERR_GAMUT);
        }
        {
            pgloss_perceptual out{1, 1, 1, 1, 1};
            CHECK_CALL(t[13], pgloss_perceptual_from_physical(&p, &out),
                  {S(OK), S(WARN_ALPHA_UNTRUSTED), S(ERR_NONFINITE), S(ERR_NEGATIVE), S(ERR_ALPHA)}, np,
                  {out.L, out.a, out.b, out.c, out.d});
        }
        {
            const double lab[3] = {x, y, z};
            double rgb[3] = {1, 1, 1};
            const pgloss_status st = pgloss_rgb_from_lab(lab, rgb);
            check(t[14], st, {S(OK), S(ERR_NONFINITE), S(ERR_LIGHTNESS), S(ERR_GAMUT)}, nxyz, {rgb[0], rgb[1], rgb[2]},
                  st != PGLOSS_ERR_GAMUT);
            double lab2[3] = {1, 1, 1};
            const double in[3] = {rng.below(2) ? std::fabs(x) : x, rng.below(2) ? std::fabs(y) : y, rng.below(2) ? std::fabs(z) : z};
            const bool ni = !fin(in[0]) || !fin(in[1]) || !fin(in[2]);
            CHECK_CALL(t[15], pgloss_lab_from_rgb(in, lab2), {S(OK), S(ERR_NONFINITE), S(ERR_NEGATIVE)}, ni,
                  {lab2[0], lab2[1], lab2[2]});
            double yv = 1;
            CHECK_CALL(t[16], pgloss_luminance(in, &yv), kOkNf, ni, {yv});
        }
        {
            const pgloss_status s = static_cast<pgloss_status>(static_cast<int>(rng.below(40)) - 20);
            const char *a = pgloss_status_string(s), *b = pgloss_status_name(s);
            t[17].add(PGLOSS_OK);
            if (!a || !b || !*a || !*b) ++t[17].bad_value;
        }
    }
    for (const Tally &x : t) {
        x.print();
        EXPECT_EQ(x.nonfinite_out, 0u) << x.fn;
        EXPECT_EQ(x.bad_status, 0u) << x.fn;
        EXPECT_EQ(x.bad_value, 0u) << x.fn;
    }
}

// The three bugs the stress test found, as targeted regressions (exact inputs).
TEST(Stress, Regressions) {
    // (c) Finite L* beyond ~6.6e104 overflowed Y to +Inf.
    double y = 1;
    EXPECT_EQ(pgloss_luminance_from_lightness(1e105, &y), PGLOSS_ERR_NONFINITE);
    EXPECT_EQ(y, 0.0);
    EXPECT_EQ(pgloss_luminance_from_lightness(DBL_MAX, &y), PGLOSS_ERR_NONFINITE);
    EXPECT_EQ(pgloss_luminance_from_lightness(6e104, &y), PGLOSS_OK);
    EXPECT_TRUE(std::isfinite(y));
    // ... and c beyond ~5e102 in eq. 7 gave ρs = 0 with status OK.
    double rd, rs, al;
    EXPECT_EQ(pgloss_physical_from_gloss(50, 1e200, 0.9, &rd, &rs, &al), PGLOSS_ERR_NONFINITE);
    EXPECT_EQ(rs, 0.0);
    // (b) α = FLT_MAX in the batch sampler gave NaN directions.
    pgloss_material m;
    const pgloss_physical p = physical(0, 0, 0, 0.5, FLT_MAX, FLT_MAX, PGLOSS_NORM_WARD);
    ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
    const float ox = 0.3f, oy = 0.1f, oz = 0.9f, u0 = 0.0f, u1 = 0.5f, u2 = 0.3f;
    float wx, wy, wz, pdf, r, g, b;
    EXPECT_EQ(pgloss_sample_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, 1, soa(&ox, &oy, &oz), soa(&u0, &u1, &u2),
                                  soa_out(&wx, &wy, &wz), col_out(&pdf), soa_out(&r, &g, &b), nullptr, nullptr),
              PGLOSS_OK);
    EXPECT_TRUE(std::isfinite(wx) && std::isfinite(wy) && std::isfinite(wz));
    // (a) A density that rounds to 0 in float must come with weight 0 (and pdf 0). Found by the
    // random stress: α = 1e19, wo at cos θo = 1e-30, u1 = 2^-149: the double pdf is ~1e-60,
    // the stored float pdf 0, and the weight was written as 43.6.
    const pgloss_physical q = physical(0, 0, 0, 0.5, 1e19, 1e19, PGLOSS_NORM_WARD);
    ASSERT_EQ(pgloss_material_init(&m, &q), PGLOSS_OK);
    const float ua[3] = {0.0f, FLT_TRUE_MIN, 0.25f};
    pgloss_sample_record s;
    EXPECT_EQ(pgloss_sample(&m, {1.0f, 0.0f, 1e-30f}, ua, PGLOSS_LOBE_ALL, &s), PGLOSS_OK);
    EXPECT_EQ(s.pdf, 0.0f);
    EXPECT_EQ(s.weight.r, 0.0f);
    EXPECT_EQ(s.weight.g, 0.0f);
    EXPECT_EQ(s.weight.b, 0.0f);
}

}  // namespace
