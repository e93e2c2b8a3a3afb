// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The pgloss tool's dispatcher and the parsing and reporting that its commands share
 * (cli_common.h). */
#include "cli_common.h"

#include <errno.h>
#include <float.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define PGLOSS_CLI_COMMAND(id) extern const pgloss_cli_command pgloss_cmd_##id;
#include "cli_commands.def"
#undef PGLOSS_CLI_COMMAND

static const pgloss_cli_command *const COMMANDS[] = {
#define PGLOSS_CLI_COMMAND(id) &pgloss_cmd_##id,
#include "cli_commands.def"
#undef PGLOSS_CLI_COMMAND
};
#define N_COMMANDS (sizeof COMMANDS / sizeof COMMANDS[0])

static const char NORM_LINE[] = "norm: ward (eq. 2, default) | ward-dur | bounded\n";
enum { MAX_WORDS = 16, MAX_WORD = 32 };

static int is_digit(char ch) { return ch >= '0' && ch <= '9'; }

const char *pgloss_cli_quote(const char *text, char buf[PGLOSS_CLI_QUOTE_SIZE])
{
    static const char hex[] = "0123456789abcdef";
    size_t k = 0, n = 0;
    buf[k++] = '\'';
    for (; text[n] && n < 64; ++n) {
        const unsigned char ch = (unsigned char)text[n];
        if (ch >= 0x20 && ch < 0x7f) {
            buf[k++] = (char)ch;
        } else {
            buf[k++] = '\\'; buf[k++] = 'x'; buf[k++] = hex[ch >> 4]; buf[k++] = hex[ch & 15];
        }
    }
    buf[k++] = '\'';
    if (text[n]) {
        memcpy(buf + k, "...", 3);
        k += 3;
    }
    buf[k] = '\0';
    return buf;
}

/* The usage line's argument words of a command, copied into names; returns their number. */
static int words(const char *args, char names[MAX_WORDS][MAX_WORD])
{
    int n = 0;
    for (const char *p = args; *p && n < MAX_WORDS;) {
        while (*p == ' ')
            ++p;
        size_t len = strcspn(p, " ");
        if (!len)
            break;
        if (len >= MAX_WORD)
            len = MAX_WORD - 1;
        memcpy(names[n], p, len);
        names[n++][len] = '\0';
        p += strcspn(p, " ");
    }
    return n;
}

static void usage_line(const pgloss_cli_command *c, FILE *f)
{
    fprintf(f, "usage: pgloss %s%s%s\n", c->name, *c->args ? " " : "", c->args);
}

int pgloss_cli_usage_error(pgloss_cli *cli, const char *fmt, ...)
{
    va_list ap;
    fprintf(cli->err, "pgloss %s: ", cli->command->name);
    va_start(ap, fmt);
    vfprintf(cli->err, fmt, ap);
    va_end(ap);
    fputc('\n', cli->err);
    usage_line(cli->command, cli->err);
    return PGLOSS_CLI_USAGE;
}

/* Case-insensitive: is s (after a sign) one of strtod's spellings of infinity or NaN? */
static int is_inf_or_nan(const char *s)
{
    static const char *const spellings[] = {"inf", "infinity", "nan"};
    if (*s == '+' || *s == '-')
        ++s;
    for (size_t k = 0; k < sizeof spellings / sizeof spellings[0]; ++k) {
        const char *a = s, *b = spellings[k];
        while (*a && *b && (*a | 0x20) == *b)
            ++a, ++b;
        if (!*b && (!*a || (k == 2 && *a == '(')))
            return 1;
    }
    return 0;
}

int pgloss_cli_number(pgloss_cli *cli, const char *name, const char *text, double *v)
{
    char q[PGLOSS_CLI_QUOTE_SIZE];
    /* The grammar (cli_common.h), checked here: strtod alone would also take hexadecimal,
     * inf/nan, leading spaces and, in other locales, other digits. */
    const char *p = text;
    int digits = 0, nonzero = 0;
    if (*p == '+' || *p == '-')
        ++p;
    for (; is_digit(*p); ++p, ++digits)
        nonzero |= *p != '0';
    if (*p == '.')
        for (++p; is_digit(*p); ++p, ++digits)
            nonzero |= *p != '0';
    if (digits && (*p == 'e' || *p == 'E')) {
        const char *e = p + 1 + (p[1] == '+' || p[1] == '-');
        if (is_digit(*e))
            for (p = e; is_digit(*p); ++p) {}
    }
    if (!digits || *p) {
        const char *why = "is not a number";
        if (is_inf_or_nan(text))
            why = "is not a finite number";
        else if ((text[0] == '0' && (text[1] | 0x20) == 'x') ||
                 ((text[0] == '+' || text[0] == '-') && text[1] == '0' && (text[2] | 0x20) == 'x'))
            why = "is not a decimal number";
        else
            for (const char *s = text; *s; ++s)
                if ((unsigned char)*s >= 0x80) {
                    why = "is not a number (digits are ASCII 0-9)";
                    break;
                }
        pgloss_cli_usage_error(cli, "%s: %s %s", name, pgloss_cli_quote(text, q), why);
        return 0;
    }
    const double x = strtod(text, NULL);
    /* ERANGE also flags subnormal results, which are accepted: only overflow, and a nonzero
     * number that rounds to 0, are out of range. */
    if (x > DBL_MAX || x < -DBL_MAX) {
        pgloss_cli_usage_error(cli, "%s: %s is out of range (|x| > 1.8e308)", name, pgloss_cli_quote(text, q));
        return 0;
    }
    if (x == 0.0 && nonzero) {
        pgloss_cli_usage_error(cli, "%s: %s is out of range (0 < |x| < 4.9e-324)", name, pgloss_cli_quote(text, q));
        return 0;
    }
    *v = x;
    return 1;
}

