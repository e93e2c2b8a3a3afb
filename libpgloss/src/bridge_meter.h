// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * The gloss bridge's meter and table interpolant (docs/bridge.md), internal. One copy, used by
 * the library (bridge.c) and by the table generator (tools/bridge_tables.c), so that the tables
 * and the library read an image by the same arithmetic.
 *
 * The meter works on inner products over the sphere's pixels. An image X is fitted by
 * ρd·D + ρs·W(α) (D: the Lambertian sphere, W(α): Ward's lobe of eq. 2 with ρs = 1); W(α) is
 * Catmull-Rom in log α over NW node images, so ⟨X, W(α)⟩ and ⟨W(α), W(α)⟩ are sums over four
 * nodes of the products ⟨X, W_k⟩ and of the Ward Gram matrix (band of half-width 3). A target
 * image is β·Dt + St (base luminance β times its diffuse image, plus its specular image), so
 * its products are affine or quadratic in β: the tables hold, per (F0, α), the products
 *   ⟨Dt, W_k⟩ (NW), ⟨St, W_k⟩ (NW), ⟨Dt, D⟩, ⟨St, D⟩, ⟨Dt, Dt⟩, ⟨Dt, St⟩, ⟨St, St⟩,
 * and β enters exactly. Images depend smoothly on F0 and α where the reading (an arg min)
 * need not, so interpolating the products, not the readings, is what keeps the tables small.
 */
#ifndef PGLOSS_BRIDGE_METER_H
#define PGLOSS_BRIDGE_METER_H

#include <math.h>
#include <stddef.h>

/* The meter's Ward nodes: NW log-spaced α in [AMIN, AMAX]. */
#define PGLOSS__METER_NW 56
#define PGLOSS__METER_AMIN 0.004
#define PGLOSS__METER_AMAX 0.8
/* Products per table node: 2 NW, then ⟨Dt,D⟩ ⟨St,D⟩ ⟨Dt,Dt⟩ ⟨Dt,St⟩ ⟨St,St⟩. */
#define PGLOSS__METER_NP (2 * PGLOSS__METER_NW + 5)

/* Catmull-Rom weights at fractional node position x on n nodes, and (dw, may be NULL) their
 * derivatives in x. At the ends the missing neighbour is the linear extrapolation of the last
 * two nodes (v[-1] = 2 v[0] − v[1]), so a quantity linear along the axis is interpolated
 * exactly up to the ends. */
static inline void pgloss__cr_weights_d(double x, int n, int idx[4], double w[4], double dw[4])
{
    int i = (int)floor(x);
    if (i < 0) i = 0;
    if (i > n - 2) i = n - 2;
    const double t = x - i, t2 = t * t, t3 = t2 * t;
    w[0] = -0.5 * t3 + t2 - 0.5 * t;
    w[1] = 1.5 * t3 - 2.5 * t2 + 1;
    w[2] = -1.5 * t3 + 2 * t2 + 0.5 * t;
    w[3] = 0.5 * t3 - 0.5 * t2;
    double d[4] = {-1.5 * t2 + 2 * t - 0.5, 4.5 * t2 - 5 * t, -4.5 * t2 + 4 * t + 0.5, 1.5 * t2 - t};
    idx[0] = i - 1; idx[1] = i; idx[2] = i + 1; idx[3] = i + 2;
    if (idx[0] < 0) {
        w[1] += 2 * w[0]; w[0] = -w[0];
        d[1] += 2 * d[0]; d[0] = -d[0];
        idx[0] = 1;
    }
    if (idx[3] > n - 1) {
        w[2] += 2 * w[3]; w[3] = -w[3];
        d[2] += 2 * d[3]; d[3] = -d[3];
        idx[3] = n - 2;
    }
    if (dw)
        for (int k = 0; k < 4; ++k) dw[k] = d[k];
}
static inline void pgloss__cr_weights(double x, int n, int idx[4], double w[4])
{
    pgloss__cr_weights_d(x, n, idx, w, (double *)0);
}

/* The scene's Ward basis: Gram band gram[k*7 + (l − k + 3)] = ⟨W_k, W_l⟩ for |l − k| ≤ 3,
 * dw[k] = ⟨D, W_k⟩, dd = ⟨D, D⟩. */
typedef struct {
    const double *gram;
    const double *dw;
    double dd;
} pgloss__meter_basis;

/* Least squares of X on (D, W(α)) at la = log α from X's products xw (NW), xd = ⟨X, D⟩:
 * writes ρd, ρs and returns the explained part Q = ⟨X, fit⟩ (the residual is ⟨X, X⟩ − Q)
 * and, in dq, dQ/dla, in closed form: the fit's α is where dQ/dla = 0. */
static inline double pgloss__meter_fit(const pgloss__meter_basis *b, double la, const double *xw, double xd,
                                       double *rd, double *rs, double *dq)
{
    const double h = log(PGLOSS__METER_AMAX / PGLOSS__METER_AMIN) / (PGLOSS__METER_NW - 1);
    int idx[4];
    double w[4], dw[4], y = 0, dy = 0, bw = 0, dbw = 0, c = 0, dc = 0;
    pgloss__cr_weights_d((la - log(PGLOSS__METER_AMIN)) / h, PGLOSS__METER_NW, idx, w, dw);
    for (int i = 0; i < 4; ++i) {
        y += w[i] * xw[idx[i]];
        dy += dw[i] * xw[idx[i]];
        bw += w[i] * b->dw[idx[i]];
        dbw += dw[i] * b->dw[idx[i]];
        for (int j = 0; j < 4; ++j) {
            const double g = b->gram[idx[i] * 7 + (idx[j] - idx[i] + 3)];
            c += w[i] * w[j] * g;
            dc += 2 * dw[i] * w[j] * g;
        }
    }
    const double a = b->dd, det = a * c - bw * bw, x = xd;
    const double num = x * x * c - 2 * x * y * bw + y * y * a;
    const double dnum = x * x * dc - 2 * x * (dy * bw + y * dbw) + 2 * y * dy * a, ddet = a * dc - 2 * bw * dbw;
    *rd = (x * c - y * bw) / det;
    *rs = (y * a - x * bw) / det;
    *dq = (dnum * det - num * ddet) / (det * det) / h;
    return num / det;
}

/* The meter's reading (ρd, ρs, α, relative RMS residual) of an image with products xw (NW),
 * xd = ⟨X, D⟩, xx = ⟨X, X⟩: the best node, then the root of dQ/dla in the node interval on its
 * rising side, by regula falsi (Illinois) kept inside a shrinking bracket. (A search on the
 * residual itself would find α only to the square root of the rounding error, too coarse to
 * invert.) */
static inline void pgloss__meter_read(const pgloss__meter_basis *b, const double *xw, double xd, double xx,
                                      double out[4])
{
    const double lmin = log(PGLOSS__METER_AMIN), lmax = log(PGLOSS__METER_AMAX);
    const double h = (lmax - lmin) / (PGLOSS__METER_NW - 1);
    double rd, rs, dq, best = -INFINITY;
    int kb = 0;
    for (int k = 0; k < PGLOSS__METER_NW; ++k) { /* at a node W(α) is the node image */
        const double y = xw[k], bw = b->dw[k], c = b->gram[k * 7 + 3];
        const double q = (xd * xd * c - 2 * xd * y * bw + y * y * b->dd) / (b->dd * c - bw * bw);
        if (q > best) {
            best = q;
            kb = k;
        }
    }
    double lo = lmin + kb * h, hi = lo, glo, ghi;
    pgloss__meter_fit(b, lo, xw, xd, &rd, &rs, &glo);
    ghi = glo;
    if (glo > 0 && kb < PGLOSS__METER_NW - 1) {
        hi = lo + h;
        pgloss__meter_fit(b, hi, xw, xd, &rd, &rs, &ghi);
    } else if (glo < 0 && kb > 0) {
        lo = hi - h;
        pgloss__meter_fit(b, lo, xw, xd, &rd, &rs, &glo);
    }
    double la = glo <= 0 ? lo : hi; /* no sign change: the maximum is at that end */
    if (glo > 0 && ghi < 0) {
        int side = 0;
        for (int it = 0; it < 100 && hi - lo > 1e-15; ++it) {
            la = (lo * ghi - hi * glo) / (ghi - glo);
            if (!(la > lo && la < hi)) la = 0.5 * (lo + hi);
            pgloss__meter_fit(b, la, xw, xd, &rd, &rs, &dq);
            if (dq == 0) break;
            if (dq > 0) {
                lo = la; glo = dq;
                if (side == 1) ghi *= 0.5;
                side = 1;
            } else {
                hi = la; ghi = dq;
                if (side == -1) glo *= 0.5;
                side = -1;
            }
        }
    }
    const double q = pgloss__meter_fit(b, la, xw, xd, &out[0], &out[1], &dq);
    out[2] = exp(la);
    out[3] = xx > 0 ? sqrt(fmax(xx - q, 0) / xx) : 0;
}

/* The reading of the target image β·Dt + St from its products p (PGLOSS__METER_NP). */
static inline void pgloss__meter_read_target(const pgloss__meter_basis *b, const double *p, double beta,
                                             double out[4])
{
    const int n = PGLOSS__METER_NW;
    double xw[PGLOSS__METER_NW];
    for (int k = 0; k < n; ++k) xw[k] = beta * p[k] + p[n + k];
    const double xd = beta * p[2 * n] + p[2 * n + 1];
    const double xx = beta * beta * p[2 * n + 2] + 2 * beta * p[2 * n + 3] + p[2 * n + 4];
    pgloss__meter_read(b, xw, xd, xx, out);
}

/* Bicubic Catmull-Rom at fractional node position (u0, u1) in a table of n0 × n1 nodes (first
 * index outer) of np floats each; writes np doubles. */
static inline void pgloss__bicubic(const float *table, int n0, int n1, int np, double u0, double u1, double *out)
{
    int i0[4], i1[4];
    double w0[4], w1[4];
    pgloss__cr_weights(u0, n0, i0, w0);
    pgloss__cr_weights(u1, n1, i1, w1);
    for (int q = 0; q < np; ++q) out[q] = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double w = w0[i] * w1[j];
            const float *v = &table[((size_t)i0[i] * (size_t)n1 + (size_t)i1[j]) * (size_t)np];
            for (int q = 0; q < np; ++q) out[q] += w * v[q];
        }
}

