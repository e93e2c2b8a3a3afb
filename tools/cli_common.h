// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * The pgloss tool's commands and the helpers they share.
 *
 * A command is one `const pgloss_cli_command pgloss_cmd_<id>` in a file tools/cmd_*.c, plus
 * one line PGLOSS_CLI_COMMAND(<id>) in tools/cli_commands.def (which orders `pgloss --help`).
 * Every tools/cmd_*.c is built into the tool.
 *
 * One grammar and one set of messages and exit codes for every command:
 *   - a number is decimal ASCII, [+-]digits[.digits][(e|E)[+-]digits] (".5" and "5." too), finite,
 *     and representable: |x| <= DBL_MAX, and nonzero input does not round to 0 (subnormals
 *     such as 4.9e-324 are accepted). No hexadecimal, inf/nan, spaces or non-ASCII digits;
 *   - a wrong argument prints "pgloss CMD: <reason>" and the command's usage line on stderr;
 *   - exit codes: PGLOSS_CLI_OK (0: result ok, or a warning), PGLOSS_CLI_ERROR (1: the core's
 *     verdict is an error), PGLOSS_CLI_USAGE (2: wrong arguments), PGLOSS_CLI_WRITE (3: the
 *     output could not be written).
 */
#ifndef PGLOSS_CLI_COMMON_H
#define PGLOSS_CLI_COMMON_H

#include <stdio.h>

#include "pgloss/pgloss.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { PGLOSS_CLI_OK = 0, PGLOSS_CLI_ERROR = 1, PGLOSS_CLI_USAGE = 2, PGLOSS_CLI_WRITE = 3 };

typedef struct pgloss_cli_command pgloss_cli_command;

/* Where a command writes, and which command is running (for its messages). */
typedef struct pgloss_cli {
    FILE *out;
    FILE *err;
    const pgloss_cli_command *command;
} pgloss_cli;

struct pgloss_cli_command {
    const char *name; /* as typed: "to-physical" */
    /* The usage line's arguments, e.g. "c1 d1 c2 d2" or "rho_d rho_s alpha [norm]": the words
     * are the names pgloss_cli_args gives the numbers in its messages; "" for none. */
    const char *args;
    const char *help; /* one line for `pgloss --help` */
    /* argv: the argc words after the command's name. Returns an exit code. */
    int (*run)(pgloss_cli *cli, int argc, char **argv);
};

/* The tool: argv[0] is the program, argv[1] the command. Writes to out and err, returns the
 * exit code; does not close the streams (see pgloss_cli_finish). */
int pgloss_cli_main(int argc, char **argv, FILE *out, FILE *err);

/* Flushes and, for stdout, closes out; if anything written to it was lost, says so on err and
 * returns PGLOSS_CLI_WRITE, else rc. */
int pgloss_cli_finish(FILE *out, FILE *err, int rc);

/* The arguments of a command whose args are numbers, optionally followed by "[norm]": checks
 * the count, parses each number (named by its word in args) and the normalisation (default
 * ward). v holds one double per number. Returns 1, or 0 after printing the reason and the
 * usage line. */
int pgloss_cli_args(pgloss_cli *cli, int argc, char **argv, double *v, pgloss_normalization *norm);

/* One number of the grammar above, named `name` in the message. Returns 1, or 0 after
 * printing the reason and the usage line. */
int pgloss_cli_number(pgloss_cli *cli, const char *name, const char *text, double *v);

/* ward | ward-dur | bounded. Returns 1, or 0 after printing the reason and the usage line. */
int pgloss_cli_norm(pgloss_cli *cli, const char *text, pgloss_normalization *norm);

/* text as a message shows it: quoted, bytes outside printable ASCII as \xHH (no terminal
 * escapes, and a look-alike such as a fullwidth digit shows as what it is), long text cut
 * with "...". Returns buf. */
#define PGLOSS_CLI_QUOTE_SIZE 300
const char *pgloss_cli_quote(const char *text, char buf[PGLOSS_CLI_QUOTE_SIZE]);

/* "pgloss CMD: <printf message>" and the usage line on err; returns PGLOSS_CLI_USAGE. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 2, 3)))
#endif
int pgloss_cli_usage_error(pgloss_cli *cli, const char *fmt, ...);

/* The status line ("status: ok" or "status: NAME (reason)") on out; the exit code. */
int pgloss_cli_report(pgloss_cli *cli, pgloss_status st);

/* A bridge target's short name (pgloss/bridge.h); 0 after the reason and the usage line. */
int pgloss_cli_bridge_target(pgloss_cli *cli, const char *text, pgloss_bridge_target *t);

/* A target's parameters from FILE.json under the target's own names (what `pgloss bridge`
 * prints, or a bare object); absent ior and specular take the target's defaults. Returns
 * PGLOSS_CLI_OK, or PGLOSS_CLI_USAGE after the reason. */
int pgloss_cli_bridge_params_file(pgloss_cli *cli, pgloss_bridge_target t, const char *path,
                                  pgloss_bridge_params *p);

/* Two verdicts as one: the first error, else the first warning, else ok. */
pgloss_status pgloss_cli_worst(pgloss_status a, pgloss_status b);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_CLI_COMMON_H */
