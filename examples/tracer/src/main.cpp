// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// pgloss-tracer — render a scene, or the paper's Figs. 4 and 12.
#include "cli.hpp"
#include "figures.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>
#include <string>
#include <time.h>
#include <unistd.h>

namespace {

// Resident memory of the process (Linux /proc/self/statm), MiB; 0 where it cannot be read.
double resident_mib() {
    std::ifstream f("/proc/self/statm");
    double pages = 0, resident = 0;
    f >> pages >> resident;
    return f ? resident * double(sysconf(_SC_PAGESIZE)) / 1048576.0 : 0.0;
}
double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
// Wall and CPU seconds since a mark.
struct Stopwatch {
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    double cpu = cpu_seconds();
    double wall_s() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(); }
    double cpu_s() const { return cpu_seconds() - cpu; }
};

// Set by the first SIGINT/SIGTERM during `render`: the render stops after the tiles under way
// and what it has is written. A second signal ends the program at once.
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");
extern "C" void on_signal(int sig) {
    g_cancel = true;
    std::signal(sig, SIG_DFL);
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
        "  --sampler independent|sobol            random numbers (default independent)\n"
        "  --light-sampling solid-angle|area      rectangular lights (default area)\n"
        "  --embree         every ray through Embree (small scenes have their own intersector)\n"
        "  --quiet          no progress bar\n"
        "  --version        print the version      -h, --help  this text\n"
        "render: Ctrl-C stops early and writes what has been rendered (exit 130); twice ends at once.\n",
        stderr);
}

}  // namespace

int main(int argc, char **argv) {
    pgt::CliOptions o;
    try {
        o = pgt::parse_cli(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const pgt::CliError &e) {
        std::fprintf(stderr, "pgloss-tracer: %s\n", e.what());
        if (argc < 2) usage();
        return 2;
    }
    using Cmd = pgt::CliOptions::Command;
    if (o.command == Cmd::HELP) {
        usage();
        return 0;
    }
    if (o.command == Cmd::VERSION) {
        std::printf("pgloss-tracer %s (libpgloss %s)\n", PGLOSS_TRACER_VERSION, pgloss_version());
        return 0;
    }
    try {
        if (o.command == Cmd::RENDER) {
            const double mib0 = resident_mib();
            const Stopwatch load_t;
            pgt::Scene sc = pgt::load_scene(o.scene_path);
            const double load_s = load_t.wall_s(), load_cpu = load_t.cpu_s();
            pgt::RenderSettings s = sc.settings;
            if (o.width > 0) s.width = o.width, s.height = o.height;
            if (o.spp > 0) s.spp = o.spp;
            if (o.time_s > 0) {
                s.time_budget_s = o.time_s;
                if (o.spp <= 0) s.spp = 1 << 20;
            }
            if (!o.mode.empty()) s.mode = pgt::parse_mode(o.mode);
            if (o.seed >= 0) s.seed = unsigned(o.seed);
            if (!o.sampler.empty()) s.sampler = o.sampler == "sobol" ? pgt::Sampler::SOBOL : pgt::Sampler::INDEPENDENT;
            if (!o.light_sampling.empty()) s.solid_angle_lights = o.light_sampling == "solid-angle";
            s.embree_always = o.embree;
            const std::string &out = o.out;
            std::filesystem::path parent = std::filesystem::path(out).parent_path();
            if (!parent.empty()) std::filesystem::create_directories(parent);
            const Stopwatch build_t;
            pgt::Renderer r(sc);
            const double build_s = build_t.wall_s(), build_cpu = build_t.cpu_s(), scene_mib = resident_mib() - mib0;
            pgt::RenderOptions ro;
            ro.threads = o.threads;
            ro.progress = !o.quiet;
            ro.label = std::filesystem::path(o.scene_path).stem().string();
            ro.cancel = &g_cancel;
            std::signal(SIGINT, on_signal);
            std::signal(SIGTERM, on_signal);
            pgt::RenderStats st;
            pgt::Image img = r.render(s, ro, &st);
            if (st.interrupted && st.samples == 0)
                throw std::runtime_error("interrupted before any tile was finished; nothing written");
            pgt::write_exr(img, out + ".exr");
            pgt::write_png(pgt::display_image(img, sc.tonemap), out + ".png");
            std::printf("%s.exr %s.png: %dx%d, %d spp, %s, %.2f s, %.2f Mrays/s, %.2f Msamples/s, %.2f s CPU; "
                        "scene: load %.2f s, BVH %.2f s (CPU %.2f s, %.2f s), +%.0f MiB\n",
                        out.c_str(), out.c_str(), s.width, s.height, st.spp, pgt::mode_name(s.mode), st.seconds,
                        double(st.rays) / st.seconds * 1e-6, double(st.samples) / st.seconds * 1e-6, st.cpu_seconds,
                        load_s, build_s, load_cpu, build_cpu, scene_mib);
            if (st.interrupted) {
                std::fprintf(stderr, "pgloss-tracer: interrupted; wrote the %llu samples rendered (%d spp or more "
                                     "per pixel)\n", static_cast<unsigned long long>(st.samples), st.spp);
                return 130;
            }
        } else {
            pgt::FigureOptions fo;
            fo.scene_path = o.scene_path.empty() ? std::string(PGLOSS_TRACER_DIR) + "/scenes/stimulus.scene" : o.scene_path;
            if (!o.out.empty()) fo.out_dir = o.out;
            fo.width = o.width, fo.height = o.height, fo.spp = o.spp, fo.time_total_s = o.time_s;
            fo.threads = o.threads, fo.progress = !o.quiet;
            if (o.command == Cmd::FIG4) pgt::render_fig4(fo);
            else pgt::render_fig12(fo);
        }
    } catch (const std::exception &e) {  // printable: paths and OIIO's messages may carry any bytes
        std::fprintf(stderr, "pgloss-tracer: %s\n", pgt::printable(e.what()).c_str());
        return 1;
    }
    return 0;
}
