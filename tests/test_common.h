// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the statistical / consistency / albedo / stress tests of libpgloss:
// sample-count scaling for sanitizer builds, a fixed-seed RNG (PCG32), direction and
// adversarial-value generators, an independent double-precision reference of the formulas
// documented in pgloss/brdf.h (the test oracle), adaptive quadrature in double, and the
// regularised incomplete gamma function (chi-square p-values).
#ifndef PGLOSS_TEST_COMMON_H
#define PGLOSS_TEST_COMMON_H

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "pgloss/pgloss.h"

namespace pgt {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFloatEps = 1.0 / 16777216.0;  // 2^-24, unit roundoff of float

// ---------------------------------------------------------------------------------------
// Run-time scale of the sample counts. Sanitizer builds run the same tests with fewer
// samples: PGLOSS_SANITIZED=1 in the environment (scripts/test-core.sh sets it for the
// ASan/UBSan build) or a compiler that says it instruments (GCC __SANITIZE_ADDRESS__,
// Clang __has_feature) selects the factor 0.25; PGLOSS_TEST_SCALE=x overrides it (x > 0).
// The Release build always runs at scale 1 unless PGLOSS_TEST_SCALE says otherwise, and the
// chi-square test insists on >= 10^6 samples there.
// ---------------------------------------------------------------------------------------
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define PGLOSS_TEST_COMPILED_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define PGLOSS_TEST_COMPILED_SANITIZED 1
#endif
#endif
#ifndef PGLOSS_TEST_COMPILED_SANITIZED
#define PGLOSS_TEST_COMPILED_SANITIZED 0
#endif

inline bool sanitized_build() {
    const char *s = std::getenv("PGLOSS_SANITIZED");
    if (s && *s && std::string(s) != "0") return true;
    return PGLOSS_TEST_COMPILED_SANITIZED != 0;
}

inline bool scale_overridden() {
    const char *s = std::getenv("PGLOSS_TEST_SCALE");
    return s && *s && std::atof(s) > 0.0;
}

inline double test_scale() {
    if (scale_overridden()) return std::atof(std::getenv("PGLOSS_TEST_SCALE"));
    return sanitized_build() ? 0.25 : 1.0;
}

inline std::size_t scaled(std::size_t n, std::size_t minimum = 1) {
    const double v = static_cast<double>(n) * test_scale();
    return std::max(static_cast<std::size_t>(v), minimum);
}
// ---------------------------------------------------------------------------------------
// RNG: PCG32 (O'Neill 2014, XSH-RR 64/32), seeded through splitmix64.
// ---------------------------------------------------------------------------------------
inline std::uint64_t splitmix64(std::uint64_t &x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class Pcg32 {
public:
    explicit Pcg32(std::uint64_t seed, std::uint64_t stream = 1) {
        std::uint64_t sm = seed;
        state_ = 0;
        inc_ = (splitmix64(sm) ^ stream) << 1 | 1u;
        next_u32();
        state_ += splitmix64(sm);
        next_u32();
    }
    std::uint32_t next_u32() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        std::uint32_t xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        std::uint32_t rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    std::uint64_t next_u64() {
        std::uint64_t hi = next_u32();
        return (hi << 32) | next_u32();
    }
    // Uniform float in [0, 1): multiples of 2^-24, so the largest is 1 - 2^-24.
    float uniform_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }
    // Uniform double in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1p-53; }
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(uniform() * n); }

private:
    std::uint64_t state_ = 0, inc_ = 0;
};

// ---------------------------------------------------------------------------------------
// Small vector helpers in double.
// ---------------------------------------------------------------------------------------
struct V3 {
    double x = 0, y = 0, z = 0;
};
inline V3 v3(const pgloss_vec3 &v) { return {v.x, v.y, v.z}; }
inline pgloss_vec3 to_f(const V3 &v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
inline double dot(const V3 &a, const V3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 add(const V3 &a, const V3 &b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 scale(const V3 &a, double s) { return {a.x * s, a.y * s, a.z * s}; }

// Normalises as brdf.h documents (scale by the largest |component| first). Returns false
// for zero-length or non-finite vectors.
inline bool normalize(V3 &v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
    double m = std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z)));
    if (!(m > 0)) return false;
    V3 s = scale(v, 1.0 / m);
    double l = std::sqrt(dot(s, s));
    v = scale(s, 1.0 / l);
    return true;
}

