// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The gloss bridge (pgloss/bridge.h, docs/bridge.md): the tables of the bridge's gloss-meter
 * readings, their tricubic interpolant, its inversion, and each target's parameter names. */
#include <math.h>
#include <string.h>

#include "pgloss/bridge.h"

#include "bridge_meter.h"
#include "microfacet_d.h"
#include "bridge_tables.inc"

/* The tables as the shared reader takes them (bridge_meter.h). */
static const pgloss__bridge_tables TABLES = {
    pgloss__bridge_products, pgloss__bridge_rint, PGLOSS__BRIDGE_NF0, PGLOSS__BRIDGE_NAT, PGLOSS__BRIDGE_NFR,
    PGLOSS__BRIDGE_RINT_MODEL0, PGLOSS__BRIDGE_F0_MIN, PGLOSS__BRIDGE_F0_MAX, PGLOSS__BRIDGE_AT_MIN,
    PGLOSS__BRIDGE_AT_MAX, {pgloss__bridge_gram, pgloss__bridge_dw, PGLOSS__BRIDGE_DD}};

/* The BRDF model each target renders with (the models of tools/bridge_tables.c). */
enum { MODEL_PRINCIPLED = 0, MODEL_MATERIALX = 1, MODEL_RP_GGX = 2, MODEL_RP_BECKMANN = 3 };
static const int TARGET_MODEL[PGLOSS_BRIDGE_TARGET_COUNT] = {
    MODEL_MATERIALX, MODEL_MATERIALX, MODEL_PRINCIPLED, MODEL_PRINCIPLED,
    MODEL_PRINCIPLED, MODEL_RP_GGX, MODEL_RP_BECKMANN};
static const char *const TARGET_NAME[PGLOSS_BRIDGE_TARGET_COUNT] = {
    "openpbr", "standard_surface", "gltf", "gltf_core", "principled", "roughplastic_ggx",
    "roughplastic_beckmann"};

/* F0 of the default IOR 1.5 of OpenPBR, glTF and Principled: ((1.5 − 1)/(1.5 + 1))² = 0.04. */
#define F0_IOR_1_5 0.04
/* Mitsuba's ext_ior default, "air" (src/core/ior table of mitsuba3: 1.000277). */
#define MITSUBA_AIR_IOR 1.000277
/* The axes' weights in the nearest-reachable search: L* first (one L* unit weighs as one unit
 * of c: a step of 25 of eq. 5's isogloss steps), then eq. 5's gloss distance. */
#define WEIGHT_L 1.0
#define WEIGHT_D PGLOSS_D_WEIGHT

static int valid_target(pgloss_bridge_target t) { return (int)t >= 0 && (int)t < PGLOSS_BRIDGE_TARGET_COUNT; }
static int ggx_roughness(pgloss_bridge_target t)
{
    return t != PGLOSS_BRIDGE_ROUGHPLASTIC_GGX && t != PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN;
}
static double f0_of_ior(double ior) { const double r = (ior - 1) / (ior + 1); return r * r; }
static double ior_of_f0(double f0) { const double s = sqrt(f0); return (1 + s) / (1 - s); }

int pgloss__bridge_model_of(int target)
{
    return valid_target((pgloss_bridge_target)target) ? TARGET_MODEL[target] : -1;
}

const char *pgloss_bridge_target_name(pgloss_bridge_target target)
{
    return valid_target(target) ? TARGET_NAME[target] : "unknown";
}

pgloss_status pgloss_bridge_target_from_name(const char *name, pgloss_bridge_target *target)
{
    if (!name || !target)
        return PGLOSS_ERR_NULL;
    for (int k = 0; k < PGLOSS_BRIDGE_TARGET_COUNT; ++k)
        if (!strcmp(name, TARGET_NAME[k])) {
            *target = (pgloss_bridge_target)k;
            return PGLOSS_OK;
        }
    return PGLOSS_ERR_ARGUMENT;
}

