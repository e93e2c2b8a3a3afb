// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The pgloss tool's commands on the paper's model: convert between perceptual (L*, a*, b*, c, d)
 * and physical (ρd, ρs, α) parameters, check validity, match gloss, gloss distance, envelope,
 * evaluate the BRDF, and the paper's worked examples. Each prints its result, then the core's
 * verdict on the input as the status line. */
#include <math.h>

#include "cli_common.h"

#define DEG (3.14159265358979323846 / 180.0)

static int to_physical(pgloss_cli *cli, int argc, char **argv)
{
    double v[5];
    pgloss_normalization n;
    if (!pgloss_cli_args(cli, argc, argv, v, &n))
        return PGLOSS_CLI_USAGE;
    const pgloss_perceptual q = {v[0], v[1], v[2], v[3], v[4]};
    pgloss_physical p;
    const pgloss_status st = pgloss_physical_from_perceptual(&q, n, &p);
    if (st >= 0 || st == PGLOSS_ERR_GAMUT)
        fprintf(cli->out, "rho_d = (%.6f, %.6f, %.6f)  rho_s = %.6f  alpha = %.6f\n", p.rho_d[0], p.rho_d[1],
                p.rho_d[2], p.rho_s, p.alpha_x);
    if (st < 0)
        return pgloss_cli_report(cli, st);
    return pgloss_cli_report(cli, pgloss_check_perceptual(&q));
}

/* to-perceptual (rho_d rho_s alpha) and to-perceptual-rgb (r g b rho_s alpha). */
static int to_perceptual(pgloss_cli *cli, int argc, char **argv)
{
    double v[5];
    if (!pgloss_cli_args(cli, argc, argv, v, NULL))
        return PGLOSS_CLI_USAGE;
    const int k = argc == 5 ? 2 : 0; /* where rho_s - 1 is: the last of r, g, b, or rho_d */
    const pgloss_physical p = {{v[0], v[k / 2], v[k]}, v[k + 1], v[k + 2], v[k + 2], PGLOSS_NORM_WARD};
    pgloss_perceptual q;
    const pgloss_status st = pgloss_perceptual_from_physical(&p, &q);
    if (st >= 0)
        fprintf(cli->out, "L* = %.4f  a* = %.4f  b* = %.4f  c = %.6f  d = %.6f\n", q.L, q.a, q.b, q.c, q.d);
    if (st < 0)
        return pgloss_cli_report(cli, st);
    return pgloss_cli_report(cli, pgloss_check_physical(&p));
}

static int check(pgloss_cli *cli, int argc, char **argv)
{
    double v[3];
    pgloss_normalization n;
    if (!pgloss_cli_args(cli, argc, argv, v, &n))
        return PGLOSS_CLI_USAGE;
    const pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], v[2], n};
    return pgloss_cli_report(cli, pgloss_check_physical(&p));
}

static int match(pgloss_cli *cli, int argc, char **argv)
{
    double v[3], d2, s2;
    if (!pgloss_cli_args(cli, argc, argv, v, NULL))
        return PGLOSS_CLI_USAGE;
    /* The given paint must be one (ρd + ρs <= 1, ...). The match keeps d (§5.2), so α plays no
     * part: 0.1, inside the trusted range, leaves the check's verdict to ρd and ρs. */
    const pgloss_physical given = {{v[0], v[0], v[0]}, v[1], 0.1, 0.1, PGLOSS_NORM_WARD};
    const pgloss_status in = pgloss_check_physical(&given);
    if (in < 0)
        return pgloss_cli_report(cli, in);
    const pgloss_status st = pgloss_match_gloss(v[0], v[1], v[2], &d2, &s2);
    if (st >= 0 || st == PGLOSS_ERR_ENVELOPE)
        fprintf(cli->out, "rho_d = %.6f  rho_s = %.6f\n", d2, s2);
    return pgloss_cli_report(cli, st);
}

/* Is (c, d) a gloss that some paint has? The envelope is widest at L* = 0 (Fig. 10, c <= 1), so
 * the core's check of the black paint with this gloss is the verdict: NEGATIVE (c < 0), ALPHA
 * (d >= 1), ENVELOPE (c > 1), the warning ALPHA_UNTRUSTED (d < 0.8). */
