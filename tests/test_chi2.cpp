// Chi-square goodness-of-fit of pgloss_sample against pgloss_pdf (the pbrt / Mitsuba
// method): >= 10^6 samples per configuration are histogrammed on a (cos θ, φ) grid over
// the upper hemisphere, refined around the mirror direction so that α = 0.01 lobes are
// resolved; the expected count of each cell is N ∫∫ pdf d(cos θ) dφ by adaptive
// Gauss–Legendre cubature in double; rejected samples (pdf == 0) form one more cell whose
// expected count is N (1 − ∫ pdf). Cells with expected count < 5 are pooled. The p-value
// comes from our own regularised incomplete gamma function, tested here against known
// values, with a Šidák-corrected family-wise significance of 0.01.
#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <mutex>
#include <numeric>
#include <string>
#include <vector>

#include "test_common.h"

using namespace pgt;

namespace {

constexpr double kFamilyAlpha = 0.01;
constexpr std::size_t kMinSamples = 1000000;  // the minimum, normal build

std::size_t sample_count() {
    // Never below 10^6 in a normal build; sanitizer builds (or PGLOSS_TEST_SCALE < 1) may
    // use fewer to stay within their time budget.
    std::size_t n = scaled(kMinSamples, 50000);
    if (!sanitized_build() && !std::getenv("PGLOSS_TEST_SCALE")) n = std::max(n, kMinSamples);
    return n;
}

// ---------------------------------------------------------------------------------------
// Tests of the statistics helpers themselves.
// ---------------------------------------------------------------------------------------
double poisson_cdf_log_sum(long n_minus_1, double x) {
    // P(Poisson(x) <= n-1) = Q(n, x), summed in log space (independent of gamma_q).
    double m = -1e300;
    std::vector<double> t(static_cast<std::size_t>(n_minus_1) + 1);
    for (long k = 0; k <= n_minus_1; ++k) {
        t[static_cast<std::size_t>(k)] = -x + k * std::log(x) - std::lgamma(k + 1.0);
        m = std::max(m, t[static_cast<std::size_t>(k)]);
    }
    double s = 0;
    for (double v : t) s += std::exp(v - m);
    return std::exp(m) * s;
}

TEST(Chi2Stats, IncompleteGammaKnownValues) {
    for (double x : {0.01, 0.1, 1.0, 3.0, 10.0, 50.0, 200.0}) {
        EXPECT_NEAR(gamma_q(1.0, x) / std::exp(-x), 1.0, 1e-12) << x;           // Q(1,x) = e^-x
        EXPECT_NEAR(gamma_p(0.5, x), std::erf(std::sqrt(x)), 1e-13) << x;       // P(1/2,x) = erf √x
        EXPECT_NEAR(gamma_q(0.5, x) / std::erfc(std::sqrt(x)), 1.0, 1e-11) << x;
        EXPECT_NEAR(gamma_p(2.0, x), 1 - std::exp(-x) * (1 + x), 1e-13) << x;
    }
    // Integer a: Q(n, x) = P(Poisson(x) <= n - 1), summed directly.
    const std::pair<long, double> cases[] = {{5, 3.0}, {5, 9.0}, {50, 40.0}, {50, 65.0},
                                             {1000, 950.0}, {1000, 1050.0}, {5000, 5000.0},
                                             {5000, 5200.0}, {5000, 4800.0}};
    for (auto [n, x] : cases) {
        double ref = poisson_cdf_log_sum(n - 1, x);
        EXPECT_NEAR(gamma_q(static_cast<double>(n), x), ref, 1e-11 + 1e-9 * ref) << n << " " << x;
        EXPECT_NEAR(gamma_p(static_cast<double>(n), x), 1 - ref, 1e-11 + 1e-9 * (1 - ref)) << n << " " << x;
    }
    // Chi-square table values (upper-tail quantiles).
    EXPECT_NEAR(chi2_survival(3.841458820694124, 1), 0.05, 1e-9);
    EXPECT_NEAR(chi2_survival(6.634896601021214, 1), 0.01, 1e-9);
    EXPECT_NEAR(chi2_survival(5.991464547107979, 2), 0.05, 1e-9);   // = exp(-x/2)
    EXPECT_NEAR(chi2_survival(18.307038053275146, 10), 0.05, 1e-8);
    EXPECT_NEAR(chi2_survival(135.80672317102676, 100), 0.01, 1e-7);
    EXPECT_NEAR(chi2_survival(124.34211340400407, 100), 0.05, 1e-7);
    // Šidák.
    EXPECT_NEAR(sidak(0.01, 1), 0.01, 1e-15);
    EXPECT_NEAR(1 - std::pow(1 - sidak(0.01, 40), 40), 0.01, 1e-14);
}

TEST(Chi2Stats, CubatureKnownIntegrals) {
    Cubature2D cub;
    // Smooth: ∫∫ cos x e^y over [0, π/2]×[0, 1] = e - 1.
    double v = cub.integrate([](double x, double y) { return std::cos(x) * std::exp(y); }, 0, kPi / 2, 0, 1,
                             1e-14, 1e-13);
    EXPECT_NEAR(v, std::exp(1.0) - 1, 1e-12);
    // Sharp: a Gaussian bump of width 1e-3 in the unit square, mass ≈ 2π σ²·(fraction inside).
    const double s = 1e-3;
    double g = cub.integrate(
        [s](double x, double y) {
            double dx = x - 0.3, dy = y - 0.6;
            return std::exp(-(dx * dx + dy * dy) / (2 * s * s));
        },
        0, 1, 0, 1, 1e-14, 1e-10);
    EXPECT_NEAR(g / (2 * kPi * s * s), 1.0, 1e-8);
}

// ---------------------------------------------------------------------------------------
// Configurations.
// ---------------------------------------------------------------------------------------
struct Config {
    std::string name;
    pgloss_physical phys;
    unsigned mask;
    double cos_o;
    double phi_o;
};

std::string fmt_num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    std::string s(b);
    for (char &c : s)
        if (c == '.' || c == '-' || c == '+') c = '_';
    return s;
}

