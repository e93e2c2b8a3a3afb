// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The virtual glossmeter (pgloss/glossmeter.h): the instrument geometries, the measurement
 * equation's quadrature and the readings. The derivation of the quadrature and the aperture
 * sources are in docs/glossmeter.md. */
#include <math.h>
#include <string.h>
#include "internal.h"
#include "lobe_d.h"
#include "pgloss/glossmeter.h"

#define DEG (PGLOSS_PI / 180.0)

/* ---- geometries ------------------------------------------------------------------------------ */

/* Source image and receptors (degrees): in-plane centre, width, height. Sources of every number:
 * glossmeter.h's table; the ASSUMED ones are marked there and in docs/glossmeter.md. */
static const pgloss_glossmeter_window SOURCE_D523 = {0.0, 0.75, 2.5};  /* ASSUMED (D523 Table 1 as quoted) */
static const pgloss_glossmeter_window REC_20 = {0.0, 1.8, 3.6};        /* 1.8: DIN EN ISO 13803; 3.6 ASSUMED */
static const pgloss_glossmeter_window REC_60 = {0.0, 4.4, 11.7};       /* ASSUMED */
static const pgloss_glossmeter_window REC_85 = {0.0, 4.0, 6.0};        /* ASSUMED */
static const pgloss_glossmeter_window HAZE_LO = {-2.0, 1.0, 3.6};      /* centre: Rhopoint; size ASSUMED */
static const pgloss_glossmeter_window HAZE_HI = {2.0, 1.0, 3.6};
static const pgloss_glossmeter_window DOI_SOURCE = {0.0, 0.1, 2.5};    /* ASSUMED */
static const pgloss_glossmeter_window DOI_REC = {0.0, 0.1, 3.6};       /* ASSUMED */
static const pgloss_glossmeter_window DOI_LO = {-0.3, 0.1, 3.6};       /* ±0.3°: ASTM E430 / Hunter */
static const pgloss_glossmeter_window DOI_HI = {0.3, 0.1, 3.6};

pgloss_status pgloss_glossmeter_geometry_of(pgloss_glossmeter_kind kind, pgloss_glossmeter_geometry *g)
{
    if (!g)
        return PGLOSS_ERR_NULL;
    memset(g, 0, sizeof *g);
    g->standard_index = PGLOSS_GLOSS_STANDARD_INDEX;
    g->source = SOURCE_D523;
    switch (kind) {
    case PGLOSS_GLOSS_20:
        g->theta_deg = 20.0;
        g->specular = REC_20;
        return PGLOSS_OK;
    case PGLOSS_GLOSS_60:
    case PGLOSS_HAZE_INDEX:
    case PGLOSS_CONTRAST_60:
        g->theta_deg = 60.0;
        g->specular = REC_60;
        return PGLOSS_OK;
    case PGLOSS_GLOSS_85:
        g->theta_deg = 85.0;
        g->specular = REC_85;
        return PGLOSS_OK;
    case PGLOSS_HAZE_20:
        g->theta_deg = 20.0;
        g->specular = REC_20;
        g->off[0] = HAZE_LO;
        g->off[1] = HAZE_HI;
        g->n_off = 2;
        return PGLOSS_OK;
    case PGLOSS_DOI_30:
        g->theta_deg = 30.0;
        g->source = DOI_SOURCE;
        g->specular = DOI_REC;
        g->off[0] = DOI_LO;
        g->off[1] = DOI_HI;
        g->n_off = 2;
        return PGLOSS_OK;
    case PGLOSS_GLOSSMETER_KINDS:
        break;
    }
    memset(g, 0, sizeof *g);
    return PGLOSS_ERR_ARGUMENT;
}

