// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss — command-line front end of libpgloss: convert between perceptual (L*, a*, b*, c, d)
 * and physical (ρd, ρs, α) parameters, check validity, match gloss, evaluate the BRDF. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pgloss/pgloss.h"

int pgloss_cli_bridge(int argc, char **argv);

#define DEG (3.14159265358979323846 / 180.0)

static const char *USAGE =
    "usage: pgloss <command> [args]\n"
    "  to-physical L a b c d [norm]     perceptual (Fig. 13) -> rho_d (linear Rec.709 RGB), rho_s, alpha\n"
    "  to-perceptual rho_d rho_s alpha  achromatic physical -> L*, c, d (eqs. 3, 4)\n"
    "  to-perceptual-rgb r g b rho_s alpha\n"
    "  check rho_d rho_s alpha [norm]   is the paint inside the paper's model, and if not, why\n"
    "  match rho_d rho_s L_target       same apparent gloss at another lightness (Fig. 12)\n"
    "  distance c1 d1 c2 d2             gloss difference (eq. 5)\n"
    "  envelope L                       largest c at lightness L (Fig. 10)\n"
    "  eval rho_d rho_s alpha theta_o phi_o theta_i phi_i [norm]\n"
    "                                   BRDF value and pdf, angles in degrees\n"
    "  demo                             the paper's worked examples\n"
    "  bridge TARGET L a b c d | bridge --from TARGET FILE.json   paint <-> renderer parameters (JSON)\n"
    "  --version                        the version of the pgloss library in use\n"
    "norm: ward (eq. 2, default) | ward-dur | bounded\n";

static int parse_double(const char *s, const char *name, double *out)
{
    char *end = NULL;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE) {
        fprintf(stderr, "pgloss: %s: '%s' is not a number\n", name, s);
        return 0;
    }
    *out = v;
    return 1;
}

static int parse_norm(const char *s, pgloss_normalization *n)
{
    if (!strcmp(s, "ward")) *n = PGLOSS_NORM_WARD;
    else if (!strcmp(s, "ward-dur")) *n = PGLOSS_NORM_WARD_DUR;
    else if (!strcmp(s, "bounded")) *n = PGLOSS_NORM_BOUNDED;
    else {
        fprintf(stderr, "pgloss: normalization: '%s' is not one of ward, ward-dur, bounded\n", s);
        return 0;
    }
    return 1;
}

/* Parses argv[0..n-1] into v under the given names. */
static int parse_all(char **argv, int n, const char *const *names, double *v)
{
    for (int k = 0; k < n; ++k)
        if (!parse_double(argv[k], names[k], &v[k]))
            return 0;
    return 1;
}

static int report(pgloss_status st)
{
    if (st == PGLOSS_OK)
        printf("status: ok\n");
    else
        printf("status: %s (%s)\n", pgloss_status_name(st), pgloss_status_string(st));
    return st < 0 ? 1 : 0;
}

static int cmd_to_physical(char **argv, int argc)
{
    static const char *const names[] = {"L", "a", "b", "c", "d"};
    double v[5];
    pgloss_normalization n = PGLOSS_NORM_WARD;
    if ((argc != 5 && argc != 6) || !parse_all(argv, 5, names, v) || (argc == 6 && !parse_norm(argv[5], &n)))
        return 2;
    const pgloss_perceptual q = {v[0], v[1], v[2], v[3], v[4]};
    pgloss_physical p;
    const pgloss_status st = pgloss_physical_from_perceptual(&q, n, &p);
    if (st >= 0 || st == PGLOSS_ERR_GAMUT)
        printf("rho_d = (%.6f, %.6f, %.6f)  rho_s = %.6f  alpha = %.6f\n", p.rho_d[0], p.rho_d[1],
               p.rho_d[2], p.rho_s, p.alpha_x);
    if (st < 0)
        return report(st);
    return report(pgloss_check_perceptual(&q));
}