std::vector<Config> make_configs() {
    std::vector<Config> c;
    const pgloss_normalization norms[3] = {PGLOSS_NORM_WARD, PGLOSS_NORM_WARD_DUR, PGLOSS_NORM_BOUNDED};
    int k = 0;
    // Specular only, isotropic, every α of the issue at four incidences; normalisations cycle.
    for (double a : {0.01, 0.05, 0.2, 0.5})
        for (double co : {1.0, 0.7, 0.3, 0.05}) {
            pgloss_normalization n = norms[k++ % 3];
            c.push_back({"spec_a" + fmt_num(a) + "_cos" + fmt_num(co) + "_" + norm_name(n),
                         physical(0, 0, 0, 0.9, a, a, n), PGLOSS_LOBE_ALL, co, 0.3});
        }
    // Mixed materials, every normalisation.
    for (pgloss_normalization n : norms)
        for (double a : {0.01, 0.2})
            for (double co : {0.8, 0.05})
                c.push_back({"mixed_a" + fmt_num(a) + "_cos" + fmt_num(co) + "_" + norm_name(n),
                             physical(0.3, 0.2, 0.1, 0.1, a, a, n), PGLOSS_LOBE_ALL, co, 1.1});
    // Mixed, normal incidence (closed-form total mass).
    c.push_back({"mixed_a0_1_cos1_BOUNDED", physical(0.5, 0.4, 0.3, 0.2, 0.1, 0.1, PGLOSS_NORM_BOUNDED),
                 PGLOSS_LOBE_ALL, 1.0, 0.0});
    // Diffuse only.
    c.push_back({"diffuse_cos0_6_WARD", physical(0.5, 0.5, 0.5, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD),
                 PGLOSS_LOBE_ALL, 0.6, 0.7});
    c.push_back({"diffuse_cos0_05_BOUNDED", physical(0.8, 0.1, 0.3, 0.0, 0.01, 0.01, PGLOSS_NORM_BOUNDED),
                 PGLOSS_LOBE_ALL, 0.05, 2.0});
    // Anisotropic.
    c.push_back({"aniso_0_05x0_3_cos0_7_WARD", physical(0, 0, 0, 0.5, 0.05, 0.3, PGLOSS_NORM_WARD),
                 PGLOSS_LOBE_ALL, 0.7, 0.3});
    c.push_back({"aniso_0_05x0_3_cos0_05_WARD_DUR", physical(0, 0, 0, 0.5, 0.05, 0.3, PGLOSS_NORM_WARD_DUR),
                 PGLOSS_LOBE_ALL, 0.05, 0.3});
    c.push_back({"aniso_0_3x0_05_cos0_3_BOUNDED", physical(0, 0, 0, 0.5, 0.3, 0.05, PGLOSS_NORM_BOUNDED),
                 PGLOSS_LOBE_ALL, 0.3, 1.9});
    c.push_back({"aniso_0_05x0_3_cos1_BOUNDED", physical(0, 0, 0, 0.5, 0.05, 0.3, PGLOSS_NORM_BOUNDED),
                 PGLOSS_LOBE_ALL, 1.0, 0.0});
    c.push_back({"aniso_mixed_0_01x0_1_cos0_5_WARD", physical(0.2, 0.3, 0.4, 0.3, 0.01, 0.1, PGLOSS_NORM_WARD),
                 PGLOSS_LOBE_ALL, 0.5, 0.9});
    // Lobe masks on a mixed material.
    c.push_back({"mask_diffuse_WARD", physical(0.4, 0.4, 0.4, 0.3, 0.1, 0.1, PGLOSS_NORM_WARD),
                 PGLOSS_LOBE_DIFFUSE, 0.5, 0.4});
    c.push_back({"mask_specular_WARD_DUR", physical(0.4, 0.4, 0.4, 0.3, 0.1, 0.1, PGLOSS_NORM_WARD_DUR),
                 PGLOSS_LOBE_SPECULAR, 0.5, 0.4});
    c.push_back({"mask_specular_BOUNDED_cos0_05", physical(0.4, 0.4, 0.4, 0.3, 0.05, 0.05, PGLOSS_NORM_BOUNDED),
                 PGLOSS_LOBE_SPECULAR, 0.05, 0.4});
    // A lobe sharper than the range, oblique.
    c.push_back({"spec_a0_002_cos0_7_WARD", physical(0, 0, 0, 0.9, 0.002, 0.002, PGLOSS_NORM_WARD),
                 PGLOSS_LOBE_ALL, 0.7, 0.3});
    return c;
}