pgloss_status pgloss_fresnel_dielectric(double n, double c, double *r)
{
    if (!r)
        return PGLOSS_ERR_NULL;
    *r = 0.0;
    if (!isfinite(n) || !isfinite(c))
        return PGLOSS_ERR_NONFINITE;
    if (!(n > 1.0) || !(c >= 0.0 && c <= 1.0) || n > 1e150)
        return PGLOSS_ERR_ARGUMENT;
    /* Unpolarised: the mean of the s and p reflectances, written with g = sqrt(n² − 1 + c²)
     * (Walter et al. 2007, eq. 22; Cook & Torrance 1982). */
    const double g = sqrt(n * n - 1.0 + c * c);
    const double a = (n - 1.0) * (n + 1.0) / ((g + c) * (g + c)); /* (g − c)/(g + c) without cancellation */
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    *r = 0.5 * a * a * (1.0 + b * b);
    return PGLOSS_OK;
}

/* ---- windows and directions ------------------------------------------------------------------ */

typedef struct gm_rect { double s0, s1, t0, t1; } gm_rect;

static int window_ok(const pgloss_glossmeter_window *w)
{
    return isfinite(w->center_deg) && isfinite(w->width_deg) && isfinite(w->height_deg) &&
           w->width_deg > 0.0 && w->width_deg < 30.0 && w->height_deg > 0.0 && w->height_deg < 30.0 &&
           fabs(w->center_deg) < 30.0;
}

static gm_rect rect_of(const pgloss_glossmeter_window *w)
{
    gm_rect r;
    r.s0 = tan((w->center_deg - 0.5 * w->width_deg) * DEG);
    r.s1 = tan((w->center_deg + 0.5 * w->width_deg) * DEG);
    r.t1 = tan(0.5 * w->height_deg * DEG);
    r.t0 = -r.t1;
    return r;
}

/* Everything a flux needs: the frame (sin θ, cos θ), the azimuth's rotation, the rectangles. */
typedef struct gm_setup {
    double st, ct;            /* sin θ, cos θ */
    double ca, sa;            /* cos, sin of the azimuth */
    gm_rect src, rec;
    double ws, wt;            /* grading widths in s and t */
} gm_setup;

/* Validates g and fills the parts of a setup that do not depend on the window. */
static pgloss_status setup_geometry(const pgloss_glossmeter_geometry *g, double azimuth_deg, gm_setup *u)
{
    if (!isfinite(g->theta_deg) || !isfinite(g->standard_index) || !isfinite(azimuth_deg))
        return PGLOSS_ERR_NONFINITE;
    if (!(g->theta_deg > 0.0 && g->theta_deg < 90.0) || !(g->standard_index > 1.0) ||
        g->standard_index > 1e6 || fabs(azimuth_deg) > 1e6 || g->n_off < 0 || g->n_off > 2)
        return PGLOSS_ERR_ARGUMENT;
    if (!window_ok(&g->source) || !window_ok(&g->specular))
        return PGLOSS_ERR_ARGUMENT;
    for (int k = 0; k < g->n_off; ++k)
        if (!window_ok(&g->off[k]))
            return PGLOSS_ERR_ARGUMENT;
    u->st = sin(g->theta_deg * DEG);
    u->ct = cos(g->theta_deg * DEG);
    u->ca = cos(azimuth_deg * DEG);
    u->sa = sin(azimuth_deg * DEG);
    u->src = rect_of(&g->source);
    /* Every window must stay above the horizon: z ∝ cos θ − s sin θ > 0 (with a margin, so that
     * the Ward normalisation's 1/sqrt(cos) stays moderate). */
    const double smax = 0.999 * u->ct / u->st;
    if (u->src.s1 >= smax || rect_of(&g->specular).s1 >= smax)
        return PGLOSS_ERR_ARGUMENT;
    for (int k = 0; k < g->n_off; ++k)
        if (rect_of(&g->off[k]).s1 >= smax)
            return PGLOSS_ERR_ARGUMENT;
    return PGLOSS_OK;
}

/* The unit direction of window point (s, t), rotated into the sample's frame, and the factor
 * that turns ds dt into dω: (1 + s² + t²)^(-3/2). Source points (src = 1) point towards the
 * light, receptor points towards the receptor; the mirror of source (s, t) is receptor (s, −t). */
