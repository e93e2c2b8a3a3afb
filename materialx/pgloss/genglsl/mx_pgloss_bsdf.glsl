// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// <pgloss_bsdf> for MaterialX's genglsl: eq. 2 through glsl/pgloss.glsl (the GLSL port of
// libpgloss; nothing of the model is re-implemented here).
#include "pbrlib/genglsl/lib/mx_closure_type.glsl"
#include "pbrlib/genglsl/lib/mx_microfacet_specular.glsl"
#include "../../../glsl/pgloss.glsl"

// Direct light: pgloss_eval in the shading frame of N, times cos θi. Environment light (an
// approximation for previews): ρd times the environment irradiance, plus ρs times MaterialX's
// prefiltered GGX radiance at α without Fresnel. Invalid parameters (status < 0) give black,
// as the C core's material does.
void mx_pgloss_bsdf(ClosureData closureData, float weight, vec3 rho_d, float rho_s, float alpha,
                    int normalization, vec3 N, inout BSDF bsdf)
{
    bsdf.throughput = vec3(0.0);
    if (weight < M_FLOAT_EPS)
        return;
    vec3 V = closureData.V;
    N = mx_forward_facing_normal(N, V);
    pgloss_material m;
    if (pgloss_material_init(m, pgloss_physical(rho_d, rho_s, alpha, alpha, normalization)) < 0)
        return;
    if (closureData.closureType == CLOSURE_TYPE_REFLECTION)
    {
        mat3 frame = mx_orthonormal_basis(N);   // columns: tangent, bitangent, normal
        vec3 wo = V * frame;
        vec3 wi = closureData.L * frame;
        vec3 f;
        pgloss_eval(m, wo, wi, PGLOSS_LOBE_ALL, f);
        bsdf.response = f * max(wi.z, 0.0) * closureData.occlusion * weight;
    }
    else if (closureData.closureType == CLOSURE_TYPE_INDIRECT)
    {
        FresnelData fd = mx_init_fresnel_schlick(vec3(1.0), vec3(1.0), vec3(1.0), 5.0, 0.0, 1.5);
        vec3 X = mx_orthonormal_basis(N)[0];
        vec3 Ls = mx_environment_radiance(N, V, X, vec2(max(m.alpha_x, 1e-4)), 0, fd);
        bsdf.response = (m.rho_d * mx_environment_irradiance(N) + m.rho_s * Ls) * weight;
    }
}