const std::vector<Config> &configs() {
    static const std::vector<Config> c = make_configs();
    return c;
}

// ---------------------------------------------------------------------------------------
// The histogram grid: cos θ in [0, 1] and φ' = φ − φo in [0, 2π) (the mirror direction at
// φ' = π, so the refined band never wraps). Uniform coarse edges plus a fine band around
// the mirror direction sized by the lobe width (8 max(αx, αy) radians).
// ---------------------------------------------------------------------------------------
struct Grid {
    std::vector<double> ce, pe;
    double phi_o = 0;
    std::size_t nc() const { return ce.size() - 1; }
    std::size_t np() const { return pe.size() - 1; }
    std::size_t cells() const { return nc() * np(); }
    // Cell of a direction (double components), or -1 if not in the upper hemisphere.
    long cell(double x, double y, double z) const {
        double l = std::sqrt(x * x + y * y + z * z);
        double c = z / l;
        if (!(c > 0)) return -1;
        double p = std::atan2(y, x) - phi_o;
        p = std::fmod(p, 2 * kPi);
        if (p < 0) p += 2 * kPi;
        std::size_t ic = static_cast<std::size_t>(std::upper_bound(ce.begin(), ce.end(), c) - ce.begin());
        std::size_t ip = static_cast<std::size_t>(std::upper_bound(pe.begin(), pe.end(), p) - pe.begin());
        ic = std::min(std::max<std::size_t>(ic, 1), nc()) - 1;
        ip = std::min(std::max<std::size_t>(ip, 1), np()) - 1;
        return static_cast<long>(ic * np() + ip);
    }
};

