// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/* CIELAB (D65) ↔ linear RGB of a working colour space, for the colour part of the paper's
 * Fig. 13. The matrices are derived (in 40-digit arithmetic) from the primaries and the white
 * of each space (D65 is (0.3127, 0.3290)), so that neutral L*a*b* maps to R = G = B. */
#include "internal.h"
#include "perceptual_d.h"
#include "pgloss/perceptual.h"

/* RGB ↔ XYZ (D65) per working space, indexed by pgloss_color_space. Printed by
 * `python3 tests/vectors/generate.py --print-color-matrices` (40-digit derivation from the
 * primaries and whites; ACEScg includes the Bradford adaptation ACES white → D65). Row 1
 * of to_xyz is the space's luminance; for Rec. 709 it equals PGLOSS_LUMA_*. */
typedef struct space_matrices {
    double to_xyz[3][3];
    double from_xyz[3][3];
} space_matrices;

static const space_matrices SPACES[4] = {
    { /* linear_rec709 */
        {{0.41239079926595948, 0.35758433938387796, 0.18048078840183429},
         {0.21263900587151036, 0.71516867876775593, 0.072192315360733715},
         {0.019330818715591851, 0.11919477979462599, 0.95053215224966058}},
        {{3.2409699419045213, -1.5373831775700935, -0.49861076029300328},
         {-0.96924363628087983, 1.8759675015077207, 0.041555057407175613},
         {0.055630079696993608, -0.20397695888897656, 1.0569715142428786}},
    },
    { /* acescg */
        {{0.65223754188628869, 0.12823613599971256, 0.16998224916567053},
         {0.26767218012533683, 0.67433998880155077, 0.057987831073112443},
         {-0.0053818157663877058, 0.0013690602090958336, 1.0930705063171704}},
        {{1.6605853264911827, -0.31529556082587068, -0.24150932760837673},
         {-0.65992606322415459, 1.6083914695660548, 0.017298594705445494},
         {0.009002569137834213, -0.0035668763903373268, 0.91364331276310418}},
    },
    { /* linear_display_p3 */
        {{0.48657094864821626, 0.26566769316909294, 0.19821728523436249},
         {0.22897456406974884, 0.69173852183650619, 0.079286914093744998},
         {0, 0.045113381858902575, 1.0439443689009757}},
        {{2.4934969119414245, -0.93138361791912361, -0.40271078445071684},
         {-0.82948896956157503, 1.7626640603183468, 0.023624685841943591},
         {0.035845830243784335, -0.076172389268041707, 0.95688452400768731}},
    },
    { /* linear_rec2020 */
        {{0.63695804830129132, 0.14461690358620838, 0.16888097516417205},
         {0.26270021201126703, 0.67799807151887104, 0.059301716469861945},
         {0, 0.028072693049087508, 1.0609850577107909}},
        {{1.7166511879712676, -0.35567078377639239, -0.2533662813736598},
         {-0.66668435183248898, 1.616481236634939, 0.015768545813911131},
         {0.017639857445310915, -0.042770613257808655, 0.94210312123547402}},
    },
};

const double *pgloss__from_xyz_matrix(pgloss_color_space space)
{
    return &SPACES[space].from_xyz[0][0];
}

const double *pgloss__to_xyz_matrix(pgloss_color_space space)
{
    return &SPACES[space].to_xyz[0][0];
}

pgloss_status pgloss_rgb_from_lab_ex(const double lab[3], pgloss_color_space space, double rgb[3])
{
    if (!rgb)
        return PGLOSS_ERR_NULL;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    if (!lab)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    /* The batch's per-element code (perceptual_d.h): the same bits. A channel within the
     * tolerance below 0 is on the gamut boundary up to rounding: it is returned as 0, so that
     * what this accepts every other function accepts too. */
    return (pgloss_status)pgloss__rgb_from_lab_k(lab[0], lab[1], lab[2],
                                                 pgloss__from_xyz_matrix(space), &rgb[0],
                                                 &rgb[1], &rgb[2]);
}

pgloss_status pgloss_rgb_from_lab(const double lab[3], double rgb[3])
{
    return pgloss_rgb_from_lab_ex(lab, PGLOSS_COLOR_SPACE_LINEAR_REC709, rgb);
}

pgloss_status pgloss_lab_from_rgb_ex(const double rgb[3], pgloss_color_space space, double lab[3])
{
    if (!lab)
        return PGLOSS_ERR_NULL;
    lab[0] = lab[1] = lab[2] = 0.0;
    if (!rgb)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    /* The batch's per-element code (perceptual_d.h): the same bits. */
    double Y;
    return (pgloss_status)pgloss__lab_from_rgb_k(rgb[0], rgb[1], rgb[2],
                                                 pgloss__to_xyz_matrix(space), &lab[0], &lab[1],
                                                 &lab[2], &Y);
}

pgloss_status pgloss_lab_from_rgb(const double rgb[3], double lab[3])
{
    return pgloss_lab_from_rgb_ex(rgb, PGLOSS_COLOR_SPACE_LINEAR_REC709, lab);
}

pgloss_status pgloss_luminance_ex(const double rgb[3], pgloss_color_space space, double *Y)
{
    if (!Y)
        return PGLOSS_ERR_NULL;
    *Y = 0.0;
    if (!rgb)
        return PGLOSS_ERR_NULL;
    if (!pgloss__valid_color_space(space))
        return PGLOSS_ERR_ARGUMENT;
    if (!isfinite(rgb[0]) || !isfinite(rgb[1]) || !isfinite(rgb[2]))
        return PGLOSS_ERR_NONFINITE;
    const double *w = SPACES[space].to_xyz[1];
    const double y = w[0] * rgb[0] + w[1] * rgb[1] + w[2] * rgb[2];
    if (!isfinite(y))
        return PGLOSS_ERR_NONFINITE;
    *Y = y;
    return PGLOSS_OK;
}

pgloss_status pgloss_luminance(const double rgb[3], double *Y)
{
    return pgloss_luminance_ex(rgb, PGLOSS_COLOR_SPACE_LINEAR_REC709, Y);
}
