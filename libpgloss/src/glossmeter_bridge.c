// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The virtual glossmeter of the gloss bridge's targets (pgloss_glossmeter_readings_bridge,
 * docs/glossmeter.md): each target's shading model (pgloss_bridge_shading_init, bridge_model.c)
 * in luminance, the base colour's Rec. 709 Y for the base. */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "microfacet_d.h"
#include "pgloss/bridge_model.h"
#include "pgloss/glossmeter.h"

typedef struct gmb_target {
    pgloss_bridge_shading s;
    double beta; /* the base colour's luminance */
} gmb_target;

static double target_eval(const double wo[3], const double wi[3], void *user)
{
    const gmb_target *t = (const gmb_target *)user;
    double spec, diffuse;
    pgloss_bridge_shading_eval(&t->s, wo, wi, &spec, &diffuse);
    return spec + diffuse * t->beta;
}

static double target_mirror(double cos_i, void *user)
{
    const gmb_target *t = (const gmb_target *)user;
    return pgloss__fresnel_any_d(fmax(cos_i, 1e-12), t->s.eta);
}

pgloss_status pgloss_glossmeter_readings_bridge(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                                double azimuth_deg, double tol, pgloss_glossmeter_readings *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!params || !out)
        return PGLOSS_ERR_NULL;
    gmb_target t;
    double f0, alpha;
    pgloss_status st = pgloss_bridge_model_inputs(target, params, &t.beta, &f0, &alpha);
    if (st != PGLOSS_OK)
        return st;
    st = pgloss_bridge_shading_init(target, params, &t.s);
    if (st != PGLOSS_OK)
        return st;
    const int mirror = t.s.alpha < PGLOSS_BRIDGE_ALPHA_MIRROR;
    const pgloss_glossmeter_brdf b = {target_eval, mirror ? target_mirror : NULL, &t,
                                      mirror ? 0.0 : t.s.alpha};
    return pgloss_glossmeter_readings_brdf(&b, azimuth_deg, tol, out);
}