void add_uniform(std::vector<double> &e, double a, double b, int n) {
    for (int i = 0; i <= n; ++i) e.push_back(a + (b - a) * i / n);
}
void finish_edges(std::vector<double> &e) {
    std::sort(e.begin(), e.end());
    std::vector<double> out;
    for (double v : e)
        if (out.empty() || v - out.back() > 1e-10) out.push_back(v);
    e.swap(out);
}

Grid make_grid(const Config &cfg, const Ref &ref) {
    Grid g;
    g.phi_o = cfg.phi_o;
    const int coarse_c = 40, coarse_p = 80, fine = 48;
    add_uniform(g.ce, 0, 1, coarse_c);
    add_uniform(g.pe, 0, 2 * kPi, coarse_p);
    if ((cfg.mask & ref.lobes) & PGLOSS_LOBE_SPECULAR) {
        double w = 8 * std::max(ref.ax, ref.ay);
        double tr = std::acos(cfg.cos_o);
        double clo = std::cos(std::min(tr + w, kPi / 2)), chi = std::cos(std::max(tr - w, 0.0));
        if (chi - clo < 0.5) add_uniform(g.ce, clo, chi, fine);
        double s = std::sin(tr);
        if (s > 1e-6 && w / s < kPi / 2) add_uniform(g.pe, kPi - w / s, kPi + w / s, fine);
    }
    finish_edges(g.ce);
    finish_edges(g.pe);
    g.ce.front() = 0;
    g.ce.back() = 1;
    g.pe.front() = 0;
    g.pe.back() = 2 * kPi;
    return g;
}

// ---------------------------------------------------------------------------------------
// The test.
// ---------------------------------------------------------------------------------------
struct Outcome {
    std::size_t n = 0, accepted = 0, rejected = 0;
    std::size_t below_horizon_accepted = 0, wrong_lobe = 0, bad_status = 0;
    double mass = 0;  // ∫ pdf over the hemisphere
    double stat = 0, p = 1;
    int dof = 0;
    std::size_t cells = 0, pooled_cells = 0;
};

struct Row {
    std::string name;
    Outcome o;
};
std::mutex g_rows_mutex;
std::vector<Row> g_rows;

