// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// render.cpp — the path tracer (see render.hpp).
#include "render.hpp"

#include "sampler.hpp"
#include "sphrect.hpp"

#include <embree3/rtcore.h>
#include <pgloss/batch.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <system_error>
#include <thread>
#include <time.h>
#include <unistd.h>
#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

namespace pgt {

namespace {

constexpr float kPi = 3.14159265358979323846f;

struct Frame {  // orthonormal basis around n (Duff et al. 2017)
    glm::vec3 t{0}, b{0}, n{0};
    Frame() = default;
    explicit Frame(glm::vec3 nn) : n(nn) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float bb = n.x * n.y * a;
        t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * bb, -sign * n.x);
        b = glm::vec3(bb, sign + n.y * n.y * a, -n.y);
    }
    pgloss_vec3 to_local(glm::vec3 v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
    glm::vec3 to_world(pgloss_vec3 v) const { return v.x * t + v.y * b + v.z * n; }
};

float max3(glm::vec3 v) { return std::max(v.x, std::max(v.y, v.z)); }
float power_heuristic(float a, float b) {
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0f;
}

enum class GeomKind { SPHERE, MESH, LIGHT };
struct GeomRef {
    GeomKind kind;
    int index;
    int material = -1;  // the mesh's or sphere's (a checker's index, resolved per hit)
};

// Flush-to-zero and denormals-are-zero for the scope (restored after): Embree asks for them
// (a subnormal in traversal or shading costs ~100 cycles), and pgloss's float lobe takes
// underflow to 0 either way. Set in every worker, so the image does not depend on which
// thread rendered a tile.
struct DenormalsOff {
#if defined(__SSE__) || defined(_M_X64)
    unsigned saved = _mm_getcsr();
    DenormalsOff() { _mm_setcsr(saved | 0x8040u); }  // FTZ (bit 15) | DAZ (bit 6)
    ~DenormalsOff() { _mm_setcsr(saved); }
#endif
};

// Joins every joinable thread when it goes out of scope, also while an exception unwinds
// (a joinable std::thread destroyed would call std::terminate).
struct JoinAll {
    std::vector<std::thread> &threads;
    ~JoinAll() {
        for (auto &t : threads)
            if (t.joinable()) t.join();
    }
};

struct Hit {
    bool hit = false;
    float t = 0;
    glm::vec3 p, n;  // n: unit geometric normal, not yet face-forwarded
    GeomRef ref{GeomKind::MESH, -1};
};

// The pinhole camera: the direction through image position (px, py) of a w × h image.
struct Pinhole {
    glm::vec3 f, r, u;
    float th, w, h;
    Pinhole(const Camera &c, int width, int height) : w(float(width)), h(float(height)) {
        f = glm::normalize(c.look_at - c.position);
        r = glm::normalize(glm::cross(f, c.up));
        u = glm::cross(r, f);
        th = std::tan(0.5f * c.fov_deg * kPi / 180.0f);
    }
    glm::vec3 dir(float px, float py) const {
        float sx = (2.0f * px / w - 1.0f) * (w / h) * th;
        float sy = (1.0f - 2.0f * py / h) * th;
        return glm::normalize(f + sx * r + sy * u);
    }
};

// What the previous vertex of a path did, to weight emission found by its BRDF-sampled ray.
enum class Prev { CAMERA, MIS, BRDF, LIGHT };

// One camera path in flight (a wavefront holds a tile's paths of a pass).
struct PathState {
    glm::vec3 o{0}, d{0};            // the ray to trace next
    glm::vec3 beta{1}, L{0};         // throughput, radiance so far
    glm::vec3 prev_n{0};
    float prev_pdf = 0;
    Prev prev = Prev::CAMERA;
    int depth = 0;                   // index of the vertex the next hit will be
    PathSampler smp;                 // its random numbers (sampler.hpp)
};

// A next-event estimate's shadow ray o + t d, 0 < t < tmax, and what it adds to path's
// radiance if nothing occludes it: a step's are gathered in a list of their own, read in order
// by the shadow passes (not from the paths' scattered state).
struct ShadowRay {
    glm::vec3 o, d, c;
    float tmax;
    std::uint32_t path;
};

// Paths traced together: enough for full packets until the last bounces, few enough that
// their state stays in the core's L2 cache.
#ifndef PGT_WAVEFRONT
#define PGT_WAVEFRONT 1024
#endif
constexpr size_t kWavefront = PGT_WAVEFRONT;

// What a path's shading step found before its lobe calls (stage 1 of a wavefront step), for
// the lobe calls batched per material (stage 2) and the path's update (stage 3).
struct ShadeRec {
    Frame frame;
    glm::vec3 p{0}, n{0};            // the offset origin of the next rays, the facing normal
    glm::vec3 wi{0}, Le{0};          // next-event estimate: direction to the light, its radiance
    pgloss_vec3 wo{0, 0, 1}, wil{0, 0, 1};  // local directions: to the viewer, to the light
    float pdf_light = 0, tmax = 0;
    float u[3] = {0, 0, 0};          // the BRDF sample's random numbers
    float ul[2] = {0, 0};            // the light sample's
    int li = -1;                     // the light sampled; -1: no next-event estimate
    int mat = -1;                    // material index; -1: the path ends at this hit
    Prev strat = Prev::LIGHT;
    bool nee = false;                // a next-event estimate to weight
    bool shadow = false;             // it waits for its shadow ray (p, wi, tmax), which adds shadow_c
    glm::vec3 shadow_c{0};
};

// The structure-of-arrays inputs and outputs of the batched lobe calls (pgloss/batch.h).
enum Lane { WOX, WOY, WOZ, WIX, WIY, WIZ, U0, U1, U2, FR, FG, FB, FPDF,
            SX, SY, SZ, SPDF, SR, SG, SB, NLANES };

// A worker's scratch lists for trace_wavefront (kept across tiles: no allocation per sample).
struct Wavefront {
    std::vector<std::uint32_t> active, next, order;
    std::vector<ShadowRay> shadows;
    std::vector<std::uint32_t> embree;  // hybrid scenes: the step's rays that Embree traces
    std::vector<Hit> hits;
    std::vector<PathState> paths;
    std::vector<ShadeRec> recs;
    std::vector<std::uint32_t> count;  // per material
    std::vector<float> soa;            // NLANES arrays of the wavefront's length
};

}  // namespace

const char *region_name(int r) {
    switch (r) {
    case REGION_NONE: return "none";
    case REGION_WALL: return "walls";
    case REGION_FLOOR: return "floor";
    case REGION_CEILING: return "ceiling";
    case REGION_SPHERE: return "sphere";
    case REGION_LIGHT: return "light";
    case REGION_OTHER: return "other";
    case REGION_SHADOW: return "shadow";
    }
    return "?";
}

struct Renderer::Impl {
    const Scene &scene;
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;       // every primitive that Embree holds (in a hybrid scene: built by need_all)
    RTCScene rtc_mesh = nullptr;  // a hybrid scene's `mesh` lines alone
    std::once_flag rtc_once;
    std::vector<GeomRef> geoms;  // by geomID (the same IDs in both scenes)
    // A scene with few spheres has them intersected here, analytically, and only its
    // triangles in Embree: Embree 3 traverses a separate BVH for its sphere primitives, which
    // doubled the cost of every ray in the stimulus scene (one sphere, 14 triangles).
    static constexpr size_t kAnalyticSpheres = 16;
    bool analytic_spheres = false;
    bool use_quads = false;  // meshes and lights as Embree quads (pairs_into_quads)
    float eps = 1e-4f;           // ray offset, scaled to the scene
    std::vector<RectFrame> rects;  // per light, for solid-angle sampling (sphrect.hpp)
    // A scene of at most kSmallTriangles triangles and kAnalyticSpheres spheres (the stimulus:
    // 14 and 1) is intersected here too, each packet of 16 rays against every primitive in
    // lane loops the compiler vectorises: cheaper than any traversal of a BVH of 2 nodes
    // (Embree took ~40 ns a ray for the stimulus box).
    static constexpr size_t kSmallTriangles = 32;
    struct Tri {
        glm::vec3 v0, e1, e2, n;  // n: unit normal
        GeomRef ref;
    };
    std::vector<Tri> tris;
    // A pair of triangles (a, b, c), (a, c, d) that is a parallelogram (the scene's boxes,
    // quads and lights) is tested once, as a plane and two edge coordinates: u = (p − a)·du,
    // v = (p − a)·dv with du, dv the dual basis of its edges b − a, d − a.
    struct Para {
        glm::vec3 v0, n, du, dv;  // n: unit normal
        float nv0;                // n·v0
        GeomRef ref;
    };
    std::vector<Para> paras;  // at most kSmallTriangles / 2: a bit each in a std::uint32_t
    // For shadow rays (shadow_skip): the boxes whose six faces are parallelograms, shrunk by
    // eps/2, and the bit of the only light's parallelogram (0 if there are other lights).
    struct Room {
        glm::vec3 lo, hi;
        std::uint32_t paras;  // the bits of its faces
    };
    std::vector<Room> rooms;
    std::uint32_t only_light = 0;
    bool small_scene = false;
    // A *hybrid* scene — `mesh` lines, and boxes, quads and lights of at most kSmallTriangles
    // triangles, at most kAnalyticSpheres spheres (the mug scene) — has the latter in the lane
    // loops and only its meshes in Embree: the room's large faces and the light no longer
    // overlap every node of the BVH, and a ray whose segment misses the meshes' bounds (most
    // rays between walls, floor and light) is not given to Embree at all.
    bool hybrid = false;
    glm::vec3 mesh_lo{0}, mesh_hi{0};  // the bounds of rtc_mesh, widened by eps
    bool packet16 = false;             // whether Embree traces packets of 16 natively (AVX-512)

