// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss — command-line front end of libpgloss. The commands are in tools/cmd_*.c, listed in
 * tools/cli_commands.def; their shared parsing and reporting in tools/cli_common.c. */
#include "cli_common.h"

int main(int argc, char **argv)
{
    return pgloss_cli_finish(stdout, stderr, pgloss_cli_main(argc, argv, stdout, stderr));
}
