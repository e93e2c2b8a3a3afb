// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/version.h — the version of pgloss, written here and nowhere else: CMake's
 * project(VERSION), the shared library's soname, the CMake and pkg-config packages, Python's
 * pgloss.__version__ and `pgloss --version` all read these lines (CHANGELOG.md says how to
 * release). The macros give the version a program was compiled against; pgloss_version()
 * gives the version of the library it runs with.
 */
#ifndef PGLOSS_VERSION_H
#define PGLOSS_VERSION_H

#include "pgloss/export.h"

#define PGLOSS_VERSION_MAJOR 0
#define PGLOSS_VERSION_MINOR 2
#define PGLOSS_VERSION_PATCH 0
#define PGLOSS_VERSION_STRING "0.2.0"

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the linked library, "MAJOR.MINOR.PATCH" (a static string). */
PGLOSS_API const char *pgloss_version(void);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_VERSION_H */