    static bool is_mesh_line(const Mesh &m) { return m.label.compare(0, 5, "mesh:") == 0; }
    GeomRef mesh_ref(size_t i) const { return {GeomKind::MESH, int(i), scene.meshes[i].material}; }
    GeomRef sphere_ref(size_t i) const { return {GeomKind::SPHERE, int(i), scene.spheres[i].material}; }
    // What shading reads of a checker, in a small array of its own (a Material, with its name
    // and both forms of its lobe, is a few hundred bytes): hit by every shading point of the room.
    struct Checker {
        glm::vec3 offset{0};
        float inv_size = 1;
        int a = -1, b = -1;  // a < 0: not a checker
    };
    std::vector<Checker> checkers;  // by material index
    static std::vector<glm::vec3> light_corners(const AreaLight &l) {
        return {l.corner, l.corner + l.edge1, l.corner + l.edge1 + l.edge2, l.corner + l.edge2};
    }

    explicit Impl(const Scene &s) : scene(s) {
        // A Scene built in code has not been through the parser's checks.
        auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        for (const AreaLight &l : s.lights)
            if (!finite(l.radiance) || !std::isfinite(l.area) || !(l.area > 0) || !finite(l.corner) ||
                !finite(l.edge1) || !finite(l.edge2))
                throw SceneError(s.path + ": a light has a non-finite radiance or geometry");
        if (s.has_environment && !finite(s.environment))
            throw SceneError(s.path + ": the environment's radiance is not finite");
        device = rtcNewDevice("threads=1");  // our own threads call into Embree; BVH build is small
        if (!device) throw std::runtime_error("Embree: rtcNewDevice failed");
        packet16 = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED) != 0;
        float extent = 1.0f;
        analytic_spheres = s.spheres.size() <= kAnalyticSpheres;
        for (const Sphere &sp : s.spheres) extent = std::max(extent, max3(glm::abs(sp.center)) + sp.radius);
        for (const Mesh &m : s.meshes)
            for (auto &p : m.vertices) extent = std::max(extent, max3(glm::abs(p)));
        eps = 1e-4f * extent;
        for (const AreaLight &l : s.lights) rects.push_back(rect_frame(l.corner, l.edge1, l.edge2, l.normal));
        nlights = s.lights.size() + (s.has_environment ? 1 : 0);
        for (const Material &m : s.materials)
            checkers.push_back(m.checker ? Checker{m.check_offset, 1.0f / m.check_size, m.check_a, m.check_b} : Checker{});
        // Which primitives the lane loops take: all (a small scene), all but the `mesh` lines
        // (a hybrid scene), or none.
        for (int pass = 0; pass < 2; ++pass) {
            tris.clear(), paras.clear();
            bool meshes_left_out = false;
            for (size_t i = 0; i < s.meshes.size(); ++i) {
                if (pass == 1 && is_mesh_line(s.meshes[i])) meshes_left_out = true;
                else add_lane_prims(s.meshes[i].vertices, s.meshes[i].faces, mesh_ref(i));
            }
            for (size_t i = 0; i < s.lights.size(); ++i)
                add_lane_prims(light_corners(s.lights[i]), {{0, 1, 2}, {0, 2, 3}}, {GeomKind::LIGHT, int(i)});
            const bool fits = analytic_spheres && tris.size() + 2 * paras.size() <= kSmallTriangles;
            if (pass == 0 && fits) {
                small_scene = true;
                break;
            }
            hybrid = pass == 1 && fits && meshes_left_out;
        }
        if (!small_scene && !hybrid) tris.clear(), paras.clear();
        for (size_t k = 0; k < paras.size(); ++k)
            if (paras[k].ref.kind == GeomKind::LIGHT && s.lights.size() == 1 && !s.has_environment) only_light |= 1u << k;
        for (size_t i = 0; i < s.meshes.size(); ++i) {
            if (s.meshes[i].label != "box") continue;
            Room room{glm::vec3(std::numeric_limits<float>::infinity()), glm::vec3(-std::numeric_limits<float>::infinity()), 0u};
            size_t faces = 0;
            for (size_t k = 0; k < paras.size(); ++k)
                if (paras[k].ref.kind == GeomKind::MESH && paras[k].ref.index == int(i)) room.paras |= 1u << k, ++faces;
            if (2 * faces != s.meshes[i].faces.size()) continue;  // not all of it in the lane loops
            for (const glm::vec3 &v : s.meshes[i].vertices) room.lo = glm::min(room.lo, v), room.hi = glm::max(room.hi, v);
            room.lo += 0.5f * eps, room.hi -= 0.5f * eps;  // rays leave surfaces eps off them
            rooms.push_back(room);
        }
        if (!hybrid) {
            build_all();
            return;
        }
        // Embree's default (medium) build quality: at 1M triangles it takes half the time of
        // high's, and the rays cost the same (mug.scene at 960 and 983,040 triangles).
        rtc_mesh = rtcNewScene(device);
        mesh_lo = glm::vec3(std::numeric_limits<float>::infinity()), mesh_hi = -mesh_lo;
        for (size_t i = 0; i < s.meshes.size(); ++i) {
            const Mesh &m = s.meshes[i];
            if (!is_mesh_line(m)) continue;
            // The IDs build_all gives (meshes first: the spheres are analytic here). Triangles,
            // even where they pair into quads: Embree's quad leaves cost 25 % more work per ray
            // at 1M triangles (callgrind) and the same at 960 (quads save memory and build time).
            add_embree(rtc_mesh, unsigned(i), false, m.vertices, m.faces, mesh_ref(i), true);
            for (const glm::uvec3 &f : m.faces)
                for (unsigned k : {f.x, f.y, f.z}) mesh_lo = glm::min(mesh_lo, m.vertices[k]), mesh_hi = glm::max(mesh_hi, m.vertices[k]);
        }
        mesh_lo -= eps, mesh_hi += eps;
        rtcCommitScene(rtc_mesh);
    }
    ~Impl() {
        if (rtc) rtcReleaseScene(rtc);
        if (rtc_mesh) rtcReleaseScene(rtc_mesh);
        if (device) rtcReleaseDevice(device);
    }

    // Every primitive in one Embree scene: what a scene that is neither small nor hybrid
    // traces, and what --embree traces (a hybrid scene builds it when a render first asks).
    void build_all() {
        const Scene &s = scene;
        rtc = rtcNewScene(device);
        rtcSetSceneBuildQuality(rtc, RTC_BUILD_QUALITY_HIGH);
        unsigned id = 0;
        for (size_t i = 0; i < s.spheres.size() && !analytic_spheres; ++i) {
            const Sphere &sp = s.spheres[i];
            RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto *v = static_cast<float *>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                    RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
            v[0] = sp.center.x, v[1] = sp.center.y, v[2] = sp.center.z, v[3] = sp.radius;
            attach(rtc, id++, g, sphere_ref(size_t(i)));
        }
        // One primitive type for the whole scene (Embree traverses one BVH per type): quads
        // when every mesh pairs up (the stimulus scene: ~1.5x faster traversal than its 14
        // triangles), else triangles.
        use_quads = std::all_of(s.meshes.begin(), s.meshes.end(), [](const Mesh &m) { return pairs_into_quads(m.faces); });
        for (size_t i = 0; i < s.meshes.size(); ++i)
            add_embree(rtc, id++, use_quads, s.meshes[i].vertices, s.meshes[i].faces, mesh_ref(i));
        for (size_t i = 0; i < s.lights.size(); ++i)
            add_embree(rtc, id++, use_quads, light_corners(s.lights[i]), {{0, 1, 2}, {0, 2, 3}}, {GeomKind::LIGHT, int(i)});
        rtcCommitScene(rtc);
    }
    // The scene that --embree traces, built once.
    void need_all() {
        std::call_once(rtc_once, [this] {
            if (!rtc) build_all();
        });
    }

    void attach(RTCScene sc, unsigned id, RTCGeometry g, GeomRef ref) {
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(sc, g, id);
        rtcReleaseGeometry(g);
        if (geoms.size() <= id) geoms.resize(id + 1);
        geoms[id] = ref;
    }
    // Whether triangles k and k + 1 are a pair (a, b, c), (a, c, d), as the scene's boxes,
    // quads and lights and fan-triangulated OBJ quads are: the pair is then Embree's quad
    // (b, c, d, a), whose two triangles (b, c, a) and (d, a, c) are the pair itself.
    static bool is_pair(const std::vector<glm::uvec3> &faces, size_t k) {
        return k + 1 < faces.size() && faces[k + 1].x == faces[k].x && faces[k + 1].y == faces[k].z;
    }
    static bool pairs_into_quads(const std::vector<glm::uvec3> &faces) {
        if (faces.size() % 2 != 0) return false;
        for (size_t k = 0; k < faces.size(); k += 2)
            if (!is_pair(faces, k)) return false;
        return true;
    }
    // The lane loops' primitives of a mesh or light: parallelograms and other triangles, while
    // there are at most kSmallTriangles (a parallelogram counts two).
    void add_lane_prims(const std::vector<glm::vec3> &verts, const std::vector<glm::uvec3> &faces, GeomRef ref) {
        for (size_t k = 0; k < faces.size() && tris.size() + 2 * paras.size() <= kSmallTriangles; ++k) {
            const glm::uvec3 &f = faces[k];
            const glm::vec3 a = verts[f.x], b = verts[f.y], c = verts[f.z];
            if (is_pair(faces, k)) {
                const glm::vec3 d = verts[faces[k + 1].z], e1 = b - a, e2 = d - a;
                const glm::vec3 n = glm::cross(e1, e2);
                const float tol = 1e-6f * (glm::length(e1) + glm::length(e2));
                if (glm::length(a + e1 + e2 - c) <= tol && glm::length(n) > 0) {  // a parallelogram
                    const glm::vec3 du = glm::cross(e2, n), dv = glm::cross(n, e1);
                    const glm::vec3 un = glm::normalize(n);
                    paras.push_back({a, un, du / glm::dot(e1, du), dv / glm::dot(e2, dv), glm::dot(un, a), ref});
                    ++k;
                    continue;
                }
            }
            tris.push_back({a, b - a, c - a, glm::normalize(glm::cross(b - a, c - a)), ref});
        }
    }
    // A mesh or light as Embree quads (every pair, pairs_into_quads) or triangles; shared:
    // Embree reads the triangles' indices from faces itself (which outlives the scene)
    // instead of a copy.
    void add_embree(RTCScene sc, unsigned id, bool quads, const std::vector<glm::vec3> &verts,
                    const std::vector<glm::uvec3> &faces, GeomRef ref, bool shared = false) {
        RTCGeometry g = rtcNewGeometry(device, quads ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
        auto *v = static_cast<float *>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), verts.size()));
        for (size_t k = 0; k < verts.size(); ++k) v[3 * k] = verts[k].x, v[3 * k + 1] = verts[k].y, v[3 * k + 2] = verts[k].z;
        if (quads) {
            auto *ix = static_cast<unsigned *>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                                                        4 * sizeof(unsigned), faces.size() / 2));
            for (size_t k = 0; k < faces.size(); k += 2) {
                unsigned *q = ix + 2 * k;
                q[0] = faces[k].y, q[1] = faces[k].z, q[2] = faces[k + 1].z, q[3] = faces[k].x;
            }
        } else if (shared) {
            static_assert(sizeof(glm::uvec3) == 3 * sizeof(unsigned), "faces are packed RTC_FORMAT_UINT3");
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, faces.data(), 0,
                                       sizeof(glm::uvec3), faces.size());
        } else {
            auto *ix = static_cast<unsigned *>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                        3 * sizeof(unsigned), faces.size()));
            for (size_t k = 0; k < faces.size(); ++k) ix[3 * k] = faces[k].x, ix[3 * k + 1] = faces[k].y, ix[3 * k + 2] = faces[k].z;
        }
        attach(sc, id, g, ref);
    }

    Hit intersect(glm::vec3 o, glm::vec3 d, std::uint64_t &rays) const {
        ++rays;
        if (hybrid) {  // the lane loops, one ray in every lane, then the meshes before that hit
            Packet pk;
            for (size_t j = 0; j < 16; ++j) pk.set(j, o, d, std::numeric_limits<float>::infinity());
            small_intersect<false>(pk);
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            RTCRayHit rh{};
            set_ray(rh.ray, o, d, pk.tfar[0]);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(rtc_mesh, &ctx, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return make_small_hit(o, d, pk.prim[0], pk.tfar[0]);
            return make_hit(o, d, rh.hit.geomID, rh.ray.tfar, glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z), -1);
        }
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh{};
        rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
        rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = 0xffffffffu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        int si = -1;
        rh.ray.tfar = sphere_hit(o, d, rh.ray.tfar, si);
        rtcIntersect1(rtc, &ctx, &rh);
        return make_hit(o, d, rh.hit.geomID, rh.ray.tfar, glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z), si);
    }

    // The nearest analytic sphere along o + t d, 0 < t < tmax: returns its t and sets idx, or
    // returns tmax. The roots as in Haines et al. 2019 (Ray Tracing Gems, ch. 7): the
    // discriminant from the distance of the centre to the ray, and the smaller root from the
    // larger one, so that neither cancels for a distant or a large sphere.
    float sphere_hit(glm::vec3 o, glm::vec3 d, float tmax, int &idx) const {
        if (!analytic_spheres) return tmax;
        const float a = glm::dot(d, d);
        for (size_t i = 0; i < scene.spheres.size(); ++i) {
            const Sphere &sp = scene.spheres[i];
            const glm::vec3 f = o - sp.center;
            const float b = -glm::dot(f, d);  // the roots of a t² − 2 b t + c
            const glm::vec3 l = f + (b / a) * d;
            const float r2 = sp.radius * sp.radius;
            const float disc = a * (r2 - glm::dot(l, l));
            if (!(disc >= 0)) continue;
            const float q = b + std::copysign(std::sqrt(disc), b);
            if (q == 0) continue;
            const float c = glm::dot(f, f) - r2;
            const float t0 = c / q, t1 = q / a;
            const float tn = std::min(t0, t1), tf = std::max(t0, t1);
            const float t = tn > 0 ? tn : tf;
            if (t > 0 && t < tmax) tmax = t, idx = int(i);
        }
        return tmax;
    }

    // Packets of 16 rays for the small-scene intersector (structure of arrays).
    struct Packet {
        alignas(64) float ox[16], oy[16], oz[16], dx[16], dy[16], dz[16], tfar[16];
        alignas(64) int prim[16];  // the triangle's index (parallelograms follow the triangles), -2 - the sphere's; -1: none

        // Lane j: the ray o + t d, 0 < t < tmax, nothing hit yet.
        void set(size_t j, const glm::vec3 &o, const glm::vec3 &d, float tmax) {
            ox[j] = o.x, oy[j] = o.y, oz[j] = o.z;
            dx[j] = d.x, dy[j] = d.y, dz[j] = d.z;
            tfar[j] = tmax;
            prim[j] = -1;
        }
    };

    // The closest parallelogram, triangle or sphere along each ray of p with 0 < t < p.tfar
    // (any, if any_hit): Möller & Trumbore 1997 for the triangles, edges inclusive (a ray
    // through an edge two primitives share hits one of them), the spheres as sphere_hit.
    //
    // any_hit is for shadow rays, which end short of the light they aim at: it leaves out the
    // parallelograms that cannot occlude any ray of p (shadow_skip).
    template <bool any_hit>
    void small_intersect(Packet &p) const {
        const std::uint32_t skip = any_hit ? shadow_skip(p) : 0u;
        for (size_t k = 0; k < paras.size(); ++k) {
            if (skip >> k & 1u) continue;
            const Para &Q = paras[k];
            const int id = int(tris.size() + k);
            for (int j = 0; j < 16; ++j) {
                const float dn = p.dx[j] * Q.n.x + p.dy[j] * Q.n.y + p.dz[j] * Q.n.z;
                const float t = (Q.nv0 - (p.ox[j] * Q.n.x + p.oy[j] * Q.n.y + p.oz[j] * Q.n.z)) / dn;
                const float px = p.ox[j] - Q.v0.x + t * p.dx[j], py = p.oy[j] - Q.v0.y + t * p.dy[j],
                            pz = p.oz[j] - Q.v0.z + t * p.dz[j];
                const float u = px * Q.du.x + py * Q.du.y + pz * Q.du.z;
                const float v = px * Q.dv.x + py * Q.dv.y + pz * Q.dv.z;
                const bool h = (u >= 0.0f) & (u <= 1.0f) & (v >= 0.0f) & (v <= 1.0f) & (t > 0.0f) & (t < p.tfar[j]);
                p.tfar[j] = h ? (any_hit ? -std::numeric_limits<float>::infinity() : t) : p.tfar[j];
                p.prim[j] = h ? id : p.prim[j];
            }
        }
        for (size_t k = 0; k < tris.size(); ++k) {
            const Tri &T = tris[k];
            const int id = int(k);
            for (int j = 0; j < 16; ++j) {
                const float px = p.dy[j] * T.e2.z - p.dz[j] * T.e2.y;
                const float py = p.dz[j] * T.e2.x - p.dx[j] * T.e2.z;
                const float pz = p.dx[j] * T.e2.y - p.dy[j] * T.e2.x;
                const float det = T.e1.x * px + T.e1.y * py + T.e1.z * pz;
                const float inv = 1.0f / det;  // det 0: ±inf or NaN below, and no hit
                const float tx = p.ox[j] - T.v0.x, ty = p.oy[j] - T.v0.y, tz = p.oz[j] - T.v0.z;
                const float u = (tx * px + ty * py + tz * pz) * inv;
                const float qx = ty * T.e1.z - tz * T.e1.y, qy = tz * T.e1.x - tx * T.e1.z, qz = tx * T.e1.y - ty * T.e1.x;
                const float v = (p.dx[j] * qx + p.dy[j] * qy + p.dz[j] * qz) * inv;
                const float t = (T.e2.x * qx + T.e2.y * qy + T.e2.z * qz) * inv;
                const bool h = (u >= 0.0f) & (v >= 0.0f) & (u + v <= 1.0f) & (t > 0.0f) & (t < p.tfar[j]);
                p.tfar[j] = h ? (any_hit ? -std::numeric_limits<float>::infinity() : t) : p.tfar[j];
                p.prim[j] = h ? id : p.prim[j];
            }
        }
        for (size_t k = 0; k < scene.spheres.size(); ++k) {
            const Sphere &sp = scene.spheres[k];
            const float r2 = sp.radius * sp.radius;
            const int id = -2 - int(k);
            for (int j = 0; j < 16; ++j) {
                const float fx = p.ox[j] - sp.center.x, fy = p.oy[j] - sp.center.y, fz = p.oz[j] - sp.center.z;
                const float a = p.dx[j] * p.dx[j] + p.dy[j] * p.dy[j] + p.dz[j] * p.dz[j];
                const float b = -(fx * p.dx[j] + fy * p.dy[j] + fz * p.dz[j]);
                const float ba = b / a;
                const float lx = fx + ba * p.dx[j], ly = fy + ba * p.dy[j], lz = fz + ba * p.dz[j];
                const float disc = a * (r2 - (lx * lx + ly * ly + lz * lz));
                const float q = b + std::copysign(std::sqrt(std::max(disc, 0.0f)), b);
                const float c = fx * fx + fy * fy + fz * fz - r2;
                const float t0 = c / q, t1 = q / a;
                const float tn = std::min(t0, t1), tf = std::max(t0, t1);
                const float t = tn > 0.0f ? tn : tf;
                const bool h = (disc >= 0.0f) & (q != 0.0f) & (t > 0.0f) & (t < p.tfar[j]);
                p.tfar[j] = h ? (any_hit ? -std::numeric_limits<float>::infinity() : t) : p.tfar[j];
                p.prim[j] = h ? id : p.prim[j];
            }
        }
    }

    // The parallelograms (a bit each) that no shadow ray of p can meet: the only light, when
    // there is no other (a shadow ray stops short of it), and the faces of a box that holds
    // both ends of every ray, eps/2 inside (a segment inside a convex box does not cross it).
    std::uint32_t shadow_skip(const Packet &p) const {
        std::uint32_t skip = only_light;
        for (const Room &b : rooms) {
            int inside = 0;  // lanes (a count, which the compiler vectorises)
            for (int j = 0; j < 16; ++j) {
                const float ex = p.ox[j] + p.tfar[j] * p.dx[j], ey = p.oy[j] + p.tfar[j] * p.dy[j],
                            ez = p.oz[j] + p.tfar[j] * p.dz[j];
                inside += (p.ox[j] > b.lo.x) & (p.ox[j] < b.hi.x) & (p.oy[j] > b.lo.y) & (p.oy[j] < b.hi.y) &
                          (p.oz[j] > b.lo.z) & (p.oz[j] < b.hi.z) & (ex > b.lo.x) & (ex < b.hi.x) &
                          (ey > b.lo.y) & (ey < b.hi.y) & (ez > b.lo.z) & (ez < b.hi.z);
            }
            if (inside == 16) skip |= b.paras;
        }
        return skip;
    }

    // The hit record of a ray whose closest primitive small_intersect found (prim, t).
    Hit make_small_hit(glm::vec3 o, glm::vec3 d, int prim, float t) const {
        Hit h;
        if (prim == -1) return h;
        h.hit = true;
        h.t = t;
        h.p = o + t * d;
        if (prim >= 0 && size_t(prim) < tris.size()) {
            h.ref = tris[size_t(prim)].ref;
            h.n = tris[size_t(prim)].n;
        } else if (prim >= 0) {
            h.ref = paras[size_t(prim) - tris.size()].ref;
            h.n = paras[size_t(prim) - tris.size()].n;
        } else {
            h.ref = sphere_ref(size_t(-2 - prim));
            h.n = glm::normalize(h.p - scene.spheres[size_t(-2 - prim)].center);
        }
        return h;
    }

    // The hit record of a ray (o, d) whose closest hit is Embree's (geomID, t, Ng), or else the
    // sphere: the analytic sphere hit before t (sphere_hit), or -1.
    Hit make_hit(glm::vec3 o, glm::vec3 d, unsigned geom_id, float t, glm::vec3 ng, int sphere) const {
        Hit h;
        if (geom_id == RTC_INVALID_GEOMETRY_ID && sphere < 0) return h;
        h.hit = true;
        h.t = t;
        h.p = o + h.t * d;
        h.ref = geom_id == RTC_INVALID_GEOMETRY_ID ? sphere_ref(size_t(sphere)) : geoms[geom_id];
        if (h.ref.kind == GeomKind::SPHERE) {
            const Sphere &s = scene.spheres[size_t(h.ref.index)];
            h.n = glm::normalize(h.p - s.center);
        } else {
            h.n = glm::normalize(ng);
        }
        return h;
    }

    bool occluded(glm::vec3 o, glm::vec3 d, float tfar, std::uint64_t &rays) const {
        ++rays;
        if (hybrid) {
            Packet pk;
            for (size_t j = 0; j < 16; ++j) pk.set(j, o, d, tfar);
            small_intersect<true>(pk);
            if (pk.prim[0] != -1) return true;
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            RTCRay r{};
            set_ray(r, o, d, tfar);
            rtcOccluded1(rtc_mesh, &ctx, &r);
            return r.tfar < 0.0f;
        }
        int si = -1;
        if (sphere_hit(o, d, tfar, si) < tfar) return true;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay r{};
        r.org_x = o.x, r.org_y = o.y, r.org_z = o.z;
        r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
        r.tnear = 0.0f;
        r.tfar = tfar;
        r.mask = 0xffffffffu;
        rtcOccluded1(rtc, &ctx, &r);
        return r.tfar < 0.0f;
    }

    // Embree's ray o + t d, 0 < t < tfar, in a single ray or lane j of a packet.
    static void set_ray(RTCRay &r, glm::vec3 o, glm::vec3 d, float tfar) {
        r.org_x = o.x, r.org_y = o.y, r.org_z = o.z;
        r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z;
        r.tnear = 0.0f, r.tfar = tfar, r.time = 0.0f;
        r.mask = 0xffffffffu, r.id = 0, r.flags = 0;
    }
    template <class RayK>  // RTCRay8, RTCRay16
    static void set_ray(RayK &r, size_t j, glm::vec3 o, glm::vec3 d, float tfar) {
        r.org_x[j] = o.x, r.org_y[j] = o.y, r.org_z[j] = o.z;
        r.dir_x[j] = d.x, r.dir_y[j] = d.y, r.dir_z[j] = d.z;
        r.tnear[j] = 0.0f, r.tfar[j] = tfar, r.time[j] = 0.0f;
        r.mask[j] = 0xffffffffu, r.id[j] = 0, r.flags[j] = 0;
    }

    static void intersect(const int *valid, RTCScene sc, RTCIntersectContext *ctx, RTCRayHit8 *rh) {
        rtcIntersect8(valid, sc, ctx, rh);
    }
    static void intersect(const int *valid, RTCScene sc, RTCIntersectContext *ctx, RTCRayHit16 *rh) {
        rtcIntersect16(valid, sc, ctx, rh);
    }
    static void occluded(const int *valid, RTCScene sc, RTCIntersectContext *ctx, RTCRay8 *r) {
        rtcOccluded8(valid, sc, ctx, r);
    }
    static void occluded(const int *valid, RTCScene sc, RTCIntersectContext *ctx, RTCRay16 *r) {
        rtcOccluded16(valid, sc, ctx, r);
    }
    // A hybrid scene's meshes for the rays paths[wf.active[i]], i in wf.embree, each as far as
    // its lane loops' hit wf.hits[i]: where a mesh is nearer, it becomes the hit. In packets
    // of K, Embree's native width (16 with AVX-512; with AVX2 it splits a packet of 16 into
    // copies of two).
    template <class RayHitK, size_t K>
    void mesh_closest(const PathState *paths, Wavefront &wf, RTCIntersectContext &ctx) const {
        const size_t ne = wf.embree.size();
        for (size_t b = 0; b < ne; b += K) {
            const size_t cnt = std::min(K, ne - b);
            alignas(64) int valid[K];
            alignas(64) RayHitK rh;
            for (size_t j = 0; j < K; ++j) {
                const size_t i = wf.embree[b + std::min(j, cnt - 1)];
                const PathState &ps = paths[wf.active[i]];
                valid[j] = j < cnt ? -1 : 0;
                set_ray(rh.ray, j, ps.o, ps.d, wf.hits[i].hit ? wf.hits[i].t : std::numeric_limits<float>::infinity());
                rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
            }
            intersect(valid, rtc_mesh, &ctx, &rh);
            for (size_t j = 0; j < cnt; ++j) {
                if (rh.hit.geomID[j] == RTC_INVALID_GEOMETRY_ID) continue;
                const size_t i = wf.embree[b + j];
                const PathState &ps = paths[wf.active[i]];
                wf.hits[i] = make_hit(ps.o, ps.d, rh.hit.geomID[j], rh.ray.tfar[j],
                                      glm::vec3(rh.hit.Ng_x[j], rh.hit.Ng_y[j], rh.hit.Ng_z[j]), -1);
            }
        }
    }
    // The shadow rays wf.shadows[i], i in wf.embree, against a hybrid scene's meshes:
    // each unoccluded one adds its next-event estimate.
    template <class RayK, size_t K>
    void mesh_occluded(PathState *paths, const Wavefront &wf, RTCIntersectContext &ctx) const {
        const size_t ne = wf.embree.size();
        for (size_t b = 0; b < ne; b += K) {
            const size_t cnt = std::min(K, ne - b);
            alignas(64) int valid[K];
            alignas(64) RayK r;
            for (size_t j = 0; j < K; ++j) {
                const ShadowRay &sr = wf.shadows[wf.embree[b + std::min(j, cnt - 1)]];
                valid[j] = j < cnt ? -1 : 0;
                set_ray(r, j, sr.o, sr.d, sr.tmax);
            }
            occluded(valid, rtc_mesh, &ctx, &r);
            for (size_t j = 0; j < cnt; ++j)
                if (!(r.tfar[j] < 0.0f)) {
                    const ShadowRay &sr = wf.shadows[wf.embree[b + j]];
                    paths[sr.path].L += sr.c;
                }
        }
    }

    // Whether the segment of each ray of p, 0 < t < p.tfar, can meet the meshes' bounds (a
    // hybrid scene): the slab test, where a NaN from a zero direction component counts as
    // meeting them.
    void meets_meshes(const Packet &p, bool meets[16]) const {
        for (int j = 0; j < 16; ++j) {
            const float ix = 1.0f / p.dx[j], iy = 1.0f / p.dy[j], iz = 1.0f / p.dz[j];
            const float x0 = (mesh_lo.x - p.ox[j]) * ix, x1 = (mesh_hi.x - p.ox[j]) * ix;
            const float y0 = (mesh_lo.y - p.oy[j]) * iy, y1 = (mesh_hi.y - p.oy[j]) * iy;
            const float z0 = (mesh_lo.z - p.oz[j]) * iz, z1 = (mesh_hi.z - p.oz[j]) * iz;
            const float lo = std::max(std::max(std::min(x0, x1), std::min(y0, y1)), std::max(std::min(z0, z1), 0.0f));
            const float hi = std::min(std::min(std::max(x0, x1), std::max(y0, y1)), std::min(std::max(z0, z1), p.tfar[j]));
            meets[j] = !(lo > hi);
        }
    }

    // The material index at p: mi itself, or the check of a checker that p falls in.
    int material_index_at(int mi, glm::vec3 p) const {
        const Checker &c = checkers[size_t(mi)];
        if (c.a < 0) return mi;
        glm::vec3 q = glm::floor((p - c.offset) * c.inv_size);
        long parity = (long(q.x) + long(q.y) + long(q.z)) & 1L;
        return parity ? c.b : c.a;
    }

    // Emitted radiance of light li towards a point, seen along direction -wi (wi points at the light).
    glm::vec3 light_emission(const AreaLight &l, float cos_l) const {
        if (cos_l <= 0) return glm::vec3(0);
        if (!l.isotropic) return l.radiance;
        return l.radiance / cos_l;
    }

    // The solid-angle pdf with which next-event estimation from o picks the point of light li
    // that a ray from o reaches at distance t with cosine cos_l: the same choice of technique
    // (spherical rectangle or area) as the sampling from o made.
    float light_pdf(bool solid_angle, size_t li, glm::vec3 o, float t, float cos_l) const {
        if (solid_angle) {
            const SphRect q = sphrect_setup(rects[li], o);
            if (q.state == SphRect::OK) return float(1.0 / q.S);
        }
        return t * t / (scene.lights[li].area * cos_l);
    }

    size_t nlights = 0;  // area lights and the environment
    size_t light_count() const { return nlights; }


    // Stage 1 of a path's shading step: what the path found along its last ray (hit).
    // Emission reached by the ray is added to ps.L; the light sample of the next-event
    // estimate and the BRDF sample's random numbers go into r, for the lobe calls. Returns
    // false when the path ends here (r.mat = -1).
    __attribute__((always_inline)) bool shade_begin(PathState &ps, const Hit &hit, const RenderSettings &set, ShadeRec &r) const {
        const Mode mode = set.mode;
        const int max_depth = set.max_depth;
        const glm::vec3 d = ps.d;
        const float nl = float(light_count());
        r.shadow = false;
        r.mat = -1;
        if (!hit.hit) {
            if (scene.has_environment && ps.prev != Prev::LIGHT) {
                float w = 1;
                if (ps.prev == Prev::MIS)
                    w = power_heuristic(ps.prev_pdf, std::max(0.0f, glm::dot(ps.prev_n, d)) / kPi / nl);
                ps.L += ps.beta * scene.environment * w;
            }
            return false;
        }
        if (hit.ref.kind == GeomKind::LIGHT) {
            const AreaLight &l = scene.lights[size_t(hit.ref.index)];
            float cos_l = -glm::dot(l.normal, d);
            if (cos_l > 0 && ps.prev != Prev::LIGHT) {
                float w = 1;
                if (ps.prev == Prev::MIS) {
                    float pdf_light = light_pdf(set.solid_angle_lights, size_t(hit.ref.index), ps.o, hit.t, cos_l) / nl;
                    w = power_heuristic(ps.prev_pdf, pdf_light);
                }
                ps.L += ps.beta * light_emission(l, cos_l) * w;
            }
            return false;  // lights do not reflect
        }
        if (ps.depth + 1 > max_depth) return false;
        const int mi = material_index_at(hit.ref.material, hit.p);
        const pgloss_material &m = scene.materials[size_t(mi)].ward;
        if (m.lobes == PGLOSS_LOBE_NONE) return false;
        r.mat = mi;
        r.n = glm::dot(hit.n, d) < 0 ? hit.n : -hit.n;  // two-sided: face the viewer
        r.frame = Frame(r.n);
        r.wo = r.frame.to_local(-d);
        r.p = hit.p + eps * r.n;
        PathSampler &smp = ps.smp;

        // Strategy at this vertex: no MIS work where there is no specular lobe.
        r.strat = mode == Mode::BRDF ? Prev::BRDF
                : mode == Mode::LIGHT ? Prev::LIGHT
                : (m.lobes & PGLOSS_LOBE_SPECULAR) ? Prev::MIS : Prev::LIGHT;

        r.nee = false;
        r.wil = r.wo;  // a valid direction for the batched call where there is no estimate
        r.li = -1;
        if (r.strat != Prev::BRDF && nl > 0) {  // next-event estimation: its numbers now, the rest in light_sample
            // (a scene with one light draws no number to choose it)
            r.li = light_count() == 1 ? 0 : int(std::min(size_t(smp.get1() * nl), light_count() - 1));
            const glm::vec2 ul = smp.get2();
            r.ul[0] = ul.x, r.ul[1] = ul.y;
        }
        // The BRDF sample's random numbers, drawn now: each path's stream is consumed in the
        // order of the scalar recursion (light sample, BRDF sample, Russian roulette).
        r.u[0] = smp.get1();
        const glm::vec2 ud = smp.get2();
        r.u[1] = ud.x, r.u[2] = ud.y;
        return true;
    }

    // Stage 1b: the light sample of a next-event estimate (r.li, r.ul from stage 1). A loop of
    // its own over the step's hits: its chain of square root and divisions overlaps across
    // paths there, instead of stalling the long stage 1 of one path.
    void light_sample(ShadeRec &r, bool solid_angle) const {
        const float nl = float(light_count());
        const size_t li = size_t(r.li);
        const float u1 = r.ul[0], u2 = r.ul[1];
        glm::vec3 wi, Le;
        float pdf_light, tmax;
        bool ok = true;
        if (li < scene.lights.size()) {
            const AreaLight &l = scene.lights[li];
            glm::vec3 y;
            float pdf_angle = 0;  // > 0: sampled uniformly in the light's solid angle, pdf 1/S
            if (solid_angle) {    // (the set-up only where asked: it is a dozen doubles)
                const SphRect q = sphrect_setup(rects[li], r.p);
                if (q.state == SphRect::OK) {
                    const glm::dvec2 st = sphrect_sample(rects[li], q, u1, u2);
                    y = glm::vec3(rects[li].corner + st.x * rects[li].ex + st.y * rects[li].ey);
                    pdf_angle = float(1.0 / q.S);
                }
            }
            if (!(pdf_angle > 0)) y = l.corner + u1 * l.edge1 + u2 * l.edge2;  // uniform in area
            glm::vec3 dv = y - r.p;
            float dist2 = glm::dot(dv, dv), dist = std::sqrt(dist2);
            wi = dv * (1.0f / dist);
            float cos_l = -glm::dot(l.normal, wi);
            ok = cos_l > 0 && dist2 > 0;
            pdf_light = !ok ? 0 : pdf_angle > 0 ? pdf_angle : dist2 / (l.area * cos_l);
            Le = ok ? light_emission(l, cos_l) : glm::vec3(0);
            tmax = dist * (1.0f - 1e-4f);
        } else {  // environment: cosine-weighted about n
            float rr = std::sqrt(u1), phi = 2 * kPi * u2;
            pgloss_vec3 lw{rr * std::cos(phi), rr * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u1))};
            wi = r.frame.to_world(lw);
            pdf_light = lw.z / kPi;
            ok = pdf_light > 0;
            Le = scene.environment;
            tmax = std::numeric_limits<float>::infinity();
        }
        pgloss_vec3 wil = r.frame.to_local(wi);
        if (ok && wil.z > 0) {
            r.nee = true;
            r.wil = wil, r.wi = wi, r.Le = Le, r.pdf_light = pdf_light / nl, r.tmax = tmax;
        }
    }

    // Stage 3: the next-event estimate from the lobe's f and pdf at r.wil (left in
    // r.shadow_c for its shadow ray), and the path continued by the BRDF sample (s_*).
    // Returns false when the path ends (the shadow ray, if any, is still traced).
    bool shade_end(PathState &ps, ShadeRec &r, glm::vec3 f, float pdf_brdf, pgloss_vec3 s_wi,
                   float s_pdf, glm::vec3 s_weight) const {
        if (r.nee) {
            const float w = r.strat == Prev::MIS ? power_heuristic(r.pdf_light, pdf_brdf) : 1.0f;
            glm::vec3 c = ps.beta * f * r.Le * (r.wil.z * w / r.pdf_light);
            if (max3(c) > 0) {
                r.shadow = true;
                r.shadow_c = c;
            }
        }
        // Continue the path by BRDF sampling.
        if (!(s_pdf > 0)) return false;
        ps.beta *= s_weight;
        ps.prev = r.strat;
        ps.prev_pdf = s_pdf;
        ps.prev_n = r.n;
        ps.o = r.p;
        ps.d = glm::normalize(r.frame.to_world(s_wi));
        if (ps.depth >= 3) {  // Russian roulette
            float q = std::min(0.95f, max3(ps.beta));
            if (!(ps.smp.get1() < q)) return false;
            ps.beta *= 1.0f / q;
        }
        ++ps.depth;
        return true;
    }

    // Stage 2: the lobe calls of the step's shading points, batched per material
    // (pgloss_eval_pdf_batch for the next-event estimates, pgloss_sample_batch for the BRDF
    // samples: the library's vector loops, on the running CPU's best instruction set), then
    // stage 3 for each path.
    void shade_batched(PathState *paths, Wavefront &wf, size_t na) const {
        const size_t nm = scene.materials.size();
        wf.count.assign(nm + 1, 0);
        for (size_t i = 0; i < na; ++i)
            if (wf.recs[i].mat >= 0) ++wf.count[size_t(wf.recs[i].mat) + 1];
        for (size_t m = 0; m < nm; ++m) wf.count[m + 1] += wf.count[m];  // bucket starts
        const size_t total = wf.count[nm];
        wf.order.resize(total);
        {
            std::vector<std::uint32_t> &pos = wf.next;  // reused as the buckets' cursors
            pos.assign(wf.count.begin(), wf.count.end() - 1);
            for (size_t i = 0; i < na; ++i)
                if (wf.recs[i].mat >= 0) wf.order[pos[size_t(wf.recs[i].mat)]++] = std::uint32_t(i);
        }
        // Sized once: a vector resized to each step's count would zero what it grows by every step.
        if (wf.soa.size() < size_t(NLANES) * total) wf.soa.resize(size_t(NLANES) * kWavefront);
        float *v[NLANES];
        for (int l = 0; l < NLANES; ++l) v[l] = wf.soa.data() + size_t(l) * total;
        for (size_t j = 0; j < total; ++j) {
            const ShadeRec &r = wf.recs[wf.order[j]];
            v[WOX][j] = r.wo.x, v[WOY][j] = r.wo.y, v[WOZ][j] = r.wo.z;
            v[WIX][j] = r.wil.x, v[WIY][j] = r.wil.y, v[WIZ][j] = r.wil.z;
            v[U0][j] = r.u[0], v[U1][j] = r.u[1], v[U2][j] = r.u[2];
        }
        for (size_t m = 0; m < nm; ++m) {
            const size_t b = wf.count[m], n = wf.count[m + 1] - b;
            if (n == 0) continue;
            const pgloss_material &mat = scene.materials[m].ward;
            constexpr size_t F = sizeof(float);
            const pgloss_strided3 wo = pgloss_strided3_soa(v[WOX] + b, v[WOY] + b, v[WOZ] + b, F);
            const pgloss_strided3 wi = pgloss_strided3_soa(v[WIX] + b, v[WIY] + b, v[WIZ] + b, F);
            // Statuses are not needed: the directions are unit and the random numbers finite
            // by construction, and an invalid element gets zeros (its path ends).
            (void)pgloss_eval_pdf_batch(nullptr, &mat, nullptr, mat.lobes, n, wo, wi,
                                        pgloss_strided3_out_soa(v[FR] + b, v[FG] + b, v[FB] + b, F),
                                        pgloss_strided_out_of(v[FPDF] + b, F), nullptr);
            (void)pgloss_sample_batch(nullptr, &mat, nullptr, mat.lobes, n, wo,
                                      pgloss_strided3_soa(v[U0] + b, v[U1] + b, v[U2] + b, F),
                                      pgloss_strided3_out_soa(v[SX] + b, v[SY] + b, v[SZ] + b, F),
                                      pgloss_strided_out_of(v[SPDF] + b, F),
                                      pgloss_strided3_out_soa(v[SR] + b, v[SG] + b, v[SB] + b, F), nullptr, nullptr);
        }
        for (size_t j = 0; j < total; ++j) {
            const std::uint32_t i = wf.order[j];
            PathState &ps = paths[wf.active[i]];
            const bool alive = shade_end(ps, wf.recs[i], glm::vec3(v[FR][j], v[FG][j], v[FB][j]), v[FPDF][j],
                                         pgloss_vec3{v[SX][j], v[SY][j], v[SZ][j]}, v[SPDF][j],
                                         glm::vec3(v[SR][j], v[SG][j], v[SB][j]));
            wf.recs[i].mat = alive ? 0 : -1;  // now: whether the path goes on
        }
    }

    // Traces the paths of a wavefront to their ends, in lock step: each step intersects the
    // live paths' rays 16 at a time (rtcIntersect16), shades every hit, then traces the
    // step's shadow rays 16 at a time (rtcOccluded16). Packets of 16 amortise Embree's
    // per-call cost and traverse the small BVH for 16 rays at once. Each path keeps its own
    // random stream and adds to its own L in the order of the scalar recursion, so the result
    // does not depend on how the paths are grouped into packets.
    void trace_wavefront(PathState *paths, size_t n, Wavefront &wf, const RenderSettings &set,
                         std::uint64_t &rays) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        wf.active.resize(n);
        for (size_t i = 0; i < n; ++i) wf.active[i] = std::uint32_t(i);
        while (!wf.active.empty()) {
            const size_t na = wf.active.size();
            wf.hits.resize(na);
            const bool small = small_scene && !set.embree_always;
            const bool hyb = hybrid && !set.embree_always;  // lane loops, then Embree for the meshes
            wf.embree.clear();
            for (size_t b = 0; (small || hyb) && b < na; b += 16) {
                const size_t cnt = std::min<size_t>(16, na - b);
                Packet pk;
                for (size_t j = 0; j < 16; ++j) {
                    const PathState &ps = paths[wf.active[b + std::min(j, cnt - 1)]];
                    pk.set(j, ps.o, ps.d, std::numeric_limits<float>::infinity());
                }
                small_intersect<false>(pk);
                bool meets[16];
                if (hyb) meets_meshes(pk, meets);
                for (size_t j = 0; j < cnt; ++j) {
                    const PathState &ps = paths[wf.active[b + j]];
                    wf.hits[b + j] = make_small_hit(ps.o, ps.d, pk.prim[j], pk.tfar[j]);
                    if (hyb && meets[j]) wf.embree.push_back(std::uint32_t(b + j));
                }
            }
            if (hyb) {  // the meshes, for the rays whose segment to the lane loops' hit can meet them
                if (packet16) mesh_closest<RTCRayHit16, 16>(paths, wf, ctx);
                else mesh_closest<RTCRayHit8, 8>(paths, wf, ctx);
            }
            for (size_t b = 0; !small && !hyb && b < na; b += 16) {
                const size_t cnt = std::min<size_t>(16, na - b);
                alignas(64) int valid[16];
                alignas(64) RTCRayHit16 rh;
                int sphere_idx[16];
                for (size_t j = 0; j < 16; ++j) {
                    const PathState &ps = paths[wf.active[b + std::min(j, cnt - 1)]];
                    valid[j] = j < cnt ? -1 : 0;
                    sphere_idx[j] = -1;
                    set_ray(rh.ray, j, ps.o, ps.d, sphere_hit(ps.o, ps.d, std::numeric_limits<float>::infinity(), sphere_idx[j]));
                    rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
                    rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
                }
                rtcIntersect16(valid, rtc, &ctx, &rh);
                for (size_t j = 0; j < cnt; ++j) {
                    const PathState &ps = paths[wf.active[b + j]];
                    wf.hits[b + j] = make_hit(ps.o, ps.d, rh.hit.geomID[j], rh.ray.tfar[j],
                                              glm::vec3(rh.hit.Ng_x[j], rh.hit.Ng_y[j], rh.hit.Ng_z[j]), sphere_idx[j]);
                }
            }
            rays += na;
            wf.recs.resize(na);
            for (size_t i = 0; i < na; ++i) shade_begin(paths[wf.active[i]], wf.hits[i], set, wf.recs[i]);
            for (size_t i = 0; i < na; ++i)
                if (wf.recs[i].mat >= 0 && wf.recs[i].li >= 0) light_sample(wf.recs[i], set.solid_angle_lights);
            shade_batched(paths, wf, na);
            wf.next.clear();
            wf.shadows.clear();
            for (size_t i = 0; i < na; ++i) {  // in the wavefront's order: packets as before
                const ShadeRec &r = wf.recs[i];
                if (r.shadow) wf.shadows.push_back({r.p, r.wi, r.shadow_c, r.tmax, wf.active[i]});
                if (wf.recs[i].mat >= 0) wf.next.push_back(wf.active[i]);
            }
            const size_t ns = wf.shadows.size();
            wf.embree.clear();  // hybrid: the shadow rays that the lane loops let through and can meet a mesh
            for (size_t b = 0; (small || hyb) && b < ns; b += 16) {
                const size_t cnt = std::min<size_t>(16, ns - b);
                Packet pk;
                for (size_t j = 0; j < 16; ++j) {
                    const ShadowRay &sr = wf.shadows[b + std::min(j, cnt - 1)];
                    pk.set(j, sr.o, sr.d, sr.tmax);
                }
                small_intersect<true>(pk);
                bool meets[16];
                if (hyb) meets_meshes(pk, meets);
                for (size_t j = 0; j < cnt; ++j)
                    if (pk.prim[j] == -1) {
                        if (hyb && meets[j]) wf.embree.push_back(std::uint32_t(b + j));
                        else paths[wf.shadows[b + j].path].L += wf.shadows[b + j].c;
                    }
            }
            if (packet16) mesh_occluded<RTCRay16, 16>(paths, wf, ctx);
            else mesh_occluded<RTCRay8, 8>(paths, wf, ctx);
            for (size_t b = 0; !small && !hyb && b < ns; b += 16) {
                const size_t cnt = std::min<size_t>(16, ns - b);
                alignas(64) int valid[16];
                alignas(64) RTCRay16 r;
                for (size_t j = 0; j < 16; ++j) {
                    const ShadowRay &sr = wf.shadows[b + std::min(j, cnt - 1)];
                    int si = -1;
                    const bool by_sphere = j < cnt && sphere_hit(sr.o, sr.d, sr.tmax, si) < sr.tmax;
                    valid[j] = j < cnt && !by_sphere ? -1 : 0;
                    set_ray(r, j, sr.o, sr.d, by_sphere ? -std::numeric_limits<float>::infinity() : sr.tmax);
                }
                rtcOccluded16(valid, rtc, &ctx, &r);
                for (size_t j = 0; j < cnt; ++j)
                    if (!(r.tfar[j] < 0.0f)) paths[wf.shadows[b + j].path].L += wf.shadows[b + j].c;
            }
            rays += ns;
            std::swap(wf.active, wf.next);
        }
    }
};

