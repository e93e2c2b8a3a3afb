// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* CIELAB (D65) ↔ linear Rec. 709 RGB for the colour part of the paper's Fig. 13. The matrices
 * are derived (in 40-digit arithmetic) from the Rec. 709 primaries and the D65 chromaticity
 * (0.3127, 0.3290), so that neutral L*a*b* maps to R = G = B. */
#include "internal.h"
#include "pgloss/perceptual.h"

static const double RGB_TO_XYZ[3][3] = {
    {0.41239079926595948, 0.35758433938387796, 0.18048078840183429},
    {0.21263900587151036, 0.71516867876775593, 0.072192315360733715},
    {0.019330818715591851, 0.11919477979462599, 0.95053215224966058},
};
static const double XYZ_TO_RGB[3][3] = {
    {3.2409699419045213, -1.5373831775700935, -0.49861076029300328},
    {-0.96924363628087983, 1.8759675015077207, 0.041555057407175613},
    {0.055630079696993608, -0.20397695888897656, 1.0569715142428786},
};
#define WHITE_X (0.3127 / 0.3290)
#define WHITE_Z (0.3583 / 0.3290)
#define DELTA (6.0 / 29.0)

/* CIELAB's companding function and its inverse (CIE 15:2004), in the exact rational form. */
static double lab_f(double t)
{
    return t > PGLOSS_CIE_EPSILON ? cbrt(t) : (PGLOSS_CIE_KAPPA * t + 16.0) / 116.0;
}

static double lab_finv(double t)
{
    return t > DELTA ? t * t * t : 3.0 * DELTA * DELTA * (t - 4.0 / 29.0);
}

static void mul3(const double M[3][3], const double v[3], double out[3])
{
    for (int r = 0; r < 3; ++r)
        out[r] = M[r][0] * v[0] + M[r][1] * v[1] + M[r][2] * v[2];
}

pgloss_status pgloss_rgb_from_lab(const double lab[3], double rgb[3])
{
    if (!rgb)
        return PGLOSS_ERR_NULL;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    if (!lab)
        return PGLOSS_ERR_NULL;
    if (!isfinite(lab[0]) || !isfinite(lab[1]) || !isfinite(lab[2]))
        return PGLOSS_ERR_NONFINITE;
    if (lab[0] < 0.0 || lab[0] > 100.0)
        return PGLOSS_ERR_LIGHTNESS;
    const double fy = (lab[0] + 16.0) / 116.0;
    double xyz[3], out[3];
    xyz[0] = WHITE_X * lab_finv(fy + lab[1] / 500.0);
    pgloss_luminance_from_lightness(lab[0], &xyz[1]); /* exact on both branches */
    xyz[2] = WHITE_Z * lab_finv(fy - lab[2] / 200.0);
    mul3(XYZ_TO_RGB, xyz, out);
    if (!isfinite(out[0]) || !isfinite(out[1]) || !isfinite(out[2]))
        return PGLOSS_ERR_NONFINITE;
    rgb[0] = out[0]; rgb[1] = out[1]; rgb[2] = out[2];
    for (int k = 0; k < 3; ++k)
        if (out[k] < -PGLOSS_BOUNDARY_TOLERANCE)
            return PGLOSS_ERR_GAMUT;
    /* Within the tolerance below 0 a channel is on the gamut boundary up to rounding: it is
     * returned as 0, so that what this accepts every other function accepts too. */
    for (int k = 0; k < 3; ++k)
        rgb[k] = out[k] < 0.0 ? 0.0 : out[k];
    return PGLOSS_OK;
}

pgloss_status pgloss_lab_from_rgb(const double rgb[3], double lab[3])
{
    if (!lab)
        return PGLOSS_ERR_NULL;
    lab[0] = lab[1] = lab[2] = 0.0;
    if (!rgb)
        return PGLOSS_ERR_NULL;
    if (!isfinite(rgb[0]) || !isfinite(rgb[1]) || !isfinite(rgb[2]))
        return PGLOSS_ERR_NONFINITE;
    if (rgb[0] < 0.0 || rgb[1] < 0.0 || rgb[2] < 0.0)
        return PGLOSS_ERR_NEGATIVE;
    double xyz[3];
    mul3(RGB_TO_XYZ, rgb, xyz);
    const double fx = lab_f(xyz[0] / WHITE_X), fy = lab_f(xyz[1]), fz = lab_f(xyz[2] / WHITE_Z);
    const double out[3] = {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
    if (!isfinite(out[0]) || !isfinite(out[1]) || !isfinite(out[2]))
        return PGLOSS_ERR_NONFINITE;
    lab[0] = out[0]; lab[1] = out[1]; lab[2] = out[2];
    return PGLOSS_OK;
}

pgloss_status pgloss_luminance(const double rgb[3], double *Y)
{
    if (!Y)
        return PGLOSS_ERR_NULL;
    *Y = 0.0;
    if (!rgb)
        return PGLOSS_ERR_NULL;
    if (!isfinite(rgb[0]) || !isfinite(rgb[1]) || !isfinite(rgb[2]))
        return PGLOSS_ERR_NONFINITE;
    const double y = pgloss__luminance3(rgb[0], rgb[1], rgb[2]);
    if (!isfinite(y))
        return PGLOSS_ERR_NONFINITE;
    *Y = y;
    return PGLOSS_OK;
}
