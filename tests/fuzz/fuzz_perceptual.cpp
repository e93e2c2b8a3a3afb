// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the perceptual and colour functions (perceptual.h, color.h).
// Contracts asserted (from the headers):
//   - every status is documented (an error or warning code of status.h); outputs are finite;
//   - the round trips the headers promise: L* ↔ Y, (ρd, ρs, α) ↔ (L, c, d), Lab ↔ RGB,
//     perceptual ↔ physical;
//   - one rule at the boundaries: what check_perceptual accepts, physical_from_perceptual
//     converts, and its result makes a material (material_init) that check_physical accepts.
#include "fuzz_common.hpp"

#include <pgloss/pgloss.h>

#include <cstring>
#include <vector>

namespace {

bool documented(pgloss_status s) { return s >= PGLOSS_ERR_RANDOM && s <= PGLOSS_WARN_ALPHA_UNTRUSTED; }
bool near(double a, double b, double rel, double abs_tol) {
    return std::fabs(a - b) <= rel * std::max(std::fabs(a), std::fabs(b)) + abs_tol;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size) {
    fz::Bytes b(data, size);
    const double rd = b.real(0, 1), rs = b.real(0, 1), alpha = b.real(1e-6, 1);
    const double L = b.real(0, 100), A = b.real(-128, 128), B = b.real(-128, 128);
    const double c = b.real(0, 0.3), d = b.real(0.5, 1);

    // L* ↔ Y.
    double l = -1, y = -1;
    pgloss_status s = pgloss_lightness_from_luminance(rd, &l);
    FZ_CHECK(documented(s) && std::isfinite(l));
    if (s == PGLOSS_OK) {
        s = pgloss_luminance_from_lightness(l, &y);
        FZ_CHECK(s == PGLOSS_OK && std::isfinite(y));
        FZ_CHECK(near(y, rd, 1e-12, 1e-300));
    }
    s = pgloss_luminance_from_lightness(L, &y);
    FZ_CHECK(documented(s) && std::isfinite(y));

    // Eqs. 3–8 both ways.
    double gl, gc, gd;
    s = pgloss_gloss_from_physical(rd, rs, alpha, &gl, &gc, &gd);
    FZ_CHECK(documented(s) && std::isfinite(gl) && std::isfinite(gc) && std::isfinite(gd));
    if (s >= 0) FZ_CHECK(gd < 1);
    if (s >= 0 && rd <= 1) {  // eq. 6's domain is L* in [0, 100], i.e. ρd <= 1
        double brd, brs, ba;
        const pgloss_status t = pgloss_physical_from_gloss(gl, gc, gd, &brd, &brs, &ba);
        FZ_CHECK(t >= 0);
        FZ_CHECK(near(brd, rd, 1e-12, 1e-300));
        FZ_CHECK(near(brs, rs, 1e-9, 1e-15 * rd + 1e-300));
        FZ_CHECK(std::fabs(ba - alpha) <= 0x1p-51 * std::max(1.0, alpha));  // two roundings near max(1, α)
    }
    double prd, prs, pa;
    s = pgloss_physical_from_gloss(L, c, d, &prd, &prs, &pa);
    FZ_CHECK(documented(s) && std::isfinite(prd) && std::isfinite(prs) && std::isfinite(pa));

    double D, cmax, mrd, mrs;
    s = pgloss_gloss_distance(c, d, b.real(0, 0.3), b.real(0.5, 1), &D);
    FZ_CHECK(documented(s) && std::isfinite(D) && D >= 0);
    s = pgloss_envelope_contrast(L, &cmax);
    FZ_CHECK(documented(s) && std::isfinite(cmax) && cmax >= 0);
    s = pgloss_match_gloss(rd, rs, L, &mrd, &mrs);
    FZ_CHECK(documented(s) && std::isfinite(mrd) && std::isfinite(mrs));
    const size_t n = b.byte() % 65;
    std::vector<double> cs(n + 1, -7), ds(n + 1, -7);
    s = pgloss_isogloss_contour(c, d, b.real(0, 0.2), n, cs.data(), ds.data());
    FZ_CHECK(documented(s));
    for (size_t k = 0; k < n; ++k) FZ_CHECK(std::isfinite(cs[k]) && std::isfinite(ds[k]));
    FZ_CHECK(cs[n] == -7 && ds[n] == -7);  // nothing written past n

    // Lab ↔ RGB.
    const double lab[3] = {L, A, B};
    double rgb[3], back[3];
    s = pgloss_rgb_from_lab(lab, rgb);
    FZ_CHECK(documented(s) && std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]));
    if (s == PGLOSS_OK) {
        FZ_CHECK(rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0);  // one rule: OK has no negative channel
        if (pgloss_lab_from_rgb(rgb, back) == PGLOSS_OK && L > 1e-6)
            for (int k = 0; k < 3; ++k) FZ_CHECK(std::fabs(back[k] - lab[k]) <= 1e-6 + 1e-9 * std::fabs(lab[k]));
    }

    // The five-parameter description (Fig. 13) and the model's checks.
    const pgloss_perceptual q{L, A, B, c, d};
    const pgloss_normalization norm = static_cast<pgloss_normalization>(b.byte() % 4);
    const pgloss_status cq = pgloss_check_perceptual(&q);
    FZ_CHECK(documented(cq));
    pgloss_physical p;
    const pgloss_status pq = pgloss_physical_from_perceptual(&q, norm, &p);
    FZ_CHECK(documented(pq));
    if (cq >= 0 && norm <= PGLOSS_NORM_BOUNDED) {
        FZ_CHECK(pq >= 0);
        pgloss_material m;
        FZ_CHECK(pgloss_material_init(&m, &p) >= 0);
        FZ_CHECK(pgloss_check_physical(&p) >= 0);
        pgloss_perceptual q2;
        FZ_CHECK(pgloss_perceptual_from_physical(&p, &q2) >= 0);
        // d → α = 1 − d → d: one rounding of each subtraction, an ulp of max(1, |d|).
        FZ_CHECK(near(q2.L, q.L, 1e-9, 1e-9) && std::fabs(q2.d - q.d) <= 0x1p-51 * std::max(1.0, std::fabs(q.d)));
        // c = ∛(ρs + Y/2) − ∛(Y/2) is infinitely sensitive to Y as Y → 0 (∛'s slope): near
        // black, rounding the colour by 1e-14 moves c by 1e-5. Compared from L* = 1 up.
        if (q.L >= 1) FZ_CHECK(near(q2.c, q.c, 1e-9, 1e-12));
    }
    pgloss_physical pp{{rd, b.byte() % 2 ? rd : b.real(0, 1), rd}, rs, alpha, b.byte() % 2 ? alpha : b.real(1e-6, 1), norm};
    pgloss_perceptual q3;
    const pgloss_status cp = pgloss_check_physical(&pp), pf = pgloss_perceptual_from_physical(&pp, &q3);
    FZ_CHECK(documented(cp) && documented(pf));
    FZ_CHECK(std::isfinite(q3.L) && std::isfinite(q3.a) && std::isfinite(q3.b) && std::isfinite(q3.c) &&
             std::isfinite(q3.d));

    // The batched forms (perceptual_batch.h): element by element the scalar function's status
    // and bits, the returned status the first error (else warning).
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    {
        double o1, o2, o3;
        signed char st = 99;
        const auto in = [](const double *x) { return pgloss_strided_of(x, 0); };
        const auto out = [](double *x) { return pgloss_strided_out_of(x, 0); };
        const pgloss_status r =
            pgloss_gloss_from_physical_batch(1, in(&rd), in(&rs), in(&alpha), out(&o1), out(&o2), out(&o3), &st);
        FZ_CHECK(r == st && st == pgloss_gloss_from_physical(rd, rs, alpha, &gl, &gc, &gd));
        FZ_CHECK(same(o1, gl) && same(o2, gc) && same(o3, gd));
    }
    {
        // an unknown normalisation (norm 3) too: the scalar function's status, after its input checks
        const auto in = [](const double *x) { return pgloss_strided_of(x, 0); };
        const pgloss_perceptual_array qa{in(&q.L), in(&q.a), in(&q.b), in(&q.c), in(&q.d)};
        double rgb[3], s0, ax, ay;
        signed char st = 99;
        const pgloss_physical_array_out po{pgloss_strided3_out_rows(rgb, sizeof(double)), pgloss_strided_out_of(&s0, 0),
                                           pgloss_strided_out_of(&ax, 0), pgloss_strided_out_of(&ay, 0)};
        const pgloss_status r =
            pgloss_physical_from_perceptual_batch(1, &qa, norm, PGLOSS_COLOR_SPACE_LINEAR_REC709, &po, &st);
        const double r0 = rgb[0], r1 = rgb[1], r2 = rgb[2];
        FZ_CHECK(r == pq && st == pq);
        FZ_CHECK(same(r0, p.rho_d[0]) && same(r1, p.rho_d[1]) && same(r2, p.rho_d[2]) && same(s0, p.rho_s) &&
                 same(ax, p.alpha_x) && same(ay, p.alpha_y));
        FZ_CHECK(pgloss_check_perceptual_batch(1, &qa, PGLOSS_COLOR_SPACE_LINEAR_REC709, &st) == cq && st == cq);
    }
    return 0;
}
