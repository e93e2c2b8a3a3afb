// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss_bridge_tables — generates libpgloss/src/bridge_tables.inc, the gloss bridge's tables
 * (docs/bridge.md). For each target BRDF model and each node of a grid over its parameters
 * (base luminance β, F0, α), it renders the stimulus sphere's pixels by a deterministic
 * quadrature and reads the image with the bridge's gloss meter: the Ward paint (ρd, ρs, α) of
 * eq. 2 whose image is nearest in luminance least squares. The table holds that reading.
 *
 *   pgloss_bridge_tables OUT.inc          write the tables
 *   pgloss_bridge_tables --check OUT.inc  exit 1 if OUT.inc differs from what would be written
 *   pgloss_bridge_tables --report         print the interpolation errors, the residuals, the control
 *   pgloss_bridge_tables --eval MODEL ETA ALPHA   the model's BRDF × cos θo per direction pair read
 *                                         from stdin ("wi.x wi.y wi.z wo.x wo.y wo.z", local frame):
 *                                         "specular diffuse-per-unit-base"; roughplastic models only
 *                                         (tests/bridge compares it with Mitsuba's own bsdf.eval)
 *
 * The scene is examples/tracer/scenes/stimulus.scene (numbers below, checked against the file
 * when it is given with --scene). Deterministic: no random numbers, fixed loop order, so the
 * output is the same bytes on every machine with IEEE double and the same libm.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bridge_meter.h"
#include "microfacet_d.h"
#include "pgloss/pgloss.h"

static void stamp(const char *what)
{
    if (getenv("PGLOSS_BRIDGE_VERBOSE"))
        fprintf(stderr, "%8.2f s  %s\n", (double)clock() / CLOCKS_PER_SEC, what);
}

#define PI 3.14159265358979323846

/* ---- The stimulus scene (examples/tracer/scenes/stimulus.scene) ---- */
static const double CAM_POS[3] = {0, 1.5, 1.95}, CAM_AT[3] = {0, 0.45, -0.5};
static const double CAM_FOV_DEG = 48.0;
#define IMG_W 160 /* the bridge's image: 160 × 120, the sphere's pixels are those whose */
#define IMG_H 120 /* centre ray hits the sphere (2,114 pixels)                          */
static const double SPH_C[3] = {0, 0.5, -0.5}, SPH_R = 0.5;
static const double BOX_MIN[3] = {-2, 0, -2}, BOX_MAX[3] = {2, 3, 2};
static const double CHECK_SIZE = 0.5, CHECK_OFF = 0.125, CHECK_A = 0.03, CHECK_B = 0.767;
static const double LIGHT_Y = 2.999, LIGHT_X0 = -0.5, LIGHT_X1 = 0.5, LIGHT_Z0 = -1.0,
                    LIGHT_Z1 = 0.0, LIGHT_L = 16.0;

typedef struct { double x, y, z; } v3;
static v3 V(double x, double y, double z) { v3 r = {x, y, z}; return r; }
static v3 add(v3 a, v3 b) { return V(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 sub(v3 a, v3 b) { return V(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 mul(v3 a, double s) { return V(a.x * s, a.y * s, a.z * s); }
static double dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static v3 cross(v3 a, v3 b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static v3 unit(v3 a) { return mul(a, 1.0 / sqrt(dot(a, a))); }
static double comp(v3 a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }

/* The checker of the box (a solid texture, as the tracer's material_index_at). */
static double check_albedo(v3 p)
{
    long q = (long)floor((p.x - CHECK_OFF) / CHECK_SIZE) + (long)floor((p.y - CHECK_OFF) / CHECK_SIZE) +
             (long)floor((p.z - CHECK_OFF) / CHECK_SIZE);
    return (q & 1L) ? CHECK_B : CHECK_A;
}

/* Does the segment from a to b (t in (0, 1)) cross the sphere? */
static int sphere_blocks(v3 a, v3 b)
{
    v3 d = sub(b, a), oc = sub(a, V(SPH_C[0], SPH_C[1], SPH_C[2]));
    double A = dot(d, d), B = dot(oc, d), C = dot(oc, oc) - SPH_R * SPH_R;
    double disc = B * B - A * C;
    if (disc <= 0) return 0;
    double s = sqrt(disc), t0 = (-B - s) / A, t1 = (-B + s) / A;
    (void)t1; /* a and b lie outside the sphere: the first root decides */
    return t0 > 1e-9 && t0 < 1 - 1e-9;
}

/* ---- Walls: six planes, each with a node grid for the irradiance ---- */
#define WALL_H (1.0 / 16.0) /* node spacing of the irradiance grid (m) */
#define PATCH 0.25          /* radiosity patch size (m) */
typedef struct {
    int axis;      /* the plane is comp(p, axis) = pos */
    double pos;
    v3 n;          /* inward normal */
    int ua, va;    /* the two in-plane axes */
    double u0, u1, v0, v1;
    int nu, nv;    /* nodes */
    double *E;     /* irradiance at the nodes */
} wall;
static wall WALLS[6];

static v3 wall_point(const wall *w, double u, double v)
{
    double c[3];
    c[w->axis] = w->pos;
    c[w->ua] = u;
    c[w->va] = v;
    return V(c[0], c[1], c[2]);
}

static void walls_init(void)
{
    for (int k = 0; k < 6; ++k) {
        wall *w = &WALLS[k];
        w->axis = k / 2;
        w->pos = (k % 2) ? BOX_MAX[w->axis] : BOX_MIN[w->axis];
        double n[3] = {0, 0, 0};
        n[w->axis] = (k % 2) ? -1 : 1;
        w->n = V(n[0], n[1], n[2]);
        w->ua = (w->axis + 1) % 3;
        w->va = (w->axis + 2) % 3;
        w->u0 = BOX_MIN[w->ua]; w->u1 = BOX_MAX[w->ua];
        w->v0 = BOX_MIN[w->va]; w->v1 = BOX_MAX[w->va];
        w->nu = (int)lround((w->u1 - w->u0) / WALL_H) + 1;
        w->nv = (int)lround((w->v1 - w->v0) / WALL_H) + 1;
        w->E = calloc((size_t)w->nu * (size_t)w->nv, sizeof(double));
    }
}

/* Direct irradiance from the light at wall point p (normal n), the sphere casting its shadow. */
#define LIGHT_N 12
static double direct_irradiance(v3 p, v3 n)
{
    double sum = 0, dA = (LIGHT_X1 - LIGHT_X0) * (LIGHT_Z1 - LIGHT_Z0) / (LIGHT_N * LIGHT_N);
    for (int i = 0; i < LIGHT_N; ++i)
        for (int j = 0; j < LIGHT_N; ++j) {
            v3 l = V(LIGHT_X0 + (i + 0.5) * (LIGHT_X1 - LIGHT_X0) / LIGHT_N, LIGHT_Y,
                     LIGHT_Z0 + (j + 0.5) * (LIGHT_Z1 - LIGHT_Z0) / LIGHT_N);
            v3 d = sub(l, p);
            double r2 = dot(d, d), r = sqrt(r2);
            double cp = dot(n, d) / r, cl = d.y / r; /* the light faces -y */
            if (cp <= 0 || cl <= 0) continue;
            if (sphere_blocks(p, l)) continue;
            sum += LIGHT_L * cp * cl * dA / r2;
        }
    return sum;
}

/* Radiosity on 0.25 m patches (direct + 10 gathers), then the irradiance at every node. */
typedef struct { v3 c, n; double rho, E, B; int wall; } patch;

static double point_patch_ff(v3 p, v3 n, const patch *q)
{
    /* Form factor from a point to a patch, the patch split 4 × 4 when it is close. */
    v3 d = sub(q->c, p);
    double r2 = dot(d, d);
    int s = r2 < 4 * PATCH * PATCH ? 4 : 1;
    const wall *w = &WALLS[q->wall];
    double uc = comp(q->c, w->ua), vc = comp(q->c, w->va), sum = 0, a = PATCH * PATCH / (s * s);
    for (int i = 0; i < s; ++i)
        for (int j = 0; j < s; ++j) {
            v3 y = wall_point(w, uc + PATCH * ((i + 0.5) / s - 0.5), vc + PATCH * ((j + 0.5) / s - 0.5));
            v3 e = sub(y, p);
            double e2 = dot(e, e), el = sqrt(e2);
            double c1 = dot(n, e) / el, c2 = -dot(q->n, e) / el;
            if (c1 <= 0 || c2 <= 0) continue;
            sum += c1 * c2 * a / (PI * e2);
        }
    if (sum > 0 && sphere_blocks(p, q->c)) sum = 0;
    return sum;
}

static void solve_walls(void)
{
    int np = 0;
    for (int k = 0; k < 6; ++k)
        np += (int)lround((WALLS[k].u1 - WALLS[k].u0) / PATCH) * (int)lround((WALLS[k].v1 - WALLS[k].v0) / PATCH);
    patch *P = calloc((size_t)np, sizeof(patch));
    int m = 0;
    for (int k = 0; k < 6; ++k) {
        const wall *w = &WALLS[k];
        int nu = (int)lround((w->u1 - w->u0) / PATCH), nv = (int)lround((w->v1 - w->v0) / PATCH);
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                patch *q = &P[m++];
                double u = w->u0 + (i + 0.5) * PATCH, v = w->v0 + (j + 0.5) * PATCH;
                q->c = wall_point(w, u, v);
                q->n = w->n;
                q->wall = k;
                q->rho = 0;
                q->E = 0;
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b) {
                        v3 y = wall_point(w, u + PATCH * (a - 0.5) / 2, v + PATCH * (b - 0.5) / 2);
                        q->rho += 0.25 * check_albedo(y);
                        q->E += 0.25 * direct_irradiance(y, w->n);
                    }
            }
    }
    /* Form factors between patches (point at the centre to patch). */
    float *F = malloc(sizeof(float) * (size_t)np * (size_t)np);
    for (int i = 0; i < np; ++i)
        for (int j = 0; j < np; ++j)
            F[(size_t)i * np + j] = (i == j || P[i].wall == P[j].wall) ? 0.0f : (float)point_patch_ff(P[i].c, P[i].n, &P[j]);
    double *Bn = malloc(sizeof(double) * (size_t)np);
    for (int i = 0; i < np; ++i) P[i].B = P[i].rho * P[i].E;
    for (int it = 0; it < 10; ++it) {
        for (int i = 0; i < np; ++i) {
            double g = 0;
            for (int j = 0; j < np; ++j) g += F[(size_t)i * np + j] * P[j].B;
            Bn[i] = P[i].rho * (P[i].E + g);
        }
        for (int i = 0; i < np; ++i) P[i].B = Bn[i];
    }
    /* Nodes: direct at the node, indirect gathered from the patches' radiosity. */
    for (int k = 0; k < 6; ++k) {
        wall *w = &WALLS[k];
        for (int i = 0; i < w->nu; ++i)
            for (int j = 0; j < w->nv; ++j) {
                v3 y = wall_point(w, w->u0 + i * WALL_H, w->v0 + j * WALL_H);
                v3 yin = add(y, mul(w->n, 1e-7));
                double e = direct_irradiance(yin, w->n);
                for (int q = 0; q < np; ++q)
                    if (P[q].wall != k) e += point_patch_ff(yin, w->n, &P[q]) * P[q].B;
                w->E[(size_t)i * w->nv + j] = e;
            }
    }
    free(Bn);
    free(F);
    free(P);
}

static double wall_irradiance(const wall *w, double u, double v)
{
    double fu = (u - w->u0) / WALL_H, fv = (v - w->v0) / WALL_H;
    int i = (int)floor(fu), j = (int)floor(fv);
    if (i < 0) i = 0;
    if (j < 0) j = 0;
    if (i > w->nu - 2) i = w->nu - 2;
    if (j > w->nv - 2) j = w->nv - 2;
    double a = fu - i, b = fv - j;
    const double *E = w->E;
    size_t s = (size_t)w->nv;
    return (1 - a) * ((1 - b) * E[i * s + j] + b * E[i * s + j + 1]) +
           a * ((1 - b) * E[(i + 1) * s + j] + b * E[(i + 1) * s + j + 1]);
}

/* Radiance arriving at x from direction d (unit), x on the sphere, d leaving it. light: 1 to
 * count the light's emission, 0 to leave it out (it is then integrated by explicit sampling). */
static double incident(v3 x, v3 d, int light)
{
    if (d.y > 0) {
        double t = (LIGHT_Y - x.y) / d.y;
        double lx = x.x + t * d.x, lz = x.z + t * d.z;
        if (lx >= LIGHT_X0 && lx <= LIGHT_X1 && lz >= LIGHT_Z0 && lz <= LIGHT_Z1)
            return light ? LIGHT_L : 0.0;
    }
    double tbest = 1e300;
    int kbest = 0;
    for (int a = 0; a < 3; ++a) {
        double da = comp(d, a);
        if (da == 0) continue;
        double t = ((da > 0 ? BOX_MAX[a] : BOX_MIN[a]) - comp(x, a)) / da;
        if (t < tbest) { tbest = t; kbest = 2 * a + (da > 0); }
    }
    const wall *w = &WALLS[kbest];
    v3 y = add(x, mul(d, tbest));
    return check_albedo(y) / PI * wall_irradiance(w, comp(y, w->ua), comp(y, w->va));
}

/* ---- The camera and the sphere's pixels ---- */
typedef struct { v3 f, r, u; double th; } camera;
static camera CAM;
static void camera_init(void)
{
    CAM.f = unit(sub(V(CAM_AT[0], CAM_AT[1], CAM_AT[2]), V(CAM_POS[0], CAM_POS[1], CAM_POS[2])));
    CAM.r = unit(cross(CAM.f, V(0, 1, 0)));
    CAM.u = cross(CAM.r, CAM.f);
    CAM.th = tan(0.5 * CAM_FOV_DEG * PI / 180.0);
}
/* The camera ray through image position (px, py) hits the sphere at x with normal n, view wo. */
static int camera_hit(double px, double py, v3 *x, v3 *n, v3 *wo)
{
    double sx = (2 * px / IMG_W - 1) * ((double)IMG_W / IMG_H) * CAM.th, sy = (1 - 2 * py / IMG_H) * CAM.th;
    v3 d = unit(add(CAM.f, add(mul(CAM.r, sx), mul(CAM.u, sy))));
    v3 o = V(CAM_POS[0], CAM_POS[1], CAM_POS[2]), oc = sub(o, V(SPH_C[0], SPH_C[1], SPH_C[2]));
    double b = dot(d, oc), c = dot(oc, oc) - SPH_R * SPH_R, disc = b * b - c;
    if (disc <= 0) return 0;
    double t = -b - sqrt(disc);
    *x = add(o, mul(d, t));
    *n = unit(sub(*x, V(SPH_C[0], SPH_C[1], SPH_C[2])));
    *wo = mul(d, -1);
    return 1;
}

static void frame(v3 n, v3 *s, v3 *t)
{
    *s = unit(fabs(n.x) > 0.5 ? cross(n, V(0, 1, 0)) : cross(n, V(1, 0, 0)));
    *t = cross(n, *s);
}

static double frac(double x) { return x - floor(x); }

/* Pixels and their quadrature. Specular: per pixel, NR × NA half-vector cells (a cap, then
 * rings log-spaced in θh up to π/2), each cell with its own sub-pixel position (an R2
 * sequence), so one sample covers the pixel and the cell. Diffuse: SUB × SUB sub-pixel shading
 * points, each with the light sampled on a grid and the walls by stratified cosine directions. */
#define NR 48
#define NA 20
#define NS (NR * NA)
#define TH0 0.0006
#define SUB 3
#define HEMI 16
#define NMU 32 /* hat-function bins in μi for the diffuse moments */
typedef struct { float mo, mi, t2, cd, w; } spec_sample; /* μo, μi, tan²θh, ωo·h, weight */
static int NPIX;
static spec_sample *SS; /* NPIX × NS */
static double *DIFF_MO; /* NPIX × SUB² : μo at the diffuse shading points (−1 where it misses) */
static double *DIFF_H;  /* NPIX × SUB² × NMU : irradiance/π binned by μi (hat functions) */

static void hat_add(double *H, double mu, double val)
{
    double f = mu * (NMU - 1);
    int i = (int)floor(f);
    if (i >= NMU - 1) i = NMU - 2;
    if (i < 0) i = 0;
    double a = f - i;
    H[i] += (1 - a) * val;
    H[i + 1] += a * val;
}

static void build_samples(void)
{
    int cnt = 0;
    v3 x, n, wo;
    for (int py = 0; py < IMG_H; ++py)
        for (int px = 0; px < IMG_W; ++px) cnt += camera_hit(px + 0.5, py + 0.5, &x, &n, &wo);
    NPIX = cnt;
    SS = calloc((size_t)NPIX * NS, sizeof(spec_sample));
    DIFF_MO = calloc((size_t)NPIX * SUB * SUB, sizeof(double));
    DIFF_H = calloc((size_t)NPIX * SUB * SUB * NMU, sizeof(double));
    double q = pow(0.5 * PI / TH0, 1.0 / (NR - 1));
    int p = 0;
    for (int py = 0; py < IMG_H; ++py)
        for (int px = 0; px < IMG_W; ++px) {
            if (!camera_hit(px + 0.5, py + 0.5, &x, &n, &wo)) continue;
            double poff = frac(p * 0.6180339887498949);
            for (int r = 0; r < NR; ++r) {
                double ta = r == 0 ? 0 : TH0 * pow(q, r - 1), tb = TH0 * pow(q, r);
                if (r == NR - 1) tb = 0.5 * PI;
                double ca = cos(ta), cb = cos(tb), area = (ca - cb) * 2 * PI / NA;
                double ch = 0.5 * (ca + cb), sh = sqrt(1 - ch * ch);
                for (int a = 0; a < NA; ++a) {
                    int j = r * NA + a;
                    spec_sample *s = &SS[(size_t)p * NS + j];
                    double sx = frac(0.5 + poff + j * 0.7548776662466927), sy = frac(0.5 + poff + j * 0.5698402909980532);
                    v3 xs, ns, ws, t1, t2;
                    if (!camera_hit(px + sx, py + sy, &xs, &ns, &ws)) continue;
                    double phi = 2 * PI * (a + frac(r * 0.6180339887498949 + poff)) / NA;
                    frame(ns, &t1, &t2);
                    v3 h = add(mul(ns, ch), add(mul(t1, sh * cos(phi)), mul(t2, sh * sin(phi))));
                    double oh = dot(ws, h), mo = dot(ns, ws);
                    if (oh <= 0 || mo <= 0) continue;
                    v3 wi = sub(mul(h, 2 * oh), ws);
                    double mi = dot(ns, wi);
                    if (mi <= 0) continue;
                    double L = incident(add(xs, mul(ns, 1e-9)), wi, 1);
                    s->mo = (float)mo;
                    s->mi = (float)mi;
                    s->t2 = (float)((1 - ch * ch) / (ch * ch));
                    s->cd = (float)oh;
                    s->w = (float)(L * mi * 4 * oh * area);
                }
            }
            for (int k = 0; k < SUB * SUB; ++k) {
                double sx = (k % SUB + 0.5) / SUB, sy = (k / SUB + 0.5) / SUB;
                v3 xs, ns, ws, t1, t2;
                double *H = &DIFF_H[((size_t)p * SUB * SUB + k) * NMU];
                if (!camera_hit(px + sx, py + sy, &xs, &ns, &ws)) { DIFF_MO[(size_t)p * SUB * SUB + k] = -1; continue; }
                DIFF_MO[(size_t)p * SUB * SUB + k] = dot(ns, ws);
                v3 xo = add(xs, mul(ns, 1e-9));
                frame(ns, &t1, &t2);
                double dA = (LIGHT_X1 - LIGHT_X0) * (LIGHT_Z1 - LIGHT_Z0) / (4.0 * LIGHT_N * LIGHT_N);
                for (int i = 0; i < 2 * LIGHT_N; ++i)
                    for (int jj = 0; jj < 2 * LIGHT_N; ++jj) {
                        v3 l = V(LIGHT_X0 + (i + 0.5) * (LIGHT_X1 - LIGHT_X0) / (2 * LIGHT_N), LIGHT_Y,
                                 LIGHT_Z0 + (jj + 0.5) * (LIGHT_Z1 - LIGHT_Z0) / (2 * LIGHT_N));
                        v3 d = sub(l, xo);
                        double r2 = dot(d, d), rr = sqrt(r2), mu = dot(ns, d) / rr, cl = d.y / rr;
                        if (mu <= 0 || cl <= 0) continue;
                        hat_add(H, mu, LIGHT_L * mu * cl * dA / r2 / PI);
                    }
                for (int i = 0; i < HEMI; ++i)
                    for (int jj = 0; jj < HEMI; ++jj) {
                        double u1 = (i + 0.5) / HEMI, u2 = (jj + frac(0.5 + i * 0.6180339887498949)) / HEMI;
                        double mu = sqrt(1 - u1), st = sqrt(u1), ph = 2 * PI * u2;
                        v3 d = add(mul(ns, mu), add(mul(t1, st * cos(ph)), mul(t2, st * sin(ph))));
                        /* cosine-weighted: ∫ L μ dω / π ≈ mean of L */
                        hat_add(H, mu, incident(xo, d, 0) / (HEMI * HEMI));
                    }
            }
            ++p;
        }
}

/* ---- The target BRDF models (docs/bridge.md cites each source) ---- */
enum { M_PRINCIPLED, M_MATERIALX, M_RP_GGX, M_RP_BECKMANN, M_COUNT };
static const char *const MODEL_NAME[M_COUNT] = {"principled", "materialx", "roughplastic_ggx",
                                                "roughplastic_beckmann"};

/* The models' Fresnel, D and G are the library's (microfacet_d.h), which the glossmeter of bridge
 * targets evaluates too; M_* here number the models as its PGLOSS__MF_* do. */
static inline double f0_of_eta(double eta) { return ((eta - 1) / (eta + 1)) * ((eta - 1) / (eta + 1)); }
static double eta_of_f0(double f0) { double s = sqrt(f0); return (1 + s) / (1 - s); }

/* Ring r of the albedo quadrature over the half vector (96 rings, log-spaced in θh from a 1e-4
 * cap to π/2, 48 cells over a half circle): its centre cosine and sine, cell area, tan²θh;
 * and the cells' cos φ. Computed once (hring_init). */
#define HR 96
#define HA 48
static struct { double ch, sh, area, t2; } HRING[HR];
static double HCOS[HA];
static void hring_init(void)
{
    const double q = pow(0.5 * PI / 1e-4, 1.0 / (HR - 1));
    for (int r = 0; r < HR; ++r) {
        double ta = r == 0 ? 0 : 1e-4 * pow(q, r - 1), tb = r == HR - 1 ? 0.5 * PI : 1e-4 * pow(q, r);
        double ca = cos(ta), cb = cos(tb), ch = 0.5 * (ca + cb);
        HRING[r].ch = ch;
        HRING[r].sh = sqrt(1 - ch * ch);
        HRING[r].area = (ca - cb) * PI / HA;
        HRING[r].t2 = (1 - ch * ch) / (ch * ch);
    }
    for (int k = 0; k < HA; ++k) HCOS[k] = cos(PI * (k + 0.5) / HA);
}

/* Integral over the half vector h of g(h) for a view at cosine mu in the local frame:
 * directional albedos. kind 0: D G /(4 μo) (F = 1); 1: times F(ωo·h, eta); 2: times Schlick's
 * (1 − ωo·h)^5. Log-polar rings in θh as the pixel quadrature, 96 × 48 cells over a half
 * circle (the integrand is even in φ). */
static double albedo(int m, double mu, double a, int kind, double eta)
{
    double so = sqrt(1 - mu * mu), sum = 0;
    for (int r = 0; r < HR; ++r) {
        const double ch = HRING[r].ch, sh = HRING[r].sh, area = HRING[r].area, t2 = HRING[r].t2;
        for (int k = 0; k < HA; ++k) {
            double oh = so * sh * HCOS[k] + mu * ch;
            if (oh <= 0) continue;
            double mi = 2 * oh * ch - mu;
            if (mi <= 0) continue;
            double f = pgloss__mf_DG_d(m, mi, mu, t2, a) / (4 * mi * mu);
            if (kind == 1) f *= pgloss__fresnel_any_d(oh, eta);
            if (kind == 2) f *= pow(1 - oh, 5);
            sum += 2 * f * mi * 4 * oh * area;
        }
    }
    return sum;
}

/* Mitsuba's rough-interface transmittance t(μ) (eval_transmittance) and reflectance
 * (eval_reflectance), by the same integral over microfacet normals m: the visible normals
 * D(m) G1(wi, m) (wi·m)/μ dω_m (no cos θm: they integrate to 1), times (1 − F) G1(refracted)
 * or F G1(reflected). Divided by the rings' own sum of the visible normals, which cancels
 * their midpoint rule's bias (−0.34 % at every α) and meets Mitsuba's Gauss-Legendre values
 * to 1e-4 (docs/bridge.md). */
static double rough_interface(int m, double mu, double a, double eta, int transmit)
{
    const double g1i = m == M_RP_BECKMANN ? pgloss__beck_G1_d(mu, a) : 1 / (1 + pgloss__ggx_lambda_d(mu, a));
    double so = sqrt(1 - mu * mu), sum = 0, norm = 0;
    for (int r = 0; r < HR; ++r) {
        const double ch = HRING[r].ch, sh = HRING[r].sh, area = HRING[r].area, t2 = HRING[r].t2;
        const double D = m == M_RP_BECKMANN ? pgloss__beck_D_d(t2, a) : pgloss__ggx_D_d(t2, a);
        for (int k = 0; k < HA; ++k) {
            double c = so * sh * HCOS[k] + mu * ch; /* wi·m */
            if (c <= 0) continue;
            const double vis = 2 * D * g1i * c / mu * area; /* the visible normals' measure */
            norm += vis;
            double F = pgloss__fresnel_any_d(c, eta), vz, val;
            if (transmit) {
                double ct2 = 1 - (1 - c * c) / (eta * eta);
                if (ct2 <= 0) continue;
                vz = -mu / eta + ch * (c / eta - sqrt(ct2)); /* z of the refracted direction */
                if (vz >= 0) continue;
                val = 1 - F;
            } else {
                vz = 2 * c * ch - mu;
                if (vz <= 0) continue;
                val = F;
            }
            /* |v| = 1 for both the reflected and the refracted direction: |vz| is its cosine. */
            double g1o = m == M_RP_BECKMANN ? pgloss__beck_G1_d(fabs(vz), a) : 1 / (1 + pgloss__ggx_lambda_d(fabs(vz), a));
            sum += vis * val * g1o;
        }
    }
    return sum / norm;
}

/* ---- Images over the sphere's pixels ---- */
#define NMO 33 /* μ nodes of the per-view factors */
static double interp_mu(const double *t, double mu)
{
    double f = mu * (NMO - 1);
    int i = (int)floor(f);
    if (i >= NMO - 1) i = NMO - 2;
    if (i < 0) i = 0;
    return t[i] + (f - i) * (t[i + 1] - t[i]);
}

/* The Lambertian image (ρd = 1): each pixel's irradiance / π, averaged over its sub-pixels. */
static void image_lambert(double *img, const double *view_factor /* NMO or NULL */,
                          const double *mu_factor /* NMU or NULL */)
{
    for (int p = 0; p < NPIX; ++p) {
        double sum = 0;
        for (int k = 0; k < SUB * SUB; ++k) {
            double mo = DIFF_MO[(size_t)p * SUB * SUB + k];
            if (mo < 0) continue;
            const double *H = &DIFF_H[((size_t)p * SUB * SUB + k) * NMU];
            double e = 0;
            for (int b = 0; b < NMU; ++b) e += H[b] * (mu_factor ? mu_factor[b] : 1.0);
            sum += e * (view_factor ? interp_mu(view_factor, mo) : 1.0);
        }
        img[p] = sum / (SUB * SUB);
    }
}

/* Ward's specular lobe, eq. 2, on the pixel samples: the same formula as pgloss_eval's
 * PGLOSS_NORM_WARD, written here on (tan²θh, μi, μo) in double because the samples store
 * those, not directions. */
static void image_ward(double *img, double a)
{
    for (int p = 0; p < NPIX; ++p) {
        double sum = 0;
        const spec_sample *s = &SS[(size_t)p * NS];
        for (int j = 0; j < NS; ++j) {
            if (s[j].w == 0) continue;
            sum += s[j].w * exp(-s[j].t2 / (a * a)) / (4 * PI * a * a * sqrt((double)s[j].mi * s[j].mo));
        }
        img[p] = sum;
    }
}

/* A target's specular lobe with Fresnel at eta and a per-view factor (NMO table or NULL).
 * The lobe's D G w / (4 μi μo) per sample depends on the model and α only: it is kept for the
 * last (model, α), and the Fresnel factor comes from a table in ωo·h for each eta. */
#define NFT 4097
static double *GBUF;
static int GBUF_M = -1;
static double GBUF_A = -1;
static void image_spec(double *img, int m, double a, double eta, const double *view_factor)
{
    if (!GBUF) GBUF = malloc(sizeof(double) * (size_t)NPIX * NS);
    if (GBUF_M != m || GBUF_A != a) {
        for (size_t j = 0; j < (size_t)NPIX * NS; ++j) {
            const spec_sample *s = &SS[j];
            GBUF[j] = s->w == 0 ? 0 : s->w * pgloss__mf_DG_d(m, s->mi, s->mo, s->t2, a) / (4.0 * s->mi * s->mo);
        }
        GBUF_M = m;
        GBUF_A = a;
    }
    static double Ft[NFT];
    for (int k = 0; k < NFT; ++k) Ft[k] = pgloss__fresnel_any_d(k == 0 ? 1e-6 : (double)k / (NFT - 1), eta);
    for (int p = 0; p < NPIX; ++p) {
        double sum = 0;
        const spec_sample *s = &SS[(size_t)p * NS];
        const double *G = &GBUF[(size_t)p * NS];
        for (int j = 0; j < NS; ++j) {
            if (G[j] == 0) continue;
            double f = s[j].cd * (NFT - 1);
            int i = (int)f;
            if (i > NFT - 2) i = NFT - 2;
            double F = Ft[i] + (f - i) * (Ft[i + 1] - Ft[i]);
            sum += G[j] * F * (view_factor ? interp_mu(view_factor, s[j].mo) : 1.0);
        }
        img[p] = sum;
    }
}

/* ---- The gloss meter of the bridge: Ward (ρd, ρs, α) by luminance least squares ---- */
/* The meter itself (pgloss__meter_*) is libpgloss/src/bridge_meter.h, shared with the library. */
#define NW PGLOSS__METER_NW
#define NP PGLOSS__METER_NP
static double w_alpha(int k)
{
    return PGLOSS__METER_AMIN * pow(PGLOSS__METER_AMAX / PGLOSS__METER_AMIN, (double)k / (NW - 1));
}
static double *WIMG; /* NW × NPIX: the Ward node images */
static double *DIMG; /* NPIX: Lambert */
static double GRAM[NW * 7], DW[NW];
static pgloss__meter_basis BASIS;

static double inner(const double *x, const double *y)
{
    double s = 0;
    for (int p = 0; p < NPIX; ++p) s += x[p] * y[p];
    return s;
}

static void meter_init(void)
{
    for (int k = 0; k < NW; ++k) {
        DW[k] = inner(DIMG, &WIMG[(size_t)k * NPIX]);
        for (int o = -3; o <= 3; ++o)
            GRAM[k * 7 + o + 3] = k + o >= 0 && k + o < NW ? inner(&WIMG[(size_t)k * NPIX], &WIMG[(size_t)(k + o) * NPIX]) : 0;
    }
    BASIS.gram = GRAM;
    BASIS.dw = DW;
    BASIS.dd = inner(DIMG, DIMG);
}

/* The products of a target's diffuse and specular images (bridge_meter.h's layout). */
static void products(const double *Dt, const double *St, double *P)
{
    for (int k = 0; k < NW; ++k) {
        P[k] = inner(Dt, &WIMG[(size_t)k * NPIX]);
        P[NW + k] = inner(St, &WIMG[(size_t)k * NPIX]);
    }
    P[2 * NW] = inner(Dt, DIMG);
    P[2 * NW + 1] = inner(St, DIMG);
    P[2 * NW + 2] = inner(Dt, Dt);
    P[2 * NW + 3] = inner(Dt, St);
    P[2 * NW + 4] = inner(St, St);
}

/* The reading of an image X (NPIX). */
static void meter(const double *X, double out[4])
{
    double xw[NW];
    for (int k = 0; k < NW; ++k) xw[k] = inner(X, &WIMG[(size_t)k * NPIX]);
    pgloss__meter_read(&BASIS, xw, inner(X, DIMG), inner(X, X), out);
}

/* ---- One target model at one (F0, α) node: its diffuse image per unit β and its specular image ---- */
static double trap_mu(const double *t) /* 2 ∫ t(μ) μ dμ over the NMO nodes */
{
    double s = 0;
    for (int i = 0; i < NMO - 1; ++i) {
        double m0 = (double)i / (NMO - 1), m1 = (double)(i + 1) / (NMO - 1);
        s += 0.5 * (t[i] * m0 + t[i + 1] * m1) * (m1 - m0);
    }
    return 2 * s;
}
static double mu_node(int i) { return i == 0 ? 1e-3 : (double)i / (NMO - 1); }

/* Mitsuba's table of t(μ): MI_RES nodes on [0, 1], linear between them (lerp_gather). */
#define MI_RES 64
static double mi_lerp(const double *t, double mu)
{
    const double f = mu * (MI_RES - 1);
    int i = (int)f;
    if (i > MI_RES - 2) i = MI_RES - 2;
    return t[i] + (f - i) * (t[i + 1] - t[i]);
}

/* Mitsuba's internal reflectance R_int = 2 · mean_k R(μ_k) μ_k over the 64 nodes of its t table
 * (roughplastic.cpp). That mean is not a quadrature rule (it weighs μ = 0 and 1 fully and
 * divides by 64): it sits 1–10 % of 1 − R_int below 2∫Rμ dμ (docs/bridge.md), and below
 * α ≈ 0.01 it steps with F0 as the critical angle crosses its nodes. Mitsuba's renders follow
 * it, so the model does. */
static double mitsuba_rint(int m, double f0, double a)
{
    const double eta = eta_of_f0(f0);
    double s = 0;
    for (int k = 0; k < MI_RES; ++k) {
        const double mu = fmax(1e-6, (double)k / (MI_RES - 1));
        s += rough_interface(m, mu, a, 1 / eta, 0) * mu;
    }
    return 2 * s / MI_RES;
}

/* The factor of the diffuse image that target_images leaves out: 1/(η² (1 − R_int)) for
 * roughplastic, 1 for the layered models. */
static double diffuse_scale(int m, double f0, double a)
{
    if (m == M_PRINCIPLED || m == M_MATERIALX) return 1;
    const double eta = eta_of_f0(f0);
    return 1 / (eta * eta * (1 - mitsuba_rint(m, f0, a)));
}

static void target_images(int m, double f0, double a, double *Dt, double *St)
{
    double eta = eta_of_f0(f0), E[NMO], vf[NMO], df[NMO];
    if (m == M_PRINCIPLED || m == M_MATERIALX) {
        static double S5[NMO], Ec[NMO], last_a = -1;
        static int last_m = -1;
        double EF[NMO], Fh[NMO];
        if (last_m != m || last_a != a) { /* E and S5 do not depend on eta */
            for (int i = 0; i < NMO; ++i) {
                Ec[i] = albedo(m, mu_node(i), a, 0, eta);
                S5[i] = albedo(m, mu_node(i), a, 2, eta);
            }
            last_m = m;
            last_a = a;
        }
        for (int i = 0; i < NMO; ++i) {
            E[i] = Ec[i];
            EF[i] = albedo(m, mu_node(i), a, 1, eta);
            Fh[i] = pgloss__fresnel_any_d(mu_node(i), eta);
        }
        double Eavg = trap_mu(E);
        if (m == M_PRINCIPLED) {
            /* Cycles: energy_scale × darkening = 1 + Fms (1 − E)/E (microfacet_ggx_preserve_energy),
             * Fms from Kulla & Conty; the base is weighted by 1 − albedo of the layer. */
            double Fss = trap_mu(Fh), Fms = Fss * Eavg / (1 - Fss * (1 - Eavg));
            for (int i = 0; i < NMO; ++i) {
                vf[i] = 1 + Fms * (1 - E[i]) / E[i];
                df[i] = 1 - vf[i] * EF[i];
            }
        } else {
            /* MaterialX: comp = 1 + Fss (1 − E)/E with Fss = F0 + (1 − F0)/21
             * (mx_ggx_energy_compensation); throughput 1 − comp · (F0 A + B) (mx_dielectric_bsdf). */
            double Fss = f0 + (1 - f0) / 21.0;
            for (int i = 0; i < NMO; ++i) {
                vf[i] = 1 + Fss * (1 - E[i]) / E[i];
                df[i] = 1 - vf[i] * (f0 * (E[i] - S5[i]) + S5[i]);
            }
        }
        image_lambert(Dt, df, NULL);
        image_spec(St, m, a, eta, vf);
    } else {
        /* Mitsuba roughplastic (nonlinear = false): R t(μi) t(μo) / (π η² (1 − R_int)), with
         * Mitsuba's own table of t (src/bsdfs/roughplastic.cpp, MI_ROUGH_TRANSMITTANCE_RES):
         * t at μ_k = max(1e-6, k/63), k < 64, looked up linearly (lerp_gather). The factor
         * 1/(η² (1 − R_int)) is left out here: it is diffuse_scale, tabulated apart. */
        double tm[MI_RES], tb[NMU];
        for (int k = 0; k < MI_RES; ++k) tm[k] = rough_interface(m, fmax(1e-6, (double)k / (MI_RES - 1)), a, eta, 1);
        for (int i = 0; i < NMO; ++i) vf[i] = mi_lerp(tm, mu_node(i));
        for (int b = 0; b < NMU; ++b) tb[b] = mi_lerp(tm, (double)b / (NMU - 1));
        image_lambert(Dt, vf, tb);
        image_spec(St, m, a, eta, NULL);
    }
}

/* roughplastic's BRDF × μo at one direction pair (the images' integrand, written per direction for
 * the comparison with Mitsuba's bsdf.eval, which returns f · cos θo): the specular term of
 * image_spec and the diffuse of target_images per unit diffuse_reflectance, with diffuse_scale. */
static void rp_eval(int m, double eta, double a, const double *tm, double rint, const double wi[3],
                    const double wo[3], double out[2])
{
    out[0] = out[1] = 0;
    if (wi[2] <= 0 || wo[2] <= 0) return;
    double h[3] = {wi[0] + wo[0], wi[1] + wo[1], wi[2] + wo[2]};
    const double hn = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    for (int k = 0; k < 3; ++k) h[k] /= hn;
    const double t2 = (1 - h[2] * h[2]) / (h[2] * h[2]), oh = wo[0] * h[0] + wo[1] * h[1] + wo[2] * h[2];
    out[0] = pgloss__fresnel_any_d(oh, eta) * pgloss__mf_DG_d(m, wi[2], wo[2], t2, a) / (4 * wi[2]);
    out[1] = mi_lerp(tm, wi[2]) * mi_lerp(tm, wo[2]) * wo[2] / (PI * eta * eta * (1 - rint));
}

static int eval_main(const char *model, double eta, double a)
{
    int m = !strcmp(model, "roughplastic_ggx") ? M_RP_GGX : !strcmp(model, "roughplastic_beckmann") ? M_RP_BECKMANN : -1;
    if (m < 0 || !(eta > 1) || !(a > 0)) {
        fprintf(stderr, "pgloss_bridge_tables --eval: MODEL is roughplastic_ggx or roughplastic_beckmann, ETA > 1, ALPHA > 0\n");
        return 2;
    }
    hring_init();
    double tm[MI_RES], wi[3], wo[3], v[2];
    for (int k = 0; k < MI_RES; ++k) tm[k] = rough_interface(m, fmax(1e-6, (double)k / (MI_RES - 1)), a, eta, 1);
    const double rint = mitsuba_rint(m, f0_of_eta(eta), a);
    while (scanf("%lf %lf %lf %lf %lf %lf", &wi[0], &wi[1], &wi[2], &wo[0], &wo[1], &wo[2]) == 6) {
        rp_eval(m, eta, a, tm, rint, wi, wo, v);
        printf("%.9g %.9g\n", v[0], v[1]);
    }
    return 0;
}

/* ---- The table grid ---- */
/* √F0 and log α evenly spaced; each axis has one node beyond each end of the range it
 * covers, so that the Catmull-Rom cells inside the range all have their four true nodes
 * (docs/bridge.md measures the choices with --report). */
#ifndef NF0
#define NF0 13
#endif
#ifndef NAT
#define NAT 22
#endif
static const double F0_MIN = 0.01, F0_MAX = 0.25, AT_MIN = 0.004, AT_MAX = 0.35;
#define NCHECK 24
static double f0_at(double u)
{
    const double s = sqrt(F0_MIN) + (sqrt(F0_MAX) - sqrt(F0_MIN)) * (u - 1) / (NF0 - 3);
    return s * s;
}
static double at_at(double u) { return AT_MIN * pow(AT_MAX / AT_MIN, (u - 1) / (NAT - 3)); }

/* Mitsuba's R_int steps with F0 at small α (mitsuba_rint): it has its own table, F0 linear on
 * NFR nodes (one beyond each end again), α on the products' nodes. */
#ifndef NFR
#define NFR 51
#endif
#define M_RP0 M_RP_GGX /* the first roughplastic model; R_int tables for M_RP0 .. M_COUNT − 1 */
static double fr_at(double u) { return F0_MIN + (F0_MAX - F0_MIN) * (u - 1) / (NFR - 3); }
static float *RINT; /* (M_COUNT − M_RP0) × NAT × NFR */

static float *TAB;    /* M_COUNT × NF0 × NAT × NP: the products */
static pgloss__bridge_tables TABLES; /* TAB and RINT as the library reads them */
static double *CHECK; /* M_COUNT × NCHECK × 7: (β, F0, α) and the reading there */

static void fill_model(int m, double *Dt, double *St)
{
    for (int j = 0; j < NAT; ++j) /* α outer: target_images keeps the lobe of the last α */
        for (int i = 0; i < NF0; ++i) {
            double P[NP];
            target_images(m, f0_at(i), at_at(j), Dt, St);
            products(Dt, St, P);
            for (int q = 0; q < NP; ++q) TAB[(((size_t)m * NF0 + i) * NAT + j) * NP + q] = (float)P[q];
        }
    if (m >= M_RP0)
        for (int j = 0; j < NAT; ++j)
            for (int i = 0; i < NFR; ++i) RINT[((size_t)(m - M_RP0) * NAT + j) * NFR + i] = (float)mitsuba_rint(m, fr_at(i), at_at(j));
}

/* A fixed low-discrepancy point k of the table's box (F0 linear, α log), salt picking the set. */
static void ld_point(int k, int salt, double *beta, double *f0, double *a)
{
    *beta = frac(0.5 + (k + salt) * 0.8191725133961645);
    *f0 = F0_MIN + (F0_MAX - F0_MIN) * frac(0.5 + (k + salt) * 0.6710436067037893);
    *a = AT_MIN * pow(AT_MAX / AT_MIN, frac(0.5 + (k + salt) * 0.5497004779019703));
}

/* Off-grid readings, rendered, for the library's interpolation test (test_bridge). */
static void fill_checks(int m, double *Dt, double *St)
{
    for (int k = 0; k < NCHECK; ++k) {
        double beta, f0, a, P[NP], r[4];
        ld_point(k, 0, &beta, &f0, &a);
        target_images(m, f0, a, Dt, St);
        products(Dt, St, P);
        pgloss__meter_read_target(&BASIS, P, beta * diffuse_scale(m, f0, a), r);
        double *c = &CHECK[((size_t)m * NCHECK + k) * 7];
        c[0] = beta; c[1] = f0; c[2] = a; c[3] = r[0]; c[4] = r[1]; c[5] = r[2]; c[6] = r[3];
    }
}

/* L*, c, d of a reading. */
static void lcd(const double r[4], double o[3])
{
    pgloss_lightness_from_luminance(fmax(r[0], 0), &o[0]);
    pgloss_contrast_gloss(fmax(r[0], 0), fmax(r[1], 0), &o[1]);
    o[2] = 1 - r[2];
}

static int cmp_double(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* --report: the tables' interpolation error against rendered readings at NREP off-grid
 * (F0, α) points per model, each at β = 0, 1/8, …, 1, in three bands of α; and the residuals. */
#define NREP 60
#define NBREP 9
static void report_model(int m, double *Dt, double *St)
{
    static const double band[4] = {0.004, 0.01, 0.1, 0.35};
    double err[3][3][NREP * NBREP], res[NREP];
    int n[3] = {0, 0, 0};
    for (int k = 0; k < NREP; ++k) {
        double beta0, f0, a, P[NP];
        ld_point(k, 1000, &beta0, &f0, &a);
        target_images(m, f0, a, Dt, St);
        products(Dt, St, P);
        const double se = diffuse_scale(m, f0, a);
        int bd = a < band[1] ? 0 : a < band[2] ? 1 : 2;
        for (int b = 0; b < NBREP; ++b) {
            double beta = (double)b / (NBREP - 1), r[4], q[4], x[3], y[3];
            pgloss__meter_read_target(&BASIS, P, beta * se, r);
            pgloss__bridge_table_read(&TABLES, m, beta, f0, a, q);
            lcd(r, x);
            lcd(q, y);
            for (int e = 0; e < 3; ++e) err[bd][e][n[bd]] = fabs(x[e] - y[e]);
            ++n[bd];
        }
        double r[4];
        pgloss__meter_read_target(&BASIS, P, beta0 * se, r);
        res[k] = r[3];
    }
    for (int bd = 0; bd < 3; ++bd) {
        if (!n[bd]) continue;
        double w[3], p95[3];
        for (int e = 0; e < 3; ++e) {
            qsort(err[bd][e], (size_t)n[bd], sizeof(double), cmp_double);
            w[e] = err[bd][e][n[bd] - 1];
            p95[e] = err[bd][e][(int)(0.95 * (n[bd] - 1))];
        }
        printf("| %-21s | %5.3f-%5.3f | %4d | %.3f / %.3f | %.5f / %.5f | %.5f / %.5f |\n", MODEL_NAME[m], band[bd],
               band[bd + 1], n[bd], p95[0], w[0], p95[1], w[1], p95[2], w[2]);
    }
    qsort(res, NREP, sizeof(double), cmp_double);
    printf("| %-21s | residual | min %.3f | median %.3f | max %.3f |\n", MODEL_NAME[m], res[0], res[NREP / 2],
           res[NREP - 1]);
}

static void print_array(FILE *f, const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) fprintf(f, "%.17g,%s", v[i], (i % 4 == 3) ? "\n" : " ");
    if (n % 4) fputc('\n', f);
}

/* The products and R_int are floats (printed to round-trip exactly): rounding them to 7 digits
 * moves no reading of --report's test points by more than 1e-5 in c or d (docs/bridge.md). */
static void print_floats(FILE *f, const float *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) fprintf(f, "%.9g,%s", (double)v[i], (i % 6 == 5) ? "\n" : " ");
    if (n % 6) fputc('\n', f);
}

static void write_tables(FILE *f)
{
    fprintf(f, "/* SPDX-FileCopyrightText: 2026 The pgloss authors\n * SPDX-License-Identifier: Apache-2.0\n"
               " * GENERATED by tools/bridge_tables.c (pgloss_bridge_tables): do not edit. docs/bridge.md\n"
               " * says what the numbers are: the meter's Ward basis of the stimulus sphere (Gram band,\n"
               " * <D, W_k>, <D, D>); per target model, per (F0, alpha) node, the products of its diffuse\n"
               " * and specular images (libpgloss/src/bridge_meter.h's layout); then off-grid checks\n"
               " * (beta, F0, alpha, rho_d, rho_s, alpha, residual) for the interpolation test. */\n");
    fprintf(f, "#if PGLOSS__METER_NW != %d\n#error \"bridge_tables.inc: made for another Ward basis\"\n#endif\n", NW);
    fprintf(f, "#define PGLOSS__BRIDGE_MODELS %d\n#define PGLOSS__BRIDGE_NF0 %d\n#define PGLOSS__BRIDGE_NAT %d\n"
               "#define PGLOSS__BRIDGE_NCHECK %d\n",
            M_COUNT, NF0, NAT, NCHECK);
    fprintf(f, "#define PGLOSS__BRIDGE_F0_MIN %.17g\n#define PGLOSS__BRIDGE_F0_MAX %.17g\n"
               "#define PGLOSS__BRIDGE_AT_MIN %.17g\n#define PGLOSS__BRIDGE_AT_MAX %.17g\n"
               "#define PGLOSS__BRIDGE_SPHERE_PIXELS %d\n",
            F0_MIN, F0_MAX, AT_MIN, AT_MAX, NPIX);
    fprintf(f, "static const double pgloss__bridge_gram[%d * 7] = {\n", NW);
    print_array(f, GRAM, (size_t)NW * 7);
    fprintf(f, "};\nstatic const double pgloss__bridge_dw[%d] = {\n", NW);
    print_array(f, DW, NW);
    fprintf(f, "};\n#define PGLOSS__BRIDGE_DD %.17g\n", BASIS.dd);
    fprintf(f, "static const float pgloss__bridge_products[%d * %d * %d * %d] = {\n", M_COUNT, NF0, NAT, NP);
    print_floats(f, TAB, (size_t)M_COUNT * NF0 * NAT * NP);
    fprintf(f, "};\n#define PGLOSS__BRIDGE_NFR %d\n#define PGLOSS__BRIDGE_RINT_MODEL0 %d\n"
               "static const float pgloss__bridge_rint[%d * %d * %d] = {\n", NFR, M_RP0, M_COUNT - M_RP0, NAT, NFR);
    print_floats(f, RINT, (size_t)(M_COUNT - M_RP0) * NAT * NFR);
    fprintf(f, "};\nstatic const double pgloss__bridge_check[%d * %d * 7] = {\n", M_COUNT, NCHECK);
    print_array(f, CHECK, (size_t)M_COUNT * NCHECK * 7);
    fprintf(f, "};\n");
}

/* The numbers of a file, in order. */
static size_t read_numbers(const char *path, double **out)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    size_t got = fread(buf, 1, (size_t)n, f);
    buf[got] = 0;
    fclose(f);
    size_t cap = 1024, k = 0;
    double *v = malloc(sizeof(double) * cap);
    for (char *p = buf; *p;) {
        if ((*p >= '0' && *p <= '9') || ((*p == '-' || *p == '.') && p[1] >= '0' && p[1] <= '9')) {
            if (p > buf && (p[-1] == '_' || (p[-1] >= 'A' && p[-1] <= 'z'))) { ++p; continue; }
            char *e;
            double x = strtod(p, &e);
            if (k == cap) v = realloc(v, sizeof(double) * (cap *= 2));
            v[k++] = x;
            p = e;
        } else {
            ++p;
        }
    }
    free(buf);
    *out = v;
    return k;
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (argc == 5 && !strcmp(argv[1], "--eval")) return eval_main(argv[2], atof(argv[3]), atof(argv[4]));
    int check = 0, report = 0;
    const char *path = NULL;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--check")) check = 1;
        else if (!strcmp(argv[i], "--report")) report = 1;
        else path = argv[i];
    }
    if (!path && !report) {
        fprintf(stderr, "usage: pgloss_bridge_tables [--check] OUT.inc | --report | --eval MODEL ETA ALPHA\n");
        return 2;
    }
    camera_init();
    hring_init();
    walls_init();
    solve_walls();
    stamp("walls");
    build_samples();
    stamp("samples");
    DIMG = malloc(sizeof(double) * (size_t)NPIX);
    image_lambert(DIMG, NULL, NULL);
    WIMG = malloc(sizeof(double) * (size_t)NW * NPIX);
    for (int k = 0; k < NW; ++k) image_ward(&WIMG[(size_t)k * NPIX], w_alpha(k));
    meter_init();
    stamp("ward basis");
    TAB = calloc((size_t)M_COUNT * NF0 * NAT * NP, sizeof(float));
    CHECK = calloc((size_t)M_COUNT * NCHECK * 7, sizeof(double));
    RINT = calloc((size_t)(M_COUNT - M_RP0) * NAT * NFR, sizeof(float));
    TABLES = (pgloss__bridge_tables){TAB, RINT, NF0, NAT, NFR, M_RP0, F0_MIN, F0_MAX, AT_MIN, AT_MAX, BASIS};
    double *Dt = malloc(sizeof(double) * (size_t)NPIX), *St = malloc(sizeof(double) * (size_t)NPIX);
    const clock_t t0 = clock();
    for (int m = 0; m < M_COUNT; ++m) {
        fill_model(m, Dt, St);
        if (path) fill_checks(m, Dt, St);
        stamp(MODEL_NAME[m]);
    }
    const double t_tables = (double)(clock() - t0) / CLOCKS_PER_SEC;
    if (report) {
        /* The control: Fig. 4's Ward paints read back as themselves. */
        double *X = malloc(sizeof(double) * (size_t)NPIX), *W = malloc(sizeof(double) * (size_t)NPIX), worst[3] = {0, 0, 0};
        const double rd[3] = {0.03, 0.193, 0.767}, rs[3] = {0.033, 0.066, 0.099}, al[3] = {0.04, 0.07, 0.1};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) {
                    double r[4];
                    image_ward(W, al[k]);
                    for (int p = 0; p < NPIX; ++p) X[p] = rd[i] * DIMG[p] + rs[j] * W[p];
                    meter(X, r);
                    worst[0] = fmax(worst[0], fabs(r[0] - rd[i]));
                    worst[1] = fmax(worst[1], fabs(r[1] - rs[j]));
                    worst[2] = fmax(worst[2], fabs(r[2] / al[k] - 1));
                }
        printf("Ward control (Fig. 4's 27 paints): worst |d rho_d| %.1e, |d rho_s| %.1e, |d alpha|/alpha %.1e\n",
               worst[0], worst[1], worst[2]);
        free(X); free(W);
        printf("grid: %d sqrt-F0 x %d log-alpha nodes x %d products x %d models, R_int %d F0 x %d alpha x %d models: "
               "%d numbers; tables in %.1f s of CPU\n", NF0, NAT, NP, M_COUNT, NFR, NAT, M_COUNT - M_RP0,
               M_COUNT * NF0 * NAT * NP + (M_COUNT - M_RP0) * NAT * NFR + NW * 8 + 1, t_tables);
        printf("\n| model | alpha band | points | |dL*| p95 / max | |dc| p95 / max | |dd| p95 / max |\n"
               "|---|---|---|---|---|---|\n");
        for (int m = 0; m < M_COUNT; ++m) report_model(m, Dt, St);
    }
    free(Dt); free(St);
    if (!path) return 0;
    if (check) {
        char tmp[4096];
        snprintf(tmp, sizeof tmp, "%s.check.tmp", path);
        FILE *f = fopen(tmp, "w");
        if (!f) { perror(tmp); return 2; }
        write_tables(f);
        fclose(f);
        double *a, *b;
        size_t na = read_numbers(tmp, &a), nb = read_numbers(path, &b);
        remove(tmp);
        int bad = na != nb;
        for (size_t i = 0; !bad && i < na; ++i)
            if (fabs(a[i] - b[i]) > 1e-6 * fmax(1.0, fabs(a[i]))) {
                fprintf(stderr, "number %zu: generated %.9e, file %.9e\n", i, a[i], b[i]);
                bad = 1;
            }
        if (bad) {
            fprintf(stderr, "out of date: %s (run: pgloss_bridge_tables %s)\n", path, path);
            return 1;
        }
        printf("%s is up to date (%zu numbers)\n", path, na);
        return 0;
    }
    FILE *f = fopen(path, "w");
    if (!f) { perror(path); return 2; }
    write_tables(f);
    fclose(f);
    return 0;
}
