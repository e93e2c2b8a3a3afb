// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// trace.frag.glsl — one progressive pass of a path tracer of the stimulus scene
// (examples/tracer/scenes/stimulus.scene, parsed by scene.js into the uniforms below) in a
// WebGL2 fragment shader. The estimator is examples/tracer/src/render.cpp's `mis` mode:
// next-event estimation on the area light plus BRDF sampling (pgloss_sample), combined with
// the power heuristic (pgloss_eval_pdf) where the surface has a specular lobe, light sampling
// alone on diffuse-only surfaces, Russian roulette after 3 bounces, max_depth from the scene.
// Every BRDF value, pdf and sample of the Ward paint comes from glsl/pgloss.glsl; a tile of
// kind 1 shows the bridge target's BRDF instead (microfacet.glsl, from pgloss_bridge_shading:
// its lobes sampled by their mixture, the light by area, combined as for the paint). render.js
// prepends both files verbatim.
//
// Output: the running sums of this pixel (ping-pong accumulation in RGBA32F targets):
// rgb = Σ radiance, a = Σ luminance² (for the noise estimate of the tests).
//#version and the pgloss.glsl inclusion are prepended by render.js.

uniform sampler2D u_prev;     // sums so far (RGBA32F)
uniform vec2 u_tile_size;     // pixels per view tile
uniform int u_tiles_x;        // tiles per row (1: one view; 3: the match-gloss grid)
uniform int u_sample0;        // index of this pass's first sample
uniform int u_spp;            // samples per pixel in this pass
uniform int u_max_depth;
uniform uint u_seed;

// Camera (scene `camera`): position, basis, tan(fov/2).
uniform vec3 u_cam_pos, u_cam_f, u_cam_r, u_cam_u;
uniform float u_cam_tan;
// Geometry: the box (all faces a 3-D checkerboard of two diffuse materials), the sphere, the light.
uniform vec3 u_box_min, u_box_max;
uniform vec3 u_check_a, u_check_b;  // ρd of the two cells
uniform float u_check_size;
uniform vec3 u_check_offset;
uniform vec3 u_sph_c;
uniform float u_sph_r;
uniform vec3 u_light_corner, u_light_e1, u_light_e2, u_light_radiance;
uniform float u_eps;          // ray offset (render.cpp: 1e-4 × scene extent)
// The sphere's paint, one per tile: physical parameters from the C core (pgloss.wasm).
uniform vec3 u_rho_d[6];
uniform float u_rho_s[6];
uniform float u_alpha[6];
uniform int u_kind[6];        // 0: the Ward paint above; 1: the target's BRDF (u_target)
uniform pgloss_bridge_shading u_target;

layout(location = 0) out vec4 o_sum;

const float PI = 3.14159265358979323846;

// PCG-RXS-M-XS 32 (O'Neill 2014), one stream per (seed, pixel, sample).
uint pcg_next(inout uint s) {
    s = s * 747796405u + 2891336453u;
    uint w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return (w >> 22u) ^ w;
}
uint hash_u(uint x) { uint s = x; return pcg_next(s); }
float rnd(inout uint s) { return float(pcg_next(s) >> 8u) * (1.0 / 16777216.0); }  // [0, 1)

// Orthonormal basis around n (Duff et al. 2017), as render.cpp's Frame.
void frame_of(vec3 n, out vec3 t, out vec3 b) {
    float sgn = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sgn + n.z);
    float bb = n.x * n.y * a;
    t = vec3(1.0 + sgn * n.x * n.x * a, sgn * bb, -sgn * n.x);
    b = vec3(bb, sgn + n.y * n.y * a, -n.y);
}

float power_heuristic(float a, float b) {
    float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;
}
float max3(vec3 v) { return max(v.x, max(v.y, v.z)); }

const int HIT_NONE = 0, HIT_BOX = 1, HIT_SPHERE = 2, HIT_LIGHT = 3;

float hit_sphere(vec3 o, vec3 d) {  // nearest t > 0, or -1
    vec3 oc = o - u_sph_c;
    float a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - u_sph_r * u_sph_r;
    float disc = b * b - a * c;
    if (disc < 0.0) return -1.0;
    float s = sqrt(disc);
    float t0 = (-b - s) / a, t1 = (-b + s) / a;
    return t0 > 0.0 ? t0 : (t1 > 0.0 ? t1 : -1.0);
}

