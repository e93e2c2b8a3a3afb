// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Readings → paint (pgloss_paint_from_gloss_units) and the paint trade's named finishes
 * (glossmeter.h). The inverse uses that every flux is linear in ρd and ρs: for a fixed α the
 * 60° gloss fixes ρs, and the second reading is then a function of α alone, solved on log α. */
#include <ctype.h>
#include <math.h>
#include <string.h>
#include "internal.h"
#include "pgloss/glossmeter.h"

/* Readings of the inverse: coarse on the scan of α, tight enough in the refinement that a round
 * trip returns d to ~1e-6. */
#define INV_TOL_SCAN 1e-4
#define INV_TOL 1e-7
#define INV_GRID 13

typedef struct inv_problem {
    double rho_d[3];
    pgloss_normalization norm;
    pgloss_gloss_second second;
    double g60, target;
    /* the diffuse lobe's own readings: 60° gloss and the second (linear) reading */
    double g60_d, x_d;
    double tol;        /* of the readings */
    pgloss_status st;  /* the worst status met on the way (a quadrature warning) */
} inv_problem;

static pgloss_status worse(pgloss_status a, pgloss_status b)
{
    if (a < 0) return a;
    if (b < 0) return b;
    return a > b ? a : b;
}

static pgloss_physical paint(const double rho_d[3], double rho_s, double alpha, pgloss_normalization n)
{
    pgloss_physical p = {{rho_d[0], rho_d[1], rho_d[2]}, rho_s, alpha, alpha, n};
    return p;
}

static double reading(inv_problem *pr, pgloss_glossmeter_kind kind, const pgloss_physical *p)
{
    pgloss_gloss_reading r;
    const pgloss_status st = pgloss_glossmeter_read_physical(kind, p, 0.0, pr->tol, &r);
    pr->st = worse(pr->st, st);
    return r.value;
}

/* ρs that gives the 60° gloss at α, and the residual of the second reading there. */
static double residual(inv_problem *pr, double alpha, double *rho_s)
{
    static const double zero[3] = {0.0, 0.0, 0.0};
    const pgloss_physical unit = paint(zero, 1.0, alpha, pr->norm);
    const double g60u = reading(pr, PGLOSS_GLOSS_60, &unit);
    const double rs = g60u > 0.0 ? (pr->g60 - pr->g60_d) / g60u : 0.0;
    *rho_s = rs;
    switch (pr->second) {
    case PGLOSS_SECOND_GLOSS_20:
        return pr->x_d + rs * reading(pr, PGLOSS_GLOSS_20, &unit) - pr->target;
    case PGLOSS_SECOND_HAZE_20:
        return pr->x_d + rs * reading(pr, PGLOSS_HAZE_20, &unit) - pr->target;
    case PGLOSS_SECOND_DOI_30: {
        /* DOI is a ratio of fluxes, not linear in ρs: read the whole paint */
        const pgloss_physical whole = paint(pr->rho_d, rs > 0.0 ? rs : 0.0, alpha, pr->norm);
        return reading(pr, PGLOSS_DOI_30, &whole) - pr->target;
    }
    case PGLOSS_SECOND_NONE:
        break;
    }
    return 0.0;
}

/* The paint of (L*, a*, b*, c, d) and the status of pgloss_check_perceptual. */
static pgloss_status finish_paint(double L, double a, double b, double Y, double rho_s, double alpha,
                                  pgloss_normalization n, pgloss_perceptual *q, pgloss_physical *p)
{
    double c;
    pgloss_contrast_gloss(Y, rho_s > 0.0 ? rho_s : 0.0, &c);
    const pgloss_perceptual qq = {L, a, b, c, 1.0 - alpha};
    *q = qq;
    pgloss_physical_from_perceptual(q, n, p);
    return pgloss_check_perceptual(q);
}