static inline double direction(const gm_setup *u, int src, double s, double t, double w[3])
{
    const double q = 1.0 + s * s + t * t;
    const double inv = 1.0 / sqrt(q);
    const double x = (src ? -(u->st + s * u->ct) : u->st + s * u->ct) * inv;
    const double y = t * inv;
    w[0] = u->ca * x + u->sa * y;
    w[1] = -u->sa * x + u->ca * y;
    w[2] = (u->ct - s * u->st) * inv;
    return inv / q;
}

/* ---- Gauss–Legendre on graded panels ---------------------------------------------------------- */

#define GM_MAX_N 16
#define GM_MAX_BREAKS 40
#define GM_MAX_NODES ((GM_MAX_BREAKS - 1) * GM_MAX_N)
static const int GM_ORDERS[3] = {6, 10, 16};
static const int GM_TAIL_ORDERS[3] = {4, 6, 10};

typedef struct gm_rule { int n; double x[GM_MAX_N], w[GM_MAX_N]; } gm_rule;

/* P_n(x) and P_n'(x) by the three-term recurrence (|x| < 1). */
static double legendre(int n, double x, double *dp)
{
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    *dp = n * (x * p1 - p0) / (x * x - 1.0);
    return p1;
}

/* Nodes and weights of the n-point Gauss–Legendre rule on [−1, 1] (Newton on P_n from
 * Tricomi's initial guesses; converged to a few ulp for n <= 16). */
static void gauss_legendre(int n, gm_rule *r)
{
    r->n = n;
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = cos(PGLOSS_PI * (i + 0.75) / (n + 0.5)), dp;
        for (int it = 0; it < 100; ++it) {
            const double dx = legendre(n, x, &dp) / dp;
            x -= dx;
            if (fabs(dx) < 1e-16)
                break;
        }
        legendre(n, x, &dp);
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        r->x[i] = -x;
        r->w[i] = w;
        r->x[n - 1 - i] = x;
        r->w[n - 1 - i] = w;
    }
}

static void sort_small(double *a, int n)
{
    for (int i = 1; i < n; ++i) {
        const double v = a[i];
        int j = i - 1;
        while (j >= 0 && a[j] > v) {
            a[j + 1] = a[j];
            --j;
        }
        a[j + 1] = v;
    }
}

/* Breakpoints of [lo, hi]: the ends, each focus and the points at w, 3w, 7w, 15w, … on either
 * side of it (panels doubling away from the focus, where a Gaussian of width ~w is smooth on the
 * panel's scale), those inside the interval; a focus outside it grades the panels nearest to it.
 * Breakpoints closer than w/8 merge. */
static int breakpoints(double lo, double hi, const double *foci, int nf, double w, double *b)
{
    int n = 0;
    b[n++] = lo;
    b[n++] = hi;
    const double span = hi - lo;
    for (int k = 0; k < nf && n < GM_MAX_BREAKS; ++k) {
        const double f = foci[k];
        if (f > lo && f < hi) b[n++] = f;
        for (double d = w; n < GM_MAX_BREAKS - 1; d = 2.0 * d + w) {
            if (f - d > lo && f - d < hi) b[n++] = f - d;
            if (f + d > lo && f + d < hi) b[n++] = f + d;
            if ((f - d <= lo && f + d >= hi) || d > 4.0 * (span + fabs(f - lo))) break;
        }
    }
    sort_small(b, n);
    const double gap = fmax(w * 0.125, span * 1e-9);
    int m = 1;
    for (int k = 1; k < n; ++k) {
        if (b[k] - b[m - 1] < gap) {
            if (k == n - 1) b[m - 1] = b[k]; /* keep hi itself */
            continue;
        }
        b[m++] = b[k];
    }
    if (m < 2) {
        b[0] = lo;
        b[1] = hi;
        m = 2;
    }
    b[0] = lo;
    b[m - 1] = hi;
    return m;
}

/* The composite rule on the panels between breakpoints b[0..nb-1]: r, and the lower-order rule
 * `tail` on panels at least 7w from the focus f (there a Gaussian lobe is below e^-24 of its
 * peak and smooth on the panel's scale; both rules rise with the order, so the error estimate
 * still covers them). */
