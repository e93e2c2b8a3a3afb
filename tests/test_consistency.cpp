// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Consistency of the BRDF entry points with each other and with the documented identities:
//   - sample's pdf is pgloss_pdf(wo, s.wi) (bit for bit: both evaluate at the returned float wi),
//     its weight is eval·cos θi / pdf, and a rejected sample has pdf 0 and weight 0;
//   - eval_pdf returns exactly (eval, pdf);
//   - the batched functions agree with the scalar ones within float rounding (scaled by the
//     conditioning of the exponential, 1 + x for E = exp(−x));
//   - eval is reciprocal, f(wo, wi) = f(wi, wo), for every normalisation (bit for bit);
//   - lobe masks add up: f_D + f_S = f_all, pdf_all = (1 − Ps) pdf_D + Ps pdf_S;
//   - ∫ pdf dω over the hemisphere = 1 − the fraction of rejected samples.
// Random materials (α log-uniform in [1e-3, 1], anisotropic, coloured, every normalisation)
// and directions from normal to grazing (cos θ down to 1e-4).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "batch_util.h"
#include "test_common.h"

using namespace pgt;

namespace {

const pgloss_normalization kNorms[3] = {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED};

pgloss_physical random_material(Pcg32 &rng) {
    const double a = std::pow(10.0, rng.uniform(-3, 0));
    const double b = rng.below(2) ? a : std::pow(10.0, rng.uniform(-3, 0));
    const double rd = rng.below(5) == 0 ? 0.0 : 0.9;  // some specular-only materials
    const double rs = rng.below(5) == 0 ? 0.0 : rng.uniform(0.01, 1.0);
    return physical(rd * rng.uniform(), rd * rng.uniform(), rd * rng.uniform(), rs, a, b, kNorms[rng.below(3)]);
}

// Direction in the upper hemisphere, cos θ log-uniform in [1e-4, 1] half of the time.
pgloss_vec3 random_dir(Pcg32 &rng) {
    const double c = rng.below(2) ? std::pow(10.0, rng.uniform(-4, 0)) : rng.uniform(1e-4, 1.0);
    return dir(c, 2 * kPi * rng.uniform());
}

double rel_err(double got, double want) {
    if (got == want) return 0;
    return std::fabs(got - want) / std::max(std::fabs(want), 1e-30);
}

const unsigned kMasks[3] = {PGLOSS_LOBE_DIFFUSE, PGLOSS_LOBE_SPECULAR, PGLOSS_LOBE_ALL};

TEST(Consistency, SampleRecordMatchesPdfAndEval) {
    Pcg32 rng(1);
    const std::size_t n = scaled(400000);
    std::size_t rejected = 0, checked_weight = 0;
    double max_w = 0;
    for (std::size_t k = 0; k < n; ++k) {
        pgloss_material m;
        const pgloss_physical p = random_material(rng);
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const pgloss_vec3 wo = random_dir(rng);
        const unsigned mask = kMasks[rng.below(3)];
        const float u[3] = {rng.uniform_float(), rng.uniform_float(), rng.uniform_float()};
        pgloss_sample_record s;
        ASSERT_EQ(pgloss_sample(&m, wo, u, mask, &s), PGLOSS_OK);
        float pdf = -1;
        pgloss_rgb f, f2;
        float pdf2 = -1;
        ASSERT_EQ(pgloss_pdf(&m, wo, s.wi, mask, &pdf), PGLOSS_OK);
        ASSERT_EQ(pgloss_eval(&m, wo, s.wi, mask, &f), PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf(&m, wo, s.wi, mask, &f2, &pdf2), PGLOSS_OK);
        // eval_pdf is exactly (eval, pdf).
        ASSERT_EQ(f2.r, f.r);
        ASSERT_EQ(f2.g, f.g);
        ASSERT_EQ(f2.b, f.b);
        ASSERT_EQ(pdf2, pdf);
        if (!(s.pdf > 0)) {
            ++rejected;
            ASSERT_EQ(s.weight.r, 0.0f);
            ASSERT_EQ(s.weight.g, 0.0f);
            ASSERT_EQ(s.weight.b, 0.0f);
            // A rejected sample is either outside the support or of a density that rounds to 0.
            ASSERT_EQ(pdf, 0.0f) << "rejected sample with pgloss_pdf > 0";
            continue;
        }
        // The record's pdf is pgloss_pdf at the returned direction, bit for bit.
        ASSERT_EQ(s.pdf, pdf);
        ASSERT_NE(s.lobe & mask & m.lobes, 0u);
        // weight = f cos θi / pdf: f and pdf are each rounded once to float, the weight once:
        // 3 roundings. Skipped where a value is subnormal or clamped at FLT_MAX.
        V3 wi = v3(s.wi);
        normalize(wi);
        const float fv[3] = {f.r, f.g, f.b}, wv[3] = {s.weight.r, s.weight.g, s.weight.b};
        for (int c = 0; c < 3; ++c) {
            if (!(pdf >= FLT_MIN) || fv[c] < FLT_MIN || fv[c] >= FLT_MAX || wv[c] >= FLT_MAX) continue;
            const double want = static_cast<double>(fv[c]) * wi.z / pdf;
            const double e = rel_err(wv[c], want);
            max_w = std::max(max_w, e);
            ASSERT_LE(e, 4 * kFloatEps) << "weight " << wv[c] << " vs eval cos / pdf " << want;
            ++checked_weight;
        }
    }
    std::printf("[consistency] sample: %zu samples, %zu rejected, %zu weights checked, max rel err %.3g "
                "(float unit roundoff %.3g)\n",
                n, rejected, checked_weight, max_w, kFloatEps);
}

TEST(Consistency, EvalIsReciprocal) {
    Pcg32 rng(2);
    const std::size_t n = scaled(400000);
    for (std::size_t k = 0; k < n; ++k) {
        pgloss_material m;
        const pgloss_physical p = random_material(rng);
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const pgloss_vec3 a = random_dir(rng), b = random_dir(rng);
        pgloss_rgb fab, fba;
        ASSERT_EQ(pgloss_eval(&m, a, b, PGLOSS_LOBE_ALL, &fab), PGLOSS_OK);
        ASSERT_EQ(pgloss_eval(&m, b, a, PGLOSS_LOBE_ALL, &fba), PGLOSS_OK);
        ASSERT_EQ(fab.r, fba.r) << norm_name(p.normalization);
        ASSERT_EQ(fab.g, fba.g);
        ASSERT_EQ(fab.b, fba.b);
    }
    // The batch too, per normalisation.
    for (pgloss_normalization nm : kNorms) {
        const pgloss_physical p = physical(0.3, 0.4, 0.5, 0.5, 0.05, 0.2, nm);
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const std::size_t nb = 4096;
        std::vector<float> ax(nb), ay(nb), az(nb), bx(nb), by(nb), bz(nb), r1(nb), g1(nb), b1(nb), r2(nb), g2(nb),
            b2(nb);
        for (std::size_t j = 0; j < nb; ++j) {
            const pgloss_vec3 a = random_dir(rng), b = random_dir(rng);
            ax[j] = a.x, ay[j] = a.y, az[j] = a.z, bx[j] = b.x, by[j] = b.y, bz[j] = b.z;
        }
        ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, nb, soa(ax.data(), ay.data(), az.data()),
                                        soa(bx.data(), by.data(), bz.data()), soa_out(r1.data(), g1.data(), b1.data()),
                                        no_out(), nullptr),
                  PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, PGLOSS_LOBE_ALL, nb, soa(bx.data(), by.data(), bz.data()),
                                        soa(ax.data(), ay.data(), az.data()), soa_out(r2.data(), g2.data(), b2.data()),
                                        no_out(), nullptr),
                  PGLOSS_OK);
        for (std::size_t j = 0; j < nb; ++j) ASSERT_EQ(r1[j], r2[j]) << norm_name(nm) << " " << j;
    }
}