// Chi-square over (observed, expected) pairs with pbrt's pooling of small expected counts.
void chi_square(std::vector<std::pair<double, double>> cells, double min_exp, Outcome &o) {
    std::sort(cells.begin(), cells.end(), [](const auto &a, const auto &b) { return a.second < b.second; });
    double stat = 0, pool_obs = 0, pool_exp = 0;
    int dof = 0;
    std::size_t pooled = 0;
    for (const auto &[obs, ex] : cells) {
        if (ex < min_exp || (pool_exp > 0 && pool_exp < min_exp)) {
            pool_obs += obs;
            pool_exp += ex;
            ++pooled;
        } else {
            stat += (obs - ex) * (obs - ex) / ex;
            ++dof;
        }
    }
    if (pool_exp > 0 || pool_obs > 0) {
        stat += pool_exp > 0 ? (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp
                             : std::numeric_limits<double>::infinity();
        ++dof;
    }
    dof -= 1;
    o.stat = stat;
    o.dof = dof;
    o.pooled_cells = pooled;
    o.p = dof > 0 ? chi2_survival(stat, dof) : (stat > 0 ? 0.0 : 1.0);
}

// Runs one configuration. `pdf_phys` lets the negative controls compare the samples of
// one material with the pdf of another.
Outcome run_config(const Config &cfg, const pgloss_physical &pdf_phys, std::size_t n, std::uint64_t seed) {
    Outcome o;
    o.n = n;
    pgloss_material m, mp;
    pgloss_status st = pgloss_material_init(&m, &cfg.phys);
    EXPECT_GE(st, 0) << pgloss_status_name(st);
    st = pgloss_material_init(&mp, &pdf_phys);
    EXPECT_GE(st, 0) << pgloss_status_name(st);
    Ref ref = Ref::from(pdf_phys);
    Grid g = make_grid(cfg, ref);
    const pgloss_vec3 wo = dir(cfg.cos_o, cfg.phi_o);

    // Samples.
    std::vector<double> hist(g.cells(), 0.0);
    Pcg32 rng(seed, 0x5eed);
    for (std::size_t i = 0; i < n; ++i) {
        float u[3] = {rng.uniform_float(), rng.uniform_float(), rng.uniform_float()};
        pgloss_sample_record r;
        if (pgloss_sample(&m, wo, u, cfg.mask, &r) != PGLOSS_OK) ++o.bad_status;
        if (!(r.pdf > 0)) {
            ++o.rejected;
            continue;
        }
        ++o.accepted;
        if (!(r.lobe & cfg.mask & m.lobes)) ++o.wrong_lobe;
        long c = g.cell(r.wi.x, r.wi.y, r.wi.z);
        if (c < 0) {
            ++o.below_horizon_accepted;
            continue;
        }
        hist[static_cast<std::size_t>(c)] += 1;
    }

    // Expected counts: ∫∫ pdf d(cos θ) dφ per cell.
    Cubature2D cub;
    std::vector<std::pair<double, double>> cells;
    cells.reserve(g.cells() + 1);
    double mass = 0;
    auto pdf_at = [&](double c, double p) {
        float v = 0;
        pgloss_pdf(&mp, wo, dir(c, p + cfg.phi_o), cfg.mask, &v);
        return static_cast<double>(v);
    };
    for (std::size_t ic = 0; ic < g.nc(); ++ic)
        for (std::size_t ip = 0; ip < g.np(); ++ip) {
            double v = cub.integrate(pdf_at, g.ce[ic], g.ce[ic + 1], g.pe[ip], g.pe[ip + 1], 1e-11, 1e-7);
            mass += v;
            cells.emplace_back(hist[ic * g.np() + ip], v * static_cast<double>(n));
        }
    o.mass = mass;
    // The rejected samples are one more multinomial cell.
    cells.emplace_back(static_cast<double>(o.rejected), std::max(0.0, 1 - mass) * static_cast<double>(n));
    o.cells = cells.size();
    chi_square(cells, 5.0, o);
    return o;
}

// Closed-form ∫ pdf at normal incidence: the specular lobe loses exactly the half vectors
// with tan²δ ≥ 1 (wi.z = 2 hz² − 1 ≤ 0), which for the sampled density have probability
// (1/2π) ∫ exp(−1 / (αx² cos² t + αy² sin² t)) dt  (= exp(−1/α²) when isotropic).
double normal_incidence_mass(const Ref &ref, unsigned mask) {
    double lost = integrate1d(
                      [&](double t) {
                          double c = std::cos(t), s = std::sin(t);
                          return std::exp(-1 / (ref.ax * ref.ax * c * c + ref.ay * ref.ay * s * s));
                      },
                      0, 2 * kPi, 1e-15) /
                  (2 * kPi);
    double ps = ref.spec_prob(mask);
    if ((mask & ref.lobes) == 0) return 0;
    return (1 - ps) + ps * (1 - lost);
}

class Chi2 : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Chi2, SampleMatchesPdf) {
    const Config &cfg = configs()[GetParam()];
    const std::size_t n = sample_count();
    Outcome o = run_config(cfg, cfg.phys, n, 0x9e3779b9ull * (GetParam() + 1));
    const double level = sidak(kFamilyAlpha, static_cast<int>(configs().size()));

    EXPECT_EQ(o.bad_status, 0u);
    EXPECT_EQ(o.below_horizon_accepted, 0u) << "accepted samples (pdf > 0) at or below the horizon";
    EXPECT_EQ(o.wrong_lobe, 0u) << "accepted samples from a lobe outside the mask";
    // ∫ pdf over the hemisphere must equal the accepted fraction (binomial, 5 sigma).
    double frac = static_cast<double>(o.accepted) / static_cast<double>(n);
    double sigma = std::sqrt(std::max(o.mass * (1 - o.mass), 1.0 / static_cast<double>(n)) / static_cast<double>(n));
    EXPECT_NEAR(frac, o.mass, 5 * sigma + 1e-6) << "accepted fraction vs ∫ pdf";
    EXPECT_LE(o.mass, 1 + 1e-6);
    // The integrator on the total mass, where it is known in closed form.
    Ref ref = Ref::from(cfg.phys);
    if (cfg.cos_o == 1.0) {
        EXPECT_NEAR(o.mass, normal_incidence_mass(ref, cfg.mask), 2e-6);
    }
    if ((cfg.mask & ref.lobes) == PGLOSS_LOBE_DIFFUSE) {
        EXPECT_NEAR(o.mass, 1.0, 2e-6);
    }

