// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-tracer — render a scene, or the paper's Figs. 4 and 12.
#include "figures.hpp"

#include <atomic>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace {

// Set by the first SIGINT/SIGTERM during `render`: the render stops after the tiles under way
// and what it has is written. A second signal ends the program at once.
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");
extern "C" void on_signal(int sig) {
    g_cancel = true;
    std::signal(sig, SIG_DFL);
}

// Whole-string numbers: "3x", "abc", "" and out-of-range values are errors that name the option.
long long parse_integer(const std::string &opt, const std::string &v, long long lo, long long hi) {
    char *end = nullptr;
    errno = 0;
    long long x = v.empty() ? 0 : std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE)
        throw std::runtime_error(opt + " wants a whole number, not '" + v + "'");
    if (x < lo || x > hi)
        throw std::runtime_error(opt + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v);
    return x;
}
double parse_seconds(const std::string &opt, const std::string &v) {
    char *end = nullptr;
    double x = v.empty() ? 0 : std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw std::runtime_error(opt + " wants seconds, not '" + v + "'");
    if (!(x > 0 && x <= 1e7)) throw std::runtime_error(opt + " must be in (0, 1e7] seconds, not " + v);
    return x;
}
// --out for `render` is a prefix (OUT.exr and OUT.png are written): a trailing .exr or .png is
// taken off; another image extension is an error rather than OUT.jpg.exr.
std::string output_prefix(const std::string &out) {
    std::string ext = std::filesystem::path(out).extension().string();
    for (char &c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".exr" || ext == ".png") return out.substr(0, out.size() - ext.size());
    for (const char *e : {".jpg", ".jpeg", ".tif", ".tiff", ".hdr", ".bmp", ".tga", ".webp", ".ppm"})
        if (ext == e)
            throw std::runtime_error("--out is a prefix (OUT.exr and OUT.png are written), so '" + out +
                                     "' would make '" + out + ".exr'; give it without '" + ext + "'");
    return out;
}

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
        "  --quiet          no progress bar\n"
        "  --version        print the version      -h, --help  this text\n"
        "render: Ctrl-C stops early and writes what has been rendered (exit 130); twice ends at once.\n",
        stderr);
}

}  // namespace

int main(int argc, char **argv) {
    if (argc < 2) {
        usage();
        return 2;
    }
    std::string cmd = argv[1];
    if (cmd == "--version") {
        std::printf("pgloss-tracer %s\n", PGLOSS_TRACER_VERSION);
        return 0;
    }
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
                size_t x = v.find('x');
                if (x == std::string::npos) throw std::runtime_error("--size wants WxH, e.g. 160x120, not '" + v + "'");
                width = int(parse_integer("--size width", v.substr(0, x), 1, pgt::limits::image_side));
                height = int(parse_integer("--size height", v.substr(x + 1), 1, pgt::limits::image_side));
                if (static_cast<long long>(width) * height > pgt::limits::pixels)
                    throw std::runtime_error("--size: at most " + std::to_string(pgt::limits::pixels) + " pixels");
            } else if (a == "--spp") spp = int(parse_integer(a, val(), 1, pgt::limits::spp));
            else if (a == "--time") time_s = parse_seconds(a, val());
            else if (a == "--mode") mode = val();
            else if (a == "--seed") seed = long(parse_integer(a, val(), 0, long(pgt::limits::seed)));
            else if (a == "--threads") threads = int(parse_integer(a, val(), 1, pgt::limits::threads));
            else if (a == "--quiet") quiet = true;
            else if (a == "-h" || a == "--help") {
                usage();
                return 0;
            } else throw std::runtime_error("unknown option '" + a + "'");
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
            out = output_prefix(out);
            std::filesystem::path parent = std::filesystem::path(out).parent_path();
            if (!parent.empty()) std::filesystem::create_directories(parent);
            pgt::Renderer r(sc);
            pgt::RenderOptions ro;
            ro.threads = threads;
            ro.progress = !quiet;
            ro.label = std::filesystem::path(scene_path).stem().string();
            ro.cancel = &g_cancel;
            std::signal(SIGINT, on_signal);
            std::signal(SIGTERM, on_signal);
            pgt::RenderStats st;
            pgt::Image img = r.render(s, ro, &st);
            if (st.interrupted && st.spp == 0 && st.samples == 0)
                throw std::runtime_error("interrupted before any tile was finished; nothing written");
            pgt::write_exr(img, out + ".exr");
            pgt::write_png(pgt::display_image(img, sc.tonemap), out + ".png");
            std::printf("%s.exr %s.png: %dx%d, %d spp, %s, %.2f s, %.2f Mrays/s, %.2f Msamples/s\n", out.c_str(),
                        out.c_str(), s.width, s.height, st.spp, pgt::mode_name(s.mode), st.seconds,
                        double(st.rays) / st.seconds * 1e-6, double(st.samples) / st.seconds * 1e-6);
            if (st.interrupted) {
                std::fprintf(stderr, "pgloss-tracer: interrupted; wrote the %llu samples rendered (%d spp or more "
                                     "per pixel)\n", static_cast<unsigned long long>(st.samples), st.spp);
                return 130;
            }
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
