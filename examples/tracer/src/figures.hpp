// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// figures.hpp — the paper's figures: Fig. 4 (Experiment 1's 27 stimuli as a labelled contact
// sheet) and Fig. 12 (gloss matching across lightness).
#pragma once
#include "image.hpp"

#include <string>

namespace pgt {

struct FigureOptions {
    std::string scene_path;  // the stimulus scene (its sphere's material must be called "paint")
    std::string out_dir = "out";
    int width = 0, height = 0;  // 0: the scene's
    int spp = 0;                // 0: the scene's
    double time_total_s = 0;    // > 0: budget for the whole figure, split evenly over its images
    int threads = 0;
    bool progress = true;
};

// Writes OUT/fig4.png (contact sheet) and OUT/fig4/<label>.exr (the 27 linear renders).
void render_fig4(const FigureOptions &o);
// Writes OUT/fig12.png and OUT/fig12/<label>.exr. Top row: ρs = 0.099, α = 0.04 for the white,
// grey and black paints; bottom row: the grey and black paints given the white one's contrast
// gloss c and DOI gloss d with pgloss_match_gloss (paper §5.2: c = 0.057, d = 0.96).
void render_fig12(const FigureOptions &o);

}  // namespace pgt