int pgloss_cli_norm(pgloss_cli *cli, const char *text, pgloss_normalization *norm)
{
    char q[PGLOSS_CLI_QUOTE_SIZE];
    if (!strcmp(text, "ward")) *norm = PGLOSS_NORM_WARD;
    else if (!strcmp(text, "ward-dur")) *norm = PGLOSS_NORM_WARD_DUR;
    else if (!strcmp(text, "bounded")) *norm = PGLOSS_NORM_BOUNDED;
    else {
        pgloss_cli_usage_error(cli, "norm: %s is not one of ward, ward-dur, bounded", pgloss_cli_quote(text, q));
        return 0;
    }
    return 1;
}

int pgloss_cli_args(pgloss_cli *cli, int argc, char **argv, double *v, pgloss_normalization *norm)
{
    char names[MAX_WORDS][MAX_WORD];
    int n = words(cli->command->args, names);
    const int has_norm = n > 0 && !strcmp(names[n - 1], "[norm]");
    n -= has_norm;
    if (argc != n && !(has_norm && argc == n + 1)) {
        if (n == 0)
            pgloss_cli_usage_error(cli, "expected no arguments, got %d", argc);
        else if (has_norm)
            pgloss_cli_usage_error(cli, "expected %d or %d arguments, got %d", n, n + 1, argc);
        else
            pgloss_cli_usage_error(cli, "expected %d argument%s, got %d", n, n == 1 ? "" : "s", argc);
        return 0;
    }
    for (int k = 0; k < n; ++k)
        if (!pgloss_cli_number(cli, names[k], argv[k], &v[k]))
            return 0;
    pgloss_normalization given = PGLOSS_NORM_WARD;
    if (argc > n && !pgloss_cli_norm(cli, argv[n], &given))
        return 0;
    if (norm)
        *norm = given;
    return 1;
}

int pgloss_cli_report(pgloss_cli *cli, pgloss_status st)
{
    if (st == PGLOSS_OK)
        fputs("status: ok\n", cli->out);
    else
        fprintf(cli->out, "status: %s (%s)\n", pgloss_status_name(st), pgloss_status_string(st));
    return st < 0 ? PGLOSS_CLI_ERROR : PGLOSS_CLI_OK;
}

pgloss_status pgloss_cli_worst(pgloss_status a, pgloss_status b)
{
    if (a < 0) return a;
    if (b < 0) return b;
    return a != PGLOSS_OK ? a : b;
}

static void usage(FILE *f)
{
    fputs("usage: pgloss <command> [args]\n", f);
    for (size_t k = 0; k < N_COMMANDS; ++k) {
        const pgloss_cli_command *c = COMMANDS[k];
        char head[128];
        snprintf(head, sizeof head, "%s%s%s", c->name, *c->args ? " " : "", c->args);
        if (strlen(head) <= 32)
            fprintf(f, "  %-32s %s\n", head, c->help);
        else
            fprintf(f, "  %s\n  %-32s %s\n", head, "", c->help);
    }
    fprintf(f, "  %-32s %s\n", "--version", "the version of the pgloss library in use");
    fputs("  pgloss <command> --help          that command's usage\n", f);
    fputs(NORM_LINE, f);
}

int pgloss_cli_main(int argc, char **argv, FILE *out, FILE *err)
{
    char q[PGLOSS_CLI_QUOTE_SIZE];
    if (argc < 2) {
        usage(err);
        return PGLOSS_CLI_USAGE;
    }
    if (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help")) {
        usage(out);
        return PGLOSS_CLI_OK;
    }
    if (!strcmp(argv[1], "--version")) {
        fprintf(out, "pgloss %s\n", pgloss_version());
        return PGLOSS_CLI_OK;
    }
    for (size_t k = 0; k < N_COMMANDS; ++k) {
        const pgloss_cli_command *c = COMMANDS[k];
        if (strcmp(argv[1], c->name))
            continue;
        if (argc == 3 && (!strcmp(argv[2], "-h") || !strcmp(argv[2], "--help"))) {
            usage_line(c, out);
            fprintf(out, "  %s\n", c->help);
            if (strstr(c->args, "[norm]"))
                fputs(NORM_LINE, out);
            return PGLOSS_CLI_OK;
        }
        pgloss_cli cli = {out, err, c};
        return c->run(&cli, argc - 2, argv + 2);
    }
    fprintf(err, "pgloss: unknown command %s (pgloss --help lists the commands)\n", pgloss_cli_quote(argv[1], q));
    return PGLOSS_CLI_USAGE;
}

int pgloss_cli_finish(FILE *out, FILE *err, int rc)
{
    /* A full disk or a closed pipe must not pass for a result: check what the C library could
     * not write, at the flush and (for stdout) at the close. */
    errno = 0;
    int lost = ferror(out) != 0;
    int why = errno;
    if (fflush(out) != 0) {
        lost = 1;
        why = errno;
    }
    if (out == stdout && fclose(out) != 0 && !lost) {
        lost = 1;
        why = errno;
    }
    if (!lost)
        return rc;
    if (why)
        fprintf(err, "pgloss: cannot write the output: %s\n", strerror(why));
    else
        fputs("pgloss: cannot write the output\n", err);
    return PGLOSS_CLI_WRITE;
}