static int nodes_of(const double *b, int nb, const gm_rule *r, const gm_rule *tail, double f, double w,
                    double *x, double *wt)
{
    int m = 0;
    for (int p = 0; p + 1 < nb; ++p) {
        const double h = 0.5 * (b[p + 1] - b[p]), c = 0.5 * (b[p + 1] + b[p]);
        const double near = b[p] > f ? b[p] - f : f > b[p + 1] ? f - b[p + 1] : 0.0;
        const gm_rule *q = near >= 7.0 * w * (1.0 - 1e-9) ? tail : r;
        for (int k = 0; k < q->n; ++k) {
            x[m] = c + h * q->x[k];
            wt[m] = h * q->w[k];
            ++m;
        }
    }
    return m;
}

/* ---- the measurement equation ---------------------------------------------------------------- */

/* The continuous part: ∫_S dωi ∫_W f(wo, wi) cos θo dωo at one order. */
static double flux_continuous(const gm_setup *u, const pgloss_glossmeter_brdf *f, const gm_rule *r,
                              const gm_rule *tail)
{
    double bs[GM_MAX_BREAKS], bt[GM_MAX_BREAKS];
    double xs[GM_MAX_NODES], ws[GM_MAX_NODES], xt[GM_MAX_NODES], wt[GM_MAX_NODES];
    double ixs[GM_MAX_NODES], iws[GM_MAX_NODES], ixt[GM_MAX_NODES], iwt[GM_MAX_NODES];
    /* Outer (source): the inner integral changes fastest where the mirror of the source point
     * crosses a window's edge, s = s0, s1 and t = −t1, −t0: panels are graded from the edges
     * inside the source. (Grading from edges outside it as well, for lobes narrower than the
     * source, cost more evaluations than the orders it saved: docs/glossmeter.md.) */
    double fo[2];
    int nfo = 0;
    for (int k = 0; k < 2; ++k) {
        const double e = k ? u->rec.s1 : u->rec.s0;
        if (e > u->src.s0 && e < u->src.s1) fo[nfo++] = e;
    }
    const int nbs = breakpoints(u->src.s0, u->src.s1, fo, nfo, u->ws, bs);
    nfo = 0;
    for (int k = 0; k < 2; ++k) {
        const double e = k ? -u->rec.t0 : -u->rec.t1;
        if (e > u->src.t0 && e < u->src.t1) fo[nfo++] = e;
    }
    const int nbt = breakpoints(u->src.t0, u->src.t1, fo, nfo, u->wt, bt);
    const int ns = nodes_of(bs, nbs, r, r, 0.0, HUGE_VAL, xs, ws);
    const int nt = nodes_of(bt, nbt, r, r, 0.0, HUGE_VAL, xt, wt);

    double total = 0.0;
    for (int a = 0; a < ns; ++a) {
        const double si = xs[a];
        double ib[GM_MAX_BREAKS];
        const int nib = breakpoints(u->rec.s0, u->rec.s1, &si, 1, u->ws, ib);
        const int nis = nodes_of(ib, nib, r, tail, si, u->ws, ixs, iws);
        for (int b = 0; b < nt; ++b) {
            const double ti = xt[b];
            double wi[3], wo[3];
            const double ji = direction(u, 1, si, ti, wi);
            const double mt = -ti;
            const int nibt = breakpoints(u->rec.t0, u->rec.t1, &mt, 1, u->wt, ib);
            const int nit = nodes_of(ib, nibt, r, tail, mt, u->wt, ixt, iwt);
            double inner = 0.0;
            for (int c = 0; c < nis; ++c) {
                double row = 0.0;
                for (int d = 0; d < nit; ++d) {
                    const double jo = direction(u, 0, ixs[c], ixt[d], wo);
                    if (wo[2] <= 0.0) continue;
                    row += iwt[d] * jo * wo[2] * f->eval(wo, wi, f->user);
                }
                inner += iws[c] * row;
            }
            total += ws[a] * wt[b] * ji * inner;
        }
    }
    return total;
}