static int cmd_to_perceptual(char **argv, int argc, int rgb)
{
    static const char *const names1[] = {"rho_d", "rho_s", "alpha"};
    static const char *const names3[] = {"r", "g", "b", "rho_s", "alpha"};
    double v[5];
    const int n = rgb ? 5 : 3;
    if (argc != n || !parse_all(argv, n, rgb ? names3 : names1, v))
        return 2;
    pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], v[2], PGLOSS_NORM_WARD};
    if (rgb) {
        p.rho_d[1] = v[1]; p.rho_d[2] = v[2];
        p.rho_s = v[3]; p.alpha_x = p.alpha_y = v[4];
    }
    pgloss_perceptual q;
    const pgloss_status st = pgloss_perceptual_from_physical(&p, &q);
    if (st >= 0)
        printf("L* = %.4f  a* = %.4f  b* = %.4f  c = %.6f  d = %.6f\n", q.L, q.a, q.b, q.c, q.d);
    if (st < 0)
        return report(st);
    return report(pgloss_check_physical(&p));
}

static int cmd_check(char **argv, int argc)
{
    static const char *const names[] = {"rho_d", "rho_s", "alpha"};
    double v[3];
    pgloss_normalization n = PGLOSS_NORM_WARD;
    if ((argc != 3 && argc != 4) || !parse_all(argv, 3, names, v) || (argc == 4 && !parse_norm(argv[3], &n)))
        return 2;
    const pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], v[2], n};
    return report(pgloss_check_physical(&p));
}

static int cmd_match(char **argv, int argc)
{
    static const char *const names[] = {"rho_d", "rho_s", "L_target"};
    double v[3], d2, s2;
    if (argc != 3 || !parse_all(argv, 3, names, v))
        return 2;
    const pgloss_status st = pgloss_match_gloss(v[0], v[1], v[2], &d2, &s2);
    if (st >= 0 || st == PGLOSS_ERR_ENVELOPE)
        printf("rho_d = %.6f  rho_s = %.6f\n", d2, s2);
    return report(st);
}

static int cmd_distance(char **argv, int argc)
{
    static const char *const names[] = {"c1", "d1", "c2", "d2"};
    double v[4], D;
    if (argc != 4 || !parse_all(argv, 4, names, v))
        return 2;
    const pgloss_status st = pgloss_gloss_distance(v[0], v[1], v[2], v[3], &D);
    if (st >= 0)
        printf("D = %.6f\n", D);
    return report(st);
}

static int cmd_envelope(char **argv, int argc)
{
    static const char *const names[] = {"L"};
    double L, c;
    if (argc != 1 || !parse_all(argv, 1, names, &L))
        return 2;
    const pgloss_status st = pgloss_envelope_contrast(L, &c);
    if (st >= 0)
        printf("c_max = %.6f\n", c);
    return report(st);
}

static pgloss_vec3 direction(double theta_deg, double phi_deg)
{
    const double t = theta_deg * DEG, p = phi_deg * DEG;
    const pgloss_vec3 w = {(float)(sin(t) * cos(p)), (float)(sin(t) * sin(p)), (float)cos(t)};
    return w;
}

static int cmd_eval(char **argv, int argc)
{
    static const char *const names[] = {"rho_d", "rho_s", "alpha", "theta_o", "phi_o", "theta_i", "phi_i"};
    double v[7];
    pgloss_normalization n = PGLOSS_NORM_WARD;
    if ((argc != 7 && argc != 8) || !parse_all(argv, 7, names, v) || (argc == 8 && !parse_norm(argv[7], &n)))
        return 2;
    const pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], v[2], n};
    pgloss_material m;
    pgloss_status st = pgloss_material_init(&m, &p);
    if (st != PGLOSS_OK)
        return report(st);
    pgloss_rgb f;
    float pdf;
    st = pgloss_eval_pdf(&m, direction(v[3], v[4]), direction(v[5], v[6]), PGLOSS_LOBE_ALL, &f, &pdf);
    if (st >= 0)
        printf("f = %.8g  pdf = %.8g\n", f.r, pdf);
    return report(st);
}

