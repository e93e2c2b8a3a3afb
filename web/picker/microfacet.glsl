// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// microfacet.glsl — the gloss bridge's target models in GLSL (ES 3.00 and 3.30): the specular
// lobe f = D G F / (4 μi μo) of libpgloss/src/microfacet_d.h (docs/bridge.md cites each target's
// source), and below it each target's whole BRDF as pgloss/bridge_model.h defines it, with its
// importance sampling, for the picker's tracer:
//   PGLOSS_MF_PRINCIPLED  GGX, height-correlated Smith G (Cycles: glTF, Blender Principled)
//   PGLOSS_MF_MATERIALX   GGX, height-correlated Smith G (MaterialX: OpenPBR, Standard Surface)
//   PGLOSS_MF_RP_GGX      GGX, separable Smith G (Mitsuba 3 roughplastic, ggx)
//   PGLOSS_MF_RP_BECKMANN Beckmann, Mitsuba's rational G1 (roughplastic, beckmann)
// F is the unpolarised Fresnel reflectance of the dielectric of relative index η at the angle
// between the view and the half vector; η = (1 + √F0)/(1 − √F0) (pgloss_mf_eta_from_f0).
// Unit directions in the local frame (normal +z), both pointing away from the surface.
//
// In float, tan²θ is formed from a direction's components ((x² + y²)/z²), not from cos θ as the
// C core does in double: 1 − cos² would cancel near the normal and the mirror direction.

const int PGLOSS_MF_PRINCIPLED = 0;
const int PGLOSS_MF_MATERIALX = 1;
const int PGLOSS_MF_RP_GGX = 2;
const int PGLOSS_MF_RP_BECKMANN = 3;
const float PGLOSS_MF_PI = 3.14159265358979323846;

