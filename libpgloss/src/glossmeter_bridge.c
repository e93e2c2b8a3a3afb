// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The virtual glossmeter of the gloss bridge's targets (pgloss_glossmeter_readings_bridge,
 * docs/glossmeter.md): each target's BRDF as the bridge's tables model it (tools/bridge_tables.c,
 * docs/bridge.md), evaluated in double from the target's parameters through
 * pgloss_bridge_model_inputs, so the conventions (α from roughness, F0 from ior and the
 * specular weight, base luminance) are bridge.c's. */
#include <math.h>
#include <string.h>

#include "internal.h"
#include "microfacet_d.h"
#include "pgloss/bridge.h"
#include "pgloss/glossmeter.h"

/* μ nodes of the per-direction factors: Mitsuba's own table size and spacing for roughplastic's
 * t(μ) (MI_ROUGH_TRANSMITTANCE_RES = 64, μ_k = max(1e-6, k/63)); the layered models' albedos
 * use the same nodes with μ_0 = 1e-3, as the table generator does. */
#ifndef GMB_NMU
#define GMB_NMU 64
#endif
/* Below this α the specular lobe is read as an ideal mirror: it then falls inside every
 * receptor it aims at to within exp(−(margin/2α)²) of its flux (docs/glossmeter.md). */
#define GMB_ALPHA_MIRROR 1e-4
/* The half-vector quadrature of the albedos: rings log-spaced in θh from a cap of
 * min(1e-4, α/100) to π/2, cells over a half circle (the integrand is even in φ). */
#define GMB_HR 96
#define GMB_HA 48

typedef struct gmb_rings {
    double ch[GMB_HR], sh[GMB_HR], area[GMB_HR], t2[GMB_HR], cphi[GMB_HA];
} gmb_rings;

typedef struct gmb_target {
    int model;
    double beta, f0, eta, alpha;
    double kd;                   /* the diffuse's constant factor (1/sr) */
    double vf[GMB_NMU];          /* the specular lobe's factor of μo (layered: energy compensation) */
    double df[GMB_NMU];          /* the diffuse's factor of μ (layered: of μo; roughplastic: t(μ)) */
    gmb_rings r;
} gmb_target;

static int layered(int m) { return m == PGLOSS__MF_PRINCIPLED || m == PGLOSS__MF_MATERIALX; }
static double mu_node(int m, int k)
{
    return k == 0 ? (layered(m) ? 1e-3 : 1e-6) : (double)k / (GMB_NMU - 1);
}
/* Linear lookup in a node table (Mitsuba's lerp_gather for t). */
static double lerp_mu(const double *t, double mu)
{
    const double f = fmin(fmax(mu, 0.0), 1.0) * (GMB_NMU - 1);
    int i = (int)f;
    if (i >= GMB_NMU - 1) i = GMB_NMU - 2;
    const double w = f - i;
    return (1 - w) * t[i] + w * t[i + 1];
}
/* 2 ∫ t(μ) μ dμ over the nodes (trapezoid). */
static double trap_mu(int m, const double *t)
{
    double s = 0;
    for (int i = 0; i + 1 < GMB_NMU; ++i) {
        const double m0 = mu_node(m, i), m1 = mu_node(m, i + 1);
        s += (t[i] * m0 + t[i + 1] * m1) * (m1 - m0);
    }
    return s;
}

static void rings_init(gmb_rings *r, double alpha)
{
    const double cap = fmin(1e-4, 1e-2 * alpha), q = pow(0.5 * PGLOSS_PI / cap, 1.0 / (GMB_HR - 1));
    for (int i = 0; i < GMB_HR; ++i) {
        const double ta = i == 0 ? 0 : cap * pow(q, i - 1), tb = i == GMB_HR - 1 ? 0.5 * PGLOSS_PI : cap * pow(q, i);
        const double ca = cos(ta), cb = cos(tb), ch = 0.5 * (ca + cb);
        r->ch[i] = ch;
        r->sh[i] = sqrt(1 - ch * ch);
        r->area[i] = (ca - cb) * PGLOSS_PI / GMB_HA;
        r->t2[i] = (1 - ch * ch) / (ch * ch);
    }
    for (int k = 0; k < GMB_HA; ++k) r->cphi[k] = cos(PGLOSS_PI * (k + 0.5) / GMB_HA);
}

/* The layered models' directional albedos at view cosine mu: E (F = 1), EF (times Fresnel) and
 * S5 (times Schlick's (1 − ωo·h)^5), over the half vector. */