pgloss_status pgloss_paint_from_gloss_units(double L, double a, double b, pgloss_normalization normalization,
                                            double gloss_60, pgloss_gloss_second second, double d_or_second,
                                            pgloss_perceptual *q, pgloss_physical *p)
{
    if (q) memset(q, 0, sizeof *q);
    if (p) memset(p, 0, sizeof *p);
    if (!q || !p)
        return PGLOSS_ERR_NULL;
    if (!isfinite(L) || !isfinite(a) || !isfinite(b) || !isfinite(gloss_60) || !isfinite(d_or_second))
        return PGLOSS_ERR_NONFINITE;
    if (!pgloss__valid_normalization(normalization))
        return PGLOSS_ERR_NORMALIZATION;
    if ((int)second < 0 || (int)second > (int)PGLOSS_SECOND_DOI_30 || gloss_60 < 0.0 ||
        (second != PGLOSS_SECOND_NONE && d_or_second < 0.0) || gloss_60 > 1e6 || d_or_second > 1e6)
        return PGLOSS_ERR_ARGUMENT;
    /* ρd of the colour (errors: LIGHTNESS, GAMUT), as Fig. 13's picker makes it */
    const pgloss_perceptual colour = {L, a, b, 0.0, 0.5};
    pgloss_physical base;
    pgloss_status st = pgloss_physical_from_perceptual(&colour, normalization, &base);
    if (st < 0)
        return st;
    double Y;
    pgloss_luminance_from_lightness(L, &Y);

    inv_problem pr;
    memset(&pr, 0, sizeof pr);
    memcpy(pr.rho_d, base.rho_d, sizeof pr.rho_d);
    pr.norm = normalization;
    pr.second = second;
    pr.g60 = gloss_60;
    pr.target = d_or_second;
    pr.tol = INV_TOL;
    /* the diffuse lobe reads the same whatever α: one broad α keeps its quadrature cheap */
    const pgloss_physical diffuse = paint(pr.rho_d, 0.0, 1.0, normalization);
    pr.g60_d = reading(&pr, PGLOSS_GLOSS_60, &diffuse);
    if (second == PGLOSS_SECOND_GLOSS_20)
        pr.x_d = reading(&pr, PGLOSS_GLOSS_20, &diffuse);
    else if (second == PGLOSS_SECOND_HAZE_20)
        pr.x_d = reading(&pr, PGLOSS_HAZE_20, &diffuse);

    double rho_s = 0.0, alpha;
    int fit = 1;
    if (second == PGLOSS_SECOND_NONE) {
        const double d = d_or_second > 0.0 && d_or_second < 1.0 ? d_or_second : PGLOSS_ASSUMED_DOI_GLOSS;
        alpha = 1.0 - d;
        residual(&pr, alpha, &rho_s);
        if (!(rho_s > 0.0))
            fit = gloss_60 == pr.g60_d;
    } else {
        /* scan log α, then refine the first bracket by the Illinois method on log α */
        const double l0 = log(PGLOSS_INVERSE_ALPHA_MIN), l1 = log(PGLOSS_INVERSE_ALPHA_MAX);
        double lx[INV_GRID], fx[INV_GRID], rsx[INV_GRID];
        int best = 0, bracket = -1;
        pr.tol = INV_TOL_SCAN;
        for (int k = 0; k < INV_GRID; ++k) {
            lx[k] = l0 + (l1 - l0) * k / (INV_GRID - 1);
            fx[k] = residual(&pr, exp(lx[k]), &rsx[k]);
            if (pr.st < 0)
                return pr.st;
            if (fabs(fx[k]) < fabs(fx[best]) && rsx[k] >= 0.0)
                best = k;
            if (bracket < 0 && k > 0 && rsx[k] >= 0.0 && rsx[k - 1] >= 0.0 &&
                ((fx[k - 1] <= 0.0 && fx[k] >= 0.0) || (fx[k - 1] >= 0.0 && fx[k] <= 0.0)))
                bracket = k - 1;
        }
        if (bracket < 0 || !(pr.g60 > pr.g60_d)) {
            fit = 0;
            alpha = exp(lx[best]);
            rho_s = rsx[best] > 0.0 ? rsx[best] : 0.0;
        } else {
            pr.tol = INV_TOL;
            double xa = lx[bracket], xb = lx[bracket + 1], ra, rb;
            double fa = residual(&pr, exp(xa), &ra), fb = residual(&pr, exp(xb), &rb);
            double x, r;
            if ((fa > 0.0) == (fb > 0.0) && fa != 0.0 && fb != 0.0) {
                /* the root is within the scan's tolerance of a grid point */
                x = fabs(fa) < fabs(fb) ? xa : xb;
                r = fabs(fa) < fabs(fb) ? ra : rb;
            } else {
                /* Illinois (regula falsi halving the retained end's value) to 1e-9 in log α */
                x = xa;
                r = ra;
                int side = 0;
                for (int it = 0; it < 60 && fabs(xb - xa) > 1e-9; ++it) {
                    x = fb != fa ? (xa * fb - xb * fa) / (fb - fa) : 0.5 * (xa + xb);
                    if (!(x > fmin(xa, xb) && x < fmax(xa, xb)))
                        x = 0.5 * (xa + xb);
                    const double fxv = residual(&pr, exp(x), &r);
                    if (fxv == 0.0)
                        break;
                    if ((fxv > 0.0) == (fb > 0.0)) {
                        xb = x;
                        fb = fxv;
                        if (side == -1) fa *= 0.5;
                        side = -1;
                    } else {
                        xa = x;
                        fa = fxv;
                        if (side == 1) fb *= 0.5;
                        side = 1;
                    }
                }
            }
            alpha = exp(x);
            rho_s = r;
        }
    }
    if (pr.st < 0)
        return pr.st;
    st = finish_paint(L, a, b, Y, rho_s, alpha, normalization, q, p);
    if (!fit)
        return PGLOSS_ERR_NO_FIT;
    if (st == PGLOSS_ERR_ENVELOPE || st == PGLOSS_ERR_ENERGY)
        return st;
    return worse(st, pr.st);
}

