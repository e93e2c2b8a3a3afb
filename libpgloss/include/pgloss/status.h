// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss/status.h — status codes returned by every pgloss function that can fail.
 *
 * Convention: PGLOSS_OK is zero, warnings are positive (the result is usable but
 * outside what the paper validated), errors are negative (the result was replaced
 * by the documented fallback, usually zero). Every output of a failed call is
 * still written with a finite, defined value, so a caller that ignores the status
 * never reads uninitialised memory, NaN or Inf.
 */
#ifndef PGLOSS_STATUS_H
#define PGLOSS_STATUS_H

#include "pgloss/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum pgloss_status {
    PGLOSS_OK = 0,
    /* Warnings (> 0): the value is computed, but outside the paper's trusted range. */
    PGLOSS_WARN_ALPHA_UNTRUSTED = 1,   /* α > 0.2 (d < 0.8): Ward's lobe is not normalised there (paper §4) */

    /* Errors (< 0): the outputs hold the documented fallback. */
    PGLOSS_ERR_NULL = -1,              /* a required pointer argument is NULL */
    PGLOSS_ERR_NONFINITE = -2,         /* an input is NaN or ±Inf, or is finite but beyond the
                                          range the function can represent: a float material
                                          parameter above FLT_MAX, or a double input whose
                                          result would overflow to ±Inf (e.g. L* > 6.6e104) */
    PGLOSS_ERR_NEGATIVE = -3,          /* a reflectance (ρd, ρs, Y, c) is negative */
    PGLOSS_ERR_ALPHA = -4,             /* α ≤ 0 (equivalently d ≥ 1) */
    PGLOSS_ERR_ENERGY = -5,            /* ρd + ρs > 1 in some channel: the paint reflects more than it receives */
    PGLOSS_ERR_ENVELOPE = -6,          /* c is beyond the envelope of gloss space at this lightness (Fig. 10) */
    PGLOSS_ERR_LIGHTNESS = -7,         /* L* outside [0, 100] */
    PGLOSS_ERR_GAMUT = -8,             /* the CIELAB colour has no non-negative linear Rec. 709 RGB */
    PGLOSS_ERR_DIRECTION = -9,         /* a direction is zero-length or not finite */
    PGLOSS_ERR_NORMALIZATION = -10,    /* unknown pgloss_normalization value */
    PGLOSS_ERR_ARGUMENT = -11,         /* another argument is out of its domain (documented per function) */
    PGLOSS_ERR_RANDOM = -12,           /* a random number is NaN (every other value, ±Inf
                                          included, is clamped to [0, 1 - 2^-24]) */
    /* The gloss bridge (bridge.h): the paint is out of the target's reach; the outputs hold
       the nearest reachable paint's parameters. */
    PGLOSS_ERR_BRIDGE_BASE = -13,      /* a base colour channel would leave [0, 1] */
    PGLOSS_ERR_BRIDGE_SPECULAR = -14,  /* F0 outside the target's range (c too high or too low) */
    PGLOSS_ERR_BRIDGE_ROUGHNESS = -15  /* α outside the target's range (d too high or too low) */
} pgloss_status;

/* A static, human-readable English sentence naming the reason; never NULL. */
PGLOSS_API const char *pgloss_status_string(pgloss_status status);

/* The enumerator's name, e.g. "PGLOSS_ERR_ENERGY"; "PGLOSS_UNKNOWN" for other values. */
PGLOSS_API const char *pgloss_status_name(pgloss_status status);

#ifdef __cplusplus
}
#endif

#endif /* PGLOSS_STATUS_H */
