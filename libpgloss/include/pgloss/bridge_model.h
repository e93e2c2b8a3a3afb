// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/bridge_model.h — a gloss-bridge target's BRDF as a renderer evaluates it: the model the
 * bridge's tables and its glossmeter read (docs/bridge.md cites each target's source), with the
 * per-direction factors that the exact models need tabulated, so that a renderer (the picker's
 * WebGL2 tracer, a path tracer linking the library) draws what the target draws:
 *
 *   f(ωo, ωi) = spec(ωo, ωi) + base_color · diffuse(ωo, ωi)                        (1/sr)
 *   spec      = D(h) G(ωo, ωi) F(ωo·h; η) / (4 μi μo) · specular_factor(μo)
 *   diffuse   = diffuse_scale · diffuse_factor(μo)                    layered models (Cycles,
 *               MaterialX): the base under the specular layer, weighted by one minus the
 *               layer's compensated directional albedo
 *   diffuse   = diffuse_scale · diffuse_factor(μi) · diffuse_factor(μo)   Mitsuba roughplastic
 *               (nonlinear = false): t(μi) t(μo) / (π η² (1 − R_int)), t the rough interface's
 *               transmittance, R_int its internal reflectance
 *
 * specular_factor is Blender Principled's multiscatter energy compensation 1 + Fms (1 − E)/E
 * (Kulla & Conty 2017, as Cycles), MaterialX's 1 + Fss (1 − E)/E (OpenPBR, Standard Surface), 1
 * for roughplastic. The tables hold PGLOSS_BRIDGE_SHADING_NMU nodes, looked up linearly in
 * μ (N − 1) (node k at μ = k/(N − 1); Mitsuba's own table layout for t(μ)).
 *
 * Double, no allocation; a status (status.h) from every function.
 */
#ifndef PGLOSS_BRIDGE_MODEL_H
#define PGLOSS_BRIDGE_MODEL_H

#include "pgloss/bridge.h"

#ifdef __cplusplus
extern "C" {
#endif

#define PGLOSS_BRIDGE_SHADING_NMU 64

/* The BRDF models of the targets (the values of web/picker/microfacet.glsl's PGLOSS_MF_*). */
typedef enum pgloss_bridge_model {
    PGLOSS_BRIDGE_MODEL_PRINCIPLED = 0,  /* GGX, height-correlated Smith; Cycles' compensation (glTF, Principled) */
    PGLOSS_BRIDGE_MODEL_MATERIALX = 1,   /* GGX, height-correlated Smith; MaterialX's compensation (OpenPBR, Standard Surface) */
    PGLOSS_BRIDGE_MODEL_RP_GGX = 2,      /* Mitsuba roughplastic: GGX, separable Smith */
    PGLOSS_BRIDGE_MODEL_RP_BECKMANN = 3  /* Mitsuba roughplastic: Beckmann, Mitsuba's rational G1 */
} pgloss_bridge_model;

typedef enum pgloss_bridge_distribution {
    PGLOSS_BRIDGE_DIST_GGX = 0,          /* Trowbridge-Reitz (Walter et al. 2007, eq. 33) */
    PGLOSS_BRIDGE_DIST_BECKMANN = 1      /* Beckmann (Walter et al. 2007, eq. 25) */
} pgloss_bridge_distribution;

/* Below this α the specular lobe is an ideal mirror of reflectance F(μo; η): shading_eval
 * leaves it out (a delta), a renderer samples it as a mirror. */
#define PGLOSS_BRIDGE_ALPHA_MIRROR 1e-4

typedef struct pgloss_bridge_shading {
    pgloss_bridge_model model;
    pgloss_bridge_distribution distribution;
    int diffuse_both;          /* 1: diffuse_factor(μi) · diffuse_factor(μo) (roughplastic); 0: of μo */
    double alpha;              /* microfacet α (isotropic; roughness² where the target says roughness) */
    double f0;                 /* normal-incidence reflectance; the target's specular weight folded in */
    double eta;                /* Fresnel's relative index, (1 + √F0)/(1 − √F0) */
    double base_color[3];      /* linear Rec. 709 */
    double diffuse_scale;      /* 1/π (layered), 1/(π η² (1 − R_int)) (roughplastic); 1/sr */
    double specular_factor[PGLOSS_BRIDGE_SHADING_NMU];
    double diffuse_factor[PGLOSS_BRIDGE_SHADING_NMU];
} pgloss_bridge_shading;

/*
 * A target's parameters (bridge.h's conventions) → its shading model. Errors: NULL; the errors
 * of pgloss_bridge_model_inputs (ARGUMENT, NONFINITE, NEGATIVE); BRIDGE_BASE (a base colour
 * channel above 1); BRIDGE_SPECULAR (F0 ≥ 1); BRIDGE_ROUGHNESS (α > 1). `out` is zeroed on error.
 */
PGLOSS_API pgloss_status pgloss_bridge_shading_init(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                                    pgloss_bridge_shading *out);

/*
 * The model at unit directions wo, wi (local frame, normal +z, both away from the surface):
 * f = *specular + *diffuse · base_color (1/sr); both 0 below the horizon. Errors: NULL.
 */
PGLOSS_API pgloss_status pgloss_bridge_shading_eval(const pgloss_bridge_shading *s, const double wo[3],
                                                    const double wi[3], double *specular, double *diffuse);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BRIDGE_MODEL_H */