Renderer::Renderer(const Scene &scene) : impl_(std::make_unique<Impl>(scene)) {}
Renderer::~Renderer() = default;

Image Renderer::render(const RenderSettings &s, const RenderOptions &opt, RenderStats *stats_out) const {
    if (s.embree_always) impl_->need_all();  // before the clocks start: building is not rendering
    using clock = std::chrono::steady_clock;
    const int w = s.width, h = s.height;
    const int tile = 16;
    const int tiles_x = (w + tile - 1) / tile, tiles_y = (h + tile - 1) / tile;
    const int ntiles = tiles_x * tiles_y;
    int nthreads = opt.threads > 0 ? opt.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // Samples per pixel each tile holds (equal unless cancelled); a tile's next pass waits for it.
    std::vector<std::atomic<int>> tile_spp(static_cast<size_t>(ntiles));
    for (auto &t : tile_spp) t.store(0, std::memory_order_relaxed);
    std::vector<double> sum(size_t(w) * size_t(h) * 3, 0.0);
    std::vector<double> sum2(opt.variance ? sum.size() : 0, 0.0);
    Image img;
    img.width = w, img.height = h;
    img.rgb.assign(sum.size(), 0.0f);
    RenderStats st;
    auto cpu_now = [] {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
    };
    const double cpu0 = cpu_now();
    auto t0 = clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - t0).count(); };
    const bool tty = opt.progress && isatty(2);
    std::atomic<std::uint64_t> rays{0}, done_samples{0}, nonfinite{0};
    std::atomic<bool> failed{false};
    std::mutex error_mutex;
    std::exception_ptr error;      // the first exception of a worker
    std::string first_nonfinite;   // where the first non-finite sample was
    auto cancelled = [&] { return failed.load() || (opt.cancel && opt.cancel->load()); };
    double last_print = -1;
    std::mutex print_mutex;

    auto print_progress = [&](bool final) {
        double t = elapsed();
        std::lock_guard<std::mutex> lock(print_mutex);
        if (!final && t - last_print < 0.25) return;
        last_print = t;
        double frac_spp = double(done_samples.load()) / (double(w) * h * s.spp);
        double frac = frac_spp;
        if (s.time_budget_s > 0) frac = std::max(frac, std::min(1.0, t / s.time_budget_s));
        frac = std::min(1.0, frac);
        double eta = frac > 0 ? t * (1 - frac) / frac : 0;
        int bar = int(frac * 30);
        std::fprintf(stderr, "\r%-18.18s [%.*s%*s] %3d%% %6.1fs ETA %5.1fs %6.2f Mrays/s%s",
                     opt.label.c_str(), bar, "##############################", 30 - bar, "", int(frac * 100),
                     t, final ? 0.0 : eta, t > 0 ? double(rays.load()) / t * 1e-6 : 0.0, final ? "\n" : "");
        std::fflush(stderr);
    };

    const Pinhole pinhole(impl_->scene.camera, w, h);
    std::vector<Wavefront> scratch(static_cast<size_t>(nthreads));  // per worker, kept across passes and tiles
    // Samples [s0, s1) of tile ti (a pass of it): traced, then added to its pixels' sums in
    // sample order. The tile's earlier passes are done (their sums are in).
    auto render_tile = [&](int id, int ti, int s0, int s1, std::uint64_t &local_rays) {
        int x0 = (ti % tiles_x) * tile, y0 = (ti / tiles_x) * tile;
        int x1 = std::min(w, x0 + tile), y1 = std::min(h, y0 + tile);
        // The tile's paths of this pass, pixel by pixel, each pixel's in sample order.
        Wavefront &wf = scratch[size_t(id)];
        auto &paths = wf.paths;
        paths.resize(size_t(x1 - x0) * size_t(y1 - y0) * size_t(s1 - s0));
        size_t pi = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::uint64_t pix = std::uint64_t(y) * std::uint64_t(w) + std::uint64_t(x);
                for (int k = s0; k < s1; ++k) {
                    PathState &ps = paths[pi++];
                    ps = PathState{};
                    ps.smp = PathSampler(s.sampler, s.seed, pix, std::uint64_t(k));
                    const glm::vec2 j = ps.smp.get2();
                    const float jx = j.x, jy = j.y;
                    ps.o = impl_->scene.camera.position;
                    ps.d = pinhole.dir(float(x) + jx, float(y) + jy);
                }
            }
        for (size_t c0 = 0; c0 < paths.size(); c0 += kWavefront)
            impl_->trace_wavefront(&paths[c0], std::min(kWavefront, paths.size() - c0), wf, s, local_rays);
        pi = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                std::uint64_t pix = std::uint64_t(y) * std::uint64_t(w) + std::uint64_t(x);
                double *acc = &sum[3 * pix];
                double *acc2 = sum2.empty() ? nullptr : &sum2[3 * pix];
                for (int k = s0; k < s1; ++k) {
                    glm::vec3 c = paths[pi++].L;
                    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z))) {
                        // Never dropped quietly: counted, and the render fails after the pass.
                        if (nonfinite.fetch_add(1) == 0) {
                            std::ostringstream o;
                            o << "pixel (" << x << ", " << y << ") sample " << k << " = (" << c.x << ", "
                              << c.y << ", " << c.z << ")";
                            std::lock_guard<std::mutex> lock(error_mutex);
                            first_nonfinite = o.str();
                        }
                        failed = true;
                        continue;
                    }
                    acc[0] += c.x, acc[1] += c.y, acc[2] += c.z;
                    if (acc2) acc2[0] += double(c.x) * c.x, acc2[1] += double(c.y) * c.y, acc2[2] += double(c.z) * c.z;
                }
            }
        rays += local_rays;
        local_rays = 0;
        done_samples += std::uint64_t(x1 - x0) * std::uint64_t(y1 - y0) * std::uint64_t(s1 - s0);
        tile_spp[size_t(ti)].store(s1, std::memory_order_release);  // the sums above are in
        if (id == 0 && tty) print_progress(false);
    };
    // Runs loop(id) on nthreads threads (this one is 0), each with denormals off; the first
    // exception of any is kept in `error` and stops the others.
    auto run_workers = [&](const std::function<void(int, std::uint64_t &)> &loop) {
        auto worker = [&](int id) noexcept {
            DenormalsOff denormals_off;  // in every worker, so every sample sees the same mode
            try {
                std::uint64_t local_rays = 0;
                loop(id, local_rays);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                failed = true;
            }
        };
        std::vector<std::thread> pool;
        JoinAll join{pool};
        for (int i = 1; i < nthreads; ++i) {
            try {
                pool.emplace_back(worker, i);
            } catch (const std::system_error &e) {  // out of threads or memory: go on with fewer
                std::fprintf(stderr, "pgloss-tracer: could not start thread %d of %d (%s); rendering with %d\n",
                             i + 1, nthreads, e.what(), i);
                nthreads = i;
                break;
            }
        }
        worker(0);
    };
    auto check_failures = [&] {
        if (error) std::rethrow_exception(error);
        if (nonfinite > 0)
            throw std::runtime_error(std::to_string(nonfinite.load()) + " samples were not finite (first: " +
                                     first_nonfinite +
                                     "); the scene's numbers overflow float somewhere, nothing was written");
    };
    // The passes: 1, 2, 4, … samples per pixel, at most opt.max_pass_spp (a time budget
    // shortens them to what fits).
    auto next_pass_spp = [&](int pass_spp, int spp_done) {
        return std::max(1, std::min({pass_spp, s.spp - spp_done, opt.max_pass_spp}));
    };
    if (s.time_budget_s <= 0 && !opt.on_pass) {
        // A fixed sample count and no image between passes: one pool of workers takes (pass,
        // tile) in pass order with no barrier between passes (a worker that would wait at one
        // for the slowest tile, or a thread that is descheduled, holds nothing up); a tile's
        // pass waits only for that tile's previous pass, which is long done unless the image
        // has fewer tiles than there are threads. The passes and tiles are those of the
        // progressive loop below, so the image is the same.
        std::vector<std::pair<int, int>> passes;
        for (int done = 0, n = 1; done < s.spp; n = std::min(2 * n, std::max(1, opt.max_pass_spp))) {
            const int k = next_pass_spp(n, done);
            passes.emplace_back(done, done + k);
            done += k;
        }
        const std::uint64_t items = std::uint64_t(passes.size()) * std::uint64_t(ntiles);
        std::atomic<std::uint64_t> next_item{0};
        run_workers([&](int id, std::uint64_t &local_rays) {
            for (;;) {
                if (cancelled()) return;  // whole tiles only: each pixel's mean stays over its own samples
                const std::uint64_t k = next_item.fetch_add(1);
                if (k >= items) return;
                const auto [s0, s1] = passes[size_t(k / std::uint64_t(ntiles))];
                const int ti = int(k % std::uint64_t(ntiles));
                while (tile_spp[size_t(ti)].load(std::memory_order_acquire) < s0) {
                    if (cancelled()) return;
                    std::this_thread::yield();
                }
                render_tile(id, ti, s0, s1, local_rays);
            }
        });
        check_failures();
    }
    int spp_done = 0;
    int pass_spp = 1;
    while ((s.time_budget_s > 0 || opt.on_pass) && spp_done < s.spp && !cancelled()) {
        double t = elapsed();
        if (s.time_budget_s > 0 && spp_done > 0) {
            if (t >= s.time_budget_s) break;
            double per_spp = t / spp_done;  // fit the next pass into what is left of the budget
            int fit = int((s.time_budget_s - t) / std::max(per_spp, 1e-9));
            if (fit < 1) break;
            pass_spp = std::min(pass_spp, fit);
        }
        pass_spp = next_pass_spp(pass_spp, spp_done);
        const int s0 = spp_done, s1 = spp_done + pass_spp;
        std::atomic<int> next_tile{0};
        run_workers([&](int id, std::uint64_t &local_rays) {
            for (;;) {
                if (cancelled()) return;  // whole tiles only: each pixel's mean stays over its own samples
                int ti = next_tile.fetch_add(1);
                if (ti >= ntiles) return;
                render_tile(id, ti, s0, s1, local_rays);
            }
        });
        check_failures();
        if (cancelled()) break;
        spp_done = s1;
        pass_spp *= 2;
        st.seconds = elapsed();
        st.rays = rays.load();
        st.samples = std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(spp_done);
        st.spp = spp_done;
        if (opt.on_pass) {
            for (size_t i = 0; i < sum.size(); ++i) img.rgb[i] = float(sum[i] / spp_done);
            if (!opt.on_pass(img, st)) break;
        }
    }
    // Samples per pixel: the tile's own count (all equal unless the render was cancelled mid-pass).
    auto pixel_spp = [&](size_t i) {
        size_t pix = i / 3, x = pix % size_t(w), y = pix / size_t(w);
        return tile_spp[(y / tile) * size_t(tiles_x) + x / tile].load(std::memory_order_relaxed);
    };
    for (size_t i = 0; i < sum.size(); ++i) {
        int n = pixel_spp(i);
        img.rgb[i] = n > 0 ? float(sum[i] / n) : 0.0f;
    }
    if (opt.variance) {
        Image &v = *opt.variance;
        v.width = w, v.height = h;
        v.rgb.assign(sum.size(), 0.0f);
        for (size_t i = 0; i < sum.size(); ++i) {
            double n = pixel_spp(i);
            if (n < 2) continue;
            double m = sum[i] / n;
            v.rgb[i] = float(std::max(0.0, (sum2[i] / n - m * m)) / (n - 1));
        }
    }
    st.spp = s.spp;
    for (const auto &t : tile_spp) st.spp = std::min(st.spp, t.load(std::memory_order_relaxed));
    st.interrupted = opt.cancel && opt.cancel->load();
    st.samples = 0;
    for (int ti = 0; ti < ntiles; ++ti) {
        int x0 = (ti % tiles_x) * tile, y0 = (ti / tiles_x) * tile;
        st.samples += std::uint64_t(std::min(w, x0 + tile) - x0) * std::uint64_t(std::min(h, y0 + tile) - y0) *
                      std::uint64_t(tile_spp[size_t(ti)].load(std::memory_order_relaxed));
    }
    st.rays = rays.load();
    st.seconds = elapsed();
    st.cpu_seconds = cpu_now() - cpu0;
    if (tty) print_progress(true);
    if (stats_out) *stats_out = st;
    return img;
}