static pgloss_status check_gloss(double c, double d)
{
    const pgloss_perceptual q = {0.0, 0.0, 0.0, c, d};
    return pgloss_check_perceptual(&q);
}

static int distance(pgloss_cli *cli, int argc, char **argv)
{
    double v[4], D;
    if (!pgloss_cli_args(cli, argc, argv, v, NULL))
        return PGLOSS_CLI_USAGE;
    const pgloss_status in = pgloss_cli_worst(check_gloss(v[0], v[1]), check_gloss(v[2], v[3]));
    if (in < 0)
        return pgloss_cli_report(cli, in);
    const pgloss_status st = pgloss_gloss_distance(v[0], v[1], v[2], v[3], &D);
    if (st >= 0)
        fprintf(cli->out, "D = %.6f\n", D);
    return pgloss_cli_report(cli, pgloss_cli_worst(st, in));
}

static int envelope(pgloss_cli *cli, int argc, char **argv)
{
    double L, c;
    if (!pgloss_cli_args(cli, argc, argv, &L, NULL))
        return PGLOSS_CLI_USAGE;
    const pgloss_status st = pgloss_envelope_contrast(L, &c);
    if (st >= 0)
        fprintf(cli->out, "c_max = %.6f\n", c);
    return pgloss_cli_report(cli, st);
}

static pgloss_vec3 direction(double theta_deg, double phi_deg)
{
    const double t = theta_deg * DEG, p = phi_deg * DEG;
    const pgloss_vec3 w = {(float)(sin(t) * cos(p)), (float)(sin(t) * sin(p)), (float)cos(t)};
    return w;
}

static int eval(pgloss_cli *cli, int argc, char **argv)
{
    double v[7];
    pgloss_normalization n;
    if (!pgloss_cli_args(cli, argc, argv, v, &n))
        return PGLOSS_CLI_USAGE;
    const pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], v[2], n};
    pgloss_material m;
    pgloss_status st = pgloss_material_init(&m, &p);
    if (st < 0)
        return pgloss_cli_report(cli, st);
    pgloss_rgb f;
    float pdf;
    st = pgloss_eval_pdf(&m, direction(v[3], v[4]), direction(v[5], v[6]), PGLOSS_LOBE_ALL, &f, &pdf);
    if (st < 0)
        return pgloss_cli_report(cli, st);
    fprintf(cli->out, "f = %.8g  pdf = %.8g\n", f.r, pdf);
    /* The material evaluates paints that are not in the model (ρd + ρs > 1, α > 0.2): say so. */
    return pgloss_cli_report(cli, pgloss_check_physical(&p));
}