/* The tables of tools/bridge_tables.c (bridge_tables.inc). Axes: the products on √F0 × log α,
 * R_int on F0 × log α, each with one node beyond each end of [min, max] (so that every cell
 * inside has its four true nodes): node 1 is min, node n − 2 is max. */
typedef struct {
    const float *products; /* models × nf0 × nat × PGLOSS__METER_NP */
    const float *rint;     /* (models − rint_model0) × nat × nfr: Mitsuba's R_int */
    int nf0, nat, nfr, rint_model0;
    double f0_min, f0_max, at_min, at_max;
    pgloss__meter_basis basis;
} pgloss__bridge_tables;

static inline double pgloss__axis(double x, double lo, double hi, int n) { return 1 + (x - lo) / (hi - lo) * (n - 3); }

/* The products p (PGLOSS__METER_NP) of model m at F0 f0 and α alpha (inside the tables'
 * range), and the factor of β: models from rint_model0 on are Mitsuba's roughplastic, whose
 * diffuse image the tables hold without its factor 1/(η² (1 − R_int)), from the R_int table. */
static inline double pgloss__bridge_table_products(const pgloss__bridge_tables *t, int m, double f0, double alpha,
                                                   double *p)
{
    const double ua = pgloss__axis(log(alpha), log(t->at_min), log(t->at_max), t->nat);
    pgloss__bicubic(&t->products[(size_t)m * (size_t)t->nf0 * (size_t)t->nat * PGLOSS__METER_NP], t->nf0, t->nat,
                    PGLOSS__METER_NP, pgloss__axis(sqrt(f0), sqrt(t->f0_min), sqrt(t->f0_max), t->nf0), ua, p);
    if (m < t->rint_model0)
        return 1;
    double rint;
    const double s = sqrt(f0), eta = (1 + s) / (1 - s);
    pgloss__bicubic(&t->rint[(size_t)(m - t->rint_model0) * (size_t)t->nat * (size_t)t->nfr], t->nat, t->nfr, 1, ua,
                    pgloss__axis(f0, t->f0_min, t->f0_max, t->nfr), &rint);
    return 1 / (eta * eta * (1 - rint));
}

/* The reading (ρd, ρs, α, residual) of model m at base luminance beta, F0 f0, α alpha. */
static inline void pgloss__bridge_table_read(const pgloss__bridge_tables *t, int m, double beta, double f0,
                                             double alpha, double out[4])
{
    double p[PGLOSS__METER_NP];
    const double scale = pgloss__bridge_table_products(t, m, f0, alpha, p);
    pgloss__meter_read_target(&t->basis, p, beta * scale, out);
}

#endif /* PGLOSS_BRIDGE_METER_H */
