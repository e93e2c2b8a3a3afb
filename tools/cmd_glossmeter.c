// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The pgloss tool's glossmeter commands (pgloss/glossmeter.h, docs/glossmeter.md): a paint's
 * readings on the paint trade's instruments, the paint of given readings, and the trade's named
 * finishes. Each prints its result, then the core's verdict as the status line; the tables
 * (glossmeter --fig4, --bench; finish --list) are tables only. */
#include <math.h>
#include <string.h>
#include <time.h>

#include "cli_common.h"

static const char *const KIND_LABEL[PGLOSS_GLOSSMETER_KINDS] = {
    "20 deg gloss (ISO 2813)", "60 deg gloss (ISO 2813)", "85 deg gloss, sheen (ISO 2813)",
    "haze 20 deg (E430/ISO 13803)", "haze index G60-G20 (D4039)", "DOI 30 deg (Hunter/E430)",
    "contrast gloss (Hunter, pgloss)"};
static const char *const KIND_UNIT[PGLOSS_GLOSSMETER_KINDS] = {"GU", "GU", "GU", "HU", "GU", "", ""};

/* An option "--name v1 .. vcount" of numbers (the shared grammar), or --norm (count 0, norm set). */
typedef struct {
    const char *name;
    int count;
    double *v;
    int given;
} option;

enum { MAX_POSITIONAL = 4 };

/* Options anywhere among the arguments, the other words (at most max) in positional. A word
 * starting with "--" is an option, so negative numbers stay numbers. Returns the number of
 * positional words, or -1 after the reason and the usage line. */
static int read_options(pgloss_cli *cli, int argc, char **argv, option *opts, int n_opts,
                        pgloss_normalization *norm, char **positional, int max)
{
    char q[PGLOSS_CLI_QUOTE_SIZE];
    int n = 0;
    for (int k = 0; k < argc; ++k) {
        const char *w = argv[k];
        if (strncmp(w, "--", 2)) {
            if (n == max) {
                pgloss_cli_usage_error(cli, "unexpected argument %s", pgloss_cli_quote(w, q));
                return -1;
            }
            positional[n++] = argv[k];
            continue;
        }
        option *o = NULL;
        for (int j = 0; j < n_opts && !o; ++j)
            if (!strcmp(w, opts[j].name))
                o = &opts[j];
        if (!o) {
            pgloss_cli_usage_error(cli, "unknown option %s", pgloss_cli_quote(w, q));
            return -1;
        }
        if (o->given++) {
            pgloss_cli_usage_error(cli, "%s given twice", o->name);
            return -1;
        }
        const int count = o->count ? o->count : 1;
        if (k + count >= argc) {
            pgloss_cli_usage_error(cli, "%s needs %s", o->name, o->count > 1 ? "3 numbers" : o->count ? "a number"
                                                                                              : "a normalisation");
            return -1;
        }
        for (int j = 0; j < count; ++j) {
            ++k;
            if (o->count ? !pgloss_cli_number(cli, o->name, argv[k], &o->v[j]) : !pgloss_cli_norm(cli, argv[k], norm))
                return -1;
        }
    }
    return n;
}

static void print_readings(FILE *out, const pgloss_glossmeter_readings *r)
{
    for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k)
        fprintf(out, "  %-32s %12.6f %-2s  (quadrature error %.1e)\n", KIND_LABEL[k], r->r[k].value, KIND_UNIT[k],
                r->r[k].error);
}

/* The readings of Fig. 4's 27 paints (paper §3.2.3.1), as text or as a Markdown table
 * (docs/guide/gloss-bridge.md). */