static int demo(pgloss_cli *cli, int argc, char **argv)
{
    static const double rd[3] = {0.03, 0.193, 0.767}, rs[3] = {0.033, 0.066, 0.099},
                        al[3] = {0.04, 0.07, 0.10};
    static const char *const names[3] = {"black", "grey", "white"};
    FILE *out = cli->out;
    if (!pgloss_cli_args(cli, argc, argv, NULL, NULL))
        return PGLOSS_CLI_USAGE;
    fprintf(out, "Experiment 1 stimuli (paper §3.2.3.1) in the perceptual gloss space (Fig. 9):\n");
    fprintf(out, "  %-6s %6s %6s %5s | %7s %7s %5s\n", "paint", "rho_d", "rho_s", "alpha", "L*", "c", "d");
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                double L, c, d;
                pgloss_gloss_from_physical(rd[i], rs[j], al[k], &L, &c, &d);
                fprintf(out, "  %-6s %6.3f %6.3f %5.2f | %7.3f %7.4f %5.2f\n", names[i], rd[i], rs[j], al[k], L,
                        c, d);
            }

    fprintf(out, "\nMatching apparent gloss (§5.2, Fig. 12): rho_s = 0.099, alpha = 0.04\n");
    double Lw, cw, dw;
    pgloss_gloss_from_physical(0.767, 0.099, 0.04, &Lw, &cw, &dw);
    fprintf(out, "  same physical gloss: ");
    for (int i = 2; i >= 0; --i) {
        double L, c, d;
        pgloss_gloss_from_physical(rd[i], 0.099, 0.04, &L, &c, &d);
        fprintf(out, "%s c = %.3f  ", names[i], c);
    }
    fprintf(out, "\n  same perceptual gloss as white (c = %.3f, d = %.2f):\n", cw, dw);
    for (int i = 2; i >= 0; --i) {
        double L, c, d, d2, s2;
        pgloss_gloss_from_physical(rd[i], 0.099, 0.04, &L, &c, &d);
        pgloss_match_gloss(0.767, 0.099, L, &d2, &s2);
        fprintf(out, "    %-5s L* = %6.2f  rho_d = %.3f  rho_s = %.4f\n", names[i], L, d2, s2);
    }

    fprintf(out, "\nIsogloss contour (§5.1, Fig. 11) around c = 0.087, d = 0.93 at D = 0.04:\n  ");
    double cs[8], ds[8];
    pgloss_isogloss_contour(0.087, 0.93, 0.04, 8, cs, ds);
    for (int k = 0; k < 8; ++k)
        fprintf(out, "(%.3f, %.4f) ", cs[k], ds[k]);

    fprintf(out, "\n\nEnvelope of gloss space (Fig. 10): largest c per lightness\n  ");
    for (int L = 0; L <= 100; L += 20) {
        double c;
        pgloss_envelope_contrast(L, &c);
        fprintf(out, "L*=%d: %.3f  ", L, c);
    }

    fprintf(out, "\n\nA dark red paint from the colour/gloss picker (Fig. 13): L*=35 a*=45 b*=25 c=0.06 d=0.95\n");
    const pgloss_perceptual q = {35.0, 45.0, 25.0, 0.06, 0.95};
    pgloss_physical p;
    const pgloss_status st = pgloss_physical_from_perceptual(&q, PGLOSS_NORM_WARD, &p);
    fprintf(out, "  rho_d = (%.4f, %.4f, %.4f)  rho_s = %.4f  alpha = %.3f  [%s]\n", p.rho_d[0], p.rho_d[1],
            p.rho_d[2], p.rho_s, p.alpha_x, pgloss_status_name(st));
    pgloss_material m;
    pgloss_material_init(&m, &p);
    pgloss_rgb f;
    float pdf;
    pgloss_eval_pdf(&m, direction(30, 0), direction(30, 180), PGLOSS_LOBE_ALL, &f, &pdf);
    fprintf(out, "  BRDF in the mirror direction at 30 degrees: f = (%.4f, %.4f, %.4f) /sr, pdf = %.3f\n", f.r, f.g,
            f.b, pdf);
    return PGLOSS_CLI_OK;
}

const pgloss_cli_command pgloss_cmd_to_physical = {
    "to-physical", "L a b c d [norm]", "perceptual (Fig. 13) -> rho_d (linear Rec.709 RGB), rho_s, alpha",
    to_physical};
const pgloss_cli_command pgloss_cmd_to_perceptual = {
    "to-perceptual", "rho_d rho_s alpha", "achromatic physical -> L*, c, d (eqs. 3, 4)", to_perceptual};
const pgloss_cli_command pgloss_cmd_to_perceptual_rgb = {
    "to-perceptual-rgb", "r g b rho_s alpha", "linear Rec.709 RGB physical -> L*, a*, b*, c, d", to_perceptual};
const pgloss_cli_command pgloss_cmd_check = {
    "check", "rho_d rho_s alpha [norm]", "is the paint inside the paper's model, and if not, why", check};
const pgloss_cli_command pgloss_cmd_match = {
    "match", "rho_d rho_s L_target", "same apparent gloss at another lightness (Fig. 12)", match};
const pgloss_cli_command pgloss_cmd_distance = {
    "distance", "c1 d1 c2 d2", "gloss difference (eq. 5) of two glosses in gloss space", distance};
const pgloss_cli_command pgloss_cmd_envelope = {
    "envelope", "L", "largest c at lightness L (Fig. 10)", envelope};
const pgloss_cli_command pgloss_cmd_eval = {
    "eval", "rho_d rho_s alpha theta_o phi_o theta_i phi_i [norm]", "BRDF value and pdf, angles in degrees", eval};
const pgloss_cli_command pgloss_cmd_demo = {"demo", "", "the paper's worked examples", demo};
