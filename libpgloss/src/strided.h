// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* Strided arrays (pgloss/batch.h) to and from the contiguous columns the loops take, one
 * chunk at a time: a column that is already contiguous and aligned is used in place, any
 * other is copied into a stack buffer (no allocation). Not installed. */
#ifndef PGLOSS_STRIDED_H
#define PGLOSS_STRIDED_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Elements per chunk of the front ends. */
#define PGLOSS__BLOCK 256

static inline int pgloss__in_place(const void *p, ptrdiff_t stride, size_t size)
{
    return stride == (ptrdiff_t)size && ((uintptr_t)p & (size - 1)) == 0;
}

/* Elements [base, base + m) of a strided input of `size`-byte values (4 or 8) as a contiguous
 * column: the array itself where it is one, else buf, filled. memcpy: any alignment. */
static inline const void *pgloss__gather(const void *p, ptrdiff_t stride, size_t size,
                                         size_t base, size_t m, void *buf)
{
    const char *s = (const char *)p + (ptrdiff_t)base * stride;
    if (pgloss__in_place(s, stride, size))
        return s;
    char *d = (char *)buf;
    if (size == 4)
        for (size_t j = 0; j < m; ++j)
            memcpy(d + 4 * j, s + (ptrdiff_t)j * stride, 4);
    else
        for (size_t j = 0; j < m; ++j)
            memcpy(d + 8 * j, s + (ptrdiff_t)j * stride, 8);
    return buf;
}

/* Where the loops write elements [base, base + m) of a strided output: the array itself where
 * it is contiguous, else buf (then pgloss__scatter copies it out). */
static inline void *pgloss__out(void *p, ptrdiff_t stride, size_t size, size_t base, void *buf)
{
    char *d = (char *)p + (ptrdiff_t)base * stride;
    return pgloss__in_place(d, stride, size) ? d : buf;
}

/* Copies the column `col` that the loops wrote to the strided output, unless it is the output
 * itself (pgloss__out). */
static inline void pgloss__scatter(void *p, ptrdiff_t stride, size_t size, size_t base,
                                   size_t m, const void *col)
{
    char *d = (char *)p + (ptrdiff_t)base * stride;
    if (col == d)
        return;
    const char *s = (const char *)col;
    if (size == 4)
        for (size_t j = 0; j < m; ++j)
            memcpy(d + (ptrdiff_t)j * stride, s + 4 * j, 4);
    else
        for (size_t j = 0; j < m; ++j)
            memcpy(d + (ptrdiff_t)j * stride, s + 8 * j, 8);
}

/* Element j of a strided input as a double. */
static inline double pgloss__value_at(const void *p, ptrdiff_t stride, size_t j, size_t size)
{
    const char *s = (const char *)p + (ptrdiff_t)j * stride;
    if (size == 8) {
        double v;
        memcpy(&v, s, 8);
        return v;
    }
    float v;
    memcpy(&v, s, 4);
    return v;
}

#endif
