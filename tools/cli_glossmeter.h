// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* The glossmeter commands of the pgloss tool (cli_glossmeter.c): each takes the arguments after
 * its name and returns the exit status (0 ok or warning, 1 an error status, 2 wrong arguments). */
#ifndef PGLOSS_CLI_GLOSSMETER_H
#define PGLOSS_CLI_GLOSSMETER_H

int pgloss_cli_glossmeter(char **argv, int argc);
int pgloss_cli_from_gloss_units(char **argv, int argc);
int pgloss_cli_finish(char **argv, int argc);

#endif
