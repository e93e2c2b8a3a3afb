// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the tracer's scene parser (examples/tracer/src/scene.cpp). Any text
// either parses into a scene inside pgt::limits or throws SceneError; any other exception,
// crash or sanitizer report is a finding. OBJ files are read from disk and are covered by
// the `mesh` keyword pointing at the shipped model (the fuzzer cannot write files).
#include "fuzz_common.hpp"

#include "scene.hpp"

#include <string>

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool within(glm::vec3 v) {
    return finite(v) && std::fabs(v.x) <= pgt::limits::coordinate && std::fabs(v.y) <= pgt::limits::coordinate &&
           std::fabs(v.z) <= pgt::limits::coordinate;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size) {
    const std::string text(reinterpret_cast<const char *>(data), size);
    pgt::Scene sc;
    try {
        sc = pgt::parse_scene(text, "fuzz.scene", PGLOSS_TRACER_DIR "/scenes");
    } catch (const pgt::SceneError &) {
        return 0;
    }
    const pgt::RenderSettings &s = sc.settings;
    FZ_CHECK(s.width >= 1 && s.height >= 1 && s.spp >= 1 && s.max_depth >= 1);
    FZ_CHECK(static_cast<long long>(s.width) * s.height <= pgt::limits::pixels);
    FZ_CHECK(pgt::camera_basis_problem(sc.camera).empty());
    FZ_CHECK(sc.camera.fov_deg > 0 && sc.camera.fov_deg < 179);
    FZ_CHECK(!sc.lights.empty() || sc.has_environment);
    for (const auto &l : sc.lights) {
        FZ_CHECK(within(l.corner) && within(l.edge1) && within(l.edge2) && finite(l.radiance) && finite(l.normal));
        FZ_CHECK(std::isfinite(l.area) && l.area > 0);
    }
    for (const auto &sp : sc.spheres) FZ_CHECK(within(sp.center) && sp.radius > 0 && sp.radius <= pgt::limits::coordinate);
    for (const auto &m : sc.meshes) {
        for (const auto &v : m.vertices) FZ_CHECK(within(v));
        for (const auto &f : m.faces) FZ_CHECK(f.x < m.vertices.size() && f.y < m.vertices.size() && f.z < m.vertices.size());
    }
    FZ_CHECK(finite(sc.environment));
    return 0;
}