/* The reading of a model at (β, F0, α) inside the tables: the meter applied to the image
 * whose products are interpolated (bridge_meter.h); β enters exactly. */
static void interpolate(int model, double beta, double f0, double alpha, double out[4])
{
    pgloss__bridge_table_read(&TABLES, model, beta, f0, alpha, out);
}

/* The box a target's (β, F0, α) must stay in. */
typedef struct { double lo[3], hi[3]; } box;

static box target_box(pgloss_bridge_target t, double beta_max)
{
    box b;
    b.lo[0] = 0;
    b.hi[0] = beta_max;
    b.lo[1] = PGLOSS__BRIDGE_F0_MIN;
    b.hi[1] = PGLOSS__BRIDGE_F0_MAX;
    if (t == PGLOSS_BRIDGE_GLTF_CORE)
        b.lo[1] = b.hi[1] = F0_IOR_1_5;
    b.lo[2] = log(PGLOSS__BRIDGE_AT_MIN);
    b.hi[2] = log(PGLOSS__BRIDGE_AT_MAX);
    return b;
}

pgloss_status pgloss_bridge_range(pgloss_bridge_target target, double *f0_min, double *f0_max,
                                  double *alpha_min, double *alpha_max)
{
    if (!f0_min || !f0_max || !alpha_min || !alpha_max)
        return PGLOSS_ERR_NULL;
    *f0_min = *f0_max = *alpha_min = *alpha_max = 0;
    if (!valid_target(target))
        return PGLOSS_ERR_ARGUMENT;
    const box b = target_box(target, 1);
    *f0_min = b.lo[1];
    *f0_max = b.hi[1];
    *alpha_min = exp(b.lo[2]);
    *alpha_max = exp(b.hi[2]);
    return PGLOSS_OK;
}

pgloss_status pgloss_bridge_read(pgloss_bridge_target target, double beta, double f0, double alpha,
                                 double reading[4])
{
    if (!reading)
        return PGLOSS_ERR_NULL;
    reading[0] = reading[1] = reading[2] = reading[3] = 0;
    if (!valid_target(target))
        return PGLOSS_ERR_ARGUMENT;
    if (!isfinite(beta) || !isfinite(f0) || !isfinite(alpha))
        return PGLOSS_ERR_NONFINITE;
    const box b = target_box(target, 1);
    pgloss_status st = PGLOSS_OK;
    const double la = alpha > 0 ? log(alpha) : b.lo[2] - 1;
    if (!(la >= b.lo[2] && la <= b.hi[2]))
        st = PGLOSS_ERR_BRIDGE_ROUGHNESS;
    if (!(f0 >= b.lo[1] && f0 <= b.hi[1]))
        st = PGLOSS_ERR_BRIDGE_SPECULAR;
    if (!(beta >= 0 && beta <= 1))
        st = PGLOSS_ERR_BRIDGE_BASE;
    interpolate(TARGET_MODEL[target], fmin(fmax(beta, b.lo[0]), b.hi[0]), fmin(fmax(f0, b.lo[1]), b.hi[1]),
                exp(fmin(fmax(la, b.lo[2]), b.hi[2])), reading);
    return st;
}

/* The paint (L*, c, d) of a reading; 0 on success. */
static int paint_of_reading(const double r[4], double *L, double *c, double *d)
{
    *L = *c = 0;
    *d = 1 - r[2];
    if (pgloss_lightness_from_luminance(fmax(r[0], 0), L) != PGLOSS_OK) return 1;
    if (pgloss_contrast_gloss(fmax(r[0], 0), fmax(r[1], 0), c) != PGLOSS_OK) return 1;
    return 0;
}

