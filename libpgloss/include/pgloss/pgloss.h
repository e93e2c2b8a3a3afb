// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
/*
 * pgloss — the psychophysically-based light reflection model of Pellacini, Ferwerda &
 * Greenberg, "Toward a Psychophysically-Based Light Reflection Model for Image Synthesis",
 * SIGGRAPH 2000: the isotropic Ward BRDF (eq. 2) re-expressed in perceptual terms — CIELAB
 * lightness L, contrast gloss c and distinctness-of-image gloss d (eqs. 3–8) — with a
 * perceptually uniform gloss distance (eq. 5).
 *
 * C11, libm only, no global mutable state, thread-safe, no allocation anywhere.
 */
#ifndef PGLOSS_PGLOSS_H
#define PGLOSS_PGLOSS_H

#include "pgloss/version.h"
#include "pgloss/status.h"
#include "pgloss/brdf.h"
#include "pgloss/batch.h"
#include "pgloss/color.h"
#include "pgloss/perceptual.h"
#include "pgloss/perceptual_batch.h"
#include "pgloss/glossmeter.h"
#include "pgloss/bridge.h"
#include "pgloss/bridge_model.h"

#endif /* PGLOSS_PGLOSS_H */