/* The mirror part: ∫ R(cos θi) dωi over the source points whose mirror (s, −t) lies in W. */
static double flux_mirror(const gm_setup *u, double (*mirror)(double, void *), void *user, const gm_rule *r)
{
    const double s0 = fmax(u->src.s0, u->rec.s0), s1 = fmin(u->src.s1, u->rec.s1);
    const double t0 = fmax(u->src.t0, -u->rec.t1), t1 = fmin(u->src.t1, -u->rec.t0);
    if (!(s1 > s0) || !(t1 > t0))
        return 0.0;
    const double hs = 0.5 * (s1 - s0), cs = 0.5 * (s1 + s0), ht = 0.5 * (t1 - t0), ct = 0.5 * (t1 + t0);
    double total = 0.0;
    for (int a = 0; a < r->n; ++a) {
        const double s = cs + hs * r->x[a];
        double row = 0.0;
        for (int b = 0; b < r->n; ++b) {
            double wi[3];
            const double j = direction(u, 1, s, ct + ht * r->x[b], wi);
            row += r->w[b] * j * mirror(wi[2], user);
        }
        total += r->w[a] * row;
    }
    return hs * ht * total;
}

static double fresnel_of(double c, void *user)
{
    double r;
    pgloss_fresnel_dielectric(*(const double *)user, c, &r);
    return r;
}

static pgloss_status standard_flux(const pgloss_glossmeter_geometry *g, const gm_setup *u0, double *flux)
{
    gm_setup u = *u0;
    u.ca = 1.0;
    u.sa = 0.0;
    u.rec = rect_of(&g->specular);
    gm_rule r;
    gauss_legendre(GM_MAX_N, &r);
    double n = g->standard_index;
    *flux = flux_mirror(&u, fresnel_of, &n, &r);
    return PGLOSS_OK;
}

pgloss_status pgloss_glossmeter_standard_flux(const pgloss_glossmeter_geometry *g, double *flux)
{
    if (!flux)
        return PGLOSS_ERR_NULL;
    *flux = 0.0;
    if (!g)
        return PGLOSS_ERR_NULL;
    gm_setup u;
    const pgloss_status st = setup_geometry(g, 0.0, &u);
    if (st != PGLOSS_OK)
        return st;
    return standard_flux(g, &u, flux);
}

/* Φ of one window with its error estimate; the tolerance is tol·|Φ| + tol·1e-4·Φ(standard). */
static pgloss_status flux_window(const pgloss_glossmeter_geometry *g, const gm_setup *u0, int window,
                                 const pgloss_glossmeter_brdf *f, double tol, double std_flux,
                                 double *flux, double *err)
{
    gm_setup u = *u0;
    u.rec = rect_of(window == 0 ? &g->specular : &g->off[window - 1]);
    const double lw = f->lobe_width > 0.0 && isfinite(f->lobe_width) ? f->lobe_width : 1e-3;
    /* A Ward/Beckmann lobe exp(−p²/α²) in slope p: moving the receptor by ds in the plane turns
     * h by ds/2, by dt/(2 cos θ) across it, so its width is √2 α in s and √2 α cos θ in t. */
    u.ws = fmax(1.4142135623730951 * lw, 1e-7);
    u.wt = fmax(1.4142135623730951 * lw * u.ct, 1e-7);
    double prev = 0.0, q = 0.0;
    *err = 0.0;
    for (int level = 0; level < 3; ++level) {
        gm_rule r, tail;
        gauss_legendre(GM_ORDERS[level], &r);
        gauss_legendre(GM_TAIL_ORDERS[level], &tail);
        q = 0.0;
        if (f->eval)
            q += flux_continuous(&u, f, &r, &tail);
        if (f->mirror)
            q += flux_mirror(&u, f->mirror, f->user, &r);
        if (!isfinite(q)) {
            *flux = *err = 0.0;
            return PGLOSS_ERR_NONFINITE;
        }
        if (level > 0) {
            *err = fabs(q - prev);
            if (*err <= tol * (fabs(q) + 1e-4 * std_flux)) {
                *flux = q;
                return PGLOSS_OK;
            }
        }
        prev = q;
    }
    *flux = q;
    return PGLOSS_WARN_QUADRATURE;
}