static void albedos(const gmb_target *t, double mu, double *E, double *EF, double *S5)
{
    const gmb_rings *r = &t->r;
    const double so = sqrt(1 - mu * mu);
    double e = 0, ef = 0, s5 = 0;
    for (int i = 0; i < GMB_HR; ++i)
        for (int k = 0; k < GMB_HA; ++k) {
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
static double rough_interface(const gmb_target *t, double mu, double eta, int transmit)
{
    const gmb_rings *r = &t->r;
    const int m = t->model;
    const double g1i = pgloss__mf_G1_d(m, mu, t->alpha), so = sqrt(1 - mu * mu);
    double sum = 0, norm = 0;
    for (int i = 0; i < GMB_HR; ++i) {
        const double D = pgloss__mf_D_d(m, r->t2[i], t->alpha);
        for (int k = 0; k < GMB_HA; ++k) {
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

/* The per-direction factors of the target at (β, F0, α). */
static void target_init(gmb_target *t)
{
    const int m = t->model;
    rings_init(&t->r, fmax(t->alpha, GMB_ALPHA_MIRROR));
    if (layered(m)) {
        double E[GMB_NMU], EF[GMB_NMU], S5[GMB_NMU], Fh[GMB_NMU];
        for (int i = 0; i < GMB_NMU; ++i) {
            if (t->alpha < GMB_ALPHA_MIRROR) { /* an ideal mirror: E = 1, EF = F(μ) */
                E[i] = 1;
                EF[i] = pgloss__fresnel_any_d(mu_node(m, i), t->eta);
                S5[i] = pow(1 - mu_node(m, i), 5);
            } else {
                albedos(t, mu_node(m, i), &E[i], &EF[i], &S5[i]);
            }
            Fh[i] = pgloss__fresnel_any_d(mu_node(m, i), t->eta);
        }
        /* Cycles (Principled): 1 + Fms (1 − E)/E with Kulla & Conty's Fms; MaterialX (OpenPBR,
         * Standard Surface): 1 + Fss (1 − E)/E with Fss = F0 + (1 − F0)/21. The base is weighted
         * by one minus the compensated albedo of the layer (tools/bridge_tables.c). */
        const double Eavg = trap_mu(m, E), Fss_c = trap_mu(m, Fh);
        const double Fms = Fss_c * Eavg / (1 - Fss_c * (1 - Eavg)), Fss = t->f0 + (1 - t->f0) / 21.0;
        for (int i = 0; i < GMB_NMU; ++i) {
            const double e = fmax(E[i], 1e-12);
            if (m == PGLOSS__MF_PRINCIPLED) {
                t->vf[i] = 1 + Fms * (1 - e) / e;
                t->df[i] = fmax(0.0, 1 - t->vf[i] * EF[i]);
            } else {
                t->vf[i] = 1 + Fss * (1 - e) / e;
                t->df[i] = fmax(0.0, 1 - t->vf[i] * (t->f0 * (E[i] - S5[i]) + S5[i]));
            }
        }
        t->kd = t->beta / PGLOSS_PI;
    } else {
        /* Mitsuba roughplastic (nonlinear = false): β t(μi) t(μo) / (π η² (1 − R_int)), with
         * R_int = 2 · mean_k R(μ_k) μ_k over its 64 nodes as roughplastic.cpp computes it. */
        double rint = 0;
        for (int i = 0; i < GMB_NMU; ++i) {
            const double mu = mu_node(m, i);
            t->vf[i] = 1;
            if (t->alpha < GMB_ALPHA_MIRROR) {
                const double ct2 = 1 - (1 - mu * mu) / (t->eta * t->eta);
                t->df[i] = ct2 > 0 ? 1 - pgloss__fresnel_any_d(mu, t->eta) : 0;
                rint += pgloss__fresnel_any_d(mu, 1 / t->eta) * mu;
            } else {
                t->df[i] = rough_interface(t, mu, t->eta, 1);
                rint += rough_interface(t, mu, 1 / t->eta, 0) * mu;
            }
        }
        rint = 2 * rint / GMB_NMU;
        t->kd = t->beta / (PGLOSS_PI * t->eta * t->eta * fmax(1 - rint, 1e-12));
    }
}

static double target_eval(const double wo[3], const double wi[3], void *user)
{
    const gmb_target *t = (const gmb_target *)user;
    const double mo = wo[2], mi = wi[2];
    if (!(mo > 0 && mi > 0))
        return 0;
    const double diffuse = layered(t->model) ? t->kd * lerp_mu(t->df, mo)
                                             : t->kd * lerp_mu(t->df, mi) * lerp_mu(t->df, mo);
    if (t->alpha < GMB_ALPHA_MIRROR)
        return diffuse;
    const double h[3] = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
    const double hl = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    /* tan²θh from the components: 1 − cos² would cancel near the mirror direction */
    const double t2 = (h[0] * h[0] + h[1] * h[1]) / (h[2] * h[2]);
    const double oh = (wo[0] * h[0] + wo[1] * h[1] + wo[2] * h[2]) / hl;
    const double spec = pgloss__mf_DG_d(t->model, mi, mo, t2, t->alpha) * pgloss__fresnel_any_d(oh, t->eta) /
                        (4 * mi * mo) * lerp_mu(t->vf, mo);
    return spec + diffuse;
}

static double target_mirror(double cos_i, void *user)
{
    const gmb_target *t = (const gmb_target *)user;
    return pgloss__fresnel_any_d(fmax(cos_i, 1e-12), t->eta);
}

pgloss_status pgloss_glossmeter_readings_bridge(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                                double azimuth_deg, double tol, pgloss_glossmeter_readings *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!params || !out)
        return PGLOSS_ERR_NULL;
    gmb_target t;
    pgloss_status st = pgloss_bridge_model_inputs(target, params, &t.beta, &t.f0, &t.alpha);
    if (st != PGLOSS_OK)
        return st;
    if (params->base_color[0] > 1 || params->base_color[1] > 1 || params->base_color[2] > 1)
        return PGLOSS_ERR_BRIDGE_BASE;
    if (!(t.f0 < 1))
        return PGLOSS_ERR_BRIDGE_SPECULAR; /* a perfect reflector: no finite index */
    if (!(t.alpha <= 1))
        return PGLOSS_ERR_BRIDGE_ROUGHNESS;
    t.model = pgloss__bridge_model_of(target);
    const double s = sqrt(t.f0);
    t.eta = (1 + s) / (1 - s);
    target_init(&t);
    const int mirror = t.alpha < GMB_ALPHA_MIRROR;
    const pgloss_glossmeter_brdf b = {target_eval, mirror ? target_mirror : NULL, &t,
                                      mirror ? 0.0 : t.alpha};
    return pgloss_glossmeter_readings_brdf(&b, azimuth_deg, tol, out);
}
