// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The gloss bridge's microfacet models in double, as the library evaluates them (the virtual
 * glossmeter of bridge targets, glossmeter_bridge.c). They are the models of
 * tools/bridge_tables.c, which builds the bridge's tables from the same formulas; docs/bridge.md
 * cites each target's source. */
#ifndef PGLOSS_MICROFACET_D_H
#define PGLOSS_MICROFACET_D_H

#include <math.h>

/* The bridge's BRDF models (bridge.c's TARGET_MODEL maps targets onto them). */
enum { PGLOSS__MF_PRINCIPLED = 0, PGLOSS__MF_MATERIALX = 1, PGLOSS__MF_RP_GGX = 2, PGLOSS__MF_RP_BECKMANN = 3 };

/* The model a bridge target renders with (bridge.c's table); -1 for an unknown target. */
int pgloss__bridge_model_of(int target);

/* Unpolarised Fresnel reflectance of an interface of relative index eta (either side of 1) at
 * incidence cosine c > 0; 1 past the critical angle. pgloss_fresnel_dielectric covers eta > 1
 * only; Mitsuba's internal reflectance needs eta < 1. */
static inline double pgloss__fresnel_any_d(double c, double eta)
{
    const double g2 = eta * eta - 1 + c * c;
    if (g2 <= 0) return 1.0;
    const double g = sqrt(g2), a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
    return 0.5 * a * a * (1 + b * b);
}

static inline double pgloss__tan2_d(double mu) { return (1 - mu * mu) / (mu * mu); }
/* GGX (Trowbridge-Reitz) D at tan²θm t2, times cos⁴θm's inverse folded in. */
static inline double pgloss__ggx_D_d(double t2, double a)
{
    const double a2 = a * a, k = a2 + t2;
    return a2 * (1 + t2) * (1 + t2) / (3.14159265358979323846 * k * k);
}
static inline double pgloss__ggx_lambda_d(double mu, double a) { return 0.5 * (sqrt(1 + a * a * pgloss__tan2_d(mu)) - 1); }
static inline double pgloss__beck_D_d(double t2, double a)
{
    return exp(-t2 / (a * a)) * (1 + t2) * (1 + t2) / (3.14159265358979323846 * a * a);
}
/* Mitsuba 3's rational fit of Beckmann's G1 (include/mitsuba/render/microfacet.h, smith_g1). */
static inline double pgloss__beck_G1_d(double mu, double a)
{
    const double t = sqrt(pgloss__tan2_d(mu));
    if (t == 0) return 1;
    const double x = 1 / (a * t);
    return x >= 1.6 ? 1.0 : (3.535 * x + 2.181 * x * x) / (1 + 2.276 * x + 2.577 * x * x);
}
static inline double pgloss__mf_G1_d(int m, double mu, double a)
{
    return m == PGLOSS__MF_RP_BECKMANN ? pgloss__beck_G1_d(mu, a) : 1 / (1 + pgloss__ggx_lambda_d(mu, a));
}
static inline double pgloss__mf_D_d(int m, double t2, double a)
{
    return m == PGLOSS__MF_RP_BECKMANN ? pgloss__beck_D_d(t2, a) : pgloss__ggx_D_d(t2, a);
}

/* The specular lobe f·(4 μi μo) without the Fresnel factor: D G. */
static inline double pgloss__mf_DG_d(int m, double mi, double mo, double t2, double a)
{
    switch (m) {
    case PGLOSS__MF_PRINCIPLED:
    case PGLOSS__MF_MATERIALX: /* height-correlated Smith (Cycles bsdf_G; MaterialX mx_ggx_smith_G2) */
        return pgloss__ggx_D_d(t2, a) / (1 + pgloss__ggx_lambda_d(mi, a) + pgloss__ggx_lambda_d(mo, a));
    case PGLOSS__MF_RP_GGX: /* separable Smith (Mitsuba MicrofacetDistribution::G) */
        return pgloss__ggx_D_d(t2, a) / ((1 + pgloss__ggx_lambda_d(mi, a)) * (1 + pgloss__ggx_lambda_d(mo, a)));
    default:
        return pgloss__beck_D_d(t2, a) * pgloss__beck_G1_d(mi, a) * pgloss__beck_G1_d(mo, a);
    }
}

#endif /* PGLOSS_MICROFACET_D_H */
