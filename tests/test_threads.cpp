// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Concurrency: threads hammer eval, pdf, eval_pdf, sample and the batches (every tier and
// instruction set) on the same materials at once. The library has no mutable global state,
// so every thread must get exactly the single-threaded results (bit for bit). Under
// ThreadSanitizer (scripts/test-tsan.sh) any data race is a failure too.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "batch_util.h"

namespace {

constexpr size_t kN = 97;  // not a multiple of any vector width: the tails run too

struct Inputs {
    std::vector<pgloss_material> mats;
    std::vector<float> ox, oy, oz, ix, iy, iz, u0, u1, u2;
};

Inputs make_inputs() {
    Inputs in;
    for (const pgloss_physical &p : {pgloss_physical{{0.193, 0.193, 0.193}, 0.066, 0.07, 0.07, PGLOSS_NORM_WARD},
                                     pgloss_physical{{0.6, 0.2, 0.05}, 0.3, 0.02, 0.15, PGLOSS_NORM_BOUNDED},
                                     pgloss_physical{{1e-5, 1e-5, 1e-5}, 0.34, 0.2, 0.2, PGLOSS_NORM_WARD_DUR}}) {
        pgloss_material m;
        EXPECT_EQ(pgloss_material_init(&m, &p), PGLOSS_OK);
        in.mats.push_back(m);
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> U(0.0f, 1.0f);
    auto dir = [&](std::vector<float> &x, std::vector<float> &y, std::vector<float> &z) {
        float ct = U(rng), st = std::sqrt(1 - ct * ct), ph = 6.2831853f * U(rng);
        x.push_back(st * std::cos(ph)), y.push_back(st * std::sin(ph)), z.push_back(ct);
    };
    for (size_t k = 0; k < kN; ++k) {
        dir(in.ox, in.oy, in.oz);
        dir(in.ix, in.iy, in.iz);
        in.u0.push_back(U(rng)), in.u1.push_back(U(rng)), in.u2.push_back(U(rng));
    }
    return in;
}

// Everything one thread computes, as raw floats.
std::vector<float> work(const Inputs &in) {
    std::vector<float> out;
    const pgloss_strided3 wo = soa(in.ox.data(), in.oy.data(), in.oz.data()), wi = soa(in.ix.data(), in.iy.data(), in.iz.data());
    std::vector<float> a(kN), b(kN), c(kN), d(kN), e(kN), f(kN), g(kN);
    std::vector<unsigned char> lobe(kN);
    for (const pgloss_material &m : in.mats) {
        for (size_t k = 0; k < kN; ++k) {
            pgloss_rgb fr;
            float pdf;
            pgloss_eval_pdf(&m, {in.ox[k], in.oy[k], in.oz[k]}, {in.ix[k], in.iy[k], in.iz[k]}, PGLOSS_LOBE_ALL, &fr, &pdf);
            out.insert(out.end(), {fr.r, fr.g, fr.b, pdf});
            pgloss_sample_record r;
            const float u[3] = {in.u0[k], in.u1[k], in.u2[k]};
            pgloss_sample(&m, {in.ox[k], in.oy[k], in.oz[k]}, u, PGLOSS_LOBE_ALL, &r);
            out.insert(out.end(), {r.wi.x, r.wi.y, r.wi.z, r.pdf, r.weight.r, r.weight.g, r.weight.b, float(r.lobe)});
        }
        for (pgloss_precision tier : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST, PGLOSS_PRECISION_REFERENCE})
            for (pgloss_isa isa : {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512}) {
                if (!pgloss_isa_supported(isa)) continue;
                const pgloss_batch_options opt = batch_options(tier, isa);
                pgloss_eval_pdf_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, kN, wo, wi, soa_out(a.data(), b.data(), c.data()),
                                      col_out(d.data()), nullptr);
                for (auto *v : {&a, &b, &c, &d}) out.insert(out.end(), v->begin(), v->end());
                pgloss_sample_batch(&opt, &m, nullptr, PGLOSS_LOBE_ALL, kN, wo, soa(in.u0.data(), in.u1.data(), in.u2.data()),
                                    soa_out(a.data(), b.data(), c.data()), col_out(d.data()),
                                    soa_out(e.data(), f.data(), g.data()), lobe.data(), nullptr);
                for (auto *v : {&a, &b, &c, &d, &e, &f, &g}) out.insert(out.end(), v->begin(), v->end());
            }
    }
    return out;
}

TEST(Threads, SharedMaterialsGiveEveryThreadTheSingleThreadedResults) {
    const Inputs in = make_inputs();
    const std::vector<float> expected = work(in);
    const int nthreads = 8, rounds = 20;
    std::vector<int> mismatches(nthreads, 0);
    std::vector<std::thread> pool;
    for (int t = 0; t < nthreads; ++t)
        pool.emplace_back([&, t] {
            for (int r = 0; r < rounds; ++r) {
                const std::vector<float> got = work(in);
                if (got.size() != expected.size() ||
                    std::memcmp(got.data(), expected.data(), got.size() * sizeof(float)) != 0)
                    ++mismatches[size_t(t)];
            }
        });
    for (auto &th : pool) th.join();
    for (int t = 0; t < nthreads; ++t) EXPECT_EQ(mismatches[size_t(t)], 0) << "thread " << t;
    std::printf("%d threads x %d rounds x %zu floats each: identical to one thread\n", nthreads, rounds, expected.size());
}

}  // namespace