static int window_count(const pgloss_glossmeter_geometry *g) { return 1 + g->n_off; }

pgloss_status pgloss_glossmeter_flux(const pgloss_glossmeter_geometry *g, int window,
                                     const pgloss_glossmeter_brdf *brdf, double azimuth_deg,
                                     double tol, double *flux, double *err)
{
    if (flux) *flux = 0.0;
    if (err) *err = 0.0;
    if (!g || !brdf || !flux || !err)
        return PGLOSS_ERR_NULL;
    if (!isfinite(tol))
        return PGLOSS_ERR_NONFINITE;
    gm_setup u;
    const pgloss_status st = setup_geometry(g, azimuth_deg, &u);
    if (st != PGLOSS_OK)
        return st;
    if (window < 0 || window >= window_count(g))
        return PGLOSS_ERR_ARGUMENT;
    double sf;
    standard_flux(g, &u, &sf);
    return flux_window(g, &u, window, brdf, tol > 0.0 ? tol : PGLOSS_GLOSSMETER_TOL, sf, flux, err);
}

/* ---- readings -------------------------------------------------------------------------------- */

static pgloss_status worse(pgloss_status a, pgloss_status b)
{
    if (a < 0) return a;
    if (b < 0) return b;
    return a > b ? a : b;
}

/* ∫_W cos θo dωo and the solid angle of the source: the contrast gloss's normalisation. */
static double projected_solid_angle(const gm_setup *u, const gm_rect *w, int src)
{
    gm_rule r;
    gauss_legendre(GM_MAX_N, &r);
    const double hs = 0.5 * (w->s1 - w->s0), cs = 0.5 * (w->s1 + w->s0);
    const double ht = 0.5 * (w->t1 - w->t0), ct = 0.5 * (w->t1 + w->t0);
    double total = 0.0;
    for (int a = 0; a < r.n; ++a)
        for (int b = 0; b < r.n; ++b) {
            double d[3];
            const double j = direction(u, src, cs + hs * r.x[a], ct + ht * r.x[b], d);
            total += r.w[a] * r.w[b] * j * (src ? 1.0 : d[2]);
        }
    return hs * ht * total;
}

