// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* pgloss_version(): the version this library was built as (pgloss/version.h). */
#include "pgloss/version.h"

const char *pgloss_version(void)
{
    return PGLOSS_VERSION_STRING;
}