static int fig4(pgloss_cli *cli, int markdown)
{
    static const double rd[3] = {0.03, 0.193, 0.767}, rs[3] = {0.033, 0.066, 0.099}, al[3] = {0.04, 0.07, 0.10};
    static const char *const names[3] = {"black", "grey", "white"};
    FILE *out = cli->out;
    if (markdown) {
        fputs("| paint | rho_d | rho_s | alpha | c | d | G20 | G60 | G85 | haze 20 | haze index | DOI 30 | contrast |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n", out);
    } else {
        fprintf(out, "%-6s %6s %6s %5s %7s %5s %8s %8s %8s %8s %8s %8s %9s\n", "paint", "rho_d", "rho_s", "alpha",
                "c", "d", "G20", "G60", "G85", "haze20", "hazeidx", "DOI30", "contrast");
    }
    double worst = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) {
                const pgloss_physical p = {{rd[i], rd[i], rd[i]}, rs[j], al[k], al[k], PGLOSS_NORM_WARD};
                pgloss_glossmeter_readings r;
                const pgloss_status st = pgloss_glossmeter_readings_physical(&p, 0.0, 1e-7, &r);
                if (st < 0)
                    return pgloss_cli_report(cli, st);
                double L, c, d;
                pgloss_gloss_from_physical(rd[i], rs[j], al[k], &L, &c, &d);
                for (int m = 0; m < PGLOSS_GLOSSMETER_KINDS; ++m)
                    worst = fmax(worst, r.r[m].error);
                if (markdown)
                    fprintf(out, "| %s | %.3f | %.3f | %.2f | %.4f | %.2f | %.3f | %.3f | %.4f | %.3f | %.3f | %.4f | %.1f |\n",
                            names[i], rd[i], rs[j], al[k], c, d, r.r[0].value, r.r[1].value, r.r[2].value,
                            r.r[3].value, r.r[4].value, r.r[5].value, r.r[6].value);
                else
                    fprintf(out, "%-6s %6.3f %6.3f %5.2f %7.4f %5.2f %8.3f %8.3f %8.4f %8.3f %8.3f %8.4f %9.1f\n",
                            names[i], rd[i], rs[j], al[k], c, d, r.r[0].value, r.r[1].value, r.r[2].value,
                            r.r[3].value, r.r[4].value, r.r[5].value, r.r[6].value);
            }
    fprintf(out, "%sLargest quadrature error estimate over the table: %.1e (same units as each column).\n",
            markdown ? "\n" : "", worst);
    return PGLOSS_CLI_OK;
}

static double seconds_now(void)
{
    struct timespec t;
    if (timespec_get(&t, TIME_UTC) != TIME_UTC)
        return 0.0;
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Run time against error: each reading at three tolerances, its actual error against a reading at
 * 1e-11, its error estimate, and the median time of 5 runs. */
static int bench(pgloss_cli *cli)
{
    static const double paints[4][3] = {{0.193, 0.066, 0.04}, {0.767, 0.099, 0.10}, {0.03, 0.05, 0.01},
                                        {0.2, 0.05, 0.003}};
    static const double tols[3] = {1e-3, 1e-6, 1e-9};
    FILE *out = cli->out;
    fputs("| paint (rho_d, rho_s, alpha) | reading | tol | median ms | actual error | estimate |\n"
          "|---|---|---:|---:|---:|---:|\n", out);
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < PGLOSS_GLOSSMETER_KINDS; ++k) {
            if (k == PGLOSS_HAZE_INDEX || k == PGLOSS_CONTRAST_60)
                continue;
            const pgloss_physical p = {{paints[i][0], paints[i][0], paints[i][0]}, paints[i][1], paints[i][2],
                                       paints[i][2], PGLOSS_NORM_WARD};
            pgloss_gloss_reading ref;
            pgloss_glossmeter_read_physical((pgloss_glossmeter_kind)k, &p, 0.0, 1e-11, &ref);
            for (int t = 0; t < 3; ++t) {
                double times[5];
                pgloss_gloss_reading r = {0.0, 0.0};
                for (int rep = 0; rep < 5; ++rep) {
                    const double t0 = seconds_now();
                    pgloss_glossmeter_read_physical((pgloss_glossmeter_kind)k, &p, 0.0, tols[t], &r);
                    times[rep] = seconds_now() - t0;
                }
                for (int a = 1; a < 5; ++a) /* median of 5 */
                    for (int b = a; b > 0 && times[b] < times[b - 1]; --b) {
                        const double x = times[b]; times[b] = times[b - 1]; times[b - 1] = x;
                    }
                fprintf(out, "| %.3f, %.3f, %.3f | %s | %.0e | %.2f | %.1e | %.1e |\n", paints[i][0], paints[i][1],
                        paints[i][2], KIND_LABEL[k], tols[t], 1e3 * times[2], fabs(r.value - ref.value), r.error);
            }
        }
    return PGLOSS_CLI_OK;
}

