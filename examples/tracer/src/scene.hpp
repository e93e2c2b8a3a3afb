// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// scene.hpp — the tracer's scene description and its small text format.
//
// A scene file is a list of lines "KEYWORD [NAME] key=value key=value …"; '#' starts a comment.
// Vectors are written "x,y,z". Every error names the file, the line and the field.
//
//   image       width=256 height=192
//   camera      position=0,1.6,1.9 look_at=0,0.5,-0.3 up=0,1,0 fov=45        (vertical fov, degrees)
//   render      spp=64 max_depth=8 seed=1 mode=mis|brdf|light
//   tonemap     exposure=1 limit=1 sharpness=2                                   (see image.hpp)
//   material NAME diffuse=ρd | diffuse=r,g,b                                   (Lambertian)
//   material NAME physical rho_d=ρd|r,g,b rho_s=ρs alpha=α [alpha_y=αy] [norm=ward|ward-dur|bounded]
//   material NAME perceptual L=L* a=a* b=b* c=c d=d [norm=…]                   (paper Fig. 13)
//   material NAME checker a=MATERIAL b=MATERIAL size=s [offset=x,y,z]            (3-D checkerboard)
//   sphere      center=x,y,z radius=r material=NAME
//   box         min=x,y,z max=x,y,z material=NAME                  (6 quads; all shading is two-sided)
//   quad        corner=p edge1=u edge2=v material=NAME
//   mesh        file=thing.obj material=NAME [scale=s] [translate=x,y,z]         (OBJ v/f, relative path)
//   light       corner=p edge1=u edge2=v radiance=L|r,g,b [emission=cosine|isotropic]
//   environment radiance=L|r,g,b                                                 (uniform, infinitely far)
//
// The area light emits from the side of edge1 × edge2. emission=cosine is a physical
// Lambertian emitter (constant radiance L); emission=isotropic makes each element an isotropic
// point source of intensity L·dA (radiance L / cosθ), which is what a POV-Ray area_light is.
//
// Every number is checked where it is parsed, against float's range and the domain below (the
// tracer works in float): a number outside it is an error that names the field, never an Inf
// that reaches Embree or an image of dropped samples.
#pragma once
#include "sampler.hpp"

#include <pgloss/pgloss.h>

#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace pgt {

// The domain of the scene format's numbers.
namespace limits {
constexpr double coordinate = 1e7;        // |x|, |y|, |z| of any point, edge, radius (scene units)
constexpr double radiance = 1e12;         // per channel; with coordinate, light power stays in float
constexpr double tonemap = 1e12;          // exposure and limit
constexpr double sharpness = 64;          // tone-map sharpness n
constexpr double checker_min = 1e-6;      // checker size, so that p / size fits a long
constexpr int image_side = 1 << 15;       // width, height
constexpr long long pixels = 1LL << 26;   // width × height (the accumulation buffers are doubles)
constexpr int spp = 1 << 24;
constexpr int max_depth = 1 << 10;
constexpr int threads = 1 << 10;
constexpr unsigned long long seed = 0xffffffffULL;
constexpr unsigned long long scene_bytes = 64ULL << 20;   // a scene file
constexpr unsigned long long obj_bytes = 1ULL << 30;      // an OBJ file
constexpr size_t triangles = size_t(1) << 25;               // in all `mesh` lines of a scene
}  // namespace limits

// `text` with every byte that a terminal would act on or could not show written as an escape:
// C0/C1 controls and DEL as \xHH, bytes that are not UTF-8 as \xHH, bidirectional-text
// controls as \u{HHHH}; printable ASCII and other UTF-8 characters unchanged. Idempotent,
// so that a message quoted inside another is not escaped twice. Scene files and command-line
// arguments are echoed in error messages through it (an ANSI escape sequence in a scene
// reached the terminal, and a NUL cut the message short).
std::string printable(const std::string &text);

// A scene that cannot be used; the message is printable() (file bytes are echoed in it).
struct SceneError : std::runtime_error {
    explicit SceneError(const std::string &what) : std::runtime_error(printable(what)) {}
};

enum class Mode { MIS, BRDF, LIGHT };

struct Material {
    std::string name;
    bool checker = false;
    pgloss_material ward{};      // when !checker
    pgloss_physical physical{};  // what ward was built from (for labels)
    int check_a = -1, check_b = -1;  // material indices, when checker
    float check_size = 1.0f;
    glm::vec3 check_offset{0.0f};
};

struct Sphere {
    glm::vec3 center;
    float radius;
    int material;
};

struct Triangle {
    glm::vec3 p0, p1, p2;
};

struct Mesh {  // triangles sharing a material (boxes and quads become meshes too)
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> faces;
    int material;
    std::string label;  // "box", "quad", "mesh:FILE"
};

struct AreaLight {
    glm::vec3 corner, edge1, edge2;
    glm::vec3 radiance;
    bool isotropic = false;
    // derived
    glm::vec3 normal;  // unit, emitting side
    float area;
};

struct Camera {
    glm::vec3 position{0, 1, 3}, look_at{0, 0, 0}, up{0, 1, 0};
    float fov_deg = 45.0f;
};

struct ToneMap {
    float exposure = 1.0f;
    float limit = 1.0f;
    float sharpness = 2.0f;
};

struct RenderSettings {
    int width = 256, height = 192;
    int spp = 64;
    int max_depth = 8;
    unsigned seed = 1;
    Mode mode = Mode::MIS;
    double time_budget_s = 0;  // 0: no budget, stop at spp
    // Next-event estimation on rectangular lights uniform in solid angle (Ureña et al. 2013,
    // sphrect.hpp) instead of uniform in area (as Mitsuba's rectangle emitter). Off by
    // default: on the stimulus scene it takes 6 % off the variance but adds 75 % to the time
    // (BENCHMARKS.md); it pays where the light is large and close.
    bool solid_angle_lights = false;
    // Trace every ray with Embree, also in a scene small enough for the renderer's own
    // 16-wide intersector (render.cpp; for tests and measurements: the images agree).
    bool embree_always = false;
    Sampler sampler = Sampler::INDEPENDENT;
};

struct Scene {
    std::string path;  // for messages
    Camera camera;
    RenderSettings settings;
    ToneMap tonemap;
    std::vector<Material> materials;  // add with add_material (it keeps the name index)
    std::vector<Sphere> spheres;
    std::vector<Mesh> meshes;
    std::vector<AreaLight> lights;
    bool has_environment = false;
    glm::vec3 environment{0.0f};

    // -1 if there is none. A hash look-up (a scene of 200,000 materials parsed in quadratic
    // time with a linear search); a linear search if `materials` was changed directly.
    int find_material(const std::string &name) const;
    // Appends m (its name not yet used) and returns its index.
    int add_material(Material m);
    // Replaces (or adds) a Ward material by name.
    void set_material(const std::string &name, const pgloss_physical &p);

private:
    std::unordered_map<std::string, int> material_index_;  // name → index into materials
};

Scene load_scene(const std::string &path);
// Reads a whole regular file of at most max_bytes (no devices, FIFOs or endless streams);
// throws SceneError naming `what` and the reason.
std::string read_text_file(const std::string &path, unsigned long long max_bytes, const std::string &what);
Scene parse_scene(const std::string &text, const std::string &path_for_messages,
                  const std::string &base_dir);
// "" when the camera has a proper basis, else why not (up zero or parallel to the view).
std::string camera_basis_problem(const Camera &c);
const char *mode_name(Mode m);
Mode parse_mode(const std::string &s);  // throws SceneError

}  // namespace pgt
