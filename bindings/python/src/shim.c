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

/* ---- Batched entry points with the enums as ints (pgloss/perceptual_batch.h,
 * pgloss/batch_materials.h). cols = {rho_d r, g, b, rho_s, alpha_x, alpha_y}. */

static pgloss_physical_array physical_array(const double *const cols[6], int normalization)
{
    pgloss_physical_array p;
    p.rho_d_r = cols[0];
    p.rho_d_g = cols[1];
    p.rho_d_b = cols[2];
    p.rho_s = cols[3];
    p.alpha_x = cols[4];
    p.alpha_y = cols[5];
    p.normalization = (pgloss_normalization)normalization;
    return p;
}

static pgloss_material_array material_array(const float *const cols[6], int normalization)
{
    pgloss_material_array m;
    m.rho_d_r = cols[0];
    m.rho_d_g = cols[1];
    m.rho_d_b = cols[2];
    m.rho_s = cols[3];
    m.alpha_x = cols[4];
    m.alpha_y = cols[5];
    m.normalization = (pgloss_normalization)normalization;
    return m;
}

int pgloss_py_check_physical_batch(size_t n, const double *const cols[6], int normalization, signed char *st)
{
    const pgloss_physical_array p = physical_array(cols, normalization);
    return (int)pgloss_check_physical_batch(n, &p, st);
}

int pgloss_py_check_perceptual_batch(size_t n, const double *const q[5], int space, signed char *st)
{
    const pgloss_perceptual_array a = {q[0], q[1], q[2], q[3], q[4]};
    return (int)pgloss_check_perceptual_batch_ex(n, a, (pgloss_color_space)space, st);
}

int pgloss_py_physical_from_perceptual_batch(size_t n, const double *const q[5], int normalization, int space,
                                             double *const out[6], signed char *st)
{
    const pgloss_perceptual_array a = {q[0], q[1], q[2], q[3], q[4]};
    const pgloss_physical_out p = {out[0], out[1], out[2], out[3], out[4], out[5]};
    return (int)pgloss_physical_from_perceptual_batch_ex(n, a, (pgloss_normalization)normalization,
                                                         (pgloss_color_space)space, p, st);
}

int pgloss_py_perceptual_from_physical_batch(size_t n, const double *const cols[6], int normalization, int space,
                                             double *const q[5], signed char *st)
{
    const pgloss_physical_array p = physical_array(cols, normalization);
    const pgloss_perceptual_out o = {q[0], q[1], q[2], q[3], q[4]};
    return (int)pgloss_perceptual_from_physical_batch_ex(n, &p, (pgloss_color_space)space, o, st);
}

int pgloss_py_rgb_from_lab_batch(size_t n, const double *const lab[3], int space, double *const rgb[3],
                                 signed char *st)
{
    const pgloss_lab_array a = {lab[0], lab[1], lab[2]};
    const pgloss_rgb_out_d o = {rgb[0], rgb[1], rgb[2]};
    return (int)pgloss_rgb_from_lab_batch_ex(n, a, (pgloss_color_space)space, o, st);
}

int pgloss_py_lab_from_rgb_batch(size_t n, const double *const rgb[3], int space, double *const lab[3],
                                 signed char *st)
{
    const pgloss_rgb_array_d a = {rgb[0], rgb[1], rgb[2]};
    const pgloss_lab_out o = {lab[0], lab[1], lab[2]};
    return (int)pgloss_lab_from_rgb_batch_ex(n, a, (pgloss_color_space)space, o, st);
}

int pgloss_py_eval_pdf_batch_materials(const float *const cols[6], int normalization, unsigned lobes, size_t n,
                                       pgloss_vec3_array wo, pgloss_vec3_array wi, pgloss_rgb_out f, float *pdf,
                                       signed char *st)
{
    const pgloss_material_array m = material_array(cols, normalization);
    return (int)pgloss_eval_pdf_batch_materials_ex(NULL, &m, lobes, n, wo, wi, f, pdf, st);
}

int pgloss_py_sample_batch_materials(const float *const cols[6], int normalization, unsigned lobes, size_t n,
                                     pgloss_vec3_array wo, const float *const u[3], pgloss_vec3_out wi, float *pdf,
                                     pgloss_rgb_out weight, unsigned char *lobe, signed char *st)
{
    const pgloss_material_array m = material_array(cols, normalization);
    return (int)pgloss_sample_batch_materials_ex(NULL, &m, lobes, n, wo, u[0], u[1], u[2], wi, pdf, weight, lobe,
                                                 st);
}

int pgloss_py_eval_pdf_batch_materials_d(const double *const cols[6], int normalization, unsigned lobes, size_t n,
                                         pgloss_vec3_array_d wo, pgloss_vec3_array_d wi, pgloss_rgb_out_d f,
                                         double *pdf, signed char *st)
{
    const pgloss_physical_array m = physical_array(cols, normalization);
    return (int)pgloss_eval_pdf_batch_materials_d_ex(NULL, &m, lobes, n, wo, wi, f, pdf, st);
}

int pgloss_py_sample_batch_materials_d(const double *const cols[6], int normalization, unsigned lobes, size_t n,
                                       pgloss_vec3_array_d wo, const double *const u[3], pgloss_vec3_out_d wi,
                                       double *pdf, pgloss_rgb_out_d weight, unsigned char *lobe, signed char *st)
{
    const pgloss_physical_array m = physical_array(cols, normalization);
    return (int)pgloss_sample_batch_materials_d_ex(NULL, &m, lobes, n, wo, u[0], u[1], u[2], wi, pdf, weight, lobe,
                                                   st);
}
