// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* A gloss-bridge target's shading model (pgloss/bridge_model.h): each target's BRDF as the
 * bridge's tables model it (tools/bridge_tables.c, docs/bridge.md), with its per-direction
 * factors, from the target's parameters through pgloss_bridge_model_inputs, so the conventions
 * (α from roughness, F0 from ior and the specular weight, base luminance) are bridge.c's. The
 * virtual glossmeter of the targets (glossmeter_bridge.c) and the picker's tracer evaluate it. */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "microfacet_d.h"
#include "pgloss/bridge_model.h"

/* μ nodes of the per-direction factors: Mitsuba's own table size and spacing for roughplastic's
 * t(μ) (MI_ROUGH_TRANSMITTANCE_RES = 64, μ_k = max(1e-6, k/63)); the layered models' albedos
 * use the same nodes with μ_0 = 1e-3, as the table generator does. */
#define NMU PGLOSS_BRIDGE_SHADING_NMU
/* The half-vector quadrature of the albedos: rings log-spaced in θh from a cap of
 * min(1e-4, α/100) to π/2, cells over a half circle (the integrand is even in φ). */
#define HR 96
#define HA 48

typedef struct rings {
    double ch[HR], sh[HR], area[HR], t2[HR], cphi[HA];
} rings;

static int layered(int m) { return m == PGLOSS__MF_PRINCIPLED || m == PGLOSS__MF_MATERIALX; }
static double mu_node(int m, int k)
{
    return k == 0 ? (layered(m) ? 1e-3 : 1e-6) : (double)k / (NMU - 1);
}
/* Linear lookup in a node table (Mitsuba's lerp_gather for t). */
static double lerp_mu(const double *t, double mu)
{
    const double f = fmin(fmax(mu, 0.0), 1.0) * (NMU - 1);
    int i = (int)f;
    if (i >= NMU - 1) i = NMU - 2;
    const double w = f - i;
    return (1 - w) * t[i] + w * t[i + 1];
}
/* 2 ∫ t(μ) μ dμ over the nodes (trapezoid). */
static double trap_mu(int m, const double *t)
{
    double s = 0;
    for (int i = 0; i + 1 < NMU; ++i) {
        const double m0 = mu_node(m, i), m1 = mu_node(m, i + 1);
        s += (t[i] * m0 + t[i + 1] * m1) * (m1 - m0);
    }
    return s;
}

static void rings_init(rings *r, double alpha)
{
    const double cap = fmin(1e-4, 1e-2 * alpha), q = pow(0.5 * PGLOSS_PI / cap, 1.0 / (HR - 1));
    for (int i = 0; i < HR; ++i) {
        const double ta = i == 0 ? 0 : cap * pow(q, i - 1), tb = i == HR - 1 ? 0.5 * PGLOSS_PI : cap * pow(q, i);
        const double ca = cos(ta), cb = cos(tb), ch = 0.5 * (ca + cb);
        r->ch[i] = ch;
        r->sh[i] = sqrt(1 - ch * ch);
        r->area[i] = (ca - cb) * PGLOSS_PI / HA;
        r->t2[i] = (1 - ch * ch) / (ch * ch);
    }
    for (int k = 0; k < HA; ++k) r->cphi[k] = cos(PGLOSS_PI * (k + 0.5) / HA);
}

/* The layered models' directional albedos at view cosine mu: E (F = 1), EF (times Fresnel) and
 * S5 (times Schlick's (1 − ωo·h)^5), over the half vector. */
static void albedos(const pgloss_bridge_shading *t, const rings *r, double mu, double *E, double *EF, double *S5)
{
    const double so = sqrt(1 - mu * mu);
    double e = 0, ef = 0, s5 = 0;
    for (int i = 0; i < HR; ++i)
        for (int k = 0; k < HA; ++k) {
            const double oh = so * r->sh[i] * r->cphi[k] + mu * r->ch[i];
            if (oh <= 0) continue;
            const double mi = 2 * oh * r->ch[i] - mu;
            if (mi <= 0) continue;
            /* f μi dωi with dωi = 4 (ωo·h) dωh, both halves of the circle */
            const double w = 2 * pgloss__mf_DG_d(t->model, mi, mu, r->t2[i], t->alpha) / (4 * mu) * 4 * oh * r->area[i];
            const double p = (1 - oh) * (1 - oh), p5 = p * p * (1 - oh);
            e += w;
            ef += w * pgloss__fresnel_any_d(oh, t->eta);
            s5 += w * p5;
        }
    *E = e;
    *EF = ef;
    *S5 = s5;
}