pgloss_status pgloss_glossmeter_read_geometry(pgloss_glossmeter_kind kind, const pgloss_glossmeter_geometry *g,
                                              const pgloss_glossmeter_brdf *brdf, double azimuth_deg,
                                              double tol, pgloss_gloss_reading *out)
{
    if (out) out->value = out->error = 0.0;
    if (!g || !brdf || !out)
        return PGLOSS_ERR_NULL;
    if (!isfinite(tol))
        return PGLOSS_ERR_NONFINITE;
    if ((int)kind < 0 || kind >= PGLOSS_GLOSSMETER_KINDS || kind == PGLOSS_HAZE_INDEX)
        return PGLOSS_ERR_ARGUMENT;
    gm_setup u;
    pgloss_status st = setup_geometry(g, azimuth_deg, &u);
    if (st != PGLOSS_OK)
        return st;
    if ((kind == PGLOSS_HAZE_20 || kind == PGLOSS_DOI_30) && g->n_off < 1)
        return PGLOSS_ERR_ARGUMENT;
    tol = tol > 0.0 ? tol : PGLOSS_GLOSSMETER_TOL;
    double sf;
    standard_flux(g, &u, &sf);
    double phi[3] = {0.0, 0.0, 0.0}, e[3] = {0.0, 0.0, 0.0};
    const int nw = kind == PGLOSS_HAZE_20 || kind == PGLOSS_DOI_30 ? window_count(g) : 1;
    for (int k = 0; k < nw; ++k) {
        st = worse(st, flux_window(g, &u, k, brdf, tol, sf, &phi[k], &e[k]));
        if (st < 0)
            return st;
    }
    switch (kind) {
    case PGLOSS_GLOSS_20:
    case PGLOSS_GLOSS_60:
    case PGLOSS_GLOSS_85:
        out->value = 100.0 * phi[0] / sf;
        out->error = 100.0 * e[0] / sf;
        break;
    case PGLOSS_HAZE_20: {
        double h = 0.0, he = 0.0;
        for (int k = 1; k < nw; ++k) {
            h += phi[k];
            he += e[k];
        }
        out->value = 100.0 * h / sf;
        out->error = 100.0 * he / sf;
        break;
    }
    case PGLOSS_DOI_30: {
        double r = 0.0, re = 0.0;
        for (int k = 1; k < nw; ++k) {
            r += phi[k] / (nw - 1);
            re += e[k] / (nw - 1);
        }
        if (!(phi[0] > 0.0))
            return PGLOSS_ERR_ARGUMENT; /* no light in the specular window */
        out->value = 100.0 * (phi[0] - r) / phi[0];
        out->error = 100.0 * (r * e[0] + phi[0] * re) / (phi[0] * phi[0]);
        break;
    }
    case PGLOSS_CONTRAST_60: {
        /* specular luminance factor over the receptor / the 45°:0° luminance factor */
        const gm_rect w = rect_of(&g->specular);
        const double bs = PGLOSS_PI * phi[0] / (projected_solid_angle(&u, &u.src, 1) * projected_solid_angle(&u, &w, 0));
        const double s45 = 0.70710678118654752;
        const double wo[3] = {0.0, 0.0, 1.0};
        const double wi[3] = {-s45 * u.ca, s45 * u.sa, s45};
        const double bd = brdf->eval ? PGLOSS_PI * brdf->eval(wo, wi, brdf->user) : 0.0;
        if (!(bd > 0.0) || !isfinite(bd))
            return PGLOSS_ERR_ARGUMENT; /* no diffuse reflection at 45°:0° */
        out->value = bs / bd;
        out->error = out->value * e[0] / fmax(phi[0], 1e-300);
        break;
    }
    default:
        return PGLOSS_ERR_ARGUMENT;
    }
    return st;
}

pgloss_status pgloss_glossmeter_read(pgloss_glossmeter_kind kind, const pgloss_glossmeter_brdf *brdf,
                                     double azimuth_deg, double tol, pgloss_gloss_reading *out)
{
    if (out) out->value = out->error = 0.0;
    if (!brdf || !out)
        return PGLOSS_ERR_NULL;
    if (kind == PGLOSS_HAZE_INDEX) {
        pgloss_gloss_reading a, b;
        pgloss_status s1 = pgloss_glossmeter_read(PGLOSS_GLOSS_60, brdf, azimuth_deg, tol, &a);
        if (s1 < 0)
            return s1;
        const pgloss_status s2 = pgloss_glossmeter_read(PGLOSS_GLOSS_20, brdf, azimuth_deg, tol, &b);
        if (s2 < 0)
            return s2;
        out->value = a.value - b.value;
        out->error = a.error + b.error;
        return worse(s1, s2);
    }
    pgloss_glossmeter_geometry g;
    const pgloss_status st = pgloss_glossmeter_geometry_of(kind, &g);
    if (st != PGLOSS_OK)
        return st;
    return pgloss_glossmeter_read_geometry(kind, &g, brdf, azimuth_deg, tol, out);
}

/* ---- pgloss paints as glossmeter BRDFs ------------------------------------------------------- */

typedef struct gm_ward { pgloss__consts_d k; int norm; } gm_ward;

static double ward_eval(const double wo[3], const double wi[3], void *user)
{
    const gm_ward *w = (const gm_ward *)user;
    double f[3], p;
    pgloss__lobe_d(&w->k, w->k.active, w->norm, wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], 1, 0, f, &p);
    return pgloss__luminance3(f[0], f[1], f[2]);
}

static double material_eval(const double wo[3], const double wi[3], void *user)
{
    const pgloss_material *m = (const pgloss_material *)user;
    double f[3];
    pgloss__eval_pdf_d(m, m->lobes & PGLOSS_LOBE_ALL, wo, wi, f, NULL);
    return pgloss__luminance3(f[0], f[1], f[2]);
}