float hit_light(vec3 o, vec3 d) {  // the parallelogram, either side
    vec3 n = cross(u_light_e1, u_light_e2);
    float den = dot(n, d);
    if (abs(den) < 1e-12) return -1.0;
    float t = dot(n, u_light_corner - o) / den;
    if (!(t > 0.0)) return -1.0;
    vec3 q = o + t * d - u_light_corner;
    float s1 = dot(q, u_light_e1) / dot(u_light_e1, u_light_e1);
    float s2 = dot(q, u_light_e2) / dot(u_light_e2, u_light_e2);
    return (s1 >= 0.0 && s1 <= 1.0 && s2 >= 0.0 && s2 <= 1.0) ? t : -1.0;
}

// The box seen from inside (the camera and every path are inside it): the nearest exit.
float hit_box(vec3 o, vec3 d, out vec3 n) {
    vec3 inv = 1.0 / d;
    vec3 t_hi = max((u_box_min - o) * inv, (u_box_max - o) * inv);
    float t = min(t_hi.x, min(t_hi.y, t_hi.z));
    n = t == t_hi.x ? vec3(1, 0, 0) : (t == t_hi.y ? vec3(0, 1, 0) : vec3(0, 0, 1));
    return t;
}

int intersect(vec3 o, vec3 d, out float t, out vec3 n) {
    int kind = HIT_NONE;
    t = 3.0e38;
    vec3 nb;
    float tb = hit_box(o, d, nb);
    if (tb > 0.0 && tb < t) { t = tb; n = nb; kind = HIT_BOX; }
    float ts = hit_sphere(o, d);
    if (ts > 0.0 && ts < t) { t = ts; n = normalize(o + ts * d - u_sph_c); kind = HIT_SPHERE; }
    float tl = hit_light(o, d);
    if (tl > 0.0 && tl < t) { t = tl; n = normalize(cross(u_light_e1, u_light_e2)); kind = HIT_LIGHT; }
    return kind;
}

// Shadow ray: only the sphere can stand between a point in the box and the light.
bool occluded(vec3 o, vec3 d, float tmax) {
    float ts = hit_sphere(o, d);
    return ts > 0.0 && ts < tmax;
}

pgloss_material checker_at(vec3 p) {
    vec3 q = floor((p - u_check_offset) / u_check_size);
    int parity = (int(q.x) + int(q.y) + int(q.z)) & 1;
    pgloss_material m;
    pgloss_material_init(m, pgloss_physical(parity == 1 ? u_check_b : u_check_a, 0.0, 1.0, 1.0, PGLOSS_NORM_WARD));
    return m;
}

vec3 camera_dir(vec2 pix) {  // pix: position in the tile, y down (render.cpp's camera_dir)
    float aspect = u_tile_size.x / u_tile_size.y;
    float sx = (2.0 * pix.x / u_tile_size.x - 1.0) * aspect * u_cam_tan;
    float sy = (1.0 - 2.0 * pix.y / u_tile_size.y) * u_cam_tan;
    return normalize(u_cam_f + sx * u_cam_r + sy * u_cam_u);
}