/* Mitsuba roughplastic's rough-interface transmittance t(μ) (transmit) or reflectance, over the
 * visible normals, normalised by their own quadrature sum (tools/bridge_tables.c,
 * rough_interface, which docs/bridge.md checks against Mitsuba 3). */
static double rough_interface(const pgloss_bridge_shading *t, const rings *r, double mu, double eta, int transmit)
{
    const int m = t->model;
    const double g1i = pgloss__mf_G1_d(m, mu, t->alpha), so = sqrt(1 - mu * mu);
    double sum = 0, norm = 0;
    for (int i = 0; i < HR; ++i) {
        const double D = pgloss__mf_D_d(m, r->t2[i], t->alpha);
        for (int k = 0; k < HA; ++k) {
            const double c = so * r->sh[i] * r->cphi[k] + mu * r->ch[i];
            if (c <= 0) continue;
            const double vis = D * g1i * c / mu * r->area[i];
            norm += vis;
            const double F = pgloss__fresnel_any_d(c, eta);
            double vz, val;
            if (transmit) {
                const double ct2 = 1 - (1 - c * c) / (eta * eta);
                if (ct2 <= 0) continue;
                vz = -mu / eta + r->ch[i] * (c / eta - sqrt(ct2));
                if (vz >= 0) continue;
                val = 1 - F;
            } else {
                vz = 2 * c * r->ch[i] - mu;
                if (vz <= 0) continue;
                val = F;
            }
            sum += vis * val * pgloss__mf_G1_d(m, fabs(vz), t->alpha);
        }
    }
    return norm > 0 ? sum / norm : 0;
}

/* The per-direction factors of the model at (F0, α). */
static void factors_init(pgloss_bridge_shading *t)
{
    const int m = t->model;
    rings r;
    rings_init(&r, fmax(t->alpha, PGLOSS_BRIDGE_ALPHA_MIRROR));
    double *vf = t->specular_factor, *df = t->diffuse_factor;
    if (layered(m)) {
        double E[NMU], EF[NMU], S5[NMU], Fh[NMU];
        for (int i = 0; i < NMU; ++i) {
            if (t->alpha < PGLOSS_BRIDGE_ALPHA_MIRROR) { /* an ideal mirror: E = 1, EF = F(μ) */
                E[i] = 1;
                EF[i] = pgloss__fresnel_any_d(mu_node(m, i), t->eta);
                S5[i] = pow(1 - mu_node(m, i), 5);
            } else {
                albedos(t, &r, mu_node(m, i), &E[i], &EF[i], &S5[i]);
            }
            Fh[i] = pgloss__fresnel_any_d(mu_node(m, i), t->eta);
        }
        /* Cycles (Principled): 1 + Fms (1 − E)/E with Kulla & Conty's Fms; MaterialX (OpenPBR,
         * Standard Surface): 1 + Fss (1 − E)/E with Fss = F0 + (1 − F0)/21. The base is weighted
         * by one minus the compensated albedo of the layer (tools/bridge_tables.c). */
        const double Eavg = trap_mu(m, E), Fss_c = trap_mu(m, Fh);
        const double Fms = Fss_c * Eavg / (1 - Fss_c * (1 - Eavg)), Fss = t->f0 + (1 - t->f0) / 21.0;
        for (int i = 0; i < NMU; ++i) {
            const double e = fmax(E[i], 1e-12);
            if (m == PGLOSS__MF_PRINCIPLED) {
                vf[i] = 1 + Fms * (1 - e) / e;
                df[i] = fmax(0.0, 1 - vf[i] * EF[i]);
            } else {
                vf[i] = 1 + Fss * (1 - e) / e;
                df[i] = fmax(0.0, 1 - vf[i] * (t->f0 * (E[i] - S5[i]) + S5[i]));
            }
        }
        t->diffuse_scale = 1 / PGLOSS_PI;
    } else {
        /* Mitsuba roughplastic (nonlinear = false): t(μi) t(μo) / (π η² (1 − R_int)), with
         * R_int = 2 · mean_k R(μ_k) μ_k over its 64 nodes as roughplastic.cpp computes it. */
        double rint = 0;
        for (int i = 0; i < NMU; ++i) {
            const double mu = mu_node(m, i);
            vf[i] = 1;
            if (t->alpha < PGLOSS_BRIDGE_ALPHA_MIRROR) {
                const double ct2 = 1 - (1 - mu * mu) / (t->eta * t->eta);
                df[i] = ct2 > 0 ? 1 - pgloss__fresnel_any_d(mu, t->eta) : 0;
                rint += pgloss__fresnel_any_d(mu, 1 / t->eta) * mu;
            } else {
                df[i] = rough_interface(t, &r, mu, t->eta, 1);
                rint += rough_interface(t, &r, mu, 1 / t->eta, 0) * mu;
            }
        }
        rint = 2 * rint / NMU;
        t->diffuse_scale = 1 / (PGLOSS_PI * t->eta * t->eta * fmax(1 - rint, 1e-12));
    }
}