TEST(Consistency, LobeMasksAddUp) {
    Pcg32 rng(3);
    const std::size_t n = scaled(400000);
    double max_f = 0, max_p = 0;
    for (std::size_t k = 0; k < n; ++k) {
        pgloss_material m;
        const pgloss_physical p = random_material(rng);
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const pgloss_vec3 wo = random_dir(rng), wi = random_dir(rng);
        pgloss_rgb fd, fs, fa;
        float pd, ps, pa;
        ASSERT_EQ(pgloss_eval_pdf(&m, wo, wi, PGLOSS_LOBE_DIFFUSE, &fd, &pd), PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf(&m, wo, wi, PGLOSS_LOBE_SPECULAR, &fs, &ps), PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf(&m, wo, wi, PGLOSS_LOBE_ALL, &fa, &pa), PGLOSS_OK);
        const float gd[3] = {fd.r, fd.g, fd.b}, gs[3] = {fs.r, fs.g, fs.b}, ga[3] = {fa.r, fa.g, fa.b};
        for (int c = 0; c < 3; ++c) {
            if (ga[c] >= FLT_MAX) continue;
            // Each of the three is rounded once from the same double terms.
            const double e = std::fabs(static_cast<double>(gd[c]) + gs[c] - ga[c]) / std::max<double>(ga[c], 1e-30);
            max_f = std::max(max_f, e);
            ASSERT_LE(e, 3 * kFloatEps) << c;
        }
        // Ps as returned (rounded to float) may differ from the double Ps inside by an ulp:
        // that moves the mixture by up to ulp(Ps)·(pd + ps).
        const double s = pgloss_specular_probability(&m, PGLOSS_LOBE_ALL);
        if (pa < FLT_MAX && pa >= FLT_MIN) {
            const double want = (1 - s) * pd + s * ps;
            const double e = std::fabs(want - pa) / pa;
            max_p = std::max(max_p, e);
            ASSERT_LE(e, 4 * kFloatEps + 2 * kFloatEps * s * (static_cast<double>(pd) + ps) / pa);
        }
    }
    std::printf("[consistency] lobe masks: max rel err f_D + f_S vs f_all %.3g, pdf mixture %.3g\n", max_f, max_p);
}

