// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* test_vectors_shim.c — C helper for test_vectors.cpp: passes an arbitrary int as a
 * pgloss_normalization argument (unknown values are part of the vectors). Converting an
 * out-of-range int to an enum is well defined in C but not in C++ (UBSan flags it). */
#include "pgloss/pgloss.h"

pgloss_status pgloss_test_physical_from_perceptual(const pgloss_perceptual *q, int normalization,
                                                   pgloss_physical *p);

pgloss_status pgloss_test_physical_from_perceptual(const pgloss_perceptual *q, int normalization,
                                                   pgloss_physical *p)
{
    return pgloss_physical_from_perceptual(q, (pgloss_normalization)normalization, p);
}
