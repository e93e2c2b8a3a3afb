// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
#include "pgloss/status.h"

const char *pgloss_status_string(pgloss_status status)
{
    switch (status) {
    case PGLOSS_OK: return "no error";
    case PGLOSS_WARN_ALPHA_UNTRUSTED:
        return "alpha > 0.2 (d < 0.8): outside the range the paper trusts; Ward's lobe is not normalised there";
    case PGLOSS_ERR_NULL: return "a required pointer argument is NULL";
    case PGLOSS_ERR_NONFINITE: return "an input is NaN or infinite, or so large that a parameter exceeds float range or the result would overflow";
    case PGLOSS_ERR_NEGATIVE: return "a reflectance or gloss value is negative";
    case PGLOSS_ERR_ALPHA: return "alpha <= 0 (d >= 1): the specular lobe has no spread";
    case PGLOSS_ERR_ENERGY:
        return "rho_d + rho_s > 1 in some channel: the paint reflects more energy than it receives";
    case PGLOSS_ERR_ENVELOPE:
        return "contrast gloss c is beyond the envelope of gloss space at this lightness (rho_d + rho_s > 1)";
    case PGLOSS_ERR_LIGHTNESS: return "lightness L* is outside [0, 100]";
    case PGLOSS_ERR_GAMUT: return "the CIELAB colour has no non-negative linear Rec. 709 RGB (out of gamut)";
    case PGLOSS_ERR_DIRECTION: return "a direction is zero-length or not finite";
    case PGLOSS_ERR_NORMALIZATION: return "unknown normalization of the specular lobe";
    case PGLOSS_ERR_ARGUMENT: return "an argument is outside its documented domain";
    case PGLOSS_ERR_RANDOM: return "a random number is NaN";
    case PGLOSS_ERR_BRIDGE_BASE:
        return "out of the target's reach: the lightness needs a base colour channel outside [0, 1] after the target's diffuse dimming";
    case PGLOSS_ERR_BRIDGE_SPECULAR:
        return "out of the target's reach: the contrast gloss c needs an F0 (IOR, specular weight) outside the target's range";
    case PGLOSS_ERR_BRIDGE_ROUGHNESS:
        return "out of the target's reach: the DOI gloss d needs a roughness outside the target's range";
    }
    return "unknown pgloss status code";
}

const char *pgloss_status_name(pgloss_status status)
{
    switch (status) {
    case PGLOSS_OK: return "PGLOSS_OK";
    case PGLOSS_WARN_ALPHA_UNTRUSTED: return "PGLOSS_WARN_ALPHA_UNTRUSTED";
    case PGLOSS_ERR_NULL: return "PGLOSS_ERR_NULL";
    case PGLOSS_ERR_NONFINITE: return "PGLOSS_ERR_NONFINITE";
    case PGLOSS_ERR_NEGATIVE: return "PGLOSS_ERR_NEGATIVE";
    case PGLOSS_ERR_ALPHA: return "PGLOSS_ERR_ALPHA";
    case PGLOSS_ERR_ENERGY: return "PGLOSS_ERR_ENERGY";
    case PGLOSS_ERR_ENVELOPE: return "PGLOSS_ERR_ENVELOPE";
    case PGLOSS_ERR_LIGHTNESS: return "PGLOSS_ERR_LIGHTNESS";
    case PGLOSS_ERR_GAMUT: return "PGLOSS_ERR_GAMUT";
    case PGLOSS_ERR_DIRECTION: return "PGLOSS_ERR_DIRECTION";
    case PGLOSS_ERR_NORMALIZATION: return "PGLOSS_ERR_NORMALIZATION";
    case PGLOSS_ERR_ARGUMENT: return "PGLOSS_ERR_ARGUMENT";
    case PGLOSS_ERR_RANDOM: return "PGLOSS_ERR_RANDOM";
    case PGLOSS_ERR_BRIDGE_BASE: return "PGLOSS_ERR_BRIDGE_BASE";
    case PGLOSS_ERR_BRIDGE_SPECULAR: return "PGLOSS_ERR_BRIDGE_SPECULAR";
    case PGLOSS_ERR_BRIDGE_ROUGHNESS: return "PGLOSS_ERR_BRIDGE_ROUGHNESS";
    }
    return "PGLOSS_UNKNOWN";
}