// Batch vs scalar: eval, pdf, eval_pdf and sample. The float kernels (float normalisation of
// the inputs, float exponent, a polynomial exp) hold each value to a few ulps times the
// condition number of E = exp(−x) with respect to float rounding of the directions:
//   κ = 1 + x + 4 sqrt(x) / (min(αx, αy) (cos θi + cos θo)),
// the last term because h = wo + wi is rounded absolutely (≈ ulp) while x = |h_t/α|² / hz².
double kappa(const Ref &ref, const Ref::Eval &e) {
    return 1 + e.x + 4 * std::sqrt(e.x) / (std::min(ref.ax, ref.ay) * (e.ci + e.co));
}

TEST(Consistency, BatchMatchesScalar) {
    Pcg32 rng(4);
    const std::size_t nb = 2048, rounds = scaled(100, 10);
    double max_f = 0, max_p = 0, max_w = 0, max_dir = 0, max_sp = 0;
    std::size_t total = 0, sample_total = 0, accept_mismatch = 0, lobe_mismatch = 0;
    std::vector<float> ox(nb), oy(nb), oz(nb), ix(nb), iy(nb), iz(nb), fr(nb), fg(nb), fb(nb), pdf(nb), fr2(nb),
        fg2(nb), fb2(nb), pdf2(nb), u0(nb), u1(nb), u2(nb), wx(nb), wy(nb), wz(nb), wr(nb), wg(nb), wb(nb);
    std::vector<unsigned char> lobe(nb);
    for (std::size_t r = 0; r < rounds; ++r) {
        pgloss_physical p = random_material(rng);
        p.alpha_x = std::max(p.alpha_x, 0.01);  // the regular range; tiny α is in the stress test
        p.alpha_y = std::max(p.alpha_y, 0.01);
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const Ref ref = Ref::from(p);
        const unsigned mask = kMasks[rng.below(3)];
        for (std::size_t j = 0; j < nb; ++j) {
            const pgloss_vec3 a = random_dir(rng), b = random_dir(rng);
            ox[j] = a.x, oy[j] = a.y, oz[j] = a.z, ix[j] = b.x, iy[j] = b.y, iz[j] = b.z;
            u0[j] = rng.uniform_float(), u1[j] = rng.uniform_float(), u2[j] = rng.uniform_float();
        }
        const pgloss_strided3 wo = soa(ox.data(), oy.data(), oz.data()), wi = soa(ix.data(), iy.data(), iz.data());
        ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi, soa_out(fr.data(), fg.data(), fb.data()),
                                        col_out(pdf.data()), nullptr),
                  PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi,
                                        soa_out(fr2.data(), fg2.data(), fb2.data()), no_out(), nullptr),
                  PGLOSS_OK);
        ASSERT_EQ(pgloss_eval_pdf_batch(nullptr, &m, nullptr, mask, nb, wo, wi, no_out3(), col_out(pdf2.data()), nullptr),
                  PGLOSS_OK);
        ASSERT_EQ(pgloss_sample_batch(nullptr, &m, nullptr, mask, nb, wo, soa(u0.data(), u1.data(), u2.data()),
                                      soa_out(wx.data(), wy.data(), wz.data()), col_out(pdf2.data()) /* overwritten below */,
                                      soa_out(wr.data(), wg.data(), wb.data()), lobe.data(), nullptr),
                  PGLOSS_OK);
        for (std::size_t j = 0; j < nb; ++j) {
            const pgloss_vec3 a{ox[j], oy[j], oz[j]}, b{ix[j], iy[j], iz[j]};
            pgloss_rgb f;
            float pv;
            ASSERT_EQ(pgloss_eval_pdf(&m, a, b, mask, &f, &pv), PGLOSS_OK);
            ASSERT_EQ(fr[j], fr2[j]);  // eval_batch == eval_pdf_batch
            const Ref::Eval re = ref.eval(a, b, mask);
            const double k = kappa(ref, re), tol = 16 * kFloatEps * k;
            const float sf[3] = {f.r, f.g, f.b}, bf[3] = {fr[j], fg[j], fb[j]};
            for (int c = 0; c < 3; ++c) {
                if (sf[c] < FLT_MIN && bf[c] < FLT_MIN) continue;  // both (nearly) 0: underflow
                const double e = rel_err(bf[c], sf[c]);
                max_f = std::max(max_f, e / k);
                ASSERT_LE(e, tol) << "eval c=" << c << " x=" << re.x << " kappa=" << k;
            }
            if (!(pv < FLT_MIN && pdf[j] < FLT_MIN)) {
                const double e = rel_err(pdf[j], pv);
                max_p = std::max(max_p, e / k);
                ASSERT_LE(e, tol) << "pdf x=" << re.x << " kappa=" << k;
            }
            ++total;

            // sample: same lobe, same direction, same pdf and weight within the same model.
            const float u[3] = {u0[j], u1[j], u2[j]};
            pgloss_sample_record s;
            ASSERT_EQ(pgloss_sample(&m, a, u, mask, &s), PGLOSS_OK);
            ++sample_total;
            if (s.lobe != lobe[j]) {
                ++lobe_mismatch;  // u0 within rounding of Ps
                continue;
            }
            const double d = std::max({std::fabs(s.wi.x - wx[j]), std::fabs(s.wi.y - wy[j]), std::fabs(s.wi.z - wz[j])});
            max_dir = std::max(max_dir, d);
            const bool acc_s = s.pdf > 0, acc_b = pdf2[j] > 0;
            if (acc_s != acc_b) {
                ++accept_mismatch;  // wi within rounding of the horizon
                continue;
            }
            if (!acc_s) continue;
            // Conditioning of the sampled pair, from the double reference at the scalar wi; wi
            // itself differs by float rounding of the sampling formulas, which moves a value
            // near grazing by ≈ ulps / cos θi more.
            const Ref::Eval rs = ref.eval(a, s.wi, mask);
            const double ks = kappa(ref, rs) / std::max(1e-3, static_cast<double>(s.wi.z));
            const double tol_s = 128 * kFloatEps * ks;
            const double ep = rel_err(pdf2[j], s.pdf);
            max_sp = std::max(max_sp, ep / ks);
            EXPECT_LE(ep, tol_s) << "sample pdf x=" << rs.x << " cos=" << s.wi.z;
            const double ew = rel_err(wr[j], s.weight.r);
            max_w = std::max(max_w, ew / ks);
            EXPECT_LE(ew, tol_s) << "sample weight x=" << rs.x << " cos=" << s.wi.z;
        }
    }
    EXPECT_LE(static_cast<double>(lobe_mismatch), 1e-4 * sample_total);
    EXPECT_LE(static_cast<double>(accept_mismatch), 1e-3 * sample_total);
    std::printf("[consistency] batch vs scalar over %zu pairs: max rel err / kappa: eval %.3g, pdf %.3g; "
                "sample over %zu: max |dwi| %.3g, max rel err / kappa: pdf %.3g, weight %.3g, lobe mismatches %zu, accept/reject "
                "mismatches %zu\n",
                total, max_f, max_p, sample_total, max_dir, max_sp, max_w, lobe_mismatch, accept_mismatch);
}