static int glossmeter(pgloss_cli *cli, int argc, char **argv)
{
    if (argc >= 1 && (!strcmp(argv[0], "--fig4") || !strcmp(argv[0], "--bench"))) {
        const int is_fig4 = argv[0][2] == 'f';
        if (is_fig4 && (argc == 1 || (argc == 2 && !strcmp(argv[1], "--markdown"))))
            return fig4(cli, argc == 2);
        if (!is_fig4 && argc == 1)
            return bench(cli);
        return pgloss_cli_usage_error(cli, "%s takes %s", argv[0], is_fig4 ? "only --markdown" : "no arguments");
    }
    double ay = NAN, az = 0.0, tol = 0.0, rgb[3];
    if (argc >= 1 && !strcmp(argv[0], "--target")) {
        /* a bridge target's material: --target TARGET FILE.json [--azimuth DEG] [--tol T] */
        pgloss_bridge_target t;
        pgloss_bridge_params bp;
        if (argc < 3)
            return pgloss_cli_usage_error(cli, "--target takes TARGET FILE.json");
        if (!pgloss_cli_bridge_target(cli, argv[1], &t))
            return PGLOSS_CLI_USAGE;
        option topts[] = {{"--azimuth", 1, &az, 0}, {"--tol", 1, &tol, 0}};
        pgloss_normalization unused = PGLOSS_NORM_WARD;
        if (read_options(cli, argc - 3, argv + 3, topts, 2, &unused, NULL, 0) < 0)
            return PGLOSS_CLI_USAGE;
        const int rc = pgloss_cli_bridge_params_file(cli, t, argv[2], &bp);
        if (rc != PGLOSS_CLI_OK)
            return rc;
        pgloss_glossmeter_readings r;
        const pgloss_status st = pgloss_glossmeter_readings_bridge(t, &bp, az, tol, &r);
        if (st >= 0) {
            fprintf(cli->out, "virtual glossmeter, %s material (docs/glossmeter.md, \"Microfacet targets\")\n",
                    pgloss_bridge_target_name(t));
            print_readings(cli->out, &r);
        }
        return pgloss_cli_report(cli, st);
    }
    option opts[] = {{"--alpha-y", 1, &ay, 0}, {"--azimuth", 1, &az, 0}, {"--tol", 1, &tol, 0}, {"--rgb", 3, rgb, 0}};
    char *pos[MAX_POSITIONAL];
    pgloss_normalization n = PGLOSS_NORM_WARD;
    const int npos = read_options(cli, argc, argv, opts, 4, &n, pos, 4);
    if (npos < 0)
        return PGLOSS_CLI_USAGE;
    if (npos < 3)
        return pgloss_cli_usage_error(cli, "expected 3 or 4 arguments besides the options, got %d", npos);
    static const char *const names[3] = {"rho_d", "rho_s", "alpha"};
    double v[3];
    for (int k = 0; k < 3; ++k)
        if (!pgloss_cli_number(cli, names[k], pos[k], &v[k]))
            return PGLOSS_CLI_USAGE;
    if (npos == 4 && !pgloss_cli_norm(cli, pos[3], &n))
        return PGLOSS_CLI_USAGE;
    pgloss_physical p = {{v[0], v[0], v[0]}, v[1], v[2], opts[0].given ? ay : v[2], n};
    if (opts[3].given)
        memcpy(p.rho_d, rgb, sizeof rgb);
    pgloss_glossmeter_readings r;
    const pgloss_status st = pgloss_glossmeter_readings_physical(&p, az, tol, &r);
    if (st >= 0) {
        fputs("virtual glossmeter (pgloss/glossmeter.h; apertures and their sources: docs/glossmeter.md)\n", cli->out);
        print_readings(cli->out, &r);
    }
    return pgloss_cli_report(cli, st);
}

static void print_paint(FILE *out, const pgloss_perceptual *q, const pgloss_physical *p)
{
    fprintf(out, "L* = %.4f  a* = %.4f  b* = %.4f  c = %.6f  d = %.6f\n", q->L, q->a, q->b, q->c, q->d);
    fprintf(out, "rho_d = (%.6f, %.6f, %.6f)  rho_s = %.6f  alpha = %.6f\n", p->rho_d[0], p->rho_d[1], p->rho_d[2],
            p->rho_s, p->alpha_x);
}

/* The inverse's verdicts that still come with a paint: the nearest one (pgloss/glossmeter.h). */
static int has_paint(pgloss_status st)
{
    return st >= 0 || st == PGLOSS_ERR_NO_FIT || st == PGLOSS_ERR_ENVELOPE || st == PGLOSS_ERR_ENERGY;
}

