// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the BRDF entry points (brdf.h, batch.h), every tier, instruction set and
// scalar type.
// Contracts asserted (from the headers):
//   - every status is one the function documents; outputs are finite, f, pdf, weight >= 0;
//     a rejected sample (pdf 0) has weight 0;
//   - the FLOAT tier is bit-identical across instruction sets;
//   - scalar (double reference) and batch agree: on the regular range (unit directions,
//     cosines >= 1e-3, α in [1e-3, 1]) within the tiers' stated error, which grows with the
//     specular exponent x as ~1e-6 (4 + x), plus the conditioning of x on the half vector's
//     rounding; elsewhere (any cosine > 0) within a factor of 2.
#include "fuzz_common.hpp"

#include <pgloss/pgloss.h>

#include <algorithm>
#include <cfloat>
#include <vector>

namespace {

struct Dir {
    pgloss_vec3 v;
    bool unit;
};

Dir direction(fz::Bytes &b) {
    const int mode = b.byte() % 6;
    if (mode == 0) return {{b.raw<float>(), b.raw<float>(), b.raw<float>()}, false};
    double ct = -0.05 + 1.05 * b.unit();
    if (mode == 1) {
        static const double grazing[] = {0.0, 1e-30, 1e-20, 1e-12, 1e-8, 1e-4, -1e-8, 1.0};
        ct = grazing[b.byte() % 8];
    }
    const double st = std::sqrt(std::max(0.0, 1 - ct * ct)), ph = 6.283185307179586 * b.unit();
    double s = 1;
    if (mode == 2) s = b.real(1e-20, 1e20);
    Dir d{{float(s * st * std::cos(ph)), float(s * st * std::sin(ph)), float(s * ct)}, mode != 2};
    const double l2 = double(d.v.x) * d.v.x + double(d.v.y) * d.v.y + double(d.v.z) * d.v.z;
    d.unit = d.unit && std::fabs(l2 - 1) <= 0x1p-20;
    return d;
}

bool documented_eval(pgloss_status s) { return s == PGLOSS_OK || s == PGLOSS_ERR_DIRECTION; }
bool documented_sample(pgloss_status s) {
    return s == PGLOSS_OK || s == PGLOSS_ERR_DIRECTION || s == PGLOSS_ERR_RANDOM;
}

// The specular exponent x = tan²δ/α² (anisotropic: ((hx/αx)² + (hy/αy)²)/hz²), in double.
double exponent(pgloss_vec3 o, pgloss_vec3 i, double ax, double ay) {
    const double hx = double(o.x) + i.x, hy = double(o.y) + i.y, hz = double(o.z) + i.z;
    return ((hx / ax) * (hx / ax) + (hy / ay) * (hy / ay)) / (hz * hz);
}

// The float lobe's half vector h = s − (D/4) d (docs/kernels.md, step 3) takes D = |i|² − |o|²
// as Σ d_k s_k, rounded relative to Σ|d_k s_k| (up to 3 roundings of 2^-24), not to D: each h_k
// moves by that error times |d_k|/4. Where a small component of h meets a small α (anisotropic,
// away from the mirror direction) x is ill-conditioned in it, as it is in the directions' own
// rounding: dx = 2 (tx dhx/αx + ty dhy/αy − x dhz)/hz, tx, ty = hx/(αx hz), hy/(αy hz).
double half_vector_error(pgloss_vec3 o, pgloss_vec3 i, double ax, double ay, double x) {
    const double sx = double(i.x) + o.x, sy = double(i.y) + o.y, sz = double(i.z) + o.z;
    const double dx = double(i.x) - o.x, dy = double(i.y) - o.y, dz = double(i.z) - o.z;
    const double dq = 0.25 * 3 * 0x1p-24 * (std::fabs(dx * sx) + std::fabs(dy * sy) + std::fabs(dz * sz));
    const double tx = sx / (ax * sz), ty = sy / (ay * sz);
    return 2 * dq * (std::fabs(tx * dx) / ax + std::fabs(ty * dy) / ay + x * std::fabs(dz)) / sz;
}

// floor: below it only the magnitude is asked for. The float tiers' exponential underflows
// (below e^-103) before the lobe's constant multiplies it, so with ρs ≤ 1 every such f is under
// 1e-30; a material far outside the model (ρs up to FLT_MAX) scales that floor by ρs.
void agree(float batch, float scalar, double tol, bool regular, double floor) {
    if (!(scalar >= floor)) {  // there the batch may underflow to less, never give more
        FZ_CHECK(batch <= 2.0f * scalar + 1e-28f);
        return;
    }
    if (regular)
        FZ_CHECK(std::fabs(double(batch) - scalar) <= tol * scalar);
    else
        FZ_CHECK(batch <= 2.0f * scalar && batch >= 0.5f * scalar);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size) {
    fz::Bytes b(data, size);
    pgloss_physical p{};
    const int shared = b.byte() % 2;
    p.rho_d[0] = b.real(0, 1);
    p.rho_d[1] = shared ? p.rho_d[0] : b.real(0, 1);
    p.rho_d[2] = shared ? p.rho_d[0] : b.real(0, 1);
    p.rho_s = b.real(0, 1);
    p.alpha_x = b.real(1e-5, 2);
    p.alpha_y = b.byte() % 2 ? p.alpha_x : b.real(1e-5, 2);
    p.normalization = static_cast<pgloss_normalization>(b.byte() % 4);
    pgloss_material m;
    const pgloss_status ms = pgloss_material_init(&m, &p);
    FZ_CHECK(ms == PGLOSS_OK || ms == PGLOSS_ERR_NONFINITE || ms == PGLOSS_ERR_NEGATIVE || ms == PGLOSS_ERR_ALPHA ||
             ms == PGLOSS_ERR_NORMALIZATION);
    if (ms < 0) FZ_CHECK(m.lobes == PGLOSS_LOBE_NONE);
    const unsigned lobes = b.byte() % 4;
    const Dir o = direction(b), i = direction(b);
    float u[3];
    for (float &x : u) x = b.byte() % 8 == 0 ? b.raw<float>() : float(b.unit()) * 0.99999994f;
    const bool regular_material = ms == PGLOSS_OK && p.alpha_x >= 1e-3 && p.alpha_x <= 1 && p.alpha_y >= 1e-3 &&
                                  p.alpha_y <= 1;
    if (ms < 0) return 0;  // a black material: nothing more to evaluate

    // Scalar reference.
    pgloss_rgb f, f2;
    float pdf = -1, pdf2 = -1;
    const pgloss_status se = pgloss_eval_pdf(&m, o.v, i.v, lobes, &f, &pdf);
    FZ_CHECK(documented_eval(se));
    FZ_CHECK(fz::finite3(f.r, f.g, f.b) && std::isfinite(pdf));
    FZ_CHECK(f.r >= 0 && f.g >= 0 && f.b >= 0 && pdf >= 0);
    FZ_CHECK(pgloss_eval(&m, o.v, i.v, lobes, &f2) == se && pgloss_pdf(&m, o.v, i.v, lobes, &pdf2) == se);
    FZ_CHECK(std::memcmp(&f, &f2, sizeof f) == 0 && std::memcmp(&pdf, &pdf2, sizeof pdf) == 0);
    pgloss_sample_record r;
    const pgloss_status ss = pgloss_sample(&m, o.v, u, lobes, &r);
    FZ_CHECK(documented_sample(ss));
    FZ_CHECK(fz::finite3(r.wi.x, r.wi.y, r.wi.z) && std::isfinite(r.pdf) && fz::finite3(r.weight.r, r.weight.g, r.weight.b));
    FZ_CHECK(r.pdf >= 0 && r.weight.r >= 0 && r.weight.g >= 0 && r.weight.b >= 0);
    if (r.pdf == 0) FZ_CHECK(r.weight.r == 0 && r.weight.g == 0 && r.weight.b == 0);

    // Batches: n copies (the fuzzer's element among others) through every tier and ISA.
    const size_t n = 1 + b.byte() % 40;
    // one direction and one set of random numbers for every element (stride 0)
    const pgloss_strided3 wo{{&o.v.x, &o.v.y, &o.v.z}, 0}, wi{{&i.v.x, &i.v.y, &i.v.z}, 0}, us{{&u[0], &u[1], &u[2]}, 0};
    const double x = exponent(o.v, i.v, m.alpha_x, m.alpha_y);
    const bool regular = regular_material && o.unit && i.unit && o.v.z >= 1e-3f && i.v.z >= 1e-3f && x <= 80;
    // Below cosines of 1e-19 the float exponent squares hx, hy before dividing by hz², so a
    // half vector within ~1e-19 of the surface in every component loses its exponent: there
    // only the contracts above are asserted.
    const bool comparable = o.unit && i.unit && o.v.z >= 1e-19f && i.v.z >= 1e-19f;
    std::vector<float> float_ref;  // FLOAT tier of the first ISA, for bit-identity
    for (pgloss_precision tier : {PGLOSS_PRECISION_FLOAT, PGLOSS_PRECISION_FAST, PGLOSS_PRECISION_REFERENCE}) {
        for (pgloss_isa isa : {PGLOSS_ISA_BASELINE, PGLOSS_ISA_AVX2, PGLOSS_ISA_AVX512}) {
            if (!pgloss_isa_supported(isa)) continue;
            const pgloss_batch_options opt{tier, isa, PGLOSS_FLOAT32};
            std::vector<float> fr(n, -1), fg(n, -1), fb(n, -1), pd(n, -1);
            const auto out3 = [](auto &a, auto &b, auto &c) {
                return pgloss_strided3_out_soa(a.data(), b.data(), c.data(), sizeof a[0]);
            };
            const auto out1 = [](auto &a) { return pgloss_strided_out_of(a.data(), sizeof a[0]); };
            const pgloss_status bs = pgloss_eval_pdf_batch(&opt, &m, nullptr, lobes, n, wo, wi, out3(fr, fg, fb), out1(pd),
                                                           nullptr);
            FZ_CHECK(bs == se);
            for (size_t k = 0; k < n; ++k) {
                FZ_CHECK(fz::finite3(fr[k], fg[k], fb[k]) && std::isfinite(pd[k]));
                FZ_CHECK(fr[k] >= 0 && fg[k] >= 0 && fb[k] >= 0 && pd[k] >= 0);
            }
            if (se == PGLOSS_OK && comparable && tier != PGLOSS_PRECISION_REFERENCE) {
                const double tol = (1e-6 * (4 + x) + half_vector_error(o.v, i.v, m.alpha_x, m.alpha_y, x)) *
                                   (tier == PGLOSS_PRECISION_FAST ? 2 : 1);
                // Where the exponent is beyond float's range (x > 87: e below FLT_MIN) the lobe's
                // constant and normalisation (up to 1/COS_MIN²) still multiply a subnormal or 0.
                const double floor = x > 87 ? HUGE_VAL : 1e-30 * std::max(1.0, double(m.rho_s));
                agree(fr[0], f.r, tol, regular, floor);
                agree(fg[0], f.g, tol, regular, floor);
                agree(fb[0], f.b, tol, regular, floor);
                agree(pd[0], pdf, tol, regular, floor);
            }
            if (tier == PGLOSS_PRECISION_FLOAT) {
                std::vector<float> all(fr);
                all.insert(all.end(), fg.begin(), fg.end());
                all.insert(all.end(), fb.begin(), fb.end());
                all.insert(all.end(), pd.begin(), pd.end());
                if (float_ref.empty()) float_ref = all;
                else FZ_CHECK(std::memcmp(all.data(), float_ref.data(), all.size() * sizeof(float)) == 0);
                // Per-element materials: the same material in every element
                // gives the uniform batch's bits; the double path keeps the contracts.
                std::vector<float> mr(n, m.rho_d[0]), mg(n, m.rho_d[1]), mb(n, m.rho_d[2]), msp(n, m.rho_s),
                    max_(n, m.alpha_x), may(n, m.alpha_y); /* the float values (p's may round to 0) */
                const pgloss_physical_array ma{pgloss_strided3_soa(mr.data(), mg.data(), mb.data(), sizeof(float)),
                                               pgloss_strided_of(msp.data(), sizeof(float)),
                                               pgloss_strided_of(max_.data(), sizeof(float)),
                                               pgloss_strided_of(may.data(), sizeof(float)), p.normalization};
                std::vector<float> er(n, -1), eg(n, -1), eb(n, -1), ep(n, -1);
                std::vector<signed char> est(n, 99);
                const pgloss_status es =
                    pgloss_eval_pdf_batch(&opt, nullptr, &ma, lobes, n, wo, wi, out3(er, eg, eb), out1(ep), est.data());
                FZ_CHECK(es == se && est[0] == se);
                // Bit for bit, the sign of zero included (pgloss_inl_material_derive makes a -0
                // reflectance +0 on both paths).
                FZ_CHECK(std::memcmp(er.data(), fr.data(), n * sizeof(float)) == 0 &&
                         std::memcmp(eg.data(), fg.data(), n * sizeof(float)) == 0 &&
                         std::memcmp(eb.data(), fb.data(), n * sizeof(float)) == 0 &&
                         std::memcmp(ep.data(), pd.data(), n * sizeof(float)) == 0);
                const double dov[3] = {o.v.x, o.v.y, o.v.z}, div[3] = {i.v.x, i.v.y, i.v.z};
                std::vector<double> dr(n, -1), dg(n, -1), db(n, -1), dp(n, -1);
                const pgloss_batch_options dopt{tier, isa, PGLOSS_FLOAT64};
                const pgloss_status ds = pgloss_eval_pdf_batch(&dopt, &m, nullptr, lobes, n,
                                                               pgloss_strided3{{&dov[0], &dov[1], &dov[2]}, 0},
                                                               pgloss_strided3{{&div[0], &div[1], &div[2]}, 0},
                                                               out3(dr, dg, db), out1(dp), nullptr);
                FZ_CHECK(ds == se);
                for (size_t k = 0; k < n; ++k) {
                    FZ_CHECK(fz::finite3(dr[k], dg[k], db[k]) && std::isfinite(dp[k]));
                    FZ_CHECK(dr[k] >= 0 && dg[k] >= 0 && db[k] >= 0 && dp[k] >= 0 && dr[k] <= FLT_MAX && dp[k] <= FLT_MAX);
                }
            }
            std::vector<float> sx(n), sy(n), sz(n), sp(n), gr(n), gg(n), gb(n);
            std::vector<unsigned char> lb(n);
            const pgloss_status bss = pgloss_sample_batch(&opt, &m, nullptr, lobes, n, wo, us, out3(sx, sy, sz), out1(sp),
                                                          out3(gr, gg, gb), lb.data(), nullptr);
            FZ_CHECK(documented_sample(bss));
            for (size_t k = 0; k < n; ++k) {
                FZ_CHECK(fz::finite3(sx[k], sy[k], sz[k]) && std::isfinite(sp[k]) && fz::finite3(gr[k], gg[k], gb[k]));
                FZ_CHECK(sp[k] >= 0 && gr[k] >= 0 && gg[k] >= 0 && gb[k] >= 0);
                if (sp[k] == 0) FZ_CHECK(gr[k] == 0 && gg[k] == 0 && gb[k] == 0);
            }
        }
    }
    return 0;
}