// ∫ pdf dω over the hemisphere (cubature in double of pgloss_pdf) equals the accepted fraction
// of pgloss_sample (binomial, 5 sigma), and at normal incidence the closed form 1 − e^{−1/α²}.
TEST(Consistency, PdfIntegratesToAcceptedFraction) {
    struct Case {
        double a, co;
        unsigned mask;
        double rd;
    };
    const Case cases[] = {{0.1, 1.0, PGLOSS_LOBE_ALL, 0.0},      {0.3, 0.5, PGLOSS_LOBE_ALL, 0.0},
                          {0.6, 0.02, PGLOSS_LOBE_ALL, 0.0},     {1.0, 1.0, PGLOSS_LOBE_ALL, 0.0},
                          {0.3, 0.1, PGLOSS_LOBE_ALL, 0.5},      {0.3, 0.1, PGLOSS_LOBE_SPECULAR, 0.5},
                          {0.3, 0.1, PGLOSS_LOBE_DIFFUSE, 0.5}};
    Pcg32 rng(5);
    const std::size_t n = scaled(400000);
    for (const Case &c : cases) {
        const pgloss_physical p = physical(c.rd, c.rd, c.rd, 0.5, c.a, c.a, PGLOSS_NORM_WARD);
        pgloss_material m;
        ASSERT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        const pgloss_vec3 wo = dir(c.co, 0.7);
        Cubature cub;  // tolerances above the float noise of pgloss_pdf, far below 1/sqrt(n)
        cub.abs_tol = 1e-10;
        cub.rel_tol = 1e-6;
        cub.max_depth = 5;
        double mass = 0;
        const int nt = 32, np = 64;
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j)
                mass += cub.integrate(
                    [&](double t, double ph) {
                        float v = 0;
                        pgloss_pdf(&m, wo, dir(1 - t, ph), c.mask, &v);
                        return static_cast<double>(v);
                    },
                    static_cast<double>(i) / nt, static_cast<double>(i + 1) / nt, 2 * kPi * j / np,
                    2 * kPi * (j + 1) / np);
        std::size_t accepted = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const float u[3] = {rng.uniform_float(), rng.uniform_float(), rng.uniform_float()};
            pgloss_sample_record s;
            pgloss_sample(&m, wo, u, c.mask, &s);
            accepted += s.pdf > 0;
        }
        const double frac = static_cast<double>(accepted) / static_cast<double>(n);
        const double sigma = std::sqrt(std::max(mass * (1 - mass), 1e-12) / static_cast<double>(n));
        EXPECT_NEAR(frac, mass, 5 * sigma + 1e-6) << "alpha " << c.a << " cos " << c.co;
        if (c.co == 1.0 && c.rd == 0.0) {
            EXPECT_NEAR(mass, 1 - std::exp(-1 / (c.a * c.a)), 1e-6);
        }
        if (c.mask == PGLOSS_LOBE_DIFFUSE) {
            EXPECT_NEAR(mass, 1.0, 1e-6);
        }
        std::printf("[consistency] alpha %.2f cos %.2f mask %u: int pdf %.6f, accepted fraction %.6f (sigma %.1e)\n",
                    c.a, c.co, c.mask, mass, frac, sigma);
    }
}

}  // namespace