std::vector<int> Renderer::regions(int w, int h) const {
    const Impl &I = *impl_;
    std::vector<int> out(size_t(w) * size_t(h), REGION_NONE);
    const Pinhole pinhole(I.scene.camera, w, h);
    std::uint64_t rays = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 o = I.scene.camera.position;
            glm::vec3 d = pinhole.dir(float(x) + 0.5f, float(y) + 0.5f);
            Hit hit = I.intersect(o, d, rays);
            int r = REGION_NONE;
            if (hit.hit) {
                if (hit.ref.kind == GeomKind::LIGHT) r = REGION_LIGHT;
                else if (hit.ref.kind == GeomKind::SPHERE) r = REGION_SPHERE;
                else if (I.scene.meshes[size_t(hit.ref.index)].label == "box") {
                    glm::vec3 n = glm::dot(hit.n, d) < 0 ? hit.n : -hit.n;
                    r = n.y > 0.5f ? REGION_FLOOR : n.y < -0.5f ? REGION_CEILING : REGION_WALL;
                } else r = REGION_OTHER;
            }
            if (r == REGION_FLOOR && !I.scene.lights.empty()) {  // fraction of the light visible
                const AreaLight &l = I.scene.lights[0];
                glm::vec3 p = hit.p + I.eps * glm::vec3(0, 1, 0);
                int visible = 0, n = 8;
                for (int i = 0; i < n; ++i)
                    for (int j = 0; j < n; ++j) {
                        glm::vec3 yl = l.corner + (float(i) + 0.5f) / float(n) * l.edge1 + (float(j) + 0.5f) / float(n) * l.edge2;
                        glm::vec3 dv = yl - p;
                        float dist = glm::length(dv);
                        visible += I.occluded(p, dv / dist, dist * (1 - 1e-4f), rays) ? 0 : 1;
                    }
                if (visible * 2 < n * n) r = REGION_SHADOW;
            }
            out[size_t(y) * size_t(w) + size_t(x)] = r;
        }
    return out;
}

}  // namespace pgt