pgloss_status pgloss_bridge_shading_init(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                         pgloss_bridge_shading *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!params || !out)
        return PGLOSS_ERR_NULL;
    double beta, f0, alpha;
    pgloss_status st = pgloss_bridge_model_inputs(target, params, &beta, &f0, &alpha);
    if (st != PGLOSS_OK)
        return st;
    if (params->base_color[0] > 1 || params->base_color[1] > 1 || params->base_color[2] > 1)
        return PGLOSS_ERR_BRIDGE_BASE;
    if (!(f0 < 1))
        return PGLOSS_ERR_BRIDGE_SPECULAR; /* a perfect reflector: no finite index */
    if (!(alpha <= 1))
        return PGLOSS_ERR_BRIDGE_ROUGHNESS;
    pgloss_bridge_shading *t = out;
    t->model = (pgloss_bridge_model)pgloss__bridge_model_of(target);
    t->distribution = t->model == PGLOSS_BRIDGE_MODEL_RP_BECKMANN ? PGLOSS_BRIDGE_DIST_BECKMANN : PGLOSS_BRIDGE_DIST_GGX;
    t->diffuse_both = !layered(t->model);
    t->alpha = alpha;
    t->f0 = f0;
    const double s = sqrt(f0);
    t->eta = (1 + s) / (1 - s);
    for (int c = 0; c < 3; ++c) t->base_color[c] = params->base_color[c];
    factors_init(t);
    return PGLOSS_OK;
}

pgloss_status pgloss_bridge_shading_eval(const pgloss_bridge_shading *t, const double wo[3], const double wi[3],
                                         double *specular, double *diffuse)
{
    if (specular) *specular = 0;
    if (diffuse) *diffuse = 0;
    if (!t || !wo || !wi || !specular || !diffuse)
        return PGLOSS_ERR_NULL;
    if (!(wo[2] > 0 && wi[2] > 0))
        return PGLOSS_OK;
    /* Cosines below 1e-12 are taken as 1e-12: the lobe's 1/(4 μi μo) and tan²θh would
     * overflow or reach 0/0 at grazing, where a unit vector's error is already larger. */
    const double mo = fmax(wo[2], 1e-12), mi = fmax(wi[2], 1e-12);
    *diffuse = t->diffuse_both ? t->diffuse_scale * lerp_mu(t->diffuse_factor, mi) * lerp_mu(t->diffuse_factor, mo)
                               : t->diffuse_scale * lerp_mu(t->diffuse_factor, mo);
    if (t->alpha < PGLOSS_BRIDGE_ALPHA_MIRROR)
        return PGLOSS_OK;
    const double h[3] = {wo[0] + wi[0], wo[1] + wi[1], mo + mi};
    const double hl = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    /* tan²θh from the components: 1 − cos² would cancel near the mirror direction */
    const double t2 = (h[0] * h[0] + h[1] * h[1]) / (h[2] * h[2]);
    const double oh = (wo[0] * h[0] + wo[1] * h[1] + mo * h[2]) / hl;
    *specular = pgloss__mf_DG_d(t->model, mi, mo, t2, t->alpha) * pgloss__fresnel_any_d(oh, t->eta) / (4 * mi * mo) *
                lerp_mu(t->specular_factor, mo);
    return PGLOSS_OK;
}