vec3 trace(vec2 pix, pgloss_material paint, bool target, inout uint rng) {
    vec3 L = vec3(0), beta = vec3(1);
    vec3 o = u_cam_pos, d = camera_dir(pix);
    vec3 ln = normalize(cross(u_light_e1, u_light_e2));
    float larea = length(cross(u_light_e1, u_light_e2));
    bool prev_mis = false, prev_light = false;  // what the previous vertex did (CAMERA: both false)
    float prev_pdf = 0.0;
    for (int depth = 0; depth < 64; ++depth) {
        float t;
        vec3 gn;
        int kind = intersect(o, d, t, gn);
        if (kind == HIT_NONE) break;
        if (kind == HIT_LIGHT) {
            float cos_l = -dot(ln, d);
            if (cos_l > 0.0 && !prev_light) {
                float w = 1.0;
                if (prev_mis) w = power_heuristic(prev_pdf, t * t / (larea * cos_l));
                L += beta * u_light_radiance * w;
            }
            break;  // lights do not reflect
        }
        if (depth + 1 > u_max_depth) break;
        vec3 hp = o + t * d;
        pgloss_material m;  // (ESSL has no ?: on structs)
        if (kind == HIT_SPHERE) m = paint; else m = checker_at(hp);
        bool tgt = target && kind == HIT_SPHERE;
        if (!tgt && m.lobes == PGLOSS_LOBE_NONE) break;
        vec3 n = dot(gn, d) < 0.0 ? gn : -gn;  // two-sided: face the viewer
        vec3 ft, fb;
        frame_of(n, ft, fb);
        vec3 wo = vec3(dot(-d, ft), dot(-d, fb), dot(-d, n));
        vec3 p = hp + u_eps * n;
        bool mis = tgt || (m.lobes & PGLOSS_LOBE_SPECULAR) != 0u;

        // Next-event estimation on the light (uniform over its area).
        float u1 = rnd(rng), u2 = rnd(rng);
        vec3 y = u_light_corner + u1 * u_light_e1 + u2 * u_light_e2;
        vec3 dv = y - p;
        float dist2 = dot(dv, dv), dist = sqrt(dist2);
        vec3 wi = dv / dist;
        float cos_l = -dot(ln, wi);
        vec3 wil = vec3(dot(wi, ft), dot(wi, fb), dot(wi, n));
        if (cos_l > 0.0 && wil.z > 0.0) {
            float pdf_light = dist2 / (larea * cos_l);
            vec3 f;
            float pdf_brdf = 0.0, w = 1.0;
            if (tgt) {
                f = pgloss_bridge_shading_eval(u_target, wo, wil);
                pdf_brdf = pgloss_bridge_shading_pdf(u_target, wo, wil);
                w = power_heuristic(pdf_light, pdf_brdf);
            } else if (mis) {
                pgloss_eval_pdf(m, wo, wil, m.lobes, f, pdf_brdf);
                w = power_heuristic(pdf_light, pdf_brdf);
            } else {
                pgloss_eval(m, wo, wil, m.lobes, f);
            }
            vec3 c = beta * f * u_light_radiance * (wil.z * w / pdf_light);
            if (max3(c) > 0.0 && !occluded(p, wi, dist * (1.0 - 1e-4))) L += c;
        }

        // Continue by BRDF sampling.
        vec3 u = vec3(rnd(rng), rnd(rng), rnd(rng));
        vec3 wi_s, weight;
        float pdf_s;
        if (tgt) {
            weight = pgloss_bridge_shading_sample(u_target, wo, u, wi_s, pdf_s);
        } else {
            pgloss_sample_record rec;
            pgloss_sample(m, wo, u, m.lobes, rec);
            wi_s = rec.wi; weight = rec.weight; pdf_s = rec.pdf;
        }
        if (!(pdf_s > 0.0)) break;
        beta *= weight;
        prev_mis = mis;
        prev_light = !mis;
        prev_pdf = pdf_s;
        o = p;
        d = normalize(wi_s.x * ft + wi_s.y * fb + wi_s.z * n);
        if (depth >= 3) {  // Russian roulette
            float q = min(0.95, max3(beta));
            if (!(rnd(rng) < q)) break;
            beta /= q;
        }
    }
    return L;
}

void main() {
    ivec2 ip = ivec2(gl_FragCoord.xy);
    vec4 sum = texelFetch(u_prev, ip, 0);
    // Tile (view) of this pixel, and the pixel position inside it with y down.
    vec2 frag = gl_FragCoord.xy - 0.5;
    vec2 canvas = vec2(textureSize(u_prev, 0));
    vec2 from_top = vec2(frag.x, canvas.y - 1.0 - frag.y);
    ivec2 tile = ivec2(floor(from_top / u_tile_size));
    vec2 in_tile = from_top - vec2(tile) * u_tile_size;
    int k = clamp(tile.y * u_tiles_x + tile.x, 0, 5);
    pgloss_material paint;
    bool target = u_kind[k] == 1;
    // A paint the core refuses (negative ρ, α <= 0, not finite) leaves its tile black: its
    // material would be black (pgloss_material_init), which would pass for a render of a black
    // paint in a lit room. (A target tile is set only from a shading model the core accepted.)
    if (pgloss_material_init(paint, pgloss_physical(u_rho_d[k], u_rho_s[k], u_alpha[k], u_alpha[k], PGLOSS_NORM_WARD)) < 0 && !target) {
        o_sum = vec4(0.0);
        return;
    }

    uint pix = uint(ip.y) * 65536u + uint(ip.x);
    for (int s = 0; s < u_spp; ++s) {
        uint rng = hash_u(hash_u(hash_u(u_seed) ^ pix) ^ uint(u_sample0 + s));
        vec2 jitter = vec2(rnd(rng), rnd(rng));
        vec3 c = trace(in_tile + jitter, paint, target, rng);
        if (any(isnan(c)) || any(isinf(c))) c = vec3(0);
        float Y = dot(c, vec3(0.2126, 0.7152, 0.0722));
        sum += vec4(c, Y * Y);
    }
    o_sum = sum;
}