/* Weighted residual of u = (β, F0, log α) against the wanted paint. */
static void residual_of_reading(const double r[4], const double want[3], double res[3])
{
    double L, c, d;
    paint_of_reading(r, &L, &c, &d);
    res[0] = WEIGHT_L * (L - want[0]);
    res[1] = c - want[1];
    res[2] = WEIGHT_D * (d - want[2]);
}
static void residual(int model, const double u[3], const double want[3], double res[3])
{
    double r[4];
    interpolate(model, u[0], u[1], exp(u[2]), r);
    residual_of_reading(r, want, res);
}

static double norm2(const double r[3]) { return r[0] * r[0] + r[1] * r[1] + r[2] * r[2]; }

/* Solve the 3 × 3 system A x = b (Gaussian elimination, partial pivoting); 0 on success. */
static int solve3(double A[3][3], double b[3], double x[3])
{
    for (int c = 0; c < 3; ++c) {
        int p = c;
        for (int r = c + 1; r < 3; ++r)
            if (fabs(A[r][c]) > fabs(A[p][c])) p = r;
        if (!(fabs(A[p][c]) > 1e-300)) return 1;
        for (int k = 0; k < 3; ++k) { double t = A[c][k]; A[c][k] = A[p][k]; A[p][k] = t; }
        { double t = b[c]; b[c] = b[p]; b[p] = t; }
        for (int r = c + 1; r < 3; ++r) {
            const double f = A[r][c] / A[c][c];
            for (int k = c; k < 3; ++k) A[r][k] -= f * A[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int r = 2; r >= 0; --r) {
        double s = b[r];
        for (int k = r + 1; k < 3; ++k) s -= A[r][k] * x[k];
        x[r] = s / A[r][r];
    }
    return 0;
}

/* Projected Levenberg-Marquardt on the box from u; returns the squared residual. */
static double solve_box(int model, const box *bx, const double want[3], double u[3])
{
    double res[3], f = 0, lambda = 1e-3;
    residual(model, u, want, res);
    f = norm2(res);
    for (int it = 0; it < 200 && f > 1e-26; ++it) {
        double J[3][3];
        for (int k = 0; k < 3; ++k) {
            double up[3] = {u[0], u[1], u[2]}, um[3] = {u[0], u[1], u[2]}, rp[3], rm[3];
            const double h = 1e-6 * (bx->hi[k] - bx->lo[k] > 0 ? bx->hi[k] - bx->lo[k] : 1);
            up[k] += h;
            um[k] -= h;
            residual(model, up, want, rp);
            residual(model, um, want, rm);
            for (int i = 0; i < 3; ++i) J[i][k] = (rp[i] - rm[i]) / (2 * h);
        }
        /* Fixed coordinates (an empty interval, or at a bound the step would cross) drop out. */
        int freec[3];
        double g[3];
        for (int k = 0; k < 3; ++k) {
            g[k] = 0;
            for (int i = 0; i < 3; ++i) g[k] += J[i][k] * res[i];
            freec[k] = bx->hi[k] > bx->lo[k] && !(u[k] <= bx->lo[k] && g[k] > 0) && !(u[k] >= bx->hi[k] && g[k] < 0);
        }
        int improved = 0;
        for (int tries = 0; tries < 12 && !improved; ++tries) {
            double A[3][3], b[3], step[3] = {0, 0, 0};
            for (int r = 0; r < 3; ++r) {
                for (int c = 0; c < 3; ++c) {
                    double s = 0;
                    for (int i = 0; i < 3; ++i) s += J[i][r] * J[i][c];
                    A[r][c] = (freec[r] && freec[c]) ? s : 0;
                }
                A[r][r] = freec[r] ? A[r][r] * (1 + lambda) + 1e-30 : 1;
                b[r] = freec[r] ? -g[r] : 0;
            }
            if (solve3(A, b, step)) { lambda *= 10; continue; }
            double un[3], rn[3];
            for (int k = 0; k < 3; ++k) un[k] = fmin(fmax(u[k] + step[k], bx->lo[k]), bx->hi[k]);
            residual(model, un, want, rn);
            const double fn = norm2(rn);
            if (fn < f) {
                memcpy(u, un, sizeof un);
                memcpy(res, rn, sizeof rn);
                improved = f - fn > 1e-30 || fn == 0 ? 1 : 2;
                f = fn;
                lambda = fmax(lambda * 0.1, 1e-12);
            } else {
                lambda *= 10;
            }
        }
        if (!improved || improved == 2) break;
    }
    return f;
}

/* The target's parameters from (base colour, F0, α). */
static void params_from(pgloss_bridge_target t, const double rgb[3], double f0, double alpha,
                        pgloss_bridge_params *p)
{
    for (int k = 0; k < 3; ++k) p->base_color[k] = rgb[k];
    p->roughness = ggx_roughness(t) ? sqrt(alpha) : alpha;
    switch (t) {
    case PGLOSS_BRIDGE_OPENPBR: /* specular_weight scales F0 (open_pbr_surface.mtlx: scaled_specular_F0) */
        p->ior = 1.5;
        p->specular = f0 / F0_IOR_1_5;
        break;
    case PGLOSS_BRIDGE_GLTF: /* KHR_materials_specular: specularFactor ≤ 1 scales F0; above 0.04 the IOR rises */
        if (f0 <= F0_IOR_1_5) {
            p->ior = 1.5;
            p->specular = f0 / F0_IOR_1_5;
        } else {
            p->ior = ior_of_f0(f0);
            p->specular = 1;
        }
        break;
    case PGLOSS_BRIDGE_GLTF_CORE:
        p->ior = 1.5;
        p->specular = 1;
        break;
    case PGLOSS_BRIDGE_PRINCIPLED: /* Specular IOR Level 0.5 leaves F0 as the IOR gives it */
        p->ior = ior_of_f0(f0);
        p->specular = 0.5;
        break;
    case PGLOSS_BRIDGE_ROUGHPLASTIC_GGX:
    case PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN:
        p->ior = ior_of_f0(f0) * MITSUBA_AIR_IOR;
        p->specular = 1;
        break;
    default: /* Standard Surface: specular 1, the IOR carries F0 */
        p->ior = ior_of_f0(f0);
        p->specular = 1;
        break;
    }
}

/* F0 from the target's parameters (the inverse of params_from's rules). */
static double f0_from(pgloss_bridge_target t, const pgloss_bridge_params *p)
{
    switch (t) {
    case PGLOSS_BRIDGE_OPENPBR: return fmin(p->specular * f0_of_ior(p->ior), 0.99999);
    case PGLOSS_BRIDGE_GLTF:
    case PGLOSS_BRIDGE_GLTF_CORE: return fmin(p->specular * f0_of_ior(p->ior), 1.0);
    case PGLOSS_BRIDGE_PRINCIPLED: return fmin(2 * p->specular * f0_of_ior(p->ior), 1.0);
    case PGLOSS_BRIDGE_ROUGHPLASTIC_GGX:
    case PGLOSS_BRIDGE_ROUGHPLASTIC_BECKMANN: return f0_of_ior(p->ior / MITSUBA_AIR_IOR);
    default: return fmin(p->specular * f0_of_ior(p->ior), 1.0);
    }
}

static void zero_params(pgloss_bridge_params *p) { memset(p, 0, sizeof *p); }

pgloss_status pgloss_bridge_from_perceptual(pgloss_bridge_target target, const pgloss_perceptual *paint,
                                            pgloss_bridge_params *params, pgloss_perceptual *reached)
{
    if (!paint || !params)
        return PGLOSS_ERR_NULL;
    zero_params(params);
    if (reached)
        memset(reached, 0, sizeof *reached);
    if (!valid_target(target))
        return PGLOSS_ERR_ARGUMENT;
    const pgloss_status chk = pgloss_check_perceptual(paint);
    if (chk < 0)
        return chk;
    const double lab[3] = {paint->L, paint->a, paint->b};
    double rgb[3], Y, rho_s;
    pgloss_rgb_from_lab(lab, rgb);
    pgloss_luminance_from_lightness(paint->L, &Y);
    pgloss_specular_from_contrast(Y, paint->c, &rho_s);
    /* The base colour keeps the paint's chromaticity: rgb · β / Y, every channel ≤ 1. */
    const double mx = fmax(rgb[0], fmax(rgb[1], rgb[2]));
    const double chroma[3] = {Y > 0 ? rgb[0] / Y : 1, Y > 0 ? rgb[1] / Y : 1, Y > 0 ? rgb[2] / Y : 1};
    const double beta_max = Y > 0 && mx > 0 ? fmin(1.0, Y / mx) : 1.0;
    const box bx = target_box(target, beta_max);
    const double want[3] = {paint->L, paint->c, paint->d};
    const int model = TARGET_MODEL[target];

    /* Start from the best node of a coarse grid over the box, then refine. The image's
     * products depend on (F0, α) alone: one interpolation serves every β. */
    double u[3] = {0, 0, 0}, best = INFINITY;
    for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 7; ++k) {
            const double f0 = bx.lo[1] + (bx.hi[1] - bx.lo[1]) * j / 4.0, la = bx.lo[2] + (bx.hi[2] - bx.lo[2]) * k / 6.0;
            double prod[PGLOSS__METER_NP];
            const double scale = pgloss__bridge_table_products(&TABLES, model, f0, exp(la), prod);
            for (int i = 0; i < 5; ++i) {
                const double beta = bx.lo[0] + (bx.hi[0] - bx.lo[0]) * i / 4.0;
                double r[4], res[3];
                pgloss__meter_read_target(&TABLES.basis, prod, beta * scale, r);
                residual_of_reading(r, want, res);
                if (norm2(res) < best) {
                    best = norm2(res);
                    u[0] = beta;
                    u[1] = f0;
                    u[2] = la;
                }
            }
        }
    const double f = solve_box(model, &bx, want, u);

    double base[3];
    for (int k = 0; k < 3; ++k) base[k] = chroma[k] * u[0];
    params_from(target, base, u[1], exp(u[2]), params);
    double r[4], L, c, d;
    interpolate(model, u[0], u[1], exp(u[2]), r);
    paint_of_reading(r, &L, &c, &d);
    if (reached) {
        double rY, lab2[3], rgb2[3];
        pgloss_luminance_from_lightness(L, &rY);
        for (int k = 0; k < 3; ++k) rgb2[k] = chroma[k] * rY;
        pgloss_lab_from_rgb(rgb2, lab2);
        reached->L = L;
        reached->a = Y > 0 ? lab2[1] : 0;
        reached->b = Y > 0 ? lab2[2] : 0;
        reached->c = c;
        reached->d = d;
    }
    if (f <= 1e-20)
        return chk; /* OK, or the warning ALPHA_UNTRUSTED */
    /* Out of reach: name the bound the nearest reachable paint sits on. */
    const double tol = 1e-9;
    if (u[0] <= bx.lo[0] + tol || u[0] >= bx.hi[0] - tol)
        return PGLOSS_ERR_BRIDGE_BASE;
    if (bx.hi[1] > bx.lo[1] && (u[1] <= bx.lo[1] + tol || u[1] >= bx.hi[1] - tol))
        return PGLOSS_ERR_BRIDGE_SPECULAR;
    if (u[2] <= bx.lo[2] + tol || u[2] >= bx.hi[2] - tol)
        return PGLOSS_ERR_BRIDGE_ROUGHNESS;
    return PGLOSS_ERR_BRIDGE_SPECULAR; /* the fixed F0 of gltf_core */
}

pgloss_status pgloss_bridge_model_inputs(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                         double *beta, double *f0, double *alpha)
{
    if (!params || !beta || !f0 || !alpha)
        return PGLOSS_ERR_NULL;
    *beta = *f0 = *alpha = 0;
    if (!valid_target(target))
        return PGLOSS_ERR_ARGUMENT;
    const pgloss_bridge_params *p = params;
    if (!isfinite(p->base_color[0]) || !isfinite(p->base_color[1]) || !isfinite(p->base_color[2]) ||
        !isfinite(p->roughness) || !isfinite(p->ior) || !isfinite(p->specular))
        return PGLOSS_ERR_NONFINITE;
    if (p->base_color[0] < 0 || p->base_color[1] < 0 || p->base_color[2] < 0 || !(p->roughness > 0) ||
        !(p->ior > 0) || p->specular < 0)
        return PGLOSS_ERR_NEGATIVE;
    if (target == PGLOSS_BRIDGE_GLTF_CORE && (p->ior != 1.5 || p->specular != 1))
        return PGLOSS_ERR_ARGUMENT;
    pgloss_luminance(p->base_color, beta);
    *f0 = f0_from(target, p);
    *alpha = ggx_roughness(target) ? p->roughness * p->roughness : p->roughness;
    return PGLOSS_OK;
}

pgloss_status pgloss_bridge_params_from_model(pgloss_bridge_target target, const double base_color[3], double f0,
                                              double alpha, pgloss_bridge_params *params)
{
    if (!base_color || !params)
        return PGLOSS_ERR_NULL;
    zero_params(params);
    if (!valid_target(target))
        return PGLOSS_ERR_ARGUMENT;
    if (!isfinite(base_color[0]) || !isfinite(base_color[1]) || !isfinite(base_color[2]) || !isfinite(f0) ||
        !isfinite(alpha))
        return PGLOSS_ERR_NONFINITE;
    if (base_color[0] < 0 || base_color[1] < 0 || base_color[2] < 0 || !(alpha > 0))
        return PGLOSS_ERR_NEGATIVE;
    if (!(f0 > 0 && f0 < 1) || (target == PGLOSS_BRIDGE_GLTF_CORE && f0 != F0_IOR_1_5))
        return PGLOSS_ERR_ARGUMENT;
    params_from(target, base_color, f0, alpha, params);
    return PGLOSS_OK;
}

pgloss_status pgloss_bridge_to_perceptual(pgloss_bridge_target target, const pgloss_bridge_params *params,
                                          pgloss_perceptual *paint, double *residual_out)
{
    if (!params || !paint)
        return PGLOSS_ERR_NULL;
    memset(paint, 0, sizeof *paint);
    if (residual_out)
        *residual_out = 0;
    double beta, f0, alpha;
    pgloss_status st = pgloss_bridge_model_inputs(target, params, &beta, &f0, &alpha);
    if (st != PGLOSS_OK)
        return st;
    const pgloss_bridge_params *p = params;
    if (p->base_color[0] > 1 || p->base_color[1] > 1 || p->base_color[2] > 1)
        st = PGLOSS_ERR_BRIDGE_BASE;
    double r[4];
    const pgloss_status rs = pgloss_bridge_read(target, fmin(beta, 1.0), f0, alpha, r);
    if (st == PGLOSS_OK)
        st = rs;
    double L, c, d, Y;
    paint_of_reading(r, &L, &c, &d);
    pgloss_luminance_from_lightness(L, &Y);
    if (beta > 0) {
        double rgb[3], lab[3];
        for (int k = 0; k < 3; ++k) rgb[k] = p->base_color[k] * Y / beta;
        pgloss_lab_from_rgb(rgb, lab);
        paint->a = lab[1];
        paint->b = lab[2];
    }
    paint->L = L;
    paint->c = c;
    paint->d = d;
    if (residual_out)
        *residual_out = r[3];
    if (st == PGLOSS_OK && r[2] > PGLOSS_ALPHA_TRUSTED_MAX)
        st = PGLOSS_WARN_ALPHA_UNTRUSTED;
    return st;
}
