// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// figures.cpp — see figures.hpp.
#include "figures.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace pgt {

namespace {

struct Paint {
    const char *name;
    double rho_d;
};
constexpr Paint kPaints[3] = {{"white", 0.767}, {"grey", 0.193}, {"black", 0.03}};  // Munsell N9, N5, N2

std::string fmt(double v) {  // ".193", ".04": the paper's labels
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    std::string s = b;
    if (s.rfind("0.", 0) == 0) s = s.substr(1);
    return s;
}

RenderSettings settings_for(const Scene &sc, const FigureOptions &o, int nimages) {
    RenderSettings s = sc.settings;
    if (o.width > 0) s.width = o.width;
    if (o.height > 0) s.height = o.height;
    if (o.spp > 0) s.spp = o.spp;
    if (o.time_total_s > 0) {
        s.time_budget_s = o.time_total_s / nimages;
        if (o.spp <= 0) s.spp = 1 << 20;  // the budget decides
    }
    return s;
}

Image render_with(Scene &sc, const pgloss_physical &p, const RenderSettings &s, const FigureOptions &o,
                  const std::string &label, RenderStats *st) {
    sc.set_material("paint", p);
    Renderer r(sc);
    RenderOptions ro;
    ro.threads = o.threads;
    ro.progress = o.progress;
    ro.label = label;
    return r.render(s, ro, st);
}

pgloss_physical ward(double rd, double rs, double a) {
    return pgloss_physical{{rd, rd, rd}, rs, a, a, PGLOSS_NORM_WARD};
}

}  // namespace

void render_fig4(const FigureOptions &o) {
    Scene sc = load_scene(o.scene_path);
    if (sc.find_material("paint") < 0) throw SceneError(o.scene_path + ": no material named 'paint'");
    RenderSettings s = settings_for(sc, o, 27);
    std::filesystem::create_directories(o.out_dir + "/fig4");
    std::vector<SheetCell> cells;
    const double rs_levels[3] = {0.033, 0.066, 0.099}, a_levels[3] = {0.04, 0.07, 0.10};
    RenderStats total;
    for (const Paint &paint : kPaints)
        for (double rs : rs_levels)
            for (double a : a_levels) {
                std::string id = std::string(paint.name) + "_" + fmt(paint.rho_d) + "_" + fmt(rs) + "_" + fmt(a);
                RenderStats st;
                Image img = render_with(sc, ward(paint.rho_d, rs, a), s, o, "fig4 " + id, &st);
                total.seconds += st.seconds, total.rays += st.rays, total.samples += st.samples;
                write_exr(img, o.out_dir + "/fig4/" + id + ".exr");
                std::ostringstream label;
                label << paint.name << " rho_d " << fmt(paint.rho_d) << "\nrho_s " << fmt(rs) << "  alpha " << fmt(a);
                cells.push_back({display_image(img, sc.tonemap), label.str()});
            }
    std::ostringstream title;
    title << "Fig. 4: Experiment 1 stimuli (Ward eq. 2, " << s.width << "x" << s.height << ", "
          << (total.samples / (27ull * unsigned(s.width) * unsigned(s.height))) << " spp)";
    write_png(contact_sheet(cells, 9, title.str()), o.out_dir + "/fig4.png");
    std::fprintf(stderr, "fig4: %s/fig4.png (%.1f s, %.2f Mrays/s)\n", o.out_dir.c_str(), total.seconds,
                 total.seconds > 0 ? double(total.rays) / total.seconds * 1e-6 : 0.0);
}

void render_fig12(const FigureOptions &o) {
    Scene sc = load_scene(o.scene_path);
    if (sc.find_material("paint") < 0) throw SceneError(o.scene_path + ": no material named 'paint'");
    RenderSettings s = settings_for(sc, o, 6);
    std::filesystem::create_directories(o.out_dir + "/fig12");
    std::vector<SheetCell> top, bottom;
    const double rs0 = 0.099, a0 = 0.04;
    double L0 = 0, c0 = 0, d0 = 0;
    pgloss_gloss_from_physical(kPaints[0].rho_d, rs0, a0, &L0, &c0, &d0);
    for (const Paint &paint : kPaints) {
        // Top: same physical gloss parameters.
        std::string id = std::string("physical_") + paint.name;
        Image img = render_with(sc, ward(paint.rho_d, rs0, a0), s, o, "fig12 " + id, nullptr);
        write_exr(img, o.out_dir + "/fig12/" + id + ".exr");
        double L, c, d;
        pgloss_gloss_from_physical(paint.rho_d, rs0, a0, &L, &c, &d);
        std::ostringstream lt;
        lt << paint.name << " rho_s " << fmt(rs0) << " alpha " << fmt(a0) << "\nc " << fmt(c) << "  d " << fmt(d);
        top.push_back({display_image(img, sc.tonemap), lt.str()});
        // Bottom: same perceptual gloss (c, d) as the white paint, at this paint's lightness.
        double Lt, rd_m, rs_m;
        pgloss_lightness_from_luminance(paint.rho_d, &Lt);
        pgloss_status stm = pgloss_match_gloss(kPaints[0].rho_d, rs0, Lt, &rd_m, &rs_m);
        if (stm < 0) throw std::runtime_error(std::string("pgloss_match_gloss: ") + pgloss_status_string(stm));
        id = std::string("perceptual_") + paint.name;
        img = render_with(sc, ward(rd_m, rs_m, 1.0 - d0), s, o, "fig12 " + id, nullptr);
        write_exr(img, o.out_dir + "/fig12/" + id + ".exr");
        std::ostringstream lb;
        lb << paint.name << " rho_s " << fmt(rs_m) << " alpha " << fmt(1.0 - d0) << "\nc " << fmt(c0) << "  d " << fmt(d0);
        bottom.push_back({display_image(img, sc.tonemap), lb.str()});
    }
    std::vector<SheetCell> cells = top;
    cells.insert(cells.end(), bottom.begin(), bottom.end());
    write_png(contact_sheet(cells, 3, "Fig. 12: same physical gloss (top), same perceptual gloss (bottom)"),
              o.out_dir + "/fig12.png");
    std::fprintf(stderr, "fig12: %s/fig12.png\n", o.out_dir.c_str());
}

}  // namespace pgt
