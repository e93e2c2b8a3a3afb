// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// microfacet.glsl — the specular lobe of the gloss bridge's target models in GLSL (ES 3.00 and
// 3.30): f = D G F / (4 μi μo), the models of libpgloss/src/microfacet_d.h (docs/bridge.md cites
// each target's source):
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
