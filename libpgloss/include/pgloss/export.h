// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/export.h — PGLOSS_API marks the functions of the public C API.
 *
 * libpgloss is compiled with hidden visibility (-fvisibility=hidden), so a shared build
 * exports exactly the functions marked here and none of the internal pgloss__ ones. On
 * Windows the same mark is __declspec(dllexport) while building the DLL (PGLOSS_BUILD,
 * set by the library's own CMake target) and __declspec(dllimport) for its users.
 * A static library defines PGLOSS_STATIC for itself and for everything that links it (the
 * CMake target's interface, pgloss.pc's Cflags): no DLL linkage, and the functions stay
 * hidden when the static library is linked into a user's shared object.
 */
#ifndef PGLOSS_EXPORT_H
#define PGLOSS_EXPORT_H

#if defined(PGLOSS_STATIC)
#  define PGLOSS_API
#elif defined(_WIN32) || defined(__CYGWIN__)
#  if defined(PGLOSS_BUILD)
#    define PGLOSS_API __declspec(dllexport)
#  else
#    define PGLOSS_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) || defined(__clang__)
#  define PGLOSS_API __attribute__((visibility("default")))
#else
#  define PGLOSS_API
#endif

#endif /* PGLOSS_EXPORT_H */
