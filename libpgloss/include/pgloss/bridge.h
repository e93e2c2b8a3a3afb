// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/bridge.h — the gloss bridge: a paint (L*, a*, b*, c, d) ↔ the parameters of the
 * dielectric BRDFs people render with (OpenPBR, Standard Surface, glTF, Blender's Principled
 * BSDF, Mitsuba 3's roughplastic).
 *
 * The criterion (docs/bridge.md): a target material has the paint (L*, c, d) that the bridge's
 * gloss meter reads from it — the Ward paint of eq. 2 (ρd, ρs, α) whose image of the stimulus
 * sphere (examples/tracer/scenes/stimulus.scene, 160 × 120, the 2,114 pixels whose centre sees
 * the sphere) is nearest to the target's image in luminance least squares, all three fitted;
 * then L* = f(ρd), c from eq. 4, d = 1 − α (eq. 3). At the parameters this header returns, the
 * fit with ρd held at f⁻¹(L*) returns the same (c, d), so either gloss-meter setup reads the paint.
 * The readings are tables (libpgloss/src/bridge_tables.inc, from tools/bridge_tables.c) over
 * (base luminance, F0, α), interpolated by tricubic Catmull-Rom splines; the forward mapping
 * inverts that interpolant, so paint → target → paint is exact to 1e-9.
 *
 * All functions are in double, allocate nothing and return a status (status.h).
 */
#ifndef PGLOSS_BRIDGE_H
#define PGLOSS_BRIDGE_H

#include "pgloss/perceptual.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The targets. Each converts its own parameters to (base colour, F0, α); docs/bridge.md cites
 * the spec or source file of each conversion. */
typedef enum pgloss_bridge_target {
    PGLOSS_BRIDGE_OPENPBR = 0,            /* OpenPBR Surface (MaterialX open_pbr_surface)       */
    PGLOSS_BRIDGE_STANDARD_SURFACE = 1,   /* Autodesk Standard Surface (MaterialX standard_surface) */
    PGLOSS_BRIDGE_GLTF = 2,               /* glTF 2.0, metallic 0, KHR_materials_ior + _specular */
    PGLOSS_BRIDGE_GLTF_CORE = 3,          /* glTF 2.0 without extensions: ior 1.5, F0 0.04 fixed  */
    PGLOSS_BRIDGE_PRINCIPLED = 4,         /* Blender Principled BSDF in Cycles (multiscatter GGX) */
    PGLOSS_BRIDGE_ROUGHPLASTIC_GGX = 5,   /* Mitsuba 3 roughplastic, distribution ggx           */
    PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN = 6 /* Mitsuba 3 roughplastic, distribution beckmann    */
} pgloss_bridge_target;
#define PGLOSS_BRIDGE_TARGET_COUNT 7

/*
 * A target's parameters, under the names each target gives them:
 *   base_color  OpenPBR base_color (base_weight 1), Standard Surface base_color (base 1),
 *               glTF baseColorFactor (linear), Principled Base Color, Mitsuba diffuse_reflectance;
 *               linear Rec. 709 in [0, 1]
 *   roughness   OpenPBR / Standard Surface specular_roughness, glTF roughnessFactor, Principled
 *               Roughness: α = roughness²; Mitsuba alpha: α itself
 *   ior         OpenPBR specular_ior, Standard Surface specular_IOR, glTF KHR_materials_ior.ior,
 *               Principled IOR, Mitsuba int_ior (with ext_ior "air" = 1.000277, its default)
 *   specular    OpenPBR specular_weight, Standard Surface specular, glTF KHR_materials_specular
 *               .specularFactor, Principled Specular IOR Level; 1 for Mitsuba (no such input)
 */
typedef struct pgloss_bridge_params {
    double base_color[3];
    double roughness;
    double ior;
    double specular;
} pgloss_bridge_params;

/* The target's short name ("openpbr", "standard_surface", "gltf", "gltf_core", "principled",
 * "roughplastic_ggx", "roughplastic_beckmann"); "unknown" for other values. */
PGLOSS_API const char *pgloss_bridge_target_name(pgloss_bridge_target target);

/* The target of a short name. Errors: NULL, ARGUMENT (no such name). */
PGLOSS_API pgloss_status pgloss_bridge_target_from_name(const char *name, pgloss_bridge_target *target);

/*
 * Paint → the target's parameters. Errors, checked in this order: NULL; ARGUMENT (unknown
 * target); the errors of pgloss_check_perceptual (NONFINITE, LIGHTNESS, NEGATIVE, ALPHA, GAMUT,
 * ENVELOPE, ENERGY: outputs 0); then, when the paint is out of the target's reach, the
 * parameters of the nearest reachable paint — the one with the nearest L*, then the nearest
 * (c, d) in eq. 5's distance — are written, `reached` holds that paint, and the status names
 * the limit met: BRIDGE_BASE (a base colour channel would leave [0, 1]), BRIDGE_SPECULAR (F0
 * outside the target's range: c too high or too low), BRIDGE_ROUGHNESS (α outside the
 * target's range: d too high or too low). Otherwise `reached` is the paint (to 1e-9) and the
 * status is OK or the warning ALPHA_UNTRUSTED. `reached` may be NULL.
 */
PGLOSS_API pgloss_status pgloss_bridge_from_perceptual(pgloss_bridge_target target,
                                                       const pgloss_perceptual *paint,
                                                       pgloss_bridge_params *params,
                                                       pgloss_perceptual *reached);

/*
 * The target's parameters → the paint it reads as, and the relative RMS residual of that
 * Ward fit over the sphere's pixels (how Ward-like the target looks; `residual` may be NULL).
 * Errors: NULL; ARGUMENT (unknown target); NONFINITE; NEGATIVE (a base colour channel, the
 * roughness, the specular input or ior ≤ 0); BRIDGE_BASE (a base colour channel above 1);
 * BRIDGE_SPECULAR / BRIDGE_ROUGHNESS (F0 or α outside the tables' range: the outputs are the
 * reading at the nearest point inside it). gltf_core requires ior 1.5 and specular 1 (ARGUMENT).
 */
PGLOSS_API pgloss_status pgloss_bridge_to_perceptual(pgloss_bridge_target target,
                                                     const pgloss_bridge_params *params,
                                                     pgloss_perceptual *paint, double *residual);

/*
 * The target-independent core: the reading (ρd, ρs, α, residual) of a target model at base
 * luminance beta, normal-incidence reflectance f0 and microfacet α (not roughness) — the
 * interpolated table. Errors: NULL, ARGUMENT, NONFINITE, BRIDGE_SPECULAR / BRIDGE_ROUGHNESS
 * (outside the table; the reading at the nearest point inside is written), BRIDGE_BASE (beta
 * outside [0, 1]; likewise).
 */
PGLOSS_API pgloss_status pgloss_bridge_read(pgloss_bridge_target target, double beta, double f0,
                                            double alpha, double reading[4]);

/*
 * The conventions alone (docs/bridge.md cites each): the target's parameters → the base
 * luminance β (Rec. 709 Y of base_color), the normal-incidence reflectance F0 and the microfacet
 * α its model renders with. Errors: NULL, ARGUMENT (unknown target; gltf_core with ior ≠ 1.5 or
 * specular ≠ 1), NONFINITE, NEGATIVE (a base colour channel < 0; roughness, ior ≤ 0; specular < 0).
 */
PGLOSS_API pgloss_status pgloss_bridge_model_inputs(pgloss_bridge_target target,
                                                    const pgloss_bridge_params *params,
                                                    double *beta, double *f0, double *alpha);

/*
 * And back: a linear Rec. 709 base colour, F0 and α → the target's parameters. The rules:
 * OpenPBR keeps specular_ior 1.5 and sets specular_weight = F0 / 0.04; glTF keeps ior 1.5 and
 * sets specularFactor = F0 / 0.04 up to F0 = 0.04, above it specularFactor 1 and the ior of F0;
 * Standard Surface (specular 1), Principled (Specular IOR Level 0.5) and Mitsuba (int_ior =
 * 1.000277 × the IOR) carry F0 in the IOR. Errors: NULL, ARGUMENT (unknown target; F0 outside
 * (0, 1); gltf_core with F0 ≠ 0.04), NONFINITE, NEGATIVE (base colour < 0, α ≤ 0).
 */
PGLOSS_API pgloss_status pgloss_bridge_params_from_model(pgloss_bridge_target target,
                                                         const double base_color[3], double f0,
                                                         double alpha, pgloss_bridge_params *params);

/* F0 and microfacet α range of a target (what its tables cover, within its own limits).
 * Errors: NULL, ARGUMENT. */
PGLOSS_API pgloss_status pgloss_bridge_range(pgloss_bridge_target target, double *f0_min,
                                             double *f0_max, double *alpha_min, double *alpha_max);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_BRIDGE_H */
