// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-tracer — render a scene, or the paper's Figs. 4 and 12.
#include "figures.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

void usage() {
    std::fputs(
        "usage: pgloss-tracer render SCENE [options]    render one scene to OUT.exr (linear) + OUT.png (display)\n"
        "       pgloss-tracer fig4 [options]            Experiment 1's 27 stimuli as a contact sheet (Fig. 4)\n"
        "       pgloss-tracer fig12 [options]           gloss matching across lightness (Fig. 12)\n"
        "options:\n"
        "  --out PATH       render: output prefix (default out/<scene name>); figures: folder (default out)\n"
        "  --scene FILE     figures: stimulus scene (default examples/tracer/scenes/stimulus.scene)\n"
        "  --size WxH       image size        --spp N        samples per pixel\n"
        "  --time S         stop after S seconds (figures: for the whole figure)\n"
        "  --mode mis|brdf|light   estimator  --seed N       --threads N (default: all)\n"
        "  --quiet          no progress bar\n",
        stderr);
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 2) {
        usage();
        return 2;
    }
    std::string cmd = argv[1];
    std::string scene_path, out;
    int width = 0, height = 0, spp = 0, threads = 0;
    long seed = -1;
    double time_s = 0;
    std::string mode;
    bool quiet = false;
    int i = 2;
    if (cmd == "render") {
        if (argc < 3) {
            usage();
            return 2;
        }
        scene_path = argv[2];
        i = 3;
    } else if (cmd == "fig4" || cmd == "fig12") {
        scene_path = std::string(PGLOSS_TRACER_DIR) + "/scenes/stimulus.scene";
    } else {
        usage();
        return cmd == "-h" || cmd == "--help" ? 0 : 2;
    }
    try {
        for (; i < argc; ++i) {
            std::string a = argv[i];
            auto val = [&]() -> std::string {
                if (i + 1 >= argc) throw std::runtime_error("option " + a + " needs a value");
                return argv[++i];
            };
            if (a == "--out") out = val();
            else if (a == "--scene") scene_path = val();
            else if (a == "--size") {
                std::string v = val();
                if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0)
                    throw std::runtime_error("--size wants WxH, e.g. 160x120, not '" + v + "'");
            } else if (a == "--spp") spp = std::stoi(val());
            else if (a == "--time") time_s = std::stod(val());
            else if (a == "--mode") mode = val();
            else if (a == "--seed") seed = std::stol(val());
            else if (a == "--threads") threads = std::stoi(val());
            else if (a == "--quiet") quiet = true;
            else throw std::runtime_error("unknown option '" + a + "'");
        }
        if (cmd == "render") {
            pgt::Scene sc = pgt::load_scene(scene_path);
            pgt::RenderSettings s = sc.settings;
            if (width > 0) s.width = width, s.height = height;
            if (spp > 0) s.spp = spp;
            if (time_s > 0) {
                s.time_budget_s = time_s;
                if (spp <= 0) s.spp = 1 << 20;
            }
            if (!mode.empty()) s.mode = pgt::parse_mode(mode);
            if (seed >= 0) s.seed = unsigned(seed);
            if (out.empty()) out = "out/" + std::filesystem::path(scene_path).stem().string();
            std::filesystem::path parent = std::filesystem::path(out).parent_path();
            if (!parent.empty()) std::filesystem::create_directories(parent);
            pgt::Renderer r(sc);
            pgt::RenderOptions ro;
            ro.threads = threads;
            ro.progress = !quiet;
            ro.label = std::filesystem::path(scene_path).stem().string();
            pgt::RenderStats st;
            pgt::Image img = r.render(s, ro, &st);
            pgt::write_exr(img, out + ".exr");
            pgt::write_png(pgt::display_image(img, sc.tonemap), out + ".png");
            std::printf("%s.exr %s.png: %dx%d, %d spp, %s, %.2f s, %.2f Mrays/s, %.2f Msamples/s\n", out.c_str(),
                        out.c_str(), s.width, s.height, st.spp, pgt::mode_name(s.mode), st.seconds,
                        double(st.rays) / st.seconds * 1e-6, double(st.samples) / st.seconds * 1e-6);
        } else {
            pgt::FigureOptions fo;
            fo.scene_path = scene_path;
            if (!out.empty()) fo.out_dir = out;
            fo.width = width, fo.height = height, fo.spp = spp, fo.time_total_s = time_s;
            fo.threads = threads, fo.progress = !quiet;
            if (cmd == "fig4") pgt::render_fig4(fo);
            else pgt::render_fig12(fo);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "pgloss-tracer: %s\n", e.what());
        return 1;
    }
    return 0;
}