/* ---- named finishes -------------------------------------------------------------------------- */

/* Master Painters Institute gloss and sheen standards, as published at
 * paintinfo.com/mpi/approved/sheen.shtml: "Gloss at 60 degrees / Sheen at 85 degrees". */
#define MPI_SOURCE "MPI gloss and sheen standards (paintinfo.com/mpi/approved/sheen.shtml)"
static const pgloss_finish FINISHES[] = {
    {"flat", "MPI G1", NAN, 5.0, NAN, 10.0, MPI_SOURCE},
    {"velvet", "MPI G2", NAN, 10.0, 10.0, 35.0, MPI_SOURCE},
    {"eggshell", "MPI G3", 10.0, 25.0, 10.0, 35.0, MPI_SOURCE},
    {"satin", "MPI G4", 20.0, 35.0, 35.0, NAN, MPI_SOURCE},
    {"semi-gloss", "MPI G5", 35.0, 70.0, NAN, NAN, MPI_SOURCE},
    {"gloss", "MPI G6", 70.0, 85.0, NAN, NAN, MPI_SOURCE},
    {"high-gloss", "MPI G7", 85.0, NAN, NAN, NAN, MPI_SOURCE},
};
#define N_FINISHES (sizeof FINISHES / sizeof FINISHES[0])

const pgloss_finish *pgloss_finish_at(size_t index)
{
    return index < N_FINISHES ? &FINISHES[index] : NULL;
}

static int same_name(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b) {
        const int x = tolower((unsigned char)*a), y = tolower((unsigned char)*b);
        if (x != y && !((x == '-' || x == '_' || x == ' ') && (y == '-' || y == '_' || y == ' ')))
            return 0;
    }
    return *a == *b;
}

const pgloss_finish *pgloss_finish_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t k = 0; k < N_FINISHES; ++k) {
        const char *level = FINISHES[k].level + 4; /* "G1" */
        char mpi[8] = "mpi-g1";
        mpi[5] = level[1];
        if (same_name(name, FINISHES[k].name) || same_name(name, level) || same_name(name, mpi) ||
            same_name(name, FINISHES[k].level))
            return &FINISHES[k];
    }
    return NULL;
}

pgloss_status pgloss_finish_paint(const pgloss_finish *f, double L, double a, double b,
                                  pgloss_normalization normalization, pgloss_perceptual *q,
                                  pgloss_physical *p, double c_range[2], double d_range[2], int *sheen_ok)
{
    if (q) memset(q, 0, sizeof *q);
    if (p) memset(p, 0, sizeof *p);
    if (c_range) c_range[0] = c_range[1] = 0.0;
    if (d_range) d_range[0] = d_range[1] = 0.0;
    if (sheen_ok) *sheen_ok = 0;
    if (!q || !p || !c_range || !d_range)
        return PGLOSS_ERR_NULL;
    if (!f)
        return PGLOSS_ERR_ARGUMENT;
    const double lo = isnan(f->gloss_60_min) ? 0.0 : f->gloss_60_min;
    const double hi = isnan(f->gloss_60_max) ? 100.0 : f->gloss_60_max;
    const pgloss_status st = pgloss_paint_from_gloss_units(L, a, b, normalization, 0.5 * (lo + hi),
                                                           PGLOSS_SECOND_NONE, PGLOSS_ASSUMED_DOI_GLOSS, q, p);
    if (st < 0 && st != PGLOSS_ERR_ENVELOPE && st != PGLOSS_ERR_ENERGY && st != PGLOSS_ERR_NO_FIT)
        return st;
    /* the span: the corners of (60° range) × (d in [0.90, 0.96]); a corner below the diffuse's
     * own reading has c = 0 */
    const double ds[2] = {0.90, 0.96}, gs[2] = {lo, hi};
    double cmin = HUGE_VAL, cmax = 0.0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            pgloss_perceptual qc;
            pgloss_physical pc;
            const pgloss_status sc = pgloss_paint_from_gloss_units(L, a, b, normalization, gs[i],
                                                                   PGLOSS_SECOND_NONE, ds[j], &qc, &pc);
            if (sc < 0 && sc != PGLOSS_ERR_ENVELOPE && sc != PGLOSS_ERR_ENERGY && sc != PGLOSS_ERR_NO_FIT)
                return sc;
            cmin = fmin(cmin, qc.c);
            cmax = fmax(cmax, qc.c);
        }
    c_range[0] = cmin;
    c_range[1] = cmax;
    d_range[0] = ds[0];
    d_range[1] = ds[1];
    if (sheen_ok) {
        pgloss_gloss_reading g85;
        pgloss_glossmeter_read_physical(PGLOSS_GLOSS_85, p, 0.0, 1e-6, &g85);
        *sheen_ok = !(g85.value < f->sheen_85_min) && !(g85.value > f->sheen_85_max);
    }
    return st;
}