    EXPECT_GE(o.p, level) << "chi2 = " << o.stat << ", dof = " << o.dof;
    std::printf("[chi2] %-36s N=%zu accepted=%.6f mass=%.6f cells=%zu pooled=%zu dof=%d chi2=%.1f p=%.4f%s\n",
                cfg.name.c_str(), n, frac, o.mass, o.cells, o.pooled_cells, o.dof, o.stat, o.p,
                o.p < level ? "  FAIL" : "");
    std::lock_guard<std::mutex> lock(g_rows_mutex);
    g_rows.push_back({cfg.name, o});
}

INSTANTIATE_TEST_SUITE_P(All, Chi2, ::testing::Range<std::size_t>(0, configs().size()),
                         [](const ::testing::TestParamInfo<std::size_t> &info) {
                             return configs()[info.param].name;
                         });

// Negative controls: the harness must reject a pdf that does not match the sampler —
// a 5% wider lobe, and a mixture whose lobe weights are swapped.
TEST(Chi2Power, RejectsWrongLobeWidth) {
    Config cfg{"neg_width", physical(0, 0, 0, 0.9, 0.05, 0.05, PGLOSS_NORM_WARD), PGLOSS_LOBE_ALL, 0.7, 0.3};
    pgloss_physical wrong = physical(0, 0, 0, 0.9, 0.0525, 0.0525, PGLOSS_NORM_WARD);
    Outcome o = run_config(cfg, wrong, sample_count(), 77);
    std::printf("[chi2-negative] 5%% wider lobe: chi2=%.1f dof=%d p=%.3g\n", o.stat, o.dof, o.p);
    EXPECT_LT(o.p, 1e-9);
}

TEST(Chi2Power, RejectsWrongLobeWeights) {
    Config cfg{"neg_weights", physical(0.3, 0.3, 0.3, 0.4, 0.1, 0.1, PGLOSS_NORM_WARD), PGLOSS_LOBE_ALL, 0.6, 0.3};
    pgloss_physical wrong = physical(0.4, 0.4, 0.4, 0.3, 0.1, 0.1, PGLOSS_NORM_WARD);
    Outcome o = run_config(cfg, wrong, sample_count(), 78);
    std::printf("[chi2-negative] swapped lobe weights: chi2=%.1f dof=%d p=%.3g\n", o.stat, o.dof, o.p);
    EXPECT_LT(o.p, 1e-9);
}

// Prints the whole table when the binary runs all configurations in one process.
class TablePrinter : public ::testing::Environment {
public:
    void TearDown() override {
        if (g_rows.size() < 2) return;
        std::sort(g_rows.begin(), g_rows.end(), [](const Row &a, const Row &b) { return a.name < b.name; });
        const double level = sidak(kFamilyAlpha, static_cast<int>(configs().size()));
        std::printf("\nChi-square goodness of fit, %zu configurations, Sidak per-test level %.3g "
                    "(family-wise 0.01)\n",
                    configs().size(), level);
        std::printf("%-36s %9s %9s %9s %6s %10s %8s\n", "configuration", "N", "accepted", "int pdf", "dof",
                    "chi2", "p");
        double pmin = 1;
        for (const Row &r : g_rows) {
            std::printf("%-36s %9zu %9.6f %9.6f %6d %10.1f %8.4f\n", r.name.c_str(), r.o.n,
                        static_cast<double>(r.o.accepted) / static_cast<double>(r.o.n), r.o.mass, r.o.dof,
                        r.o.stat, r.o.p);
            pmin = std::min(pmin, r.o.p);
        }
        std::printf("min p = %.4f\n", pmin);
    }
};
const auto *const g_printer = ::testing::AddGlobalTestEnvironment(new TablePrinter);

}  // namespace