static int demo(void)
{
    static const double rd[3] = {0.03, 0.193, 0.767}, rs[3] = {0.033, 0.066, 0.099},
                        al[3] = {0.04, 0.07, 0.10};
    static const char *const names[3] = {"black", "gray", "white"};
    printf("Experiment 1 stimuli (paper §3.2.3.1) in the perceptual gloss space (Fig. 9):\n");
    printf("  %-6s %6s %6s %5s | %7s %7s %5s\n", "paint", "rho_d", "rho_s", "alpha", "L*", "c", "d");
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                double L, c, d;
                pgloss_gloss_from_physical(rd[i], rs[j], al[k], &L, &c, &d);
                printf("  %-6s %6.3f %6.3f %5.2f | %7.3f %7.4f %5.2f\n", names[i], rd[i], rs[j], al[k], L, c, d);
            }

    printf("\nMatching apparent gloss (§5.2, Fig. 12): rho_s = 0.099, alpha = 0.04\n");
    double Lw, cw, dw;
    pgloss_gloss_from_physical(0.767, 0.099, 0.04, &Lw, &cw, &dw);
    printf("  same physical gloss: ");
    for (int i = 2; i >= 0; --i) {
        double L, c, d;
        pgloss_gloss_from_physical(rd[i], 0.099, 0.04, &L, &c, &d);
        printf("%s c = %.3f  ", names[i], c);
    }
    printf("\n  same perceptual gloss as white (c = %.3f, d = %.2f):\n", cw, dw);
    for (int i = 2; i >= 0; --i) {
        double L, c, d, d2, s2;
        pgloss_gloss_from_physical(rd[i], 0.099, 0.04, &L, &c, &d);
        pgloss_match_gloss(0.767, 0.099, L, &d2, &s2);
        printf("    %-5s L* = %6.2f  rho_d = %.3f  rho_s = %.4f\n", names[i], L, d2, s2);
    }

    printf("\nIsogloss contour (§5.1, Fig. 11) around c = 0.087, d = 0.93 at D = 0.04:\n  ");
    double cs[8], ds[8];
    pgloss_isogloss_contour(0.087, 0.93, 0.04, 8, cs, ds);
    for (int k = 0; k < 8; ++k)
        printf("(%.3f, %.4f) ", cs[k], ds[k]);

    printf("\n\nEnvelope of gloss space (Fig. 10): largest c per lightness\n  ");
    for (int L = 0; L <= 100; L += 20) {
        double c;
        pgloss_envelope_contrast(L, &c);
        printf("L*=%d: %.3f  ", L, c);
    }

    printf("\n\nA dark red paint from the colour/gloss picker (Fig. 13): L*=35 a*=45 b*=25 c=0.06 d=0.95\n");
    const pgloss_perceptual q = {35.0, 45.0, 25.0, 0.06, 0.95};
    pgloss_physical p;
    const pgloss_status st = pgloss_physical_from_perceptual(&q, PGLOSS_NORM_WARD, &p);
    printf("  rho_d = (%.4f, %.4f, %.4f)  rho_s = %.4f  alpha = %.3f  [%s]\n", p.rho_d[0], p.rho_d[1],
           p.rho_d[2], p.rho_s, p.alpha_x, pgloss_status_name(st));
    pgloss_material m;
    pgloss_material_init(&m, &p);
    pgloss_rgb f;
    float pdf;
    pgloss_eval_pdf(&m, direction(30, 0), direction(30, 180), PGLOSS_LOBE_ALL, &f, &pdf);
    printf("  BRDF in the mirror direction at 30 degrees: f = (%.4f, %.4f, %.4f) /sr, pdf = %.3f\n",
           f.r, f.g, f.b, pdf);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        fputs(USAGE, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("pgloss %s\n", pgloss_version());
        return 0;
    }
    const char *cmd = argv[1];
    char **rest = argv + 2;
    const int n = argc - 2;
    int rc;
    if (!strcmp(cmd, "to-physical")) rc = cmd_to_physical(rest, n);
    else if (!strcmp(cmd, "to-perceptual")) rc = cmd_to_perceptual(rest, n, 0);
    else if (!strcmp(cmd, "to-perceptual-rgb")) rc = cmd_to_perceptual(rest, n, 1);
    else if (!strcmp(cmd, "check")) rc = cmd_check(rest, n);
    else if (!strcmp(cmd, "match")) rc = cmd_match(rest, n);
    else if (!strcmp(cmd, "distance")) rc = cmd_distance(rest, n);
    else if (!strcmp(cmd, "envelope")) rc = cmd_envelope(rest, n);
    else if (!strcmp(cmd, "eval")) rc = cmd_eval(rest, n);
    else if (!strcmp(cmd, "demo")) rc = demo();
    else if (!strcmp(cmd, "bridge")) rc = pgloss_cli_bridge(n, rest); /* tools/cli_bridge.c */
    else {
        fprintf(stderr, "pgloss: unknown command '%s'\n%s", cmd, USAGE);
        return 2;
    }
    if (rc == 2)
        fprintf(stderr, "pgloss %s: wrong arguments\n%s", cmd, USAGE);
    return rc;
}