// Unpolarised Fresnel reflectance of an interface of relative index eta at incidence cosine
// c > 0; 1 past the critical angle (Walter et al. 2007, eq. 22).
float pgloss_mf_fresnel(float c, float eta) {
    float g2 = eta * eta - 1.0 + c * c;
    if (g2 <= 0.0) return 1.0;
    float g = sqrt(g2), a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

float pgloss_mf_eta_from_f0(float f0) {
    float s = sqrt(f0);
    return (1.0 + s) / (1.0 - s);
}

// GGX D at tan²θm t2 (Walter et al. 2007, eq. 33, with 1/cos⁴θm = (1 + tan²θm)²).
float pgloss_ggx_D(float t2, float a) {
    float a2 = a * a, k = a2 + t2;
    return a2 * (1.0 + t2) * (1.0 + t2) / (PGLOSS_MF_PI * k * k);
}
// Smith's Λ of GGX at tan²θ t2 (Heitz 2014, eq. 72).
float pgloss_ggx_lambda(float t2, float a) { return 0.5 * (sqrt(1.0 + a * a * t2) - 1.0); }
// Beckmann D (Walter et al. 2007, eq. 25).
float pgloss_beck_D(float t2, float a) {
    return exp(-t2 / (a * a)) * (1.0 + t2) * (1.0 + t2) / (PGLOSS_MF_PI * a * a);
}
// Mitsuba 3's rational fit of Beckmann's G1 (Walter et al. 2007, eq. 27).
float pgloss_beck_G1(float t2, float a) {
    if (t2 == 0.0) return 1.0;
    float x = 1.0 / (a * sqrt(t2));
    return x >= 1.6 ? 1.0 : (3.535 * x + 2.181 * x * x) / (1.0 + 2.276 * x + 2.577 * x * x);
}

// D G of model m at tan²θi ti2, tan²θo to2, tan²θh t2.
float pgloss_mf_DG(int m, float ti2, float to2, float t2, float a) {
    if (m == PGLOSS_MF_PRINCIPLED || m == PGLOSS_MF_MATERIALX)
        return pgloss_ggx_D(t2, a) / (1.0 + pgloss_ggx_lambda(ti2, a) + pgloss_ggx_lambda(to2, a));
    if (m == PGLOSS_MF_RP_GGX)
        return pgloss_ggx_D(t2, a) / ((1.0 + pgloss_ggx_lambda(ti2, a)) * (1.0 + pgloss_ggx_lambda(to2, a)));
    return pgloss_beck_D(t2, a) * pgloss_beck_G1(ti2, a) * pgloss_beck_G1(to2, a);
}

float pgloss_mf_tan2(vec3 w) { return (w.x * w.x + w.y * w.y) / (w.z * w.z); }

// The specular lobe D G F / (4 μi μo) of model m (1/sr); 0 below the horizon.
float pgloss_mf_specular(int m, float eta, float a, vec3 wo, vec3 wi) {
    if (!(wo.z > 0.0 && wi.z > 0.0)) return 0.0;
    vec3 h = wo + wi;
    float oh = dot(wo, h) * inversesqrt(dot(h, h));
    float dg = pgloss_mf_DG(m, pgloss_mf_tan2(wi), pgloss_mf_tan2(wo), pgloss_mf_tan2(h), a);
    return dg * pgloss_mf_fresnel(oh, eta) / (4.0 * wi.z * wo.z);
}

// ---- a target's whole BRDF (pgloss/bridge_model.h: the C struct's names; eval gives f in RGB) --
// f = spec · specular_factor(μo) + base_color · diffuse_scale · diffuse_factor(μo)
//     [· diffuse_factor(μi) where diffuse_both: Mitsuba roughplastic's t(μi) t(μo)];
// the 64-node tables (Cycles' / MaterialX's energy compensation and base weight, roughplastic's
// transmittance) come from the C core, packed four nodes to a vec4, looked up linearly in μ·63.
struct pgloss_bridge_shading {
    int model;                  // PGLOSS_MF_*
    int diffuse_both;
    float alpha, eta;
    vec3 base_color;
    float diffuse_scale;
    vec4 specular_factor[16];
    vec4 diffuse_factor[16];
};

float pgloss_mf_lerp_spec(in pgloss_bridge_shading t, float mu) {
    float f = clamp(mu, 0.0, 1.0) * 63.0;
    int i = min(int(f), 62);
    float w = f - float(i);
    return mix(t.specular_factor[i >> 2][i & 3], t.specular_factor[(i + 1) >> 2][(i + 1) & 3], w);
}
float pgloss_mf_lerp_diffuse(in pgloss_bridge_shading t, float mu) {
    float f = clamp(mu, 0.0, 1.0) * 63.0;
    int i = min(int(f), 62);
    float w = f - float(i);
    return mix(t.diffuse_factor[i >> 2][i & 3], t.diffuse_factor[(i + 1) >> 2][(i + 1) & 3], w);
}
float pgloss_mf_diffuse(in pgloss_bridge_shading t, vec3 wo, vec3 wi) {
    float d = t.diffuse_scale * pgloss_mf_lerp_diffuse(t, wo.z);
    return t.diffuse_both != 0 ? d * pgloss_mf_lerp_diffuse(t, wi.z) : d;
}

// f (RGB, 1/sr); 0 below the horizon.
vec3 pgloss_bridge_shading_eval(in pgloss_bridge_shading t, vec3 wo, vec3 wi) {
    if (!(wo.z > 0.0 && wi.z > 0.0)) return vec3(0.0);
    float spec = pgloss_mf_specular(t.model, t.eta, t.alpha, wo, wi) * pgloss_mf_lerp_spec(t, wo.z);
    return vec3(spec) + t.base_color * pgloss_mf_diffuse(t, wo, wi);
}

// The probability of sampling the specular lobe: its albedo's estimate F(μo) · specular_factor
// against the diffuse's, at least 1/4 (any value in (0, 1) is unbiased; the floor keeps the
// glossy reflection of the room sampled on a bright base).
float pgloss_mf_spec_prob(in pgloss_bridge_shading t, vec3 wo) {
    float s = pgloss_mf_fresnel(max(wo.z, 1e-4), t.eta) * pgloss_mf_lerp_spec(t, wo.z);
    float d = max(t.base_color.r, max(t.base_color.g, t.base_color.b)) * PGLOSS_MF_PI * t.diffuse_scale *
              pgloss_mf_lerp_diffuse(t, wo.z);
    return s + d > 0.0 ? clamp(s / (s + d), 0.25, 0.95) : 0.5;
}

// pdf (solid angle) of the half vector sampling: GGX's visible normals (Heitz 2018, JCGT 7(4)):
// G1(ωo) D(h) / (4 μo); Beckmann's D(h) cos θh (Walter et al. 2007, eq. 28) / (4 ωo·h).
float pgloss_mf_spec_pdf(in pgloss_bridge_shading t, vec3 wo, vec3 wi) {
    vec3 h = wo + wi;
    float hl2 = dot(h, h);
    if (!(hl2 > 0.0) || wi.z <= 0.0) return 0.0;
    h *= inversesqrt(hl2);
    float oh = dot(wo, h);
    if (oh <= 0.0) return 0.0;
    float t2 = pgloss_mf_tan2(h);
    if (t.model == PGLOSS_MF_RP_BECKMANN) return pgloss_beck_D(t2, t.alpha) * h.z / (4.0 * oh);
    return pgloss_ggx_D(t2, t.alpha) / ((1.0 + pgloss_ggx_lambda(pgloss_mf_tan2(wo), t.alpha)) * 4.0 * wo.z);
}

// The mixture of the specular and the cosine-weighted diffuse strategies (one-sample MIS with the
// balance heuristic: the pdf is the mixture's).
float pgloss_bridge_shading_pdf(in pgloss_bridge_shading t, vec3 wo, vec3 wi) {
    if (!(wo.z > 0.0 && wi.z > 0.0)) return 0.0;
    float ps = pgloss_mf_spec_prob(t, wo);
    return ps * pgloss_mf_spec_pdf(t, wo, wi) + (1.0 - ps) * wi.z / PGLOSS_MF_PI;
}

// A sampled half vector for ωo (u in [0, 1)²).
vec3 pgloss_mf_sample_h(in pgloss_bridge_shading t, vec3 wo, vec2 u) {
    float a = t.alpha, phi = 2.0 * PGLOSS_MF_PI * u.y;
    if (t.model == PGLOSS_MF_RP_BECKMANN) {
        float tan2 = -a * a * log(1.0 - u.x);
        float c = inversesqrt(1.0 + tan2), s = sqrt(max(0.0, 1.0 - c * c));
        return vec3(s * cos(phi), s * sin(phi), c);
    }
    // Visible normals: the view stretched to α 1, a point on the projected hemisphere, back.
    vec3 vh = normalize(vec3(a * wo.x, a * wo.y, wo.z));
    float l2 = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = l2 > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(l2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x), p1 = r * cos(phi), p2 = r * sin(phi), s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(a * nh.x, a * nh.y, max(1e-7, nh.z)));
}

// Samples ωi (u in [0, 1)³; u.z picks the lobe): writes wi and the mixture pdf, returns the
// weight f cos θi / pdf (0 with pdf 0 below the horizon).
vec3 pgloss_bridge_shading_sample(in pgloss_bridge_shading t, vec3 wo, vec3 u, out vec3 wi, out float pdf) {
    pdf = 0.0;
    wi = vec3(0.0, 0.0, 1.0);
    if (!(wo.z > 0.0)) return vec3(0.0);
    if (u.z < pgloss_mf_spec_prob(t, wo)) {
        vec3 h = pgloss_mf_sample_h(t, wo, u.xy);
        wi = 2.0 * dot(wo, h) * h - wo;
    } else {
        float r = sqrt(u.x), phi = 2.0 * PGLOSS_MF_PI * u.y;
        wi = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));
    }
    if (!(wi.z > 0.0)) return vec3(0.0);
    pdf = pgloss_bridge_shading_pdf(t, wo, wi);
    return pdf > 0.0 ? pgloss_bridge_shading_eval(t, wo, wi) * (wi.z / pdf) : vec3(0.0);
}