static pgloss_status ward_of(const pgloss_physical *p, gm_ward *w)
{
    const pgloss_status st = pgloss__check_physical_values(p, DBL_MAX);
    if (st != PGLOSS_OK)
        return st;
    if (!pgloss__valid_normalization(p->normalization))
        return PGLOSS_ERR_NORMALIZATION;
    w->k = pgloss__consts_d_of(p->rho_d[0], p->rho_d[1], p->rho_d[2], p->rho_s, p->alpha_x, p->alpha_y,
                               (int)p->normalization, PGLOSS_LOBE_ALL);
    w->norm = (int)p->normalization;
    return PGLOSS_OK;
}

/* A reading of a BRDF function whose narrowest lobe is width. */
static pgloss_status read_fn(pgloss_glossmeter_kind kind, double (*eval)(const double *, const double *, void *),
                             void *user, double width, double azimuth_deg, double tol, pgloss_gloss_reading *out)
{
    const pgloss_glossmeter_brdf b = {eval, NULL, user, width};
    return pgloss_glossmeter_read(kind, &b, azimuth_deg, tol, out);
}

pgloss_status pgloss_glossmeter_read_physical(pgloss_glossmeter_kind kind, const pgloss_physical *p,
                                              double azimuth_deg, double tol, pgloss_gloss_reading *out)
{
    if (out) out->value = out->error = 0.0;
    if (!p || !out)
        return PGLOSS_ERR_NULL;
    gm_ward w;
    const pgloss_status st = ward_of(p, &w);
    return st != PGLOSS_OK ? st
                           : read_fn(kind, ward_eval, &w, fmin(w.k.alpha_x, w.k.alpha_y), azimuth_deg, tol, out);
}

pgloss_status pgloss_glossmeter_read_material(pgloss_glossmeter_kind kind, const pgloss_material *m,
                                              double azimuth_deg, double tol, pgloss_gloss_reading *out)
{
    if (out) out->value = out->error = 0.0;
    if (!m || !out)
        return PGLOSS_ERR_NULL;
    return read_fn(kind, material_eval, (void *)m, fmin(m->alpha_x, m->alpha_y), azimuth_deg, tol, out);
}

pgloss_status pgloss_glossmeter_readings_brdf(const pgloss_glossmeter_brdf *brdf, double azimuth_deg, double tol,
                                         pgloss_glossmeter_readings *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!brdf || !out)
        return PGLOSS_ERR_NULL;
    pgloss_status all = PGLOSS_OK;
    for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k) {
        if (k == PGLOSS_HAZE_INDEX)
            continue; /* from the two gloss readings below */
        const pgloss_status st = pgloss_glossmeter_read((pgloss_glossmeter_kind)k, brdf, azimuth_deg, tol, &out->r[k]);
        if (st < 0 && !(k == PGLOSS_CONTRAST_60 && st == PGLOSS_ERR_ARGUMENT)) {
            memset(out, 0, sizeof *out);
            return st;
        }
        all = worse(all, st < 0 ? PGLOSS_OK : st);
    }
    out->r[PGLOSS_HAZE_INDEX].value = out->r[PGLOSS_GLOSS_60].value - out->r[PGLOSS_GLOSS_20].value;
    out->r[PGLOSS_HAZE_INDEX].error = out->r[PGLOSS_GLOSS_60].error + out->r[PGLOSS_GLOSS_20].error;
    return all;
}

pgloss_status pgloss_glossmeter_readings_physical(const pgloss_physical *p, double azimuth_deg, double tol,
                                                  pgloss_glossmeter_readings *out)
{
    if (out) memset(out, 0, sizeof *out);
    if (!p || !out)
        return PGLOSS_ERR_NULL;
    gm_ward w;
    const pgloss_status st = ward_of(p, &w);
    if (st != PGLOSS_OK)
        return st;
    const pgloss_glossmeter_brdf b = {ward_eval, NULL, &w, fmin(w.k.alpha_x, w.k.alpha_y)};
    return pgloss_glossmeter_readings_brdf(&b, azimuth_deg, tol, out);
}
