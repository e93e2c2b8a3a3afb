// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* shim.c — C helpers for the Python module (core.cpp): build the core's structs from plain
 * numbers, with the normalisation as an int. The vectors pass unknown normalisations
 * (3, -1, 1000) on purpose; converting such an int to the enum is defined in C but not in
 * C++, so the conversion happens here. */
#include <string.h>

#include "pgloss/pgloss.h"
#include "shim.h"

static pgloss_physical make_physical(const double v[6], int normalization)
{
    pgloss_physical p;
    memset(&p, 0, sizeof p);
    p.rho_d[0] = v[0];
    p.rho_d[1] = v[1];
    p.rho_d[2] = v[2];
    p.rho_s = v[3];
    p.alpha_x = v[4];
    p.alpha_y = v[5];
    p.normalization = (pgloss_normalization)normalization;
    return p;
}

static pgloss_perceptual make_perceptual(const double q[5])
{
    pgloss_perceptual r = {q[0], q[1], q[2], q[3], q[4]};
    return r;
}

int pgloss_py_material_init(pgloss_material *m, const double v[6], int normalization)
{
    const pgloss_physical p = make_physical(v, normalization);
    return (int)pgloss_material_init(m, &p);
}

int pgloss_py_check_physical(const double v[6], int normalization)
{
    const pgloss_physical p = make_physical(v, normalization);
    return (int)pgloss_check_physical(&p);
}

int pgloss_py_check_perceptual(const double q[5], int space)
{
    const pgloss_perceptual r = make_perceptual(q);
    return (int)pgloss_check_perceptual_ex(&r, (pgloss_color_space)space);
}

int pgloss_py_physical_from_perceptual(const double q[5], int normalization, int space, double out[6],
                                       int *normalization_out)
{
    const pgloss_perceptual r = make_perceptual(q);
    pgloss_physical p;
    memset(&p, 0, sizeof p);
    const pgloss_status st = pgloss_physical_from_perceptual_ex(&r, (pgloss_normalization)normalization,
                                                                (pgloss_color_space)space, &p);
    out[0] = p.rho_d[0];
    out[1] = p.rho_d[1];
    out[2] = p.rho_d[2];
    out[3] = p.rho_s;
    out[4] = p.alpha_x;
    out[5] = p.alpha_y;
    *normalization_out = (int)p.normalization;
    return (int)st;
}

int pgloss_py_perceptual_from_physical(const double v[6], int normalization, int space, double q[5])
{
    const pgloss_physical p = make_physical(v, normalization);
    pgloss_perceptual r = {0, 0, 0, 0, 0};
    const pgloss_status st = pgloss_perceptual_from_physical_ex(&p, (pgloss_color_space)space, &r);
    q[0] = r.L;
    q[1] = r.a;
    q[2] = r.b;
    q[3] = r.c;
    q[4] = r.d;
    return (int)st;
}

int pgloss_py_rgb_from_lab(const double lab[3], int space, double rgb[3])
{
    return (int)pgloss_rgb_from_lab_ex(lab, (pgloss_color_space)space, rgb);
}

int pgloss_py_lab_from_rgb(const double rgb[3], int space, double lab[3])
{
    return (int)pgloss_lab_from_rgb_ex(rgb, (pgloss_color_space)space, lab);
}

int pgloss_py_luminance(const double rgb[3], int space, double *Y)
{
    return (int)pgloss_luminance_ex(rgb, (pgloss_color_space)space, Y);
}
