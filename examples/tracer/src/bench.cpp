// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-tracer-bench — speed of the three estimators on Experiment 1's stimulus scene
// (a benchmark, not a test). For MIS, BRDF-only and light-only sampling it reports
//   Mrays/s     rays traced (intersection and shadow rays) per second, all threads;
//   Msamples/s  camera paths per second;
//   t(1%)       seconds until the image's MRSE against a long reference render is <= 0.01,
// where MRSE = mean over pixels of (Y - Yref)² / (Yref² + 1e-3) on luminance Y (the white
// checks are ~0.5), minus the reference's own expected contribution (its variance term), so
// the reference's noise does not count. The reference is an MIS render with --ref-spp samples.
//
//   pgloss-tracer-bench [--size 128x96] [--ref-spp 2048] [--max-time 60] [--threads N]
//                       [--paint rho_d,rho_s,alpha]
#include "image.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

namespace {

struct Result {
    double mrays = 0, msamples = 0, t_target = -1, final_mrse = 0;
    int spp_target = -1, spp = 0;
};

}  // namespace

int main(int argc, char **argv) {
    int w = 128, h = 96, ref_spp = 2048, threads = 0;
    double max_time = 60, target = 0.01;
    double rd = 0.193, rs = 0.066, a = 0.07;
    for (int i = 1; i < argc; ++i) {
        std::string o = argv[i];
        auto val = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
        if (o == "--size") std::sscanf(val().c_str(), "%dx%d", &w, &h);
        else if (o == "--ref-spp") ref_spp = std::stoi(val());
        else if (o == "--max-time") max_time = std::stod(val());
        else if (o == "--threads") threads = std::stoi(val());
        else if (o == "--paint") std::sscanf(val().c_str(), "%lf,%lf,%lf", &rd, &rs, &a);
        else {
            std::fprintf(stderr, "usage: pgloss-tracer-bench [--size WxH] [--ref-spp N] [--max-time S] [--threads N] "
                                 "[--paint rho_d,rho_s,alpha]\n");
            return 2;
        }
    }
    try {
        pgt::Scene sc = pgt::load_scene(std::string(PGLOSS_TRACER_DIR) + "/scenes/stimulus.scene");
        sc.set_material("paint", pgloss_physical{{rd, rd, rd}, rs, a, a, PGLOSS_NORM_WARD});
        pgt::Renderer renderer(sc);
        pgt::RenderSettings s = sc.settings;
        s.width = w, s.height = h;

        // Reference.
        pgt::RenderOptions ro;
        ro.threads = threads;
        ro.label = "reference (mis)";
        pgt::Image ref_var;
        ro.variance = &ref_var;
        s.mode = pgt::Mode::MIS;
        s.spp = ref_spp;
        s.seed = 12345;
        pgt::RenderStats ref_st;
        pgt::Image ref = renderer.render(s, ro, &ref_st);
        const size_t n = size_t(w) * size_t(h);
        std::vector<double> Yr(n), denom(n);
        double ref_term = 0;
        for (size_t i = 0; i < n; ++i) {
            const float *c = &ref.rgb[3 * i], *v = &ref_var.rgb[3 * i];
            Yr[i] = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            double vy = 0.2126 * 0.2126 * v[0] + 0.7152 * 0.7152 * v[1] + 0.0722 * 0.0722 * v[2];  // channels correlate: approximation
            denom[i] = Yr[i] * Yr[i] + 1e-3;
            ref_term += vy / denom[i];
        }
        ref_term /= double(n);

        const pgt::Mode modes[3] = {pgt::Mode::MIS, pgt::Mode::BRDF, pgt::Mode::LIGHT};
        Result res[3];
        for (int k = 0; k < 3; ++k) {
            Result &r = res[k];
            double callback_s = 0;
            pgt::RenderOptions o;
            o.threads = threads;
            o.label = std::string("estimator ") + pgt::mode_name(modes[k]);
            o.max_pass_spp = 4;
            o.on_pass = [&](const pgt::Image &img, const pgt::RenderStats &st) {
                auto t0 = std::chrono::steady_clock::now();
                double e = 0;
                for (size_t i = 0; i < n; ++i) {
                    const float *c = &img.rgb[3 * i];
                    double d = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] - Yr[i];
                    e += d * d / denom[i];
                }
                double mrse = e / double(n) - ref_term;
                r.final_mrse = mrse;
                r.spp = st.spp;
                double t = st.seconds - callback_s;
                r.mrays = double(st.rays) / t * 1e-6;
                r.msamples = double(st.samples) / t * 1e-6;
                callback_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                if (mrse <= target && r.t_target < 0) {
                    r.t_target = t;
                    r.spp_target = st.spp;
                    return false;
                }
                return true;
            };
            pgt::RenderSettings rs_ = s;
            rs_.mode = modes[k];
            rs_.spp = 1 << 20;
            rs_.time_budget_s = max_time;
            rs_.seed = 1 + unsigned(k);
            renderer.render(rs_, o, nullptr);
        }
        std::printf("\nstimulus scene, paint rho_d %.3g rho_s %.3g alpha %.3g, %dx%d, %d threads; "
                    "reference: MIS %d spp (%.1f s); MRSE target %.3g (reference's own share %.2g removed)\n\n",
                    rd, rs, a, w, h, threads > 0 ? threads : int(std::thread::hardware_concurrency()), ref_spp,
                    ref_st.seconds, target, ref_term);
        std::printf("| estimator | Mrays/s | Msamples/s | spp to MRSE 0.01 | time to MRSE 0.01 |\n");
        std::printf("|---|---|---|---|---|\n");
        for (int k = 0; k < 3; ++k) {
            const Result &r = res[k];
            if (r.t_target >= 0)
                std::printf("| %s | %.2f | %.3f | %d | %.2f s |\n", pgt::mode_name(modes[k]), r.mrays, r.msamples,
                            r.spp_target, r.t_target);
            else
                std::printf("| %s | %.2f | %.3f | > %d | > %.0f s (MRSE %.3g) |\n", pgt::mode_name(modes[k]), r.mrays,
                            r.msamples, r.spp, max_time, r.final_mrse);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "pgloss-tracer-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