// Direction from (cos θ, φ) in the local frame (+z = normal), in double.
inline V3 dir_d(double cos_theta, double phi) {
    double c = std::min(1.0, std::max(-1.0, cos_theta));
    double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {s * std::cos(phi), s * std::sin(phi), c};
}
inline pgloss_vec3 dir(double cos_theta, double phi) { return to_f(dir_d(cos_theta, phi)); }

// Uniform on the upper hemisphere (z in (0, 1]).
inline pgloss_vec3 random_upper(Pcg32 &rng, double zmin = 1e-4) {
    double z = zmin + (1.0 - zmin) * rng.uniform();
    return dir(z, 2.0 * kPi * rng.uniform());
}
// Uniform on the sphere.
inline pgloss_vec3 random_sphere(Pcg32 &rng) {
    return dir(2.0 * rng.uniform() - 1.0, 2.0 * kPi * rng.uniform());
}

inline bool all_finite(const pgloss_rgb &c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
inline bool all_finite(const pgloss_vec3 &v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// ---------------------------------------------------------------------------------------
// Materials.
// ---------------------------------------------------------------------------------------
inline pgloss_physical physical(double rd_r, double rd_g, double rd_b, double rho_s, double ax,
                                double ay, pgloss_normalization n) {
    pgloss_physical p{};
    p.rho_d[0] = rd_r;
    p.rho_d[1] = rd_g;
    p.rho_d[2] = rd_b;
    p.rho_s = rho_s;
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.normalization = n;
    return p;
}

inline const char *norm_name(pgloss_normalization n) {
    switch (n) {
    case PGLOSS_NORM_WARD: return "WARD";
    case PGLOSS_NORM_WARD_DUR: return "WARD_DUR";
    case PGLOSS_NORM_BOUNDED: return "BOUNDED";
    }
    return "?";
}

// ---------------------------------------------------------------------------------------
// Independent reference of the formulas of pgloss/brdf.h, in double, from the *physical*
// parameters (rounded to float as the material stores them; α raised to PGLOSS_ALPHA_MIN).
// ---------------------------------------------------------------------------------------
struct Ref {
    double rd[3] = {0, 0, 0};
    double rs = 0, ax = 1, ay = 1;
    pgloss_normalization norm = PGLOSS_NORM_WARD;
    unsigned lobes = 0;

    static Ref from(const pgloss_physical &p) {
        Ref r;
        for (int k = 0; k < 3; ++k) r.rd[k] = static_cast<float>(p.rho_d[k]);
        r.rs = static_cast<float>(p.rho_s);
        r.ax = std::max(static_cast<double>(static_cast<float>(p.alpha_x)),
                        static_cast<double>(PGLOSS_ALPHA_MIN));
        r.ay = std::max(static_cast<double>(static_cast<float>(p.alpha_y)),
                        static_cast<double>(PGLOSS_ALPHA_MIN));
        r.norm = p.normalization;
        r.lobes = 0;
        if (r.rd[0] > 0 || r.rd[1] > 0 || r.rd[2] > 0) r.lobes |= PGLOSS_LOBE_DIFFUSE;
        if (r.rs > 0) r.lobes |= PGLOSS_LOBE_SPECULAR;
        return r;
    }

    double luminance_d() const {
        return PGLOSS_LUMA_R * rd[0] + PGLOSS_LUMA_G * rd[1] + PGLOSS_LUMA_B * rd[2];
    }

    double spec_prob(unsigned mask) const {
        unsigned a = mask & lobes;
        if (a == PGLOSS_LOBE_SPECULAR) return 1.0;
        if (a != PGLOSS_LOBE_ALL) return 0.0;
        double wd = luminance_d(), ws = rs;
        return ws / (wd + ws);
    }

    // The exponent x of E = exp(-x) for unnormalised h (invariant under scaling of h).
    double exponent(const V3 &h) const {
        double a = h.x / ax, b = h.y / ay;
        return (a * a + b * b) / (h.z * h.z);
    }

    struct Eval {
        double f[3] = {0, 0, 0};
        double spec = 0;       // specular part of f
        double spec_coef = 0;  // spec = spec_coef * exp(-x)
        double x = 0;          // exponent
        double ci = 0, co = 0, hz_n = 0;  // cosines (hz_n of the normalised half vector)
        bool valid = true;     // false: a direction was zero or non-finite
    };

    Eval eval(pgloss_vec3 wo_f, pgloss_vec3 wi_f, unsigned mask) const { return eval_d(v3(wo_f), v3(wi_f), mask); }

    Eval eval_d(V3 wo, V3 wi, unsigned mask) const {
        Eval e;
        if (!normalize(wo) || !normalize(wi)) {
            e.valid = false;
            return e;
        }
        e.ci = wi.z;
        e.co = wo.z;
        if (wo.z <= 0 || wi.z <= 0) return e;
        unsigned a = mask & lobes;
        if (a & PGLOSS_LOBE_DIFFUSE)
            for (int k = 0; k < 3; ++k) e.f[k] = rd[k] / kPi;
        if (a & PGLOSS_LOBE_SPECULAR) {
            V3 h = add(wo, wi);
            e.x = exponent(h);
            double hh = dot(h, h);
            e.hz_n = h.z / std::sqrt(hh);
            double ci = std::max(wi.z, static_cast<double>(PGLOSS_COS_MIN));
            double co = std::max(wo.z, static_cast<double>(PGLOSS_COS_MIN));
            switch (norm) {
            case PGLOSS_NORM_WARD: e.spec_coef = rs / (4 * kPi * ax * ay * std::sqrt(ci * co)); break;
            case PGLOSS_NORM_WARD_DUR: e.spec_coef = rs / (4 * kPi * ax * ay * ci * co); break;
            case PGLOSS_NORM_BOUNDED:
                e.spec_coef = rs * hh / (kPi * ax * ay * h.z * h.z * h.z * h.z);
                break;
            }
            e.spec = e.spec_coef * std::exp(-e.x);
            for (int k = 0; k < 3; ++k) e.f[k] += e.spec;
        }
        return e;
    }

    struct Pdf {
        double pdf = 0, p_spec = 0, p_diff = 0, ps = 0, x = 0;
        bool valid = true;
    };

    Pdf pdf(pgloss_vec3 wo_f, pgloss_vec3 wi_f, unsigned mask) const { return pdf_d(v3(wo_f), v3(wi_f), mask); }

    Pdf pdf_d(V3 wo, V3 wi, unsigned mask) const {
        Pdf p;
        if (!normalize(wo) || !normalize(wi)) {
            p.valid = false;
            return p;
        }
        if (wo.z <= 0 || wi.z <= 0) return p;
        p.ps = spec_prob(mask);
        unsigned a = mask & lobes;
        if (a == 0) return p;
        p.p_diff = wi.z / kPi;
        V3 h = add(wo, wi);
        double l = std::sqrt(dot(h, h));
        if (l > 0) {
            h = scale(h, 1.0 / l);
            double oh = dot(wo, h);
            if (oh > 0 && h.z > 0) {
                p.x = exponent(h);
                p.p_spec = std::exp(-p.x) / (4 * kPi * ax * ay * oh * h.z * h.z * h.z);
            }
        }
        p.pdf = (1 - p.ps) * p.p_diff + p.ps * p.p_spec;
        return p;
    }

    struct Sample {
        V3 wi;
        double pdf = 0;
        double weight[3] = {0, 0, 0};
        unsigned lobe = PGLOSS_LOBE_NONE;
        double x = 0;
    };

    // The sampling algorithm of brdf.h, in double. q1 = 1 - u1 is passed instead of u1
    // (both exact for float u1 >= 0.5) so that condition numbers can perturb it.
    static void concentric(double u1, double u2, double &dx, double &dy) {
        double a = 2 * u1 - 1, b = 2 * u2 - 1;
        if (a == 0 && b == 0) {
            dx = dy = 0;
            return;
        }
        double r, t;
        if (std::fabs(a) > std::fabs(b)) {
            r = a;
            t = (kPi / 4) * (b / a);
        } else {
            r = b;
            t = kPi / 2 - (kPi / 4) * (a / b);
        }
        dx = r * std::cos(t);
        dy = r * std::sin(t);
    }

    static float clamp_u(float u) {
        const float hi = 1.0f - 0x1p-24f;
        if (!(u >= 0.0f)) return 0.0f;  // negative (NaN handled by callers)
        return u > hi ? hi : u;
    }

    Sample sample(pgloss_vec3 wo_f, const float u_in[3], unsigned mask) const {
        float u[3] = {clamp_u(u_in[0]), clamp_u(u_in[1]), clamp_u(u_in[2])};
        return sample_q(wo_f, u[0], 1.0 - static_cast<double>(u[1]), u[1], u[2], mask);
    }

    Sample sample_q(pgloss_vec3 wo_f, double u0, double q1, double u1, double u2,
                    unsigned mask) const {
        Sample s;
        V3 wo = v3(wo_f);
        if (!normalize(wo)) return s;
        unsigned a = mask & lobes;
        if (a == 0) return s;
        double ps = spec_prob(mask);
        if (u0 < ps) {
            s.lobe = PGLOSS_LOBE_SPECULAR;
            double t = 2 * kPi * u2, sr = std::sqrt(-std::log(q1));
            V3 h{ax * sr * std::cos(t), ay * sr * std::sin(t), 1.0};
            h = scale(h, 1.0 / std::sqrt(dot(h, h)));
            double oh = dot(wo, h);
            s.wi = add(scale(h, 2 * oh), scale(wo, -1.0));
        } else {
            s.lobe = PGLOSS_LOBE_DIFFUSE;
            double dx, dy;
            concentric(u1, u2, dx, dy);
            s.wi = {dx, dy, std::sqrt(std::max(0.0, 1 - dx * dx - dy * dy))};
        }
        pgloss_vec3 wif = to_f(s.wi);
        Pdf p = pdf(wo_f, wif, mask);
        s.pdf = p.pdf;
        s.x = p.x;
        if (s.pdf > 0) {
            Eval e = eval(wo_f, wif, mask);
            for (int k = 0; k < 3; ++k) s.weight[k] = e.f[k] * e.ci / s.pdf;
        }
        return s;
    }
};

// ---------------------------------------------------------------------------------------
// Quadrature in double.
// ---------------------------------------------------------------------------------------
// Adaptive 1D Gauss–Kronrod (G7/K15) on [a, b] with absolute tolerance.
template <class F>
double integrate1d(const F &f, double a, double b, double tol, int depth = 0) {
    static const double xk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                 0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                 0.207784955007898467600689403773245, 0.0};
    static const double wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                 0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                 0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
    static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                 0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = f(c);
    double k = wk[7] * fc, g = wg[3] * fc;
    for (int j = 0; j < 7; ++j) {
        const double f1 = f(c - h * xk[j]), f2 = f(c + h * xk[j]);
        k += wk[j] * (f1 + f2);
        if (j % 2 == 1) g += wg[j / 2] * (f1 + f2);
    }
    k *= h;
    g *= h;
    if (std::fabs(k - g) <= tol || depth > 30) return k;
    return integrate1d(f, a, c, tol / 2, depth + 1) + integrate1d(f, c, b, tol / 2, depth + 1);
}

// Adaptive 2D cubature on [x0,x1]×[y0,y1]: the 4×4 tensor Gauss–Legendre rule on the whole
// rectangle is compared with the sum of the rule over its four quadrants; a rectangle is
// split until the two agree within max(abs_tol, rel_tol·|I|, count_tol·sqrt|I|) (abs_tol
// quartered per level) or max_depth is reached. Returns the quadrant sum. count_tol serves
// expected counts N·I: with count_tol = c/sqrt(N) the error is at most c Poisson sigmas.
//
// Like every adaptive rule it can be fooled by a feature much narrower than the rectangle
// (both rules miss it): callers integrate over a grid whose cells are no wider than a few
// widths of the narrowest feature (the chi-square grid is refined around the lobe), and the
// tolerances must stay above the noise of the integrand (a float pdf: relative 1e-7), or the
// refinement runs to max_depth everywhere.
struct Cubature {
    double abs_tol = 1e-10, rel_tol = 1e-6, count_tol = 0;
    int max_depth = 7;
    long evaluations = 0;
    long capped = 0;  // rectangles that hit max_depth without meeting the tolerance

    template <class F>
    double integrate(const F &f, double x0, double x1, double y0, double y1) {
        return refine(f, x0, x1, y0, y1, rule(f, x0, x1, y0, y1), abs_tol, 0);
    }

private:
    template <class F>
    double rule(const F &f, double x0, double x1, double y0, double y1) {
        static const double xg[4] = {-0.861136311594052575223946488892809, -0.339981043584856264802665759103245,
                                     0.339981043584856264802665759103245, 0.861136311594052575223946488892809};
        static const double wg[4] = {0.347854845137453857373063949221999, 0.652145154862546142626936050778001,
                                     0.652145154862546142626936050778001, 0.347854845137453857373063949221999};
        const double cx = 0.5 * (x0 + x1), hx = 0.5 * (x1 - x0), cy = 0.5 * (y0 + y1), hy = 0.5 * (y1 - y0);
        double s = 0;
        for (int i = 0; i < 4; ++i) {
            double row = 0;
            for (int j = 0; j < 4; ++j) row += wg[j] * f(cx + hx * xg[i], cy + hy * xg[j]);
            s += wg[i] * row;
        }
        evaluations += 16;
        return s * hx * hy;
    }
    template <class F>
    double refine(const F &f, double x0, double x1, double y0, double y1, double whole, double tol, int depth) {
        const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
        const double q[4] = {rule(f, x0, cx, y0, cy), rule(f, cx, x1, y0, cy), rule(f, x0, cx, cy, y1),
                             rule(f, cx, x1, cy, y1)};
        const double sum = q[0] + q[1] + q[2] + q[3];
        const double a = std::fabs(sum);
        if (std::fabs(sum - whole) <= std::max(std::max(tol, rel_tol * a), count_tol * std::sqrt(a))) return sum;
        if (depth >= max_depth) {
            ++capped;
            return sum;
        }
        const double t = tol / 4;
        return refine(f, x0, cx, y0, cy, q[0], t, depth + 1) + refine(f, cx, x1, y0, cy, q[1], t, depth + 1) +
               refine(f, x0, cx, cy, y1, q[2], t, depth + 1) + refine(f, cx, x1, cy, y1, q[3], t, depth + 1);
    }
};
// ---------------------------------------------------------------------------------------
// The histogram grid, in (t, φ') with t = 1 − cos θ ∈ [0, 1] (dω = dt dφ; t keeps full
// precision near the normal) and φ' = φ − φo ∈ [0, 2π) (the mirror direction is at φ' = π,
// so the refined band never wraps). Uniform coarse edges in cos θ (32) and φ (64), plus 40
// fine edges uniform in θ and in φ over the lobe's extent (LobeBox below: where the pdf
// falls to e^-16 of its peak), when that extent is narrower than 1 rad in θ / 2 rad in φ.
// ---------------------------------------------------------------------------------------
struct Grid {
    std::vector<double> te, pe;
    double phi_o = 0;
    std::size_t nt() const { return te.size() - 1; }
    std::size_t np() const { return pe.size() - 1; }
    std::size_t cells() const { return nt() * np(); }
    // Cell of a (float) direction, or -1 at or below the horizon.
    long cell(double x, double y, double z) const {
        const double r2 = x * x + y * y, l = std::sqrt(r2 + z * z);
        const double c = z / l;
        if (!(c > 0)) return -1;
        const double t = c > 0.5 ? (r2 / (l * l)) / (1 + c) : 1 - c;  // 1 − cos θ without cancellation
        double p = std::atan2(y, x) - phi_o;
        p = std::fmod(p, 2 * kPi);
        if (p < 0) p += 2 * kPi;
        std::size_t it = static_cast<std::size_t>(std::upper_bound(te.begin(), te.end(), t) - te.begin());
        std::size_t ip = static_cast<std::size_t>(std::upper_bound(pe.begin(), pe.end(), p) - pe.begin());
        it = std::min(std::max<std::size_t>(it, 1), nt()) - 1;
        ip = std::min(std::max<std::size_t>(ip, 1), np()) - 1;
        return static_cast<long>(it * np() + ip);
    }
};

inline void finish_edges(std::vector<double> &e, double lo, double hi) {
    std::sort(e.begin(), e.end());
    std::vector<double> in;  // interior edges, without duplicates
    for (double v : e)
        if (v > lo && v < hi && (in.empty() || v - in.back() > 1e-13)) in.push_back(v);
    // No sliver at the domain ends either: an interior edge closer to an end than half of its
    // neighbouring cell is dropped.
    while (in.size() >= 2 && in.front() - lo < 0.5 * (in[1] - in[0])) in.erase(in.begin());
    while (in.size() >= 2 && hi - in.back() < 0.5 * (in[in.size() - 1] - in[in.size() - 2])) in.pop_back();
    e.clear();
    e.push_back(lo);
    e.insert(e.end(), in.begin(), in.end());
    e.push_back(hi);
}

// The extent of the specular lobe in (θ, φ'): half vectors on the rings tanδ·(cos t, sin t) =
// k·(αx cos t', αy sin t'), k = 0..4 (E = e^-16 on the outer ring), mapped to wi = 2(wo·h)h − wo
// exactly as the sampler maps them. This follows the lobe where a fixed width would not: at
// grazing wo the lobe is compressed in φ by cos θo, and an anisotropic lobe is narrow along
// one tangent axis only.
struct LobeBox {
    double th_lo = 0, th_hi = 0, ph_lo = 0, ph_hi = 0;
};
inline LobeBox lobe_box(double cos_o, double phi_o, double ax, double ay) {
    const V3 wo = v3(dir(cos_o, phi_o));
    LobeBox b{1e9, -1e9, 1e9, -1e9};
    for (int k = 0; k <= 4; ++k)
        for (int j = 0; j < 256; ++j) {
            const double t = 2 * kPi * j / 256;
            V3 h{ax * k * std::cos(t), ay * k * std::sin(t), 1.0};
            normalize(h);
            const double oh = dot(wo, h);
            const V3 wi = add(scale(h, 2 * oh), scale(wo, -1));
            const double th = wi.z <= 0 ? kPi / 2 : std::atan2(std::hypot(wi.x, wi.y), wi.z);
            double ph = std::fmod(std::atan2(wi.y, wi.x) - phi_o, 2 * kPi);
            if (ph < 0) ph += 2 * kPi;
            b.th_lo = std::min(b.th_lo, th);
            b.th_hi = std::max(b.th_hi, th);
            if (th > 1e-9) {
                b.ph_lo = std::min(b.ph_lo, ph);
                b.ph_hi = std::max(b.ph_hi, ph);
            }
        }
    return b;
}

// Inserts the (sorted) fine edges of a band, removing the coarse edges inside it and within
// half a fine cell of its ends: otherwise a coarse edge a hair away from a fine one leaves a
// sliver cell far narrower than the float resolution of the sampled directions (at grazing
// wo a sharp lobe is only ~100 float ulps wide in φ), whose count is then meaningless.
inline void add_band(std::vector<double> &e, const std::vector<double> &band) {
    const double lo = band.front() - 0.5 * (band[1] - band[0]);
    const double hi = band.back() + 0.5 * (band[band.size() - 1] - band[band.size() - 2]);
    std::vector<double> kept;
    for (double v : e)
        if (v <= lo || v >= hi) kept.push_back(v);
    kept.insert(kept.end(), band.begin(), band.end());
    e.swap(kept);
}

inline Grid make_grid(double cos_o, double phi_o, double ax, double ay, bool specular, int coarse_t = 32,
                      int coarse_p = 64, int fine = 40) {
    Grid g;
    g.phi_o = phi_o;
    for (int i = 0; i <= coarse_t; ++i) g.te.push_back(static_cast<double>(i) / coarse_t);
    for (int i = 0; i <= coarse_p; ++i) g.pe.push_back(2 * kPi * i / coarse_p);
    if (specular) {
        const LobeBox b = lobe_box(cos_o, phi_o, ax, ay);
        const double mt = 0.05 * (b.th_hi - b.th_lo), mp = 0.05 * (b.ph_hi - b.ph_lo);
        if (b.th_hi - b.th_lo < 1.0) {
            const double lo = std::max(b.th_lo - mt, 0.0), hi = std::min(b.th_hi + mt, kPi / 2);
            std::vector<double> band;
            for (int i = 0; i <= fine; ++i) {
                const double th = lo + (hi - lo) * i / fine, sh = std::sin(0.5 * th);
                band.push_back(2 * sh * sh);  // 1 − cos θ
            }
            add_band(g.te, band);
        }
        if (b.ph_hi - b.ph_lo < 2.0) {
            const double lo = std::max(b.ph_lo - mp, 0.0), hi = std::min(b.ph_hi + mp, 2 * kPi);
            std::vector<double> band;
            for (int i = 0; i <= fine; ++i) band.push_back(lo + (hi - lo) * i / fine);
            add_band(g.pe, band);
        }
    }
    finish_edges(g.te, 0, 1);
    finish_edges(g.pe, 0, 2 * kPi);
    return g;
}

// Direction at grid coordinates (t, φ').
inline V3 grid_dir(const Grid &g, double t, double p) {
    const double c = 1 - t, s = std::sqrt(std::max(0.0, t * (2 - t)));
    return {s * std::cos(p + g.phi_o), s * std::sin(p + g.phi_o), c};
}

// ∫∫ pdf(wi) dt dφ over every cell (row-major, t then φ') and the total, by cubature.
template <class Pdf>
std::vector<double> cell_integrals(const Grid &g, const Pdf &pdf, double &mass, Cubature &cub) {
    std::vector<double> prob(g.cells());
    mass = 0;
    for (std::size_t it = 0; it < g.nt(); ++it)
        for (std::size_t ip = 0; ip < g.np(); ++ip) {
            const double v = cub.integrate([&](double t, double p) { return pdf(grid_dir(g, t, p)); }, g.te[it],
                                           g.te[it + 1], g.pe[ip], g.pe[ip + 1]);
            prob[it * g.np() + ip] = v;
            mass += v;
        }
    return prob;
}

// ---------------------------------------------------------------------------------------
// Regularised incomplete gamma functions P(a, x) and Q(a, x) = 1 - P (series for
// x < a + 1, modified Lentz continued fraction otherwise; Numerical Recipes §6.2), and
// the chi-square survival function.
// ---------------------------------------------------------------------------------------
inline double gamma_p_series(double a, double x) {
    double sum = 1.0 / a, term = sum, ap = a;
    for (int n = 0; n < 100000; ++n) {
        ap += 1;
        term *= x / ap;
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-17) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}
inline double gamma_q_cf(double a, double x) {
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (std::fabs(del - 1) < 1e-16) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
inline double gamma_p(double a, double x) {
    if (x <= 0) return 0;
    return x < a + 1 ? gamma_p_series(a, x) : 1 - gamma_q_cf(a, x);
}
inline double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    return x < a + 1 ? 1 - gamma_p_series(a, x) : gamma_q_cf(a, x);
}
// P(X >= stat) for X ~ chi-square with dof degrees of freedom.
inline double chi2_survival(double stat, double dof) { return gamma_q(0.5 * dof, 0.5 * stat); }

// Šidák-corrected per-test significance for a family-wise level alpha over m tests.
inline double sidak(double alpha, int m) { return 1 - std::pow(1 - alpha, 1.0 / m); }

// ---------------------------------------------------------------------------------------
// Adversarial float/double generators (stress tests).
// ---------------------------------------------------------------------------------------
inline float special_float(Pcg32 &rng) {
    static const float v[] = {0.0f,
                              -0.0f,
                              1.0f,
                              -1.0f,
                              1.0f - 0x1p-24f,
                              0x1p-24f,
                              0.5f,
                              FLT_MIN,
                              -FLT_MIN,
                              FLT_TRUE_MIN,
                              -FLT_TRUE_MIN,
                              FLT_MAX,
                              -FLT_MAX,
                              1e-38f,
                              1e38f,
                              1e-30f,
                              1e30f,
                              1e-9f,
                              1e-10f,
                              2e-9f,
                              PGLOSS_COS_MIN,
                              PGLOSS_ALPHA_MIN,
                              1e-5f,
                              0.2f,
                              1.0f + 0x1p-23f,
                              0x1p-126f * 0.75f};
    return v[rng.below(sizeof v / sizeof v[0])];
}

// Random finite float over many magnitudes: log-uniform 2^-149..2^127 (denormals
// included), random sign, or a special value, or a plain uniform one.
inline float wild_float(Pcg32 &rng) {
    std::uint32_t kind = rng.below(8);
    if (kind == 0) return special_float(rng);
    if (kind == 1) return rng.uniform_float();
    if (kind == 2) return static_cast<float>(rng.uniform(-2, 2));
    const double e = rng.uniform(-149.0, 127.999);
    const double d = std::ldexp(1.0 + rng.uniform(), static_cast<int>(std::floor(e)));
    const float v = d >= static_cast<double>(FLT_MAX) ? FLT_MAX : static_cast<float>(d);  // no overflowing cast
    return (rng.next_u32() & 1) ? -v : v;
}
inline float nonfinite_float(Pcg32 &rng) {
    switch (rng.below(3)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    default: return -std::numeric_limits<float>::infinity();
    }
}
inline double nonfinite_double(Pcg32 &rng) {
    switch (rng.below(3)) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    default: return -std::numeric_limits<double>::infinity();
    }
}
// Random finite double over many magnitudes, including beyond float range and denormals.
inline double wild_double(Pcg32 &rng) {
    std::uint32_t kind = rng.below(10);
    if (kind <= 1) return static_cast<double>(wild_float(rng));
    if (kind == 2) return rng.uniform();
    if (kind == 3) return rng.uniform(-150, 150);
    if (kind == 4) {
        static const double v[] = {0.0, -0.0, 1.0, 100.0, 1e-300, 1e300, DBL_MAX, -DBL_MAX, DBL_MIN,
                                   DBL_TRUE_MIN, 0.5, 1 - 1e-16, 0.2, 0.8, 8.0, 216.0 / 24389.0};
        double x = v[rng.below(sizeof v / sizeof v[0])];
        return (rng.next_u32() & 1) ? -x : x;
    }
    double e = rng.uniform(-1074.0, 1023.999);
    double x = std::ldexp(1.0 + rng.uniform(), static_cast<int>(std::floor(e)));
    if (!std::isfinite(x)) x = DBL_MAX;
    return (rng.next_u32() & 1) ? -x : x;
}

}  // namespace pgt

#endif  // PGLOSS_TEST_COMMON_H