static int from_gloss_units(pgloss_cli *cli, int argc, char **argv)
{
    double L = NAN, a = 0.0, b = 0.0, g60 = NAN, g20 = NAN, haze = NAN, doi = NAN, d = NAN;
    option opts[] = {{"--L", 1, &L, 0},     {"--a", 1, &a, 0},       {"--b", 1, &b, 0},
                     {"--g60", 1, &g60, 0}, {"--g20", 1, &g20, 0},   {"--haze", 1, &haze, 0},
                     {"--doi", 1, &doi, 0}, {"--d", 1, &d, 0},       {"--norm", 0, NULL, 0}};
    pgloss_normalization n = PGLOSS_NORM_WARD;
    char *pos[1];
    if (read_options(cli, argc, argv, opts, 9, &n, pos, 0) < 0)
        return PGLOSS_CLI_USAGE;
    if (!opts[0].given || !opts[3].given)
        return pgloss_cli_usage_error(cli, "needs --L and --g60");
    if (opts[4].given + opts[5].given + opts[6].given + opts[7].given > 1)
        return pgloss_cli_usage_error(cli, "takes at most one of --g20, --haze, --doi, --d");
    pgloss_gloss_second which = PGLOSS_SECOND_NONE;
    double second = NAN;
    if (opts[4].given) which = PGLOSS_SECOND_GLOSS_20, second = g20;
    if (opts[5].given) which = PGLOSS_SECOND_HAZE_20, second = haze;
    if (opts[6].given) which = PGLOSS_SECOND_DOI_30, second = doi;
    FILE *out = cli->out;
    pgloss_perceptual q;
    pgloss_physical p;
    if (which == PGLOSS_SECOND_NONE) {
        /* One reading fixes c only for a given d: the family, and the assumed d */
        fprintf(out, "one reading: the paints reading %.4g GU at 60 deg form a family in d;\n", g60);
        fputs("  d      c         rho_s\n", out);
        for (double dd = 0.90; dd <= 0.9601; dd += 0.03) {
            const pgloss_status s = pgloss_paint_from_gloss_units(L, a, b, n, g60, PGLOSS_SECOND_NONE, dd, &q, &p);
            if (!has_paint(s))
                return pgloss_cli_report(cli, s);
            fprintf(out, "  %.2f   %.6f  %.6f%s\n", dd, q.c, p.rho_s, s < 0 ? "  (no fit)" : "");
        }
        if (!opts[7].given)
            fprintf(out, "assumed d = %.2f (alpha = 0.07, the middle of the paper's stimuli, which span Ward's "
                         "measured paints, paper 3.2.3.1); give --d, --g20, --haze or --doi to pin it\n",
                    PGLOSS_ASSUMED_DOI_GLOSS);
        second = opts[7].given ? d : PGLOSS_ASSUMED_DOI_GLOSS;
    }
    const pgloss_status st = pgloss_paint_from_gloss_units(L, a, b, n, g60, which, second, &q, &p);
    if (has_paint(st)) {
        if (st == PGLOSS_ERR_NO_FIT)
            fputs("no paint of the model reads so; the nearest in the second reading:\n", out);
        print_paint(out, &q, &p);
        pgloss_glossmeter_readings r;
        if (pgloss_glossmeter_readings_physical(&p, 0.0, 1e-7, &r) >= 0) {
            fputs("its readings (the model: eq. 2 without Fresnel, docs/glossmeter.md):\n", out);
            print_readings(out, &r);
        }
    }
    return pgloss_cli_report(cli, st);
}

/* "<= 5", "> 85", "20-35" or "-": a range of gloss units with NAN for an open bound. */
static void gu_range(char *buf, size_t size, double lo, double hi, const char *above)
{
    if (isnan(lo) && isnan(hi))
        snprintf(buf, size, "-");
    else if (isnan(lo))
        snprintf(buf, size, "<= %.0f", hi);
    else if (isnan(hi))
        snprintf(buf, size, "%s %.0f", above, lo);
    else
        snprintf(buf, size, "%.0f-%.0f", lo, hi);
}

