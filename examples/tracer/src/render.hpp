// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// render.hpp — unidirectional path tracer on Embree 3 with libpgloss BRDFs.
//
// Estimators (RenderSettings::mode):
//   mis    next-event estimation on the lights + BRDF sampling (pgloss_sample), combined by
//          multiple importance sampling with the power heuristic (Veach 1997, §9.2.4). At a
//          vertex whose material has no specular lobe, MIS buys little, so the vertex uses
//          light sampling alone (no pgloss_pdf work there); this is still unbiased because
//          light sampling covers every direction in which emission can be found.
//   brdf   BRDF sampling only: emission is counted when a sampled ray hits a light.
//   light  light sampling only: emission reached by a BRDF-sampled ray is ignored.
// All three are unbiased estimators of the same image (tests/tracer checks this).
//
// Determinism: sample s of pixel p draws its numbers from a PCG32 stream seeded by
// hash(seed, p, s), and each pixel's sum is accumulated by one thread in sample order.
// So, for a given seed and sample count, the image is bit-identical whatever the number of
// threads or the tile order. A time budget (not a sample count) makes the sample count,
// and so the image, depend on the machine's speed.
#pragma once
#include "scene.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace pgt {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // linear, row-major, 3 floats per pixel
    float *at(int x, int y) { return &rgb[3 * (size_t(y) * size_t(width) + size_t(x))]; }
    const float *at(int x, int y) const { return &rgb[3 * (size_t(y) * size_t(width) + size_t(x))]; }
};

struct RenderStats {
    double seconds = 0;
    double cpu_seconds = 0;     // CPU time of the process (all threads) during the render
    std::uint64_t rays = 0;     // rays traced: intersection and shadow rays
    std::uint64_t samples = 0;  // camera paths
    int spp = 0;               // samples per pixel, the least over the image if interrupted
    bool interrupted = false;  // stopped by RenderOptions::cancel before the requested spp
};

struct RenderOptions {
    int threads = 0;           // 0: all hardware threads
    bool progress = true;      // progress bar + ETA on stderr
    std::string label;         // shown in the progress bar
    int max_pass_spp = 16;     // samples per pixel per progressive pass, at most
    // If set and it becomes true (e.g. from a SIGINT handler), the render stops after the tiles
    // under way; the image holds every finished tile, each the mean of its own sample count.
    const std::atomic<bool> *cancel = nullptr;
    // Called after each pass with the running mean image; return false to stop early.
    std::function<bool(const Image &, const RenderStats &)> on_pass;
    // If set, receives per pixel and channel the estimated variance of the pixel's mean
    // (sample variance / spp): what the tests need for z-scores.
    Image *variance = nullptr;
};

// Region of the pixel centre's first hit, for comparisons per region (POV-Ray test).
enum Region : int {
    REGION_NONE = 0, REGION_WALL = 1, REGION_FLOOR = 2, REGION_CEILING = 3, REGION_SPHERE = 4,
    REGION_LIGHT = 5, REGION_OTHER = 6, REGION_SHADOW = 7
};
const char *region_name(int r);

class Renderer {
public:
    explicit Renderer(const Scene &scene);
    ~Renderer();
    Renderer(const Renderer &) = delete;
    Renderer &operator=(const Renderer &) = delete;

    Image render(const RenderSettings &settings, const RenderOptions &options,
                 RenderStats *stats = nullptr) const;
    // Per-pixel Region of the first hit through the pixel centre. REGION_SHADOW marks floor
    // points that see less than half of the first area light (the sphere's cast shadow).
    std::vector<int> regions(int width, int height) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace pgt