static int finish(pgloss_cli *cli, int argc, char **argv)
{
    FILE *out = cli->out;
    if (argc == 0 || !strcmp(argv[0], "--list")) {
        if (argc > 1)
            return pgloss_cli_usage_error(cli, "--list takes no arguments");
        fprintf(out, "%-11s %-7s %-16s %-16s  source\n", "finish", "level", "60 deg GU", "85 deg GU");
        for (size_t k = 0; pgloss_finish_at(k); ++k) {
            const pgloss_finish *f = pgloss_finish_at(k);
            char g[32], s[32];
            gu_range(g, sizeof g, f->gloss_60_min, f->gloss_60_max, ">");
            gu_range(s, sizeof s, f->sheen_85_min, f->sheen_85_max, ">=");
            fprintf(out, "%-11s %-7s %-16s %-16s  %s\n", f->name, f->level, g, s, f->source);
        }
        return PGLOSS_CLI_OK;
    }
    const pgloss_finish *f = pgloss_finish_find(argv[0]);
    if (!f) {
        char q[PGLOSS_CLI_QUOTE_SIZE], names[256] = "";
        for (size_t k = 0; pgloss_finish_at(k); ++k) {
            const size_t used = strlen(names);
            snprintf(names + used, sizeof names - used, "%s%s", k ? ", " : "", pgloss_finish_at(k)->name);
        }
        return pgloss_cli_usage_error(cli, "NAME: %s is not a finish: one of %s, or its level G1-G7 (pgloss finish --list)",
                                      pgloss_cli_quote(argv[0], q), names);
    }
    double L = 50.0, a = 0.0, b = 0.0;
    option opts[] = {{"--L", 1, &L, 0}, {"--a", 1, &a, 0}, {"--b", 1, &b, 0}, {"--norm", 0, NULL, 0}};
    pgloss_normalization n = PGLOSS_NORM_WARD;
    char *pos[1];
    if (read_options(cli, argc - 1, argv + 1, opts, 4, &n, pos, 0) < 0)
        return PGLOSS_CLI_USAGE;
    pgloss_perceptual q;
    pgloss_physical p;
    double cr[2], dr[2];
    int sheen;
    const pgloss_status st = pgloss_finish_paint(f, L, a, b, n, &q, &p, cr, dr, &sheen);
    fprintf(out, "%s (%s; %s)\n", f->name, f->level, f->source);
    if (has_paint(st)) {
        const double lo = isnan(f->gloss_60_min) ? 0.0 : f->gloss_60_min;
        const double hi = isnan(f->gloss_60_max) ? 100.0 : f->gloss_60_max;
        fprintf(out, "representative paint: 60 deg gloss %.1f GU (the middle of %.0f-%.0f), d = %.2f assumed\n",
                0.5 * (lo + hi), lo, hi, PGLOSS_ASSUMED_DOI_GLOSS);
        print_paint(out, &q, &p);
        fprintf(out, "the finish spans c in [%.4f, %.4f] for d in [%.2f, %.2f] (alpha 0.04-0.10, the paper's range)\n",
                cr[0], cr[1], dr[0], dr[1]);
        if (!isnan(f->sheen_85_min) || !isnan(f->sheen_85_max))
            fprintf(out, "85 deg sheen range %s by this paint: eq. 2 has no Fresnel term and reads almost nothing "
                         "at 85 deg\n", sheen ? "met" : "NOT met");
    }
    return pgloss_cli_report(cli, st);
}

const pgloss_cli_command pgloss_cmd_glossmeter = {
    "glossmeter", "rho_d rho_s alpha [norm] [--alpha-y A] [--azimuth DEG] [--tol T] [--rgb R G B] | --target TARGET FILE.json [--azimuth DEG] [--tol T] | --fig4 [--markdown] | --bench",
    "a paint's 20/60/85 deg gloss, haze and DOI readings (ISO 2813, ASTM D523/E430)", glossmeter};
const pgloss_cli_command pgloss_cmd_from_gloss_units = {
    "from-gloss-units", "--L L --g60 G [--a A] [--b B] [--g20 G | --haze H | --doi D | --d D] [--norm N]",
    "the paint that reads a 60 deg gloss (and a second reading)", from_gloss_units};
const pgloss_cli_command pgloss_cmd_finish = {
    "finish", "NAME [--L L] [--a A] [--b B] [--norm N] | --list",
    "a trade finish (MPI G1-G7) as a paint, and the c, d it spans", finish};
